#include "robot/URKinematics.h"

#include "common/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geolattice {

namespace {

Isometry dhTransform(double theta, double d, double a, double alpha) {
  Isometry t = Isometry::Identity();
  const double ct = std::cos(theta), st = std::sin(theta), ca = std::cos(alpha),
               sa = std::sin(alpha);
  t.matrix() << ct, -st * ca, st * sa, a * ct,  //
      st, ct * ca, -ct * sa, a * st,            //
      0, sa, ca, d,                             //
      0, 0, 0, 1;
  return t;
}

double wrapAngle(double x) {
  if (x > -M_PI && x <= M_PI) {
    return x;  // what std::remainder returns here, without its cost (IK calls this 6 times)
  }
  x = std::remainder(x, 2.0 * M_PI);  // (-π, π]
  return x <= -M_PI ? x + 2.0 * M_PI : x;
}

RobotModel makeModel(const char* name, double d1, double a2, double a3, double d4, double d5,
                     double d6, double reach) {
  RobotModel r;
  r.name = name;
  r.d = {d1, 0, 0, d4, d5, d6};
  r.a = {0, a2, a3, 0, 0, 0};
  r.alpha = {M_PI / 2, 0, 0, M_PI / 2, -M_PI / 2, 0};
  r.lowerLimit.fill(-2 * M_PI);
  r.upperLimit.fill(2 * M_PI);
  r.maxSpeed.fill(M_PI);  // 180°/s
  r.reach = reach;
  return r;
}

}  // namespace

// The bodies (ArmCapsules.h): offsets from Universal Robots' ROS 2 description
// (config/ur5{,e}/physical_parameters.yaml: shoulder_offset, elbow_offset), spans and radii
// fitted to its collision meshes (scripts/check-arm-capsules.py: every vertex inside, by 0.9 mm
// or more, at 200 random joint vectors).

RobotModel ur5Model() {
  RobotModel r = makeModel("ur5", 0.089159, -0.425, -0.39225, 0.10915, 0.09465, 0.0823, 0.85);
  ArmShape& s = r.shape;
  s.shoulderOffset = 0.13585;
  s.forearmOffset = 0.0165;
  s.baseTop = 0.07;
  s.shoulderFrom = -0.075;
  s.shoulderTo = 0.205;
  s.elbowFrom = -0.045;
  s.elbowTo = 0.205;
  s.wrist1From = -0.045;
  s.wrist1Past = 0.045;
  s.wrist2Behind = 0.05;
  s.wrist3Behind = 0.05;
  s.radius = {0.111, 0.062, 0.060, 0.062, 0.045, 0.041, 0.041, 0.045};  // base: its cable outlet
  return r;
}

RobotModel ur5eModel() {
  RobotModel r = makeModel("ur5e", 0.1625, -0.425, -0.3922, 0.1333, 0.0997, 0.0996, 0.85);
  ArmShape& s = r.shape;
  s.shoulderOffset = 0.138;
  s.forearmOffset = 0.007;
  s.baseTop = 0.07;
  s.shoulderFrom = -0.075;
  s.shoulderTo = 0.21;
  s.elbowFrom = -0.05;
  s.elbowTo = 0.21;
  s.wrist1From = -0.075;
  s.wrist1Past = 0.045;
  s.wrist2Behind = 0.05;
  s.wrist3Behind = 0.05;
  s.radius = {0.077, 0.064, 0.061, 0.067, 0.051, 0.061, 0.041, 0.045};
  return r;
}

RobotModel robotModelByName(const std::string& name) {
  if (name == "ur5")
    return ur5Model();
  if (name == "ur5e")
    return ur5eModel();
  throw GeoLatticeError("unknown robot '" + name + "' (expected ur5 or ur5e)");
}

bool withinLimits(const RobotModel& robot, const JointVector& q) {
  for (int j = 0; j < 6; ++j) {
    if (q[j] < robot.lowerLimit[j] || q[j] > robot.upperLimit[j])
      return false;
  }
  return true;
}

Isometry forwardKinematics(const RobotModel& r, const JointVector& q) {
  Isometry t = Isometry::Identity();
  for (int i = 0; i < 6; ++i) {
    t = t * dhTransform(q[i], r.d[i], r.a[i], r.alpha[i]);
  }
  return t;
}

