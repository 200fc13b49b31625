// UR5 / UR5e kinematics and URScript pose helpers: the URScript manual's examples, the published
// zero-joint poses, and FK(IK(T)) = T for 10 000 random reachable poses, every solution.
#include "common/Error.h"
#include "robot/Pose.h"
#include "robot/URKinematics.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

using namespace geolattice;

namespace {

void expectPose(const UrPose& got, const UrPose& want, double tol) {
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(got[i], want[i], tol) << "component " << i;
  }
}

double poseError(const Isometry& a, const Isometry& b) {
  return std::max((a.translation() - b.translation()).norm(),
                  (a.linear() - b.linear()).cwiseAbs().maxCoeff());
}

}  // namespace

TEST(Pose, UrscriptManualExamples) {
  expectPose(poseTrans({.2, .5, .1, 1.57, 0, 0}, {.2, .5, .6, 1.57, 0, 0}),
             {0.4, -0.0996, 0.60048, 3.14, 0, 0}, 5e-6);
  expectPose(poseInv({.2, .5, .1, 1.57, 0, 3.14}),
             {0.19324, 0.41794, -0.29662, 1.23993, 0, 2.47985}, 5e-6);
}

TEST(Pose, RotationVectorNearZeroAndPi) {
  for (double angle : {0.0, 1e-15, 1e-9, 1e-4, 1.0, M_PI - 1e-4, M_PI - 1e-9, M_PI}) {
    const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
    const Eigen::Vector3d rv = angle * axis;
    const Eigen::Matrix3d r = rotationMatrix(rv);
    EXPECT_LT((r - Eigen::AngleAxisd(angle, axis).toRotationMatrix()).cwiseAbs().maxCoeff(), 1e-15)
        << angle;
    const Eigen::Vector3d back = rotationVector(r);
    // At exactly π the axis sign is ambiguous: compare rotations there.
    if (angle < M_PI - 1e-6) {
      EXPECT_LT((back - rv).norm(), 1e-12 * std::max(1.0, angle)) << angle;
    }
    EXPECT_LT((rotationMatrix(back) - r).cwiseAbs().maxCoeff(), 1e-12) << angle;
  }
}

TEST(URKinematics, ZeroJointPoses) {
  expectPose(toUrPose(forwardKinematics(ur5Model(), {0, 0, 0, 0, 0, 0})),
             {-0.81725, -0.19145, -0.00549, 1.5708, 0, 0}, 5e-6);
  expectPose(toUrPose(forwardKinematics(ur5eModel(), {0, 0, 0, 0, 0, 0})),
             {-0.8172, -0.2329, 0.0628, 1.5708, 0, 0}, 5e-5);
}

TEST(URKinematics, InverseOfForwardForRandomPoses) {
  for (const RobotModel& robot : {ur5Model(), ur5eModel()}) {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> joint(-M_PI, M_PI);
    int solutions = 0, containsOriginal = 0;
    double worst = 0;
    for (int trial = 0; trial < 10000; ++trial) {
      JointVector q;
      for (double& v : q)
        v = joint(rng);
      const Isometry t = forwardKinematics(robot, q);
      const auto all = inverseKinematics(robot, t);
      ASSERT_FALSE(all.empty()) << robot.name << " trial " << trial;
      bool found = false;
      for (const JointVector& s : all) {
        worst = std::max(worst, poseError(forwardKinematics(robot, s), t));
        double d = 0;
        for (int i = 0; i < 6; ++i)
          d = std::max(d, std::abs(std::remainder(s[i] - q[i], 2 * M_PI)));
        found |= d < 1e-7;
      }
      solutions += static_cast<int>(all.size());
      containsOriginal += found;
    }
    EXPECT_LT(worst, 1e-9) << robot.name;
    EXPECT_EQ(containsOriginal, 10000) << robot.name;
    // Up to 8: poses near the edge of the workspace lose the branches that cannot reach them.
    std::printf("[ik] %s: %.2f solutions per pose on average, worst FK(IK) error %.2e\n",
                robot.name.c_str(), solutions / 10000.0, worst);
    // A pose well inside the workspace has all 8 (shoulder x wrist x elbow).
    const auto eight =
        inverseKinematics(robot, forwardKinematics(robot, {0.3, -1.2, 1.4, -0.5, 1.2, 0.4}));
    EXPECT_EQ(eight.size(), 8u) << robot.name;
  }
}

TEST(URKinematics, UnreachableAndSingular) {
  const RobotModel robot = ur5Model();
  Isometry far = Isometry::Identity();
  far.translation() = Eigen::Vector3d(2.0, 0, 0.3);
  EXPECT_TRUE(inverseKinematics(robot, far).empty());
  const SingularityDistance s = singularityDistance(robot, {0, -1.0, 1.0, 0, 0, 0});
  EXPECT_NEAR(s.wrist, 0.0, 1e-15);
  EXPECT_NEAR(s.elbow, std::sin(1.0), 1e-15);
  EXPECT_THROW(robotModelByName("ur10"), GeoLatticeError);
}
