#include "common/Error.h"
#include "io/MeshReader.h"
#include "mesh/AnalyticShapes.h"
#include "mesh/SurfaceCheck.h"

#include "../common/ErrorOf.h"
#include "../common/TestModels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

using namespace geolattice;

namespace {

// Append b to a; with weld, points of b that coincide with points of a reuse a's ids.
TriangleSurface append(TriangleSurface a, const TriangleSurface& b, const Vec3& shift, bool weld) {
  std::vector<int> id(b.points.size());
  for (size_t i = 0; i < b.points.size(); ++i) {
    const Vec3 p = b.points[i] + shift;
    id[i] = -1;
    for (size_t j = 0; weld && j < a.points.size(); ++j) {
      if ((a.points[j] - p).norm() < 1e-12) {
        id[i] = static_cast<int>(j);
      }
    }
    if (id[i] < 0) {
      id[i] = static_cast<int>(a.points.size());
      a.points.push_back(p);
    }
  }
  for (const auto& t : b.triangles) {
    a.triangles.push_back({id[t[0]], id[t[1]], id[t[2]]});
  }
  return a;
}

}  // namespace

TEST(SurfaceCheck, ClosedBoxHasNoDefects) {
  const TriangleSurface box = boxSurface(Vec3(40, 40, 60), 7.0);
  const SurfaceCheckReport r = checkSurface(box);
  EXPECT_TRUE(r.isClosedManifold());
  EXPECT_EQ(r.triangleCount, static_cast<int>(box.triangles.size()));
  EXPECT_EQ(r.boundaryEdges, 0);
  EXPECT_EQ(r.nonManifoldEdges, 0);
  EXPECT_EQ(r.inconsistentEdges, 0);
  EXPECT_EQ(r.degenerateTriangles, 0);
  EXPECT_EQ(r.outOfRangeTriangles, 0);
  EXPECT_EQ(r.unusedPoints, 0);
  EXPECT_NEAR(r.signedVolume, 96000.0, 1e-9 * 96000.0);
  EXPECT_NEAR(r.bboxDiagonal, std::sqrt(40.0 * 40 + 40 * 40 + 60 * 60), 1e-9);
  EXPECT_NO_THROW(requireClosedManifold(box));
}

TEST(SurfaceCheck, VolumeIsTranslationInvariant) {
  TriangleSurface box = boxSurface(Vec3(1, 2, 3), 0.5);
  for (Vec3& p : box.points) {
    p += Vec3(1e6, -2e6, 3e6);
  }
  EXPECT_NEAR(checkSurface(box).signedVolume, 6.0, 1e-6);
}

TEST(SurfaceCheck, OpenSurfaceIsRejectedWithTheBoundaryEdgeCount) {
  TriangleSurface box = boxSurface(Vec3(1, 1, 1), 10.0);  // 12 triangles
  box.triangles.pop_back();                               // a triangular hole: 3 boundary edges
  const SurfaceCheckReport r = checkSurface(box);
  EXPECT_EQ(r.boundaryEdges, 3);
  EXPECT_FALSE(r.isClosedManifold());
  EXPECT_EQ(
      errorOf([&] { requireClosedManifold(box); }),
      "open surface: 3 boundary edges (the surface must be closed / watertight); the first is "
      "between points 1 and 2, at (0, 0.5, 1). Close the holes: GL Place On Platform's Fill Holes "
      "(geolattice run --fill-holes), or repair the part in its CAD tool and export it again");
}

TEST(SurfaceCheck, OpenScanFromTestdataIsRejected) {
  const std::string path = testModel("bunny_open_scan.obj");
  ASSERT_FALSE(path.empty()) << "bunny_open_scan.obj not found in " << GEOLATTICE_TESTDATA;
  const TriangleSurface scan = readObj(path);
  EXPECT_EQ(checkSurface(scan).boundaryEdges, 223);
  EXPECT_NE(errorOf([&] { requireClosedManifold(scan); }).find("open surface: 223 boundary edges"),
            std::string::npos);
}

TEST(SurfaceCheck, TwoBoxesSharingAnEdgeAreNonManifold) {
  const TriangleSurface a = boxSurface(Vec3(1, 1, 1), 10.0);
  // Second box touches the first only along the edge x = 1, y = 1 (welded vertices).
  const TriangleSurface both = append(a, a, Vec3(1, 1, 0), true);
  ASSERT_EQ(both.points.size(), 14u);  // 8 + 8 - 2 shared corners
  const SurfaceCheckReport r = checkSurface(both);
  EXPECT_EQ(r.nonManifoldEdges, 1);
  EXPECT_EQ(r.boundaryEdges, 0);
  EXPECT_EQ(
      errorOf([&] { requireClosedManifold(both); }),
      "non-manifold surface: 1 edges shared by more than two triangles; the first is between "
      "points 5 and 6, at (1, 1, 0.5). Separate the touching bodies or merge them into one solid "
      "in the CAD tool (a Boolean union); or wrap it: Wrap 1 mm in GL Place On Platform");
}

TEST(SurfaceCheck, TriangleFanWithAnEdgeInThreeTrianglesIsNonManifold) {
  TriangleSurface fan;
  fan.points = {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, -1, 0)};
  fan.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}};
  const SurfaceCheckReport r = checkSurface(fan);
  EXPECT_EQ(r.nonManifoldEdges, 1);
  EXPECT_EQ(r.boundaryEdges, 6);
  // Open is reported first: it is the more basic defect.
  EXPECT_NE(errorOf([&] { requireClosedManifold(fan); }).find("open surface: 6 boundary edges"),
            std::string::npos);
}

