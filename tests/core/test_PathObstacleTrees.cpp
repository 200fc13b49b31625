// The obstacles' kd-trees of an axis-clearance pass, kept from pass to pass while the earlier
// pass's material is still on the path in order (toolpath/PathObstacleTrees.h).
#include "toolpath/NozzleAxisClearance.h"
#include "toolpath/PathObstacleTrees.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

using namespace geolattice;

namespace {

/// A bound that touches everything: forEachCandidate then reports every obstacle.
struct Everywhere {
  bool mayTouch(const Vec3&, double) const { return true; }
};

std::vector<std::tuple<double, double, double>> sorted(std::vector<Vec3> v) {
  std::vector<std::tuple<double, double, double>> t;
  for (const Vec3& x : v) {
    t.emplace_back(x.x(), x.y(), x.z());
  }
  std::sort(t.begin(), t.end());
  return t;
}

/// The obstacles of every station as PathObstacleTrees reports them, and as they are: the
/// material before it and the fixed points.
void expectObstaclesOfEveryStation(const PathObstacleTrees& trees, const std::vector<Vec3>& points,
                                   const std::vector<char>& material,
                                   const std::vector<Vec3>& fixed) {
  for (size_t k = 0; k < points.size(); ++k) {
    std::vector<Vec3> reported, expected = fixed;
    trees.forEachCandidate(Everywhere{}, static_cast<int>(k), [&](const Vec3& x) {
      reported.push_back(x);
      return false;
    });
    for (size_t j = 0; j < k; ++j) {
      if (material[j]) {
        expected.push_back(points[j]);
      }
    }
    ASSERT_EQ(sorted(reported), sorted(expected)) << "station " << k;
  }
}

/// A random walk of material with an air move every 25 points.
void randomPath(std::vector<Vec3>& points, std::vector<char>& material, int n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> step(-1.0, 1.0);
  Vec3 x = Vec3::Zero();
  for (int i = 0; i < n; ++i) {
    x += Vec3(step(random), step(random), 0.2 + 0.1 * step(random));
    points.push_back(x);
    material.push_back(i % 25 != 0);
  }
}

}  // namespace

TEST(PathObstacleTrees, KeepsTheTreeWhenPointsAreInsertedAndAirMovesChange) {
  std::vector<Vec3> points, fixed = {Vec3(0, 0, -1), Vec3(5, 5, -1)};
  std::vector<char> material;
  randomPath(points, material, 400, 7);
  PathObstacleTrees trees;
  trees.index(points, material, &fixed);
  EXPECT_EQ(trees.builds, 1);
  expectObstaclesOfEveryStation(trees, points, material, fixed);

  // Points inserted between neighbours (material and air, one a copy of its successor, as a
  // rotation step can be), and an air point dropped: the tree is kept, and every station still
  // has exactly its earlier material as obstacles.
  points.erase(points.begin() + 50);  // index 50 is an air point (50 % 25 == 0)
  material.erase(material.begin() + 50);
  for (int k = 390; k > 0; k -= 37) {
    points.insert(points.begin() + k, 0.5 * (points[k - 1] + points[k]));
    material.insert(material.begin() + k, static_cast<char>(k % 2));
  }
  points.insert(points.begin() + 100, points[100]);
  material.insert(material.begin() + 100, 1);
  trees.index(points, material, &fixed);
  EXPECT_EQ(trees.builds, 1);
  EXPECT_EQ(trees.reuses, 1);
  expectObstaclesOfEveryStation(trees, points, material, fixed);
}

TEST(PathObstacleTrees, BuildsAgainWhenMaterialMovedOrTheFixedObstaclesChanged) {
  std::vector<Vec3> points, fixed = {Vec3(0, 0, -1)};
  std::vector<char> material;
  randomPath(points, material, 300, 11);
  PathObstacleTrees trees;
  trees.index(points, material, &fixed);

  points[120].z() += 0.01;  // material moved: the old tree would hold a point that is not there
  trees.index(points, material, &fixed);
  EXPECT_EQ(trees.builds, 2);
  expectObstaclesOfEveryStation(trees, points, material, fixed);

  fixed.push_back(Vec3(1, 1, -1));
  trees.index(points, material, &fixed);
  EXPECT_EQ(trees.builds, 3);
  expectObstaclesOfEveryStation(trees, points, material, fixed);

  trees.index(points, material, nullptr);
  EXPECT_EQ(trees.builds, 4);
  expectObstaclesOfEveryStation(trees, points, material, {});
  EXPECT_EQ(trees.reuses, 0);
}

TEST(PathObstacleTrees, BuildsAgainWhenMuchMaterialWasAdded) {
  std::vector<Vec3> points;
  std::vector<char> material;
  randomPath(points, material, 200, 3);
  PathObstacleTrees trees;
  trees.index(points, material, nullptr);
  std::vector<Vec3> more = points;
  std::vector<char> moreMaterial = material;
  randomPath(more, moreMaterial, 1500, 5);  // 1440 material points added at the end
  trees.index(more, moreMaterial, nullptr);
  EXPECT_EQ(trees.builds, 2);
  expectObstaclesOfEveryStation(trees, more, moreMaterial, {});
}

TEST(PathObstacleTrees, AxisClearanceGivesTheSameAxesWithTheKeptTrees) {
  // A helix of material whose axes lean 65° towards its centre, so the far side of the turns
  // below is inside the nozzle until the axis tilts back: a pass with kept trees after points
  // were inserted gives the axes of a pass that indexes everything anew.
  std::vector<Vec3> points, axes;
  std::vector<char> material;
  const double lean = 65 * M_PI / 180;
  for (int i = 0; i < 900; ++i) {
    const double a = 2 * M_PI * i / 120.0;
    points.emplace_back(10 * std::cos(a), 10 * std::sin(a), 0.6 * i / 120.0);
    axes.push_back(
        Vec3(-std::cos(a) * std::sin(lean), -std::sin(a) * std::sin(lean), std::cos(lean)));
    material.push_back(i % 60 != 0);
  }
  NozzleModel cone;
  cone.halfAngleDeg = 45;
  AxisClearanceOptions o;
  o.blendLength = 2;
  PathObstacleTrees trees;
  std::vector<Vec3> first = axes;
  const AxisClearanceResult r1 = clearNozzleAxes(points, first, axes, material, cone, o, nullptr,
                                                 nullptr, nullptr, nullptr, &trees);
  ASSERT_GT(r1.tiltedStations, 0);
  for (int k = 880; k > 0; k -= 45) {
    points.insert(points.begin() + k, 0.5 * (points[k - 1] + points[k]));
    axes.insert(axes.begin() + k, axes[k]);
    material.insert(material.begin() + k, 1);
  }
  std::vector<Vec3> kept = axes, fresh = axes;
  const AxisClearanceResult r2 = clearNozzleAxes(points, kept, axes, material, cone, o, nullptr,
                                                 nullptr, nullptr, nullptr, &trees);
  const AxisClearanceResult r3 = clearNozzleAxes(points, fresh, axes, material, cone, o);
  EXPECT_EQ(trees.builds, 1);
  EXPECT_EQ(trees.reuses, 1);
  EXPECT_EQ(r2.collidingStations, r3.collidingStations);
  EXPECT_GT(r2.tiltedStations, 0);
  EXPECT_EQ(r2.tiltedStations, r3.tiltedStations);
  EXPECT_EQ(kept, fresh);
}
