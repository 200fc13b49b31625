#pragma once
/// @file ArmCapsules.h
/// @brief The body of a UR arm as eight capsules (a segment and a radius each) around its DH
/// chain: what the robot checks against the floor, the nozzle and the part it holds.
///
/// The DH lines between the joints are not where the arm is. The UR5's upper arm tube runs
/// 136 mm from its DH line along joint 2's axis (the shoulder offset), the forearm's 16.5 mm,
/// and the joint housings around the elbow and the wrists are cylinders of 40–67 mm radius
/// along their axes. Measured against the manufacturer's collision meshes (Universal Robots'
/// ROS 2 description, meshes/ur5{,e}/collision/*.stl placed by its kinematics): every vertex of
/// every link lies inside the capsules of its model, by 0.9 mm or more, at 200 random joint
/// vectors (scripts/check-arm-capsules.py reproduces it). The numbers are in URKinematics.cpp
/// next to each model's DH parameters.
///
/// With u the joint 2 axis (joints 2, 3 and 4 are parallel; u = (origins[3] − origins[2]) / d4,
/// origins as URKinematics.h's jointOrigins):
///  - base: the column from the floor to baseTop above the shoulder origin (origins[0]);
///  - shoulder: the joint 2 housing along u through origins[0];
///  - upper arm: origins[0] → origins[1], moved shoulderOffset along u;
///  - elbow: the joint 3 housing along u through origins[1];
///  - forearm: origins[1] → origins[2], moved forearmOffset along u;
///  - wrist 1: along u from origins[2] to origins[3] (the joint 4 housing and the arm to joint 5);
///  - wrist 2: along joint 5's axis to origins[4];
///  - wrist 3: along joint 6's axis to the flange (origins[5]): carries the plate.
#include <Eigen/Core>
#include <array>

namespace geolattice {

struct Capsule {
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
  double radius = 0;  ///< same units as a and b
};

enum ArmPart {
  kBase,
  kShoulder,
  kUpperArm,
  kElbow,
  kForearm,
  kWrist1,
  kWrist2,
  kWrist3,
  kArmParts
};

/// The parts checked against each obstacle, as ranges [first, last] of ArmPart:
///  - the nozzle: base to wrist 1 (wrist 2 and 3 are behind the plate, which the collision
///    verifier checks against the nozzle);
///  - the part held: base to wrist 2 (wrist 3 carries the plate);
///  - the floor: upper arm to wrist 3 (the base and the shoulder do not move up or down).
constexpr int kFirstNearNozzle = kBase, kLastNearNozzle = kWrist1;
constexpr int kFirstNearPart = kBase, kLastNearPart = kWrist2;
constexpr int kFirstNearFloor = kUpperArm, kLastNearFloor = kWrist3;

/// A UR arm's body around its DH chain (m; the layout in the file comment).
struct ArmShape {
  double shoulderOffset = 0;                ///< the upper arm tube's axis from its DH line, along u
  double forearmOffset = 0;                 ///< the forearm tube's axis from its DH line, along u
  double baseTop = 0;                       ///< the base column's top above origins[0]
  double shoulderFrom = 0, shoulderTo = 0;  ///< the shoulder along u from origins[0]
  double elbowFrom = 0, elbowTo = 0;        ///< the elbow along u from origins[1]
  double wrist1From = 0;                    ///< wrist 1 starts this far along u from origins[2]
  double wrist1Past = 0;                    ///< and ends this far past origins[3] along u
  double wrist2Behind = 0;  ///< wrist 2 starts this far behind origins[3] along joint 5's axis
  double wrist3Behind = 0;  ///< wrist 3 starts this far behind origins[4] along joint 6's axis
  std::array<double, kArmParts> radius{};
};

using ArmCapsules = std::array<Capsule, kArmParts>;

/// The capsules (m, base frame) of an arm of shape `shape` whose DH frames 1–6 have their
/// origins at `origins` (jointOrigins).
ArmCapsules armCapsules(const ArmShape& shape, const std::array<Eigen::Vector3d, 6>& origins);

/// Height (m, base frame z) of the lowest point of the parts that move up and down (upper arm
/// to wrist 3); the robot stands on z = 0.
double lowestArmSurface(const ArmCapsules& arm);

/// Least distance (m) of the surfaces of parts [first, last] from the segment p0–p1 (negative:
/// the segment enters one).
double armSegmentDistance(const ArmCapsules& arm, int first, int last, const Eigen::Vector3d& p0,
                          const Eigen::Vector3d& p1);

}  // namespace geolattice