bool inverseKinematicsBranch(const RobotModel& r, const Isometry& flange, int branch,
                             JointVector& q, double wristFreeAngle) {
  const int shoulder = (branch >> 2) & 1, wrist = (branch >> 1) & 1, elbow = branch & 1;
  const double d1 = r.d[0], a2 = r.a[1], a3 = r.a[2], d4 = r.d[3], d5 = r.d[4], d6 = r.d[5];
  const Eigen::Vector3d p06 = flange.translation();
  const Eigen::Matrix3d r06 = flange.linear();
  const Eigen::Vector3d p05 = p06 - d6 * r06.col(2);
  const double rxy = std::hypot(p05.x(), p05.y());
  if (rxy < std::abs(d4)) {
    return false;  // wrist centre inside the shoulder cylinder: unreachable
  }
  const double psi = std::atan2(p05.y(), p05.x());
  const double phi = std::asin(std::clamp(d4 / rxy, -1.0, 1.0));
  const double theta1 = shoulder == 0 ? psi + phi : psi + M_PI - phi;
  const double s1 = std::sin(theta1), c1 = std::cos(theta1);
  const double c5 = (p06.x() * s1 - p06.y() * c1 - d4) / d6;
  if (std::abs(c5) > 1.0 + 1e-12) {
    return false;
  }
  const double theta5 = (wrist == 0 ? 1.0 : -1.0) * std::acos(std::clamp(c5, -1.0, 1.0));
  const double s5 = std::sin(theta5);
  // z1 in flange coordinates: (s5 c6, -s5 s6, c5).
  const Eigen::Vector3d u = r06.transpose() * Eigen::Vector3d(s1, -c1, 0);
  const double theta6 = std::abs(s5) < 1e-12 ? wristFreeAngle : std::atan2(-u.y() / s5, u.x() / s5);
  // Planar 3R chain in frame 1.
  const Isometry t01 = dhTransform(theta1, d1, 0, r.alpha[0]);
  const Isometry t45 = dhTransform(theta5, d5, 0, r.alpha[4]);
  const Isometry t56 = dhTransform(theta6, d6, 0, r.alpha[5]);
  const Isometry t14 = t01.inverse() * flange * (t45 * t56).inverse();
  const double x = t14.translation().x(), y = t14.translation().y();
  const double c3 = (x * x + y * y - a2 * a2 - a3 * a3) / (2 * a2 * a3);
  if (std::abs(c3) > 1.0 + 1e-12) {
    return false;
  }
  const double theta3 = (elbow == 0 ? 1.0 : -1.0) * std::acos(std::clamp(c3, -1.0, 1.0));
  const double theta2 =
      std::atan2(y, x) - std::atan2(a3 * std::sin(theta3), a2 + a3 * std::cos(theta3));
  // R14 = Rz(θ2 + θ3 + θ4) Rx(π/2): the total angle from its first column.
  const Eigen::Matrix3d r14 = t14.linear();
  const double theta4 = std::atan2(r14(1, 0), r14(0, 0)) - theta2 - theta3;
  q = {wrapAngle(theta1), wrapAngle(theta2), wrapAngle(theta3),
       wrapAngle(theta4), wrapAngle(theta5), wrapAngle(theta6)};
  return true;
}

std::vector<JointVector> inverseKinematics(const RobotModel& r, const Isometry& flange,
                                           double wristFreeAngle) {
  std::vector<JointVector> out;
  for (int branch = 0; branch < 8; ++branch) {
    JointVector q;
    if (!inverseKinematicsBranch(r, flange, branch, q, wristFreeAngle)) {
      continue;
    }
    // Degenerate branches (straight elbow, wrist singular, shoulder on the cylinder) repeat a solution.
    bool duplicate = false;
    for (const JointVector& o : out) {
      double d = 0;
      for (int i = 0; i < 6; ++i)
        d = std::max(d, std::abs(std::remainder(o[i] - q[i], 2 * M_PI)));
      duplicate |= d < 1e-12;
    }
    if (!duplicate) {
      out.push_back(q);
    }
  }
  return out;
}

std::array<Eigen::Vector3d, 6> jointOrigins(const RobotModel& r, const JointVector& q) {
  std::array<Eigen::Vector3d, 6> origins;
  Isometry t = Isometry::Identity();
  for (int i = 0; i < 6; ++i) {
    t = t * dhTransform(q[i], r.d[i], r.a[i], r.alpha[i]);
    origins[i] = t.translation();
  }
  return origins;
}

ArmCapsules armCapsules(const RobotModel& r, const JointVector& q) {
  return armCapsules(r.shape, jointOrigins(r, q));
}

SingularityDistance singularityDistance(const RobotModel& r, const JointVector& q) {
  return singularityDistance(r, q, forwardKinematics(r, q));
}

SingularityDistance singularityDistance(const RobotModel& r, const JointVector& q,
                                        const Isometry& t) {
  const Eigen::Vector3d p05 = t.translation() - r.d[5] * t.linear().col(2);
  SingularityDistance s;
  s.shoulder = std::hypot(p05.x(), p05.y()) - std::abs(r.d[3]);
  s.elbow = std::abs(std::sin(q[2]));
  s.wrist = std::abs(std::sin(q[4]));
  return s;
}

}  // namespace geolattice
