// The UR arm's body as capsules (robot/ArmCapsules.h): where each capsule lies against the DH
// chain at known joint vectors, against analytic distances, and the lowest surface.
#include "robot/ArmCapsules.h"
#include "robot/URKinematics.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geolattice;

namespace {

void expectNear(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  EXPECT_LT((a - b).norm(), 1e-9) << a.transpose() << " vs " << b.transpose();
}

}  // namespace

TEST(ArmCapsules, EachPartLiesOffItsDHLineAsMeasured) {
  // UR5 at q = 0: the arm stretched along −x at the shoulder's height, joint 2's axis u along
  // −y (z1 = (sin θ1, −cos θ1, 0)).
  const RobotModel ur5 = ur5Model();
  const JointVector zero{0, 0, 0, 0, 0, 0};
  const std::array<Eigen::Vector3d, 6> o = jointOrigins(ur5, zero);
  const ArmCapsules arm = armCapsules(ur5, zero);
  const Eigen::Vector3d u(0, -1, 0);
  const double d1 = 0.089159;
  expectNear(o[1], Eigen::Vector3d(-0.425, 0, d1));
  // The upper arm's tube: 135.85 mm off its DH line along u (the line alone would miss it).
  expectNear(arm[kUpperArm].a, Eigen::Vector3d(0, 0, d1) + 0.13585 * u);
  expectNear(arm[kUpperArm].b, Eigen::Vector3d(-0.425, 0, d1) + 0.13585 * u);
  // The forearm's: 16.5 mm.
  expectNear(arm[kForearm].a, o[1] + 0.0165 * u);
  expectNear(arm[kForearm].b, o[2] + 0.0165 * u);
  // The joint housings along u, through their joints.
  expectNear(arm[kShoulder].a, o[0] - 0.075 * u);
  expectNear(arm[kShoulder].b, o[0] + 0.205 * u);
  expectNear(arm[kElbow].a, o[1] - 0.045 * u);
  expectNear(arm[kElbow].b, o[1] + 0.205 * u);
  expectNear(arm[kWrist1].a, o[2] - 0.045 * u);
  expectNear(arm[kWrist1].b, o[3] + 0.045 * u);
  expectNear(arm[kWrist2].b, o[4]);
  expectNear(arm[kWrist3].b, o[5]);
  expectNear(arm[kBase].a, Eigen::Vector3d::Zero());
  expectNear(arm[kBase].b, Eigen::Vector3d(0, 0, d1 + 0.07));
  EXPECT_EQ(arm[kElbow].radius, 0.062);
  EXPECT_EQ(arm[kForearm].radius, 0.045);
  // The UR5e: its own offsets (138 and 7 mm).
  const RobotModel ur5e = ur5eModel();
  const JointVector q{0.4, -1.1, 1.3, -0.7, 0.9, 0.2};
  const std::array<Eigen::Vector3d, 6> e = jointOrigins(ur5e, q);
  const ArmCapsules arm5e = armCapsules(ur5e, q);
  const Eigen::Vector3d ue = (e[3] - e[2]).normalized();
  EXPECT_NEAR(ue.dot(Eigen::Vector3d(std::sin(0.4), -std::cos(0.4), 0)), 1.0, 1e-12);
  expectNear(arm5e[kUpperArm].a, e[0] + 0.138 * ue);
  expectNear(arm5e[kForearm].b, e[2] + 0.007 * ue);
}

TEST(ArmCapsules, DistancesAreFromTheSurfaces) {
  ArmCapsules arm;
  arm.fill(Capsule{{0, 0, 5}, {0, 0, 5}, 0});  // far away
  arm[kForearm] = {{0, 0, 0}, {1, 0, 0}, 0.05};
  arm[kWrist2] = {{0, 2, 0}, {1, 2, 0}, 0.04};
  // A segment parallel to the forearm, 0.3 m off it: 0.25 m from its surface.
  EXPECT_NEAR(armSegmentDistance(arm, kUpperArm, kWrist1, {0, 0.3, 0}, {1, 0.3, 0}), 0.25, 1e-12);
  // Wrist 2 is nearer (0.2 − 0.04 below y = 2), but only when it is in the range.
  EXPECT_NEAR(armSegmentDistance(arm, kUpperArm, kWrist2, {0, 1.8, 0}, {1, 1.8, 0}), 0.16, 1e-12);
  EXPECT_NEAR(armSegmentDistance(arm, kUpperArm, kWrist1, {0, 1.8, 0}, {1, 1.8, 0}), 1.75, 1e-12);
  // Through the forearm: negative.
  EXPECT_LT(armSegmentDistance(arm, kForearm, kForearm, {0.5, -1, 0}, {0.5, 1, 0}), 0);
}

TEST(ArmCapsules, TheLowestSurfaceIsAHousingsNotAJoints) {
  // The lowest point of the moving parts' surfaces, below every joint origin by at least the
  // smallest radius (the DH lines alone would have given the origins' height).
  const RobotModel ur5 = ur5Model();
  for (const JointVector& q :
       {JointVector{0, 0.3, 0, 0, 0, 0}, JointVector{1, -0.4, 0.5, 0.1, 1.2, 0},
        JointVector{-2, -1.2, -1.9, 0.4, -0.6, 1}}) {
    const std::array<Eigen::Vector3d, 6> o = jointOrigins(ur5, q);
    const ArmCapsules arm = armCapsules(ur5, q);
    double expected = 1e9;
    for (int p = kUpperArm; p <= kWrist3; ++p) {
      expected = std::min({expected, arm[p].a.z() - arm[p].radius, arm[p].b.z() - arm[p].radius});
    }
    EXPECT_DOUBLE_EQ(lowestArmSurface(arm), expected);
    double lowestOrigin = 1e9;
    for (int k = 1; k < 6; ++k) {
      lowestOrigin = std::min(lowestOrigin, o[k].z());
    }
    EXPECT_LE(lowestArmSurface(arm), lowestOrigin - 0.041);  // every origin is inside a capsule
  }
}
