// The part the robot holds against the floor it stands on (robot/PartFloor.h): the box bound
// against analytic heights, and the path solver refusing the points where the part as printed
// so far (with the plate's footprint) would be under the floor, though the arm reaches them.
#include "common/Error.h"
#include "robot/PartFloor.h"
#include "robot/RobotPathSolver.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

using namespace geolattice;

namespace {

/// A 140 x 40 mm first layer (normals +z), then a column printed sideways at its x = 70 mm end
/// (normals +x, z = 1..20 mm).
struct SidewaysColumn {
  std::vector<Eigen::Vector3d> points, normals;
  size_t firstSideways = 0;
  SidewaysColumn() {
    for (int row = 0; row <= 8; ++row) {
      for (int k = 0; k <= 140; ++k) {
        const double x = row % 2 ? 70.0 - k : -70.0 + k;
        points.emplace_back(x, -20.0 + 5.0 * row, 0.0);
        normals.emplace_back(0, 0, 1);
      }
    }
    firstSideways = points.size();
    for (int z = 1; z <= 20; ++z) {
      points.emplace_back(70.0, 0.0, z);
      normals.emplace_back(1, 0, 0);
    }
  }
};

/// With the nozzle axis vertical, the part is turned so that n points up the axis: a part point
/// q is (q - p) · n below or above the tip (part units), whatever ψ. The lowest of the material
/// printed up to p and of the plate's footprint corners, in metres.
double analyticLowest(const RobotCell& cell, const SidewaysColumn& c, size_t i) {
  const Eigen::Vector3d& p = c.points[i];
  const Eigen::Vector3d n = c.normals[i].normalized();
  double lowest = 0;
  for (size_t j = 0; j <= i; ++j)
    lowest = std::min(lowest, (c.points[j] - p).dot(n));
  for (double x : {-70.0, 70.0})
    for (double y : {-20.0, 20.0})
      lowest = std::min(lowest, (Eigen::Vector3d(x, y, 0) - p).dot(n));
  return cell.nozzleTip.z() + cell.partScale * lowest;
}

}  // namespace

TEST(PartFloor, TheBoxBoundsThePartAtAnyPose) {
  const RobotCell cell;
  const SidewaysColumn c;
  const PartFloor floor(cell, c.points);
  for (size_t i : {size_t{0}, size_t{500}, c.firstSideways, c.points.size() - 1}) {
    for (double psi : {0.0, 1.0, 2.5}) {
      const Isometry flange = cell.flangePose(c.points[i], c.normals[i], psi);
      const double lowest = floor.lowest(flange, i);
      // Never above the material and plate it must hold (a bound) ...
      EXPECT_LE(lowest, analyticLowest(cell, c, i) + 1e-12) << i;
      // ... and here exact: the box of a flat layer and a column at its end is the material's.
      EXPECT_NEAR(lowest, analyticLowest(cell, c, i), 1e-9) << i;
    }
  }
  // The first layer under a vertical nozzle: the part hangs at the tip's height.
  const double tip = cell.nozzleTip.z();
  EXPECT_NEAR(floor.lowest(cell.flangePose(c.points[0], c.normals[0], 0.0), 0), tip, 1e-9);
  // Printed sideways at x = 70 mm, the plate's far end is 140 mm under the tip.
  EXPECT_NEAR(
      floor.lowest(cell.flangePose(c.points.back(), c.normals.back(), 0.0), c.points.size() - 1),
      tip - 0.140, 1e-9);
}

