#pragma once
/// @file URKinematics.h
/// @brief Forward and analytic inverse kinematics of the Universal Robots UR5 (CB3) and UR5e
/// from their published DH parameters (standard DH, T_i = Rz(θ_i) Tz(d_i) Tx(a_i) Rx(α_i)),
/// with joint limits, joint speed limits and distances to the three singularities.
///
/// Inverse kinematics (closed form, up to 8 solutions: shoulder left/right × wrist up/down ×
/// elbow up/down). Derivation used here, in the base frame with P05 = the wrist centre (flange
/// origin moved back by d6 along the flange z axis):
///  - joints 2-4 move in the plane normal to z1 = (sin θ1, -cos θ1, 0), which lies d4 from the
///    base axis, so P05·z1 = d4: θ1 = ψ + asin(d4 / r) or ψ + π - asin(d4 / r), ψ = atan2(P05y, P05x);
///  - the flange axis has component cos θ5 along z1: cos θ5 = (P06·z1 - d4) / d6;
///  - z1 seen in the flange frame is (sin θ5 cos θ6, -sin θ5 sin θ6, cos θ5), which gives θ6
///    (free at the wrist singularity sin θ5 = 0: then θ6 = the `wristFreeAngle` argument);
///  - T14 = T01⁻¹ T06 (T45 T56)⁻¹ is a planar 3R chain in the x1-y1 plane: elbow by the law
///    of cosines, θ2 from the triangle, θ4 from the total angle θ2 + θ3 + θ4.
#include "robot/ArmCapsules.h"
#include "robot/Pose.h"

#include <array>
#include <string>
#include <vector>

namespace geolattice {

using JointVector = std::array<double, 6>;  ///< radians

struct RobotModel {
  std::string name;
  std::array<double, 6> d{}, a{}, alpha{};           ///< DH (m, rad)
  std::array<double, 6> lowerLimit{}, upperLimit{};  ///< rad
  std::array<double, 6> maxSpeed{};                  ///< rad/s
  double reach = 0;                                  ///< m, nominal
  ArmShape shape;  ///< the links' bodies around the DH chain (ArmCapsules.h)
};

RobotModel
ur5Model();  ///< UR5 CB3: d1 0.089159, a2 -0.425, a3 -0.39225, d4 0.10915, d5 0.09465, d6 0.0823; ±360°, 180°/s
RobotModel
ur5eModel();  ///< UR5e: d1 0.1625, a2 -0.425, a3 -0.3922, d4 0.1333, d5 0.0997, d6 0.0996; ±360°, 180°/s
/// "ur5" or "ur5e"; throws GeoLatticeError otherwise.
RobotModel robotModelByName(const std::string& name);

/// Whether every joint of q lies inside the robot's limits.
bool withinLimits(const RobotModel& robot, const JointVector& q);

/// Base -> flange transform.
Isometry forwardKinematics(const RobotModel& robot, const JointVector& q);

/// One IK branch: shoulder (0/1: θ1 = ψ + asin(d4/r) or ψ + π − asin(d4/r)), wrist (0/1:
/// θ5 = +acos or −acos), elbow (0/1: θ3 = +acos or −acos); branch = 4·shoulder + 2·wrist + elbow.
/// Returns false when that branch cannot reach the pose. Joints in (-π, π].
bool inverseKinematicsBranch(const RobotModel& robot, const Isometry& flange, int branch,
                             JointVector& q, double wristFreeAngle = 0.0);

/// All real solutions for the flange pose (0 to 8), each joint in (-π, π]. wristFreeAngle is
/// used for θ6 at the wrist singularity. Unreachable poses give an empty list.
std::vector<JointVector> inverseKinematics(const RobotModel& robot, const Isometry& flange,
                                           double wristFreeAngle = 0.0);

/// The origins of the DH frames 1–6 at q (m, base frame): the shoulder (d1 above the base), the
/// elbow, wrist 1 moved onto the DH plane, the wrist 2 and 3 joints and the flange. The DH
/// lines between them are not the links' bodies (armCapsules: the upper arm's tube, for one,
/// runs 136 mm off its line).
std::array<Eigen::Vector3d, 6> jointOrigins(const RobotModel& robot, const JointVector& q);

/// The arm's body at q (m, base frame): ArmCapsules.h.
ArmCapsules armCapsules(const RobotModel& robot, const JointVector& q);

/// Distances to the singularities at q (0 = singular): shoulder = distance of the wrist centre
/// from the cylinder of radius d4 about the base axis (m), elbow = |sin θ3|, wrist = |sin θ5|.
struct SingularityDistance {
  double shoulder = 0, elbow = 0, wrist = 0;
};
SingularityDistance singularityDistance(const RobotModel& robot, const JointVector& q);
/// Same, when the flange pose of q is already known (no forward kinematics).
SingularityDistance singularityDistance(const RobotModel& robot, const JointVector& q,
                                        const Isometry& flange);

}  // namespace geolattice
