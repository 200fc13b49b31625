// The repairs a surface as read gets before it is meshed (core/mesh/SurfaceRepair.h): a face
// written twice, triangles flipped against their neighbours; boxes whose volumes are known.
#include "common/Error.h"
#include "mesh/AnalyticShapes.h"
#include "mesh/SurfaceCheck.h"
#include "mesh/SurfaceRepair.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

using namespace geolattice;

namespace {

TriangleSurface cube10() {
  return boxSurface({10, 10, 10}, 2.0);
}

void flip(std::array<int, 3>& t) {
  std::swap(t[1], t[2]);
}

}  // namespace

TEST(SurfaceRepair, AFaceWrittenTwiceIsMeshedOnce) {
  // The cube's first five triangles written again (one of them starting at another corner: the
  // same way round): the copies make its edges non-manifold.
  const TriangleSurface cube = cube10();
  TriangleSurface doubled = cube;
  for (int t = 0; t < 5; ++t) {
    auto copy = cube.triangles[t];
    if (t == 2) {
      std::rotate(copy.begin(), copy.begin() + 1, copy.end());
    }
    doubled.triangles.push_back(copy);
  }
  EXPECT_FALSE(checkSurface(doubled).isClosedManifold());
  TetrahedralizeOptions o;
  o.targetEdgeLength = 2.0;
  const TetrahedralizeResult meshed = tetrahedralizeSurface(doubled, o);
  EXPECT_EQ(meshed.repairs.duplicateTriangles, 5);
  EXPECT_EQ(meshed.repairs.reorientedTriangles, 0);
  EXPECT_EQ(meshed.repairs.mergedBodies, 0);
  EXPECT_NEAR(meshed.meshVolume, 1000.0, 1e-6 * 1000.0);

  // The other way round a pair is a wall, not a copy: both stay.
  TriangleSurface wall = cube;
  auto flipped = cube.triangles[0];
  flip(flipped);
  wall.triangles.push_back(flipped);
  EXPECT_EQ(dropDuplicateTriangles(wall), 0);
  EXPECT_EQ(wall.triangles.size(), cube.triangles.size() + 1);
  // Without copies nothing changes.
  TriangleSurface same = cube;
  EXPECT_EQ(dropDuplicateTriangles(same), 0);
  EXPECT_EQ(same.triangles, cube.triangles);
}

