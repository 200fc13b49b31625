#include "robot/ArmCapsules.h"

#include "common/SegmentDistance.h"

#include <algorithm>
#include <limits>

namespace geolattice {

ArmCapsules armCapsules(const ArmShape& s, const std::array<Eigen::Vector3d, 6>& o) {
  const Eigen::Vector3d u = (o[3] - o[2]).normalized();  // joints 2–4's axis
  const Eigen::Vector3d joint5 = (o[4] - o[3]).normalized(), joint6 = (o[5] - o[4]).normalized();
  ArmCapsules arm;
  arm[kBase] = {Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, o[0].z() + s.baseTop), 0};
  arm[kShoulder] = {o[0] + s.shoulderFrom * u, o[0] + s.shoulderTo * u, 0};
  arm[kUpperArm] = {o[0] + s.shoulderOffset * u, o[1] + s.shoulderOffset * u, 0};
  arm[kElbow] = {o[1] + s.elbowFrom * u, o[1] + s.elbowTo * u, 0};
  arm[kForearm] = {o[1] + s.forearmOffset * u, o[2] + s.forearmOffset * u, 0};
  arm[kWrist1] = {o[2] + s.wrist1From * u, o[3] + s.wrist1Past * u, 0};
  arm[kWrist2] = {o[3] - s.wrist2Behind * joint5, o[4], 0};
  arm[kWrist3] = {o[4] - s.wrist3Behind * joint6, o[5], 0};
  for (int p = 0; p < kArmParts; ++p) {
    arm[p].radius = s.radius[p];
  }
  return arm;
}

double lowestArmSurface(const ArmCapsules& arm) {
  double lowest = std::numeric_limits<double>::infinity();
  for (int p = kFirstNearFloor; p <= kLastNearFloor; ++p) {
    lowest = std::min(lowest, std::min(arm[p].a.z(), arm[p].b.z()) - arm[p].radius);
  }
  return lowest;
}

double armSegmentDistance(const ArmCapsules& arm, int first, int last, const Eigen::Vector3d& p0,
                          const Eigen::Vector3d& p1) {
  double d = std::numeric_limits<double>::infinity();
  for (int p = first; p <= last; ++p) {
    d = std::min(d, segmentDistance(arm[p].a, arm[p].b, p0, p1) - arm[p].radius);
  }
  return d;
}

}  // namespace geolattice
