// The part the robot holds against the robot's own arm (robot/PartArmClearance.h): distances of
// constructed capsules from constructed material and plate against analytic values, material
// counted from its print index on, the sweep equal to a search at every state, and the path
// solver keeping the arm off a part it drove the forearm through.
#include "common/Error.h"
#include "io/MeshReader.h"
#include "nozzle/Printhead.h"
#include "robot/ArmCapsules.h"
#include "robot/PartArmClearance.h"
#include "robot/RobotPathSolver.h"
#include "robot/URKinematics.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

using namespace geolattice;

namespace {

/// Two air points at opposite corners of a 40 x 40 mm square at z = 0 (the toolpath's
/// footprint: the plate), then a line of material along x (z = 10 mm, from x = -20 to 20 mm,
/// 0.5 mm apart), in a cell whose flange is at the base origin: part point p (mm) is at
/// (p / 1000 + (0, 0, 0.04)) m.
struct LineOfMaterial {
  RobotCell cell;
  std::vector<Eigen::Vector3d> points{{-20, -20, 0}, {20, 20, 0}};
  std::vector<int> kind{2, 2};
  LineOfMaterial() {
    for (int k = 0; k <= 80; ++k) {
      points.emplace_back(-20.0 + 0.5 * k, 0.0, 10.0);
      kind.push_back(0);
    }
  }
};

/// An arm whose every capsule is the segment from a to b (m, base frame) with that radius.
ArmCapsules armAlong(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius = 0) {
  ArmCapsules arm;
  arm.fill(Capsule{a, b, radius});
  return arm;
}

/// The least distance (m) of the surfaces of the arm's parts near the part (base to wrist 2)
/// at q from the given part points (part units) with index <= i and from the plate's footprint
/// rectangle, by sampling each capsule's segment every mm.
double sampledDistance(const RobotCell& cell, const JointVector& q,
                       const std::vector<Eigen::Vector3d>& points, size_t i) {
  const Isometry flange = forwardKinematics(cell.robot, q);
  const Isometry toPart = (flange * cell.partOnFlange).inverse();
  const ArmCapsules arm = armCapsules(cell.robot, q);
  Eigen::AlignedBox3d box;
  for (const auto& p : points) {
    box.extend(p);
  }
  double least = 1e9;
  for (int part = kFirstNearPart; part <= kLastNearPart; ++part) {
    const Capsule& c = arm[part];
    const int n = 1 + static_cast<int>((c.b - c.a).norm() / 0.001);
    for (int k = 0; k <= n; ++k) {
      const Eigen::Vector3d x =
          (toPart * (c.a + (c.b - c.a) * (static_cast<double>(k) / n))) / cell.partScale;
      double nearest = 1e9;
      for (size_t j = 0; j <= i && j < points.size(); ++j) {
        nearest = std::min(nearest, (x - points[j]).norm());
      }
      // The plate: the nearest point of the footprint rectangle at the lowest z.
      const Eigen::Vector3d onPlate(std::clamp(x.x(), box.min().x(), box.max().x()),
                                    std::clamp(x.y(), box.min().y(), box.max().y()), box.min().z());
      nearest = std::min(nearest, (x - onPlate).norm());
      least = std::min(least, nearest * cell.partScale - c.radius);
    }
  }
  return least;
}

}  // namespace