TEST(SurfaceCheck, OneFlippedTriangleIsInconsistent) {
  TriangleSurface box = boxSurface(Vec3(1, 1, 1), 10.0);
  std::swap(box.triangles[5][1], box.triangles[5][2]);
  const SurfaceCheckReport r = checkSurface(box);
  EXPECT_EQ(r.inconsistentEdges, 3);
  EXPECT_EQ(r.boundaryEdges, 0);
  EXPECT_NE(errorOf([&] {
              requireClosedManifold(box);
            }).find("inconsistently oriented triangles: 3 edges"),
            std::string::npos);
}

TEST(SurfaceCheck, InwardSurfaceIsAcceptedAndFlippedExplicitly) {
  TriangleSurface box = boxSurface(Vec3(2, 3, 4), 1.0);
  for (auto& t : box.triangles) {
    std::swap(t[0], t[1]);
  }
  SurfaceCheckReport r;
  ASSERT_NO_THROW(r = requireClosedManifold(box));
  EXPECT_NEAR(r.signedVolume, -24.0, 1e-9);
  EXPECT_EQ(orientOutward(box), static_cast<int>(box.triangles.size()));
  EXPECT_NEAR(checkSurface(box).signedVolume, 24.0, 1e-9);
  EXPECT_EQ(orientOutward(box), 0);  // already outward
}

TEST(SurfaceCheck, ZeroAreaTriangleInAClosedSurfaceIsDegenerate) {
  // Split triangle (a, b, c) at the midpoint m of edge ab and close the crack with the
  // zero-area triangle (a, b, m): still closed, manifold and consistently oriented.
  TriangleSurface box = boxSurface(Vec3(1, 1, 1), 10.0);
  const auto t = box.triangles[0];
  const int m = static_cast<int>(box.points.size());
  box.points.push_back(0.5 * (box.points[t[0]] + box.points[t[1]]));
  box.triangles[0] = {t[0], m, t[2]};
  box.triangles.push_back({m, t[1], t[2]});
  box.triangles.push_back({t[0], t[1], m});
  const SurfaceCheckReport r = checkSurface(box);
  EXPECT_EQ(r.boundaryEdges, 0);
  EXPECT_EQ(r.nonManifoldEdges, 0);
  EXPECT_EQ(r.inconsistentEdges, 0);
  EXPECT_EQ(r.degenerateTriangles, 1);
  EXPECT_EQ(r.firstDegenerateTriangle, 13);
  EXPECT_EQ(errorOf([&] { requireClosedManifold(box); }),
            "degenerate surface: 1 zero-area triangles (first: triangle 13)");
}

TEST(SurfaceCheck, RepeatedVertexTriangleIsDegenerate) {
  TriangleSurface box = boxSurface(Vec3(1, 1, 1), 10.0);
  box.triangles.push_back({2, 2, 5});
  EXPECT_EQ(checkSurface(box).degenerateTriangles, 1);
}

TEST(SurfaceCheck, OutOfRangeIndicesAreCountedWithoutCrashing) {
  TriangleSurface box = boxSurface(Vec3(1, 1, 1), 10.0);
  box.triangles[4][1] = 8;   // one past the end
  box.triangles[7][0] = -1;  // negative
  const SurfaceCheckReport r = checkSurface(box);
  EXPECT_EQ(r.outOfRangeTriangles, 2);
  EXPECT_EQ(r.firstOutOfRangeTriangle, 4);
  EXPECT_EQ(
      errorOf([&] { requireClosedManifold(box); }),
      "invalid surface: 2 triangles reference a vertex index outside 0..7 (first: triangle 4)");
}

TEST(SurfaceCheck, NonFinitePointIsRejected) {
  TriangleSurface box = boxSurface(Vec3(1, 1, 1), 10.0);
  box.points[3].y() = NAN;
  EXPECT_EQ(checkSurface(box).nonFinitePoints, 1);
  EXPECT_NE(errorOf([&] {
              requireClosedManifold(box);
            }).find("NaN or infinite coordinates (first: point 3)"),
            std::string::npos);
}

TEST(SurfaceCheck, EmptySurfaceIsRejected) {
  EXPECT_EQ(errorOf([] { requireClosedManifold(TriangleSurface{}); }),
            "empty surface: 0 points, 0 triangles");
  TriangleSurface pointsOnly;
  pointsOnly.points = {Vec3(0, 0, 0)};
  EXPECT_NE(errorOf([&] { requireClosedManifold(pointsOnly); }).find("empty surface"),
            std::string::npos);
  EXPECT_FALSE(checkSurface(TriangleSurface{}).isClosedManifold());
}

TEST(SurfaceCheck, DoublyCoveredTriangleEnclosesNoVolume) {
  TriangleSurface flat;
  flat.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  flat.triangles = {{0, 1, 2}, {0, 2, 1}};
  EXPECT_TRUE(checkSurface(flat).isClosedManifold());
  EXPECT_NE(errorOf([&] { requireClosedManifold(flat); }).find("surface encloses no volume"),
            std::string::npos);
}