TEST(SurfaceRepair, TrianglesFlippedAgainstTheirNeighboursAreTurnedBack) {
  const TriangleSurface cube = cube10();
  ASSERT_GT(cube.triangles.size(), 20u);
  // Three flipped, the first triangle among them (CGAL keeps a body's first triangle and turns
  // the others to agree: the body must then be turned back as a whole).
  TriangleSurface broken = cube;
  for (int t : {0, 7, 19}) {
    flip(broken.triangles[static_cast<size_t>(t)]);
  }
  EXPECT_GT(checkSurface(broken).inconsistentEdges, 0);
  TriangleSurface repaired = broken;
  const SurfaceRepairCounts r = repairSurface(repaired);
  EXPECT_EQ(r.reorientedTriangles, 3);
  EXPECT_EQ(repaired.triangles, cube.triangles);  // exactly the cube as it was

  // A cavity (an inner box facing inward) with one triangle flipped: turned to face inward
  // again, the solid is the outer box less the inner one.
  TriangleSurface hollow = cube10();
  TriangleSurface inner = boxSurface({4, 4, 4}, 2.0);
  const int offset = static_cast<int>(hollow.points.size());
  for (const Vec3& p : inner.points) {
    hollow.points.push_back(p + Vec3(3, 3, 3));
  }
  for (auto t : inner.triangles) {
    flip(t);  // inward
    hollow.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  const double volume = requireClosedManifold(hollow).signedVolume;
  EXPECT_NEAR(volume, 1000.0 - 64.0, 1e-9);
  flip(hollow.triangles[hollow.triangles.size() - 2]);
  EXPECT_EQ(repairSurface(hollow).reorientedTriangles, 1);
  EXPECT_NEAR(requireClosedManifold(hollow).signedVolume, volume, 1e-9);

  // Meshed from the broken cube: the mesh stage repairs it and says so.
  TetrahedralizeOptions o;
  o.targetEdgeLength = 2.0;
  const TetrahedralizeResult meshed = tetrahedralizeSurface(broken, o);
  EXPECT_EQ(meshed.repairs.reorientedTriangles, 3);
  EXPECT_NEAR(meshed.meshVolume, 1000.0, 1e-6 * 1000.0);
}

TEST(SurfaceRepair, AValidSurfaceAndAnOpenOneAreLeftAsTheyAre) {
  TriangleSurface cube = cube10();
  EXPECT_FALSE(repairSurface(cube).any());
  EXPECT_EQ(cube.triangles, cube10().triangles);
  TriangleSurface open = cube10();
  open.triangles.pop_back();
  const TriangleSurface before = open;
  EXPECT_FALSE(repairSurface(open).any());
  EXPECT_EQ(open.triangles, before.triangles);
}

// A binary STL stores float32 corners: an exporter that writes a face's corners from another
// computation than its neighbours' leaves them a few float32 steps apart, an open seam no wider
// than rounding (a generated bracket: 24 open edges, "--fill-holes" then made TetGen time out).
TEST(SurfaceRepair, ASeamAsWideAsRoundingIsWelded) {
  TriangleSurface seam = cube10();
  // The face x = 10 gets its own copies of its corners, 4 µm off (2 float32 steps at 10 mm is
  // ~2 µm).
  std::vector<int> copyOf(seam.points.size(), -1);
  for (auto& t : seam.triangles) {
    if (seam.points[t[0]].x() == 10 && seam.points[t[1]].x() == 10 && seam.points[t[2]].x() == 10) {
      for (int& v : t) {
        if (copyOf[v] < 0) {
          copyOf[v] = static_cast<int>(seam.points.size());
          seam.points.push_back(seam.points[v] + Vec3(4e-6, -3e-6, 2e-6));
        }
        v = copyOf[v];
      }
    }
  }
  ASSERT_GT(checkSurface(seam).boundaryEdges, 0);
  ASSERT_THROW(requireClosedManifold(seam), GeoLatticeError);
  const SurfaceRepairCounts repaired = repairSurface(seam);
  EXPECT_GT(repaired.weldedVertices, 0);
  const SurfaceCheckReport check = checkSurface(seam);
  EXPECT_TRUE(check.isClosedManifold());
  EXPECT_EQ(check.unusedPoints, 0);
  EXPECT_NEAR(check.signedVolume, 1000.0, 1e-3);
}

TEST(SurfaceRepair, NeedleTrianglesAreCollapsedAndTheSolidIsMeshed) {
  // An icosphere with one vertex moved to within 1e-9 mm of a neighbour: the two triangles on
  // that edge are needles of area ~0 (as marching cubes leaves them), which TetGen would get.
  TriangleSurface s = sphereSurface(Vec3(0, 0, 10), 10.0, 3);
  const auto& t0 = s.triangles[0];
  s.points[t0[1]] = s.points[t0[0]] + 1e-9 * (s.points[t0[1]] - s.points[t0[0]]).normalized();
  const SurfaceCheckReport before = checkSurface(s);
  ASSERT_EQ(before.degenerateTriangles, 2);
  EXPECT_THROW(requireClosedManifold(s), GeoLatticeError);

  TriangleSurface repaired = s;
  const SurfaceRepairCounts counts = repairSurface(repaired);
  EXPECT_EQ(counts.degenerateTriangles, 2);
  EXPECT_EQ(repaired.triangles.size(), s.triangles.size() - 2);
  const SurfaceCheckReport after = requireClosedManifold(repaired);
  EXPECT_EQ(after.degenerateTriangles, 0);
  EXPECT_NEAR(after.signedVolume, before.signedVolume, 1e-9 * std::abs(before.signedVolume));

  TetrahedralizeOptions o;
  o.targetEdgeLength = 2.0;
  const TetrahedralizeResult r = tetrahedralizeSurface(s, o);
  EXPECT_EQ(r.repairs.degenerateTriangles, 2);
  EXPECT_GT(r.tetCount, 100);
}

TEST(SurfaceRepair, ATinyWellShapedTriangleIsCollapsed) {
  // One triangle (a, b, c) of a box replaced by a copy shrunk a million times about its centroid
  // (p, q, r) and the ring of six triangles between them: the copy has area ~1e-11 mm^2 but the
  // shape of the original (as marching cubes leaves them near a grid vertex), neither needle nor
  // cap; its shortest edge is collapsed. The copy is turned by 40 degrees in the face's plane:
  // not turned, the collapsed edge's midpoint lies on the line through a corner and the copy's
  // third point, a new sliver that is not mended (the surface is then refused, as before).
  for (const double degrees : {40.0, 25.0}) {
    SCOPED_TRACE(degrees);
    TriangleSurface s = boxSurface(Vec3(30, 30, 30), 10.0);
    const std::array<int, 3> t = s.triangles.front();
    s.triangles.erase(s.triangles.begin());
    const Vec3 g = (s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) / 3.0;
    const Vec3 n = (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]);
    const Eigen::AngleAxisd turn(degrees * M_PI / 180.0, n.normalized());
    std::array<int, 3> inner{};
    for (int k = 0; k < 3; ++k) {
      inner[k] = static_cast<int>(s.points.size());
      s.points.push_back(g + 1e-6 * (turn * (s.points[t[k]] - g)));
    }
    const int a = t[0], b = t[1], c = t[2], p = inner[0], q = inner[1], r = inner[2];
    for (const std::array<int, 3>& f : std::vector<std::array<int, 3>>{
             {a, b, q}, {a, q, p}, {b, c, r}, {b, r, q}, {c, a, p}, {c, p, r}, {p, q, r}}) {
      s.triangles.push_back(f);
    }
    const SurfaceCheckReport before = checkSurface(s);
    ASSERT_EQ(before.degenerateTriangles, 1);
    ASSERT_EQ(before.boundaryEdges + before.nonManifoldEdges + before.inconsistentEdges, 0);

    TriangleSurface repaired = s;
    EXPECT_EQ(removeDegenerateTriangles(repaired), 1);
    const SurfaceCheckReport after = requireClosedManifold(repaired);
    EXPECT_EQ(after.degenerateTriangles, 0);
    EXPECT_EQ(repaired.triangles.size(), s.triangles.size() - 2);  // the copy and a neighbour
    EXPECT_NEAR(after.signedVolume, 27000.0, 1e-6);
  }
}

