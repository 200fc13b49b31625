#include "robot/StraightMove.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace geolattice {

namespace {

constexpr double kSmallestStep = 1.0 / 4096;  ///< of the move: below it a jump is a jump
constexpr double kArrivalTolerance = 1e-6;    ///< rad: the tracked joints are the planned ones

double largestChange(const JointVector& a, const JointVector& b) {
  double d = 0;
  for (int j = 0; j < 6; ++j)
    d = std::max(d, std::abs(a[j] - b[j]));
  return d;
}

/// The IK solution of the flange pose nearest to `at` (each joint moved by less than π, as the
/// controller tracks it), false when no branch reaches the pose.
bool nearestSolution(const RobotModel& robot, const Isometry& flange, const JointVector& at,
                     JointVector& nearest) {
  double best = INFINITY;
  for (int branch = 0; branch < 8; ++branch) {
    JointVector q;
    if (!inverseKinematicsBranch(robot, flange, branch, q, at[5]))
      continue;
    for (int j = 0; j < 6; ++j)
      q[j] = at[j] + std::remainder(q[j] - at[j], 2 * M_PI);
    const double d = largestChange(q, at);
    if (d < best) {
      best = d;
      nearest = q;
    }
  }
  return std::isfinite(best);
}

}  // namespace

bool followStraightMove(const RobotModel& robot, const Isometry& partOnFlange,
                        const JointVector& from, const JointVector& to, double maxStep,
                        StraightMoveVia& via) {
  via = {};
  const Isometry a = forwardKinematics(robot, from) * partOnFlange;
  const Isometry b = forwardKinematics(robot, to) * partOnFlange;
  const Eigen::Quaterniond ra(a.linear()), rb(b.linear());
  const Isometry flangeOnPart = partOnFlange.inverse();
  auto flangeAt = [&](double t) {
    Isometry tcp = Isometry::Identity();
    tcp.linear() = ra.slerp(t, rb).toRotationMatrix();
    tcp.translation() = (1 - t) * a.translation() + t * b.translation();
    return Isometry(tcp * flangeOnPart);
  };
  // Tracked steps of at most half the bound: a flip (about π in joints 4 and 6) cannot hide
  // inside one of them.
  const double track = 0.5 * maxStep;
  const double first = 1.0 / std::max(1.0, std::ceil(largestChange(from, to) / track));
  double t = 0, h = first;
  JointVector at = from, lastWaypoint = from;
  while (t < 1) {
    const double next = std::min(1.0, t + h);
    JointVector q;
    if (!nearestSolution(robot, flangeAt(next), at, q) || largestChange(q, at) > track) {
      h *= 0.5;
      if (h < kSmallestStep)
        return false;
      continue;
    }
    if (!withinLimits(robot, q))
      return false;
    if (largestChange(q, lastWaypoint) > maxStep) {
      via.t.push_back(t);
      via.joints.push_back(at);
      via.maxStep = std::max(via.maxStep, largestChange(at, lastWaypoint));
      lastWaypoint = at;
    }
    at = q;
    t = next;
    h = std::min(first, 2 * h);
  }
  via.maxStep = std::max(via.maxStep, largestChange(to, lastWaypoint));
  return largestChange(at, to) < kArrivalTolerance;
}

}  // namespace geolattice