TEST(PartFloor, APartOnlyTheArmClearsIsRefusedByThePathSolver) {
  // The nozzle 150 mm above the base plane: the first layer is held at 150 mm, but printed
  // sideways the plate's far end would be 10 mm above the floor (at any ψ: the nozzle axis is
  // vertical) while the arm itself reaches those points.
  RobotCell cell;
  cell.nozzleTip = Eigen::Vector3d(0.0, -0.40, 0.15);
  const SidewaysColumn c;
  const RobotPathOptions o;
  size_t under = 0;
  for (size_t i = 0; i < c.points.size(); ++i)
    under += analyticLowest(cell, c, i) < o.floorClearance;
  ASSERT_EQ(under, 20u);  // the sideways column, all of it
  try {
    solveRobotPath(cell, c.points, c.normals, o);
    FAIL() << "the part under the floor was not refused";
  } catch (const GeoLatticeError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("the arm and the part 20 mm above the floor"), std::string::npos)
        << message;
    // The reason named: the column (its first sampled point), the plate's far end 10 mm up.
    EXPECT_NE(message.find("the part itself (printed so far, on its plate) comes lower than "
                           "that at "),
              std::string::npos)
        << message;
    const size_t at = message.find("first point ");
    ASSERT_NE(at, std::string::npos) << message;
    const size_t first = std::stoul(message.substr(at + 12));
    EXPECT_GE(first, c.firstSideways);  // a sampled point of the column: coarse stride 2 here
    EXPECT_LT(first, c.firstSideways + 3);
    EXPECT_NE(message.find(" (10 mm above the floor at best)"), std::string::npos) << message;
  }
  // The arm alone reaches each of them above the floor (an IK solution within the limits at
  // some ψ): only the part would go under it.
  for (size_t i = c.firstSideways; i < c.points.size(); ++i) {
    bool reached = false;
    for (int k = 0; k < 72 && !reached; ++k) {
      const Isometry flange = cell.flangePose(c.points[i], c.normals[i], k * M_PI / 36);
      for (const JointVector& q : inverseKinematics(cell.robot, flange))
        reached = reached || (withinLimits(cell.robot, q) &&
                              lowestArmSurface(armCapsules(cell.robot, q)) >= o.floorClearance);
    }
    EXPECT_TRUE(reached) << "point " << i;
  }
}

TEST(PartFloor, ThePathSolverTurnsThePartAboveTheFloor) {
  // A horizontal nozzle (body along +x) 130 mm above the base plane: the first layer's plate
  // stands upright, and ψ turns it about the nozzle axis. Its 140 mm side hanging down from the
  // layer's end would reach 10 mm above the floor; the solver must turn it up.
  RobotCell cell;
  cell.nozzleTip = Eigen::Vector3d(0.0, -0.45, 0.13);
  cell.nozzleAxis = Eigen::Vector3d(1, 0, 0);
  const SidewaysColumn c;
  const std::vector<Eigen::Vector3d> points(c.points.begin(),
                                            c.points.begin() + static_cast<long>(c.firstSideways));
  const std::vector<Eigen::Vector3d> normals(
      c.normals.begin(), c.normals.begin() + static_cast<long>(c.firstSideways));
  const RobotPathOptions o;
  const RobotPath path = solveRobotPath(cell, points, normals, o);
  ASSERT_TRUE(path.works());
  EXPECT_GE(path.lowestPart, o.floorClearance);
  // Checked independently: the part at each point's joints (forward kinematics), every point
  // printed so far and the plate's corners.
  double lowest = 1e9;
  for (size_t i = 0; i < points.size(); ++i) {
    const Isometry part = forwardKinematics(cell.robot, path.joints[i]) * cell.partOnFlange;
    for (size_t j = 0; j <= i; j += 7)
      lowest = std::min(lowest, (part * (cell.partScale * points[j])).z());
    for (double x : {-70.0, 70.0})
      for (double y : {-20.0, 20.0})
        lowest = std::min(lowest, (part * (cell.partScale * Eigen::Vector3d(x, y, 0))).z());
  }
  EXPECT_GE(lowest, o.floorClearance);
  // Without the floor the same solver holds the plate lower than that.
  RobotPathOptions noFloor = o;
  noFloor.floorClearance = -1.0;
  const RobotPath free = solveRobotPath(cell, points, normals, noFloor);
  EXPECT_LT(free.lowestPart, o.floorClearance);
}