namespace {

/// `body` appended to `to`, turned inside out when `inward`.
void append(TriangleSurface& to, const TriangleSurface& body, bool inward) {
  const int offset = static_cast<int>(to.points.size());
  to.points.insert(to.points.end(), body.points.begin(), body.points.end());
  for (auto t : body.triangles) {
    to.triangles.push_back({t[0] + offset, inward ? t[2] + offset : t[1] + offset,
                            inward ? t[1] + offset : t[2] + offset});
  }
}

}  // namespace

TEST(SurfaceRepair, ABodyWrittenInsideOutIsTurnedOutward) {
  // Two equal balls, the second inside out: their volumes cancel ("encloses no volume").
  const TriangleSurface ball = sphereSurface(Vec3(0, 0, 10), 10, 3);
  const double v = checkSurface(ball).signedVolume;
  TriangleSurface s;
  append(s, ball, false);
  append(s, sphereSurface(Vec3(30, 0, 10), 10, 3), true);
  EXPECT_THROW(requireClosedManifold(s), GeoLatticeError);
  const SurfaceRepairCounts counts = repairSurface(s);
  EXPECT_EQ(counts.invertedBodies, 1);
  EXPECT_NEAR(requireClosedManifold(s).signedVolume, 2 * v, 1e-9 * v);
  // A hollow ball written outward (its cavity's wall inward) beside the same written inside out
  // as a whole: the second is turned with its cavity, the first left as it is.
  const TriangleSurface cavity = sphereSurface(Vec3(0, 0, 10), 6, 3);
  const double shell = v - checkSurface(cavity).signedVolume;
  TriangleSurface hollow;
  append(hollow, ball, false);
  append(hollow, cavity, true);
  TriangleSurface pair;
  append(pair, hollow, false);
  TriangleSurface moved = hollow;
  for (Vec3& p : moved.points) {
    p.x() += 30;
  }
  append(pair, moved, true);
  EXPECT_EQ(orientInvertedBodies(pair), 1);
  EXPECT_NEAR(checkSurface(pair).signedVolume, 2 * shell, 1e-9 * v);
  EXPECT_EQ(orientInvertedBodies(pair), 0);
  // A body inside another written outward (an embedded body, solid) and a surface inward as a
  // whole (orientOutward's case) are left as they are.
  TriangleSurface embedded;
  append(embedded, ball, false);
  append(embedded, cavity, false);
  EXPECT_EQ(orientInvertedBodies(embedded), 0);
  TriangleSurface inward;
  append(inward, hollow, true);
  EXPECT_EQ(orientInvertedBodies(inward), 0);
  EXPECT_LT(checkSurface(inward).signedVolume, 0);
}