TEST(PartArmClearance, DistancesOfCapsulesFromMaterialAndPlate) {
  LineOfMaterial part;
  part.cell.partOnFlange = Isometry(Eigen::Translation3d(0, 0, 0.04));
  const PartArmClearance clearance(part.cell, part.points, part.kind);
  const Isometry flange = Isometry::Identity();
  // An arm of lines parallel to the material line, 80 mm above it (z = 0.04 + 0.01 + 0.08 m):
  // the sampled material is within a voxel's diagonal (2√3 mm) of the material, and the result
  // a lower bound.
  const double top = 0.04 + 0.01 + 0.08;
  const auto above = armAlong({-0.1, 0, top}, {0.1, 0, top});
  const double d = clearance.distance(flange, above, part.points.size() - 1, 1.0);
  EXPECT_LE(d, 0.08 + 1e-12);
  EXPECT_GE(d, 0.08 - 0.0035);
  EXPECT_TRUE(clearance.clear(flange, above, part.points.size() - 1, 0.07));
  EXPECT_FALSE(clearance.clear(flange, above, part.points.size() - 1, 0.085));
  // Not searched beyond the limit.
  EXPECT_EQ(clearance.distance(flange, above, part.points.size() - 1, 0.05), 0.05);
  // Distances are from the capsules' surfaces: the same lines 30 mm thick are 30 mm nearer.
  const auto thick = armAlong({-0.1, 0, top}, {0.1, 0, top}, 0.03);
  const double t = clearance.distance(flange, thick, part.points.size() - 1, 1.0);
  EXPECT_NEAR(t, d - 0.03, 1e-12);
  EXPECT_TRUE(clearance.clear(flange, thick, part.points.size() - 1, 0.04));
  EXPECT_FALSE(clearance.clear(flange, thick, part.points.size() - 1, 0.055));
  // A capsule through the material touches it: 0.
  const auto through = armAlong({-0.1, 0, 0.05}, {0.1, 0, 0.05}, 0.005);
  EXPECT_EQ(clearance.distance(flange, through, part.points.size() - 1, 1.0), 0.0);
  // A link beside the line's end at x = 40 mm (material up to x = 20 mm): only the points
  // printed so far count. At index 10 the material reaches x = -16 mm; the plate, 10 mm under
  // the material, spans x in [-20, 20] mm.
  const auto beside = armAlong({0.04, 0, 0.04 + 0.01}, {0.04, 0, 0.04 + 0.2});
  const double late = clearance.distance(flange, beside, part.points.size() - 1, 1.0);
  EXPECT_LE(late, 0.02 + 1e-12);
  EXPECT_GE(late, 0.02 - 0.0035);
  // The plate's edge at x = 20 mm (22.4 mm; the material's end would give at most 20 mm).
  const double early = clearance.distance(flange, beside, 10, 1.0);
  EXPECT_LE(early, std::hypot(0.02, 0.01) + 1e-12);
  EXPECT_GE(early, std::hypot(0.02, 0.01) - 0.0035);
  // The plate is there from the start: a link 5 mm under the plate's middle.
  const auto under = armAlong({-0.01, 0, 0.04 + 0.01 - 0.015}, {0.01, 0, 0.04 - 0.005});
  EXPECT_LT(clearance.distance(flange, under, 0, 1.0), 0.006);
  // Air moves are not material: the same line as air is only the plate (10 mm under it).
  const PartArmClearance air(part.cell, part.points, std::vector<int>(part.points.size(), 2));
  EXPECT_NEAR(air.distance(flange, above, part.points.size() - 1, 1.0), 0.09, 0.0035);
}

TEST(PartArmClearance, TheSweepFindsTheLeastOfEveryState) {
  // A ring of material (radius 30 mm, 720 points) and random arm states along a path: the
  // sweep's least is the least distance() over the states, to 1 mm (never below it).
  RobotCell cell;
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 720; ++k) {
    points.emplace_back(30 * std::cos(k * M_PI / 360), 30 * std::sin(k * M_PI / 360), 5 + k / 72.0);
  }
  const PartArmClearance clearance(cell, points);
  std::mt19937 random(7);
  // Small turns (the links move less than a millimetre a state): most states are not searched.
  std::uniform_real_distribution<double> turn(-0.002, 0.002);
  JointVector q{0.3, -1.2, 1.6, -1.9, -1.5, 0.2};
  PartArmClearance::Sweep sweep(clearance, 1.0);
  double least = 1.0;
  for (size_t i = 0; i < points.size(); ++i) {
    for (double& a : q) {
      a += turn(random);
    }
    const Isometry flange = forwardKinematics(cell.robot, q);
    const ArmCapsules arm = armCapsules(cell.robot, q);
    sweep.add(flange, arm, i);
    least = std::min(least, clearance.distance(flange, arm, i, 1.0));
  }
  EXPECT_LT(least, 1.0);
  EXPECT_GE(sweep.least(), least);
  EXPECT_LE(sweep.least(), least + 0.001 + 1e-12);
}

