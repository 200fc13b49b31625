// Surface simplification before TetGen (core/mesh/SurfaceSimplification.h): a closed surface much
// finer than the tets need is coarsened to about the target edge length, stays closed and
// manifold, and stays within the tolerance of the input (checked against the exact shape).
#include "common/Error.h"
#include "mesh/AnalyticShapes.h"
#include "mesh/SurfaceCheck.h"
#include "mesh/SurfaceSimplification.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace geolattice;

namespace {

/// Distance of p from the surface of the torus of torusSurface(centre, R, r, ...): the major
/// circle in the xz-plane about the centre, the tube radius r.
double torusDistance(const Vec3& p, const Vec3& centre, double R, double r) {
  const Vec3 q = p - centre;
  const double ring = std::hypot(q.x(), q.z()) - R;
  return std::hypot(ring, q.y()) - r;
}

/// A cylinder (radius r, height h, axis z from 0) as CAD programs export it: `segments` tall thin
/// side rectangles and cap fans of slivers from the centre, every triangle needle-shaped.
TriangleSurface cadCylinder(double r, double h, int segments) {
  TriangleSurface s;
  s.points.emplace_back(0, 0, 0);
  s.points.emplace_back(0, 0, h);
  for (int k = 0; k < segments; ++k) {
    const double a = 2 * M_PI * k / segments;
    s.points.emplace_back(r * std::cos(a), r * std::sin(a), 0);
    s.points.emplace_back(r * std::cos(a), r * std::sin(a), h);
  }
  for (int k = 0; k < segments; ++k) {
    const int b0 = 2 + 2 * k, t0 = b0 + 1, b1 = 2 + 2 * ((k + 1) % segments), t1 = b1 + 1;
    s.triangles.push_back({0, b1, b0});
    s.triangles.push_back({1, t0, t1});
    s.triangles.push_back({b0, b1, t1});
    s.triangles.push_back({b0, t1, t0});
  }
  return s;
}

}  // namespace

TEST(SurfaceSimplification, RemeshingGivesWellShapedTrianglesOfTheTargetLength) {
  // 240 needles of 40 mm x 0.8 mm around a 30 mm cylinder: remeshed to 4 mm edges, closed, on
  // the cylinder, its rims kept sharp; TetGen then meshes it near the asked count.
  const TriangleSurface cad = cadCylinder(30, 40, 240);
  SimplificationOptions o;
  o.method = SimplificationMethod::IsotropicRemeshing;
  o.targetEdgeLength = 4.0;
  o.remeshEdgeFactor = 1.0;
  const SimplificationResult r = simplifySurface(cad, o);
  ASSERT_TRUE(r.simplified) << r.refused;
  EXPECT_NEAR(r.outputMeanEdge, 4.0, 1.0);
  EXPECT_TRUE(checkSurface(r.surface).isClosedManifold());
  double smallestAngle = M_PI;
  for (const auto& t : r.surface.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = r.surface.points[t[(k + 1) % 3]] - r.surface.points[t[k]];
      const Vec3 v = r.surface.points[t[(k + 2) % 3]] - r.surface.points[t[k]];
      smallestAngle = std::min(smallestAngle, std::acos(u.normalized().dot(v.normalized())));
    }
  }
  EXPECT_GT(smallestAngle * 180 / M_PI, 10.0);  // the input's needles: 0.6 degrees
  for (const Vec3& p : r.surface.points) {
    const double radial = std::hypot(p.x(), p.y());
    const bool onSide = std::abs(radial - 30) < 0.05;
    const bool onCap = std::abs(p.z()) < 1e-9 || std::abs(p.z() - 40) < 1e-9;
    EXPECT_TRUE(onSide || (onCap && radial <= 30 + 1e-9)) << p.transpose();
  }
  TetrahedralizeOptions t;  // remeshing by default: a coarse input of slivers too
  t.autoTargetTets = 15000;
  const TetrahedralizeResult tets = tetrahedralizeSurface(cad, t);
  EXPECT_TRUE(tets.simplified);
  EXPECT_GT(tets.tetCount, 15000 / 2);
  EXPECT_LT(tets.simplificationDistance, 0.25 * tets.targetEdgeLength);
  EXPECT_LT(tets.tetCount, 15000 * 2);
}

