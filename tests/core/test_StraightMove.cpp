// The controller's straight move between two joint configurations (StraightMove.h): near the
// wrist singularity a small turn of the part turns joints 4 and 6 by much more; such a move is
// continuous and gets waypoints that keep the bound, each on the straight move itself (checked
// here by forward kinematics against the interpolated TCP pose). A wrist flip to the other
// solution of the same pose and a joint sent a whole turn round are not continuous.
#include "robot/StraightMove.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

using namespace geolattice;

namespace {

constexpr double kDeg = M_PI / 180.0;

double largestChange(const JointVector& a, const JointVector& b) {
  double d = 0;
  for (int j = 0; j < 6; ++j)
    d = std::max(d, std::abs(a[j] - b[j]));
  return d;
}

const Isometry kPartOnFlange(Eigen::Translation3d(0, 0, 0.04));

/// Two configurations 2 degrees from the wrist singularity (θ5 = 2°) with joints 4 and 6 turned
/// by ±40° against each other: the part turns by about 1.4° only.
struct NearSingularMove {
  JointVector from{0.9, -1.2, 1.9, -0.5, 2 * kDeg, 0.3};
  JointVector to{0.9, -1.2, 1.9, -0.5 + 40 * kDeg, 2 * kDeg, 0.3 - 40 * kDeg};
};

}  // namespace

TEST(StraightMove, NearTheWristSingularityAContinuousMoveGetsWaypointsOnTheLine) {
  const RobotModel robot = ur5Model();
  const NearSingularMove m;
  const Isometry a = forwardKinematics(robot, m.from) * kPartOnFlange;
  const Isometry b = forwardKinematics(robot, m.to) * kPartOnFlange;
  const double turn = Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() / kDeg;
  ASSERT_LT(turn, 5.0) << "the constructed move must turn the part little";

  const double bound = 20 * kDeg;
  StraightMoveVia via;
  ASSERT_TRUE(followStraightMove(robot, kPartOnFlange, m.from, m.to, bound, via));
  ASSERT_FALSE(via.joints.empty()) << "a 40 degree step needs waypoints under a 20 degree bound";
  ASSERT_EQ(via.t.size(), via.joints.size());
  const Eigen::Quaterniond ra(a.linear()), rb(b.linear());
  JointVector previous = m.from;
  double previousT = 0, largest = 0;
  for (size_t k = 0; k < via.joints.size(); ++k) {
    SCOPED_TRACE("waypoint " + std::to_string(k));
    const double t = via.t[k];
    EXPECT_GT(t, previousT);
    EXPECT_LT(t, 1.0);
    const Isometry at = forwardKinematics(robot, via.joints[k]) * kPartOnFlange;
    const Eigen::Vector3d onLine = (1 - t) * a.translation() + t * b.translation();
    EXPECT_LT((at.translation() - onLine).norm(), 1e-9);
    EXPECT_LT(
        Eigen::AngleAxisd(ra.slerp(t, rb).toRotationMatrix().transpose() * at.linear()).angle(),
        1e-7);
    largest = std::max(largest, largestChange(previous, via.joints[k]));
    previous = via.joints[k];
    previousT = t;
  }
  largest = std::max(largest, largestChange(previous, m.to));
  EXPECT_LE(largest, bound);
  EXPECT_NEAR(via.maxStep, largest, 1e-12);

  // Under a bound the direct step keeps, no waypoint.
  ASSERT_TRUE(followStraightMove(robot, kPartOnFlange, m.from, m.to, 50 * kDeg, via));
  EXPECT_TRUE(via.joints.empty());
  EXPECT_NEAR(via.maxStep, largestChange(m.from, m.to), 1e-12);
}

TEST(StraightMove, AFlipOrAWholeTurnIsNotContinuous) {
  const RobotModel robot = ur5Model();
  const NearSingularMove m;
  StraightMoveVia via;
  // The other wrist solution of the same pose (θ5 of the other sign, the shoulder as it is).
  JointVector flipped{};
  bool haveFlipped = false;
  for (const JointVector& q : inverseKinematics(robot, forwardKinematics(robot, m.to))) {
    if (q[4] < 0 && std::abs(std::remainder(q[0] - m.to[0], 2 * M_PI)) < 1e-6) {
      flipped = q;
      haveFlipped = true;
    }
  }
  ASSERT_TRUE(haveFlipped);
  ASSERT_LT(
      (forwardKinematics(robot, flipped).matrix() - forwardKinematics(robot, m.to).matrix()).norm(),
      1e-9);
  EXPECT_FALSE(followStraightMove(robot, kPartOnFlange, m.from, flipped, 20 * kDeg, via));
  // Joint 6 a whole turn further: the same pose, but the controller does not get there.
  JointVector wound = m.to;
  wound[5] += 2 * M_PI;
  EXPECT_FALSE(followStraightMove(robot, kPartOnFlange, m.from, wound, 20 * kDeg, via));
  // Past a joint limit on the way: the same move with joint 6 started at its limit.
  JointVector atLimit = m.from, endBeyond = m.to;
  atLimit[5] = robot.lowerLimit[5] + 10 * kDeg;
  endBeyond[5] = atLimit[5] - 40 * kDeg;
  EXPECT_FALSE(followStraightMove(robot, kPartOnFlange, atLimit, endBeyond, 20 * kDeg, via));
}