namespace {

/// A cylinder wall (radius 40 mm, 80 mm tall, ten laps) printed with the nozzle axis leaning
/// 30 degrees outwards.
void leaningCylinder(std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector3d>& normals) {
  for (int lap = 0; lap < 10; ++lap) {
    for (int k = 0; k < 360; ++k) {
      const double a = k * M_PI / 180, tilt = 30 * M_PI / 180;
      points.emplace_back(40 * std::cos(a), 40 * std::sin(a), 1 + 80.0 * lap / 9);
      normals.emplace_back(std::sin(tilt) * std::cos(a), std::sin(tilt) * std::sin(a),
                           std::cos(tilt));
    }
  }
}

std::string errorOf(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
                    const std::vector<Eigen::Vector3d>& normals, const RobotPathOptions& o) {
  try {
    solveRobotPath(cell, points, normals, o);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RobotPathSolver, AnUnreachableCellNamesTheClearanceThatStopsIt) {
  RobotCell cell;
  std::vector<Eigen::Vector3d> points, normals;
  leaningCylinder(points, normals);
  RobotPathOptions o;
  o.linkPartClearance = 0.25;  // no configuration keeps the arm 250 mm off the part
  std::string e = errorOf(cell, points, normals, o);
  EXPECT_NE(e.find("unreachable cell set-up"), std::string::npos) << e;
  EXPECT_NE(e.find("250 mm off the part it holds"), std::string::npos) << e;
  EXPECT_NE(e.find("what stops it is the part it holds"), std::string::npos) << e;
  o.explainUnreachable = false;  // e.g. the layout search's ranking
  e = errorOf(cell, points, normals, o);
  EXPECT_NE(e.find("unreachable cell set-up"), std::string::npos) << e;
  EXPECT_EQ(e.find("what stops it"), std::string::npos) << e;
  // The floor: no configuration keeps the arm and the part 300 mm above it (the nozzle tip is
  // 350 mm up), every one does at any height.
  o = RobotPathOptions{};
  o.floorClearance = 0.3;
  e = errorOf(cell, points, normals, o);
  EXPECT_NE(e.find("300 mm above the floor"), std::string::npos) << e;
  EXPECT_NE(e.find("what stops it is the floor"), std::string::npos) << e;
  EXPECT_NE(e.find("raise the nozzle tip"), std::string::npos) << e;
}

TEST(RobotPathSolver, TheArmIsKeptOffThePartItHolds) {
  // A cylinder wall (radius 40 mm, 80 mm tall, ten laps) printed with the nozzle axis leaning
  // 30 degrees outwards: without the constraint the chosen plan drives the forearm through
  // the part it holds; with it (the default) the solver keeps the arm's surfaces (base to
  // wrist 2) 15 mm off, checked by sampling each capsule every mm against every point printed
  // so far and the plate.
  RobotCell cell;
  std::vector<Eigen::Vector3d> points, normals;
  leaningCylinder(points, normals);
  RobotPathOptions o;
  EXPECT_EQ(o.linkPartClearance, kLinkPartSafeDistance);
  o.linkPartClearance = 0;  // measured only
  const RobotPath free = solveRobotPath(cell, points, normals, o);
  ASSERT_TRUE(free.works());
  EXPECT_LT(free.minLinkPartDistance, 0.01);
  o.linkPartClearance = kLinkPartSafeDistance;
  const RobotPath kept = solveRobotPath(cell, points, normals, o);
  ASSERT_TRUE(kept.works());
  EXPECT_GE(kept.minLinkPartDistance, kLinkPartSafeDistance);
  double sampled = 1e9;
  for (size_t i = 0; i < points.size(); i += 9) {
    sampled = std::min(sampled, sampledDistance(cell, kept.joints[i], points, i));
  }
  EXPECT_GE(sampled, kLinkPartSafeDistance - 1e-3);
  // The solver's measure is a lower bound of the sampled one (within a voxel's diagonal).
  EXPECT_LE(kept.minLinkPartDistance, sampled + 1e-3);
}

TEST(RobotPathSolver, EachSectionOfThePrintheadKeepsTheArmItsOwnDistanceOff) {
  // The shipped printhead's profile in sections: its nozzle and heat break (radius <= 3 mm),
  // heater block and heat sink (11 mm), carriage (28.3 mm), each kept its radius + 7 mm off.
  const Printhead head(readObj(std::string(GEOLATTICE_TESTDATA) + "/printhead_slim.obj"), "slim");
  const std::vector<NozzleSection> sections = nozzleSectionsFor(head, kLinkNozzleMargin);
  ASSERT_EQ(sections.size(), 3u);
  EXPECT_EQ(sections.front().from, 0.0);
  EXPECT_NEAR(sections.back().to, 0.100, 1e-9);
  const double expected[3][2] = {{0.030, 0.003}, {0.070, 0.011}, {0.100, 0.02828}};
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(sections[k].to, expected[k][0], 0.001) << k;
    EXPECT_NEAR(sections[k].clearance, expected[k][1] + kLinkNozzleMargin, 0.0006) << k;
    if (k > 0) {
      EXPECT_EQ(sections[k].from, sections[k - 1].to);
    }
  }
  RobotCell cell;
  std::vector<Eigen::Vector3d> points, normals;
  leaningCylinder(points, normals);
  // A section is kept: 300 mm off the lowest 50 mm of the axis, no configuration reaches it.
  RobotPathOptions o;
  o.nozzleSections = {{0.0, 0.05, 0.30}};
  EXPECT_NE(errorOf(cell, points, normals, o).find("unreachable cell set-up"), std::string::npos);
  // The printhead's sections: every state of the solved path keeps each section's clearance
  // from its stretch of the axis and the carriage's above it (sampled every millimetre along
  // the axis, each capsule's surface measured here, not by the solver's segment distance).
  o.nozzleSections = sections;
  o.linkNozzleClearance = sections.back().clearance;
  const RobotPath path = solveRobotPath(cell, points, normals, o);
  ASSERT_TRUE(path.unreachable.empty());
  auto surfaceDistance = [](const Capsule& c, const Eigen::Vector3d& x) {
    const Eigen::Vector3d d = c.b - c.a;
    const double t =
        d.squaredNorm() > 0 ? std::clamp((x - c.a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    return (x - (c.a + t * d)).norm() - c.radius;
  };
  double least = 1e9;
  for (const JointVector& q : path.joints) {
    const ArmCapsules arm = armCapsules(cell.robot, q);
    for (int mm = 0; mm <= 250; ++mm) {
      const double h = mm / 1000.0;
      double keep = o.linkNozzleClearance;
      for (const NozzleSection& s : sections) {
        if (h >= s.from && h <= s.to)
          keep = std::min(keep, s.clearance);
      }
      for (int part = kFirstNearNozzle; part <= kLastNearNozzle; ++part) {
        const double d = surfaceDistance(arm[part], cell.nozzleTip + h * cell.nozzleAxis);
        least = std::min(least, d);
        ASSERT_GE(d, keep - 1e-4) << "part " << part << " at " << mm << " mm above the tip";
      }
    }
  }
  std::printf("[robot] leaning cylinder, printhead sections: arm %.1f mm from the nozzle's axis\n",
              1000 * least);
}

TEST(RobotPathSolver, TheTallestPartTheCellPrintsStandingGrowsWithTheNozzlesHeight) {
  // The default UR5 cell (nozzle tip 350 mm up): a part's top layers hold its plate that far
  // below the tip, the flange under the plate and the wrist under the flange; 20 mm above the
  // floor that leaves about 112 mm. Raised 30 mm, the tip leaves about 30 mm more; out of reach,
  // nothing.
  RobotCell cell;
  const RobotPathOptions o;
  const double tallest = tallestPart(cell, o);
  EXPECT_GT(tallest, 90.0);
  EXPECT_LT(tallest, 130.0);
  cell.nozzleTip.z() += 0.03;
  EXPECT_NEAR(tallestPart(cell, o) - tallest, 30.0, 4.0);
  // The floor decides: with a floor clearance 5 mm larger, 5 mm less (the upper arm's shoulder
  // end is always 29.2 mm up, so no pose keeps more than that).
  RobotPathOptions higherFloor = o;
  higherFloor.floorClearance += 0.005;
  EXPECT_NEAR(tallestPart(cell, higherFloor), tallestPart(cell, o) - 5.0, 2.5);
  higherFloor.floorClearance = 0.03;
  EXPECT_EQ(tallestPart(cell, higherFloor), 0.0);
  cell.nozzleTip = Eigen::Vector3d(3.0, 0, 0.35);  // 3 m away
  EXPECT_EQ(tallestPart(cell, o), 0.0);
  EXPECT_THROW(tallestPart(cell, o, 0.0), GeoLatticeError);
}