TEST(SurfaceSimplification, RemeshingFartherThanTheToleranceFallsBackToTheCollapse) {
  // A tolerance no remeshing meets: the edge collapse (bounded by it) runs instead and says so.
  const TriangleSurface sphere = sphereSurface(Vec3(0, 0, 30), 20.0, 6);
  SimplificationOptions o;
  o.targetEdgeLength = 4.0;
  o.tolerance = 1e-4;
  const SimplificationResult r = simplifySurface(sphere, o);
  EXPECT_NE(r.refused.find("remeshed surface is"), std::string::npos) << r.refused;
  if (r.simplified) {
    EXPECT_LE(r.hausdorff, 1e-4 + 1e-9);
  }
  EXPECT_TRUE(checkSurface(r.surface).isClosedManifold());
}

TEST(SurfaceSimplification, FineSphereIsCoarsenedWithinTolerance) {
  const Vec3 centre(1, 2, 30);
  const TriangleSurface sphere = sphereSurface(centre, 20.0, 6);  // 0.6 mm edges
  SimplificationOptions o;
  o.method = SimplificationMethod::EdgeCollapse;
  o.targetEdgeLength = 4.0;
  std::vector<double> progress;
  o.progress = [&](double f) {
    progress.push_back(f);
  };
  const SimplificationResult r = simplifySurface(sphere, o);
  ASSERT_TRUE(r.simplified) << r.refused;
  EXPECT_LT(r.outputTriangles, r.inputTriangles / 10);
  EXPECT_GT(r.outputMeanEdge, 2.0);
  const SurfaceCheckReport check = checkSurface(r.surface);
  EXPECT_TRUE(check.isClosedManifold());
  EXPECT_EQ(check.boundaryEdges, 0);
  EXPECT_EQ(check.nonManifoldEdges, 0);
  // The default tolerance is a quarter of the target edge: every new vertex within it of the
  // input, and the input within it of the output (the reported one-sided Hausdorff distance).
  EXPECT_LE(r.hausdorff, 1.0);
  for (const Vec3& p : r.surface.points) {
    EXPECT_LE(std::abs((p - centre).norm() - 20.0), 1.0);
  }
  ASSERT_FALSE(progress.empty());
  for (size_t i = 1; i < progress.size(); ++i) {
    EXPECT_GE(progress[i], progress[i - 1]);
  }
  EXPECT_LE(progress.back(), 1.0);
}

TEST(SurfaceSimplification, CoarseSurfaceIsLeftAlone) {
  const TriangleSurface sphere = sphereSurface(Vec3(0, 0, 0), 20.0, 3);
  SimplificationOptions o;
  o.targetEdgeLength = 4.0;
  const SimplificationResult r = simplifySurface(sphere, o);
  EXPECT_FALSE(r.simplified);
  EXPECT_EQ(r.outputTriangles, r.inputTriangles);
}

TEST(SurfaceSimplification, AbortStops) {
  const TriangleSurface sphere = sphereSurface(Vec3(0, 0, 0), 20.0, 6);
  SimplificationOptions o;
  o.targetEdgeLength = 4.0;
  o.shouldAbort = [] {
    return true;
  };
  try {
    simplifySurface(sphere, o);
    FAIL() << "no abort";
  } catch (const GeoLatticeError& e) {
    EXPECT_NE(std::string(e.what()).find("aborted"), std::string::npos) << e.what();
  }
}

// Issue 19, point 5: a 1,000,000-triangle closed surface (a scan-like 0.25 mm resolution) is
// simplified before TetGen and meshed to about the automatic 75k tets; the tet mesh stays within
// the tolerance of the exact torus. The time is measured by bench_mesh, not here.
TEST(SurfaceSimplification, MillionTriangleTorusIsMeshedToTheTargetWithinTolerance) {
  const Vec3 centre(0, 0, 40);
  const TriangleSurface torus = torusSurface(centre, 28, 12, 1000, 500);
  ASSERT_EQ(torus.triangles.size(), 1000000u);
  const TetrahedralizeResult r = tetrahedralizeSurface(torus, TetrahedralizeOptions());
  ASSERT_TRUE(r.simplified) << r.simplificationRefused;
  EXPECT_EQ(r.inputTriangles, 1000000u);
  EXPECT_LT(r.meshedTriangles, 20000u);
  EXPECT_GT(r.tetCount, 50000);
  EXPECT_LT(r.tetCount, 110000);
  // The tolerance is a quarter of the first target edge (automatic: ~7 mm for this volume).
  const double tolerance = 0.25 * 7.2;
  EXPECT_LE(r.simplificationDistance, tolerance);
  double outside = 0;
  for (const Vec3& p : r.mesh.points) {
    outside = std::max(outside, torusDistance(p, centre, 28, 12));
  }
  EXPECT_LE(outside, tolerance);
  const double exactVolume = 2 * M_PI * M_PI * 28 * 12 * 12;
  EXPECT_NEAR(r.meshVolume, exactVolume, 0.03 * exactVolume);
}
