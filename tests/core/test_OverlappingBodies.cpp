// Overlapping closed bodies become their union before meshing (core/mesh/OverlappingBodies.h):
// boxes whose volumes are known exactly, merged, left alone, and refused.
#include "mesh/AnalyticShapes.h"
#include "mesh/OverlappingBodies.h"
#include "mesh/SurfaceCheck.h"
#include "tetrahedralize/TetrahedralizeSurface.h"
#include "common/Error.h"

#include "../common/FoldedSurface.h"
#include "../common/ErrorOf.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace geolattice;

namespace {

/// A box of the given size with its lowest corner at `at`; outward unless `inward`.
TriangleSurface box(const Vec3& size, const Vec3& at, bool inward = false) {
  TriangleSurface s = boxSurface(size, 2.0);
  for (Vec3& p : s.points) {
    p += at;
  }
  if (inward) {
    for (auto& t : s.triangles) {
      std::swap(t[1], t[2]);
    }
  }
  return s;
}

TriangleSurface together(const std::vector<TriangleSurface>& parts) {
  TriangleSurface out;
  for (const TriangleSurface& s : parts) {
    const int offset = static_cast<int>(out.points.size());
    out.points.insert(out.points.end(), s.points.begin(), s.points.end());
    for (auto t : s.triangles) {
      out.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
  }
  return out;
}

}  // namespace

TEST(OverlappingBodies, TwoCrossingBoxesBecomeTheirUnion) {
  // 10 mm cubes, the second shifted by (5, 5, 5): union 2000 - 125 mm^3.
  TriangleSurface s = together({box({10, 10, 10}, {0, 0, 0}), box({10, 10, 10}, {5, 5, 5})});
  const OverlappingBodiesResult r = mergeOverlappingBodies(s);
  EXPECT_EQ(r.bodies, 2);
  EXPECT_EQ(r.merged, 1);
  const SurfaceCheckReport check = requireClosedManifold(s);
  EXPECT_NEAR(check.signedVolume, 2000.0 - 125.0, 1e-6);
  // Meshed as one solid, with no "self-intersecting surface" from TetGen.
  TetrahedralizeOptions o;
  o.targetEdgeLength = 2.0;
  const TetrahedralizeResult meshed = tetrahedralizeSurface(
      together({box({10, 10, 10}, {0, 0, 0}), box({10, 10, 10}, {5, 5, 5})}), o);
  EXPECT_EQ(meshed.repairs.mergedBodies, 1);
  EXPECT_NEAR(meshed.meshVolume, 1875.0, 1e-6 * 1875.0);
}

TEST(OverlappingBodies, AChainOfThreeIsOneSolid) {
  TriangleSurface s = together(
      {box({10, 4, 4}, {0, 0, 0}), box({10, 4, 4}, {8, 0, 0}), box({10, 4, 4}, {16, 0, 0})});
  const OverlappingBodiesResult r = mergeOverlappingBodies(s);
  EXPECT_EQ(r.bodies, 3);
  EXPECT_EQ(r.merged, 2);
  EXPECT_NEAR(requireClosedManifold(s).signedVolume, 26.0 * 16.0, 1e-6);
}

TEST(OverlappingBodies, SeparateAndNestedBodiesAreLeftAsTheyAre) {
  // Two bodies apart, and a box with a cavity (an inward shell inside, not touching): unchanged.
  for (const TriangleSurface& input :
       {together({box({10, 10, 10}, {0, 0, 0}), box({10, 10, 10}, {20, 0, 0})}),
        together({box({10, 10, 10}, {0, 0, 0}), box({4, 4, 4}, {3, 3, 3}, true)}),
        box({10, 10, 10}, {0, 0, 0})}) {
    TriangleSurface s = input;
    const OverlappingBodiesResult r = mergeOverlappingBodies(s);
    EXPECT_EQ(r.merged, 0);
    EXPECT_EQ(s.points, input.points);
    EXPECT_EQ(s.triangles, input.triangles);
  }
}

TEST(OverlappingBodies, ACavityCrossingTheOuterShellIsAnError) {
  TriangleSurface s = together({box({10, 10, 10}, {0, 0, 0}), box({4, 4, 4}, {8, 3, 3}, true)});
  const std::string m = expectedErrorOf([&] { mergeOverlappingBodies(s); });
  EXPECT_NE(m.find("inward-facing shell (a cavity) near (10, 5, 5)"), std::string::npos) << m;
}

TEST(OverlappingBodies, ABodyThatCrossesItselfIsNotMerged) {
  // A box folded through itself (a top-face vertex pushed below the bottom) and a box crossing it.
  TriangleSurface folded = box({10, 10, 10}, {0, 0, 0});
  foldTopThroughBottom(folded, 3.0);
  TriangleSurface s = together({folded, box({10, 10, 10}, {5, 5, 5})});
  const std::string m = expectedErrorOf([&] { mergeOverlappingBodies(s); });
  EXPECT_NE(m.find("crosses itself"), std::string::npos) << m;
}

TEST(OverlappingBodies, MirrorImageBodiesInAnyTurnAreMeshed) {
  // Two coarse UV spheres (6 segments, 5 bands, r 12), mirror images across x = 0 and crossing
  // there: the union's cut runs through both meshes' vertices at once and, rounded to doubles,
  // leaves slivers of area ~0 (CGAL counts them as self-intersections, meshing as degenerate
  // triangles). Turned as the orientation search turns a part, each turn is one solid.
  auto uvSphere = [](const Vec3& centre) {
    TriangleSurface s;
    const int segments = 6, bands = 5;
    s.points.push_back(centre + Vec3(0, 0, 12));
    for (int j = 1; j < bands; ++j) {
      const double phi = M_PI * j / bands;
      for (int k = 0; k < segments; ++k) {
        const double theta = 2 * M_PI * k / segments;
        s.points.push_back(centre + 12 * Vec3(std::sin(phi) * std::cos(theta),
                                              std::sin(phi) * std::sin(theta), std::cos(phi)));
      }
    }
    s.points.push_back(centre + Vec3(0, 0, -12));
    const int south = static_cast<int>(s.points.size()) - 1;
    auto ring = [&](int j, int k) {
      return 1 + (j - 1) * segments + (k % segments);
    };
    for (int k = 0; k < segments; ++k) {
      s.triangles.push_back({0, ring(1, k), ring(1, k + 1)});
      for (int j = 1; j + 1 < bands; ++j) {
        s.triangles.push_back({ring(j, k), ring(j + 1, k), ring(j + 1, k + 1)});
        s.triangles.push_back({ring(j, k), ring(j + 1, k + 1), ring(j, k + 1)});
      }
      s.triangles.push_back({south, ring(bands - 1, k + 1), ring(bands - 1, k)});
    }
    return s;
  };
  const TriangleSurface pair = together({uvSphere(Vec3(-6, 0, 12)), uvSphere(Vec3(6, 0, 12))});
  ASSERT_GT(requireClosedManifold(uvSphere(Vec3::Zero())).signedVolume, 0);
  for (int turn = 0; turn < 12; ++turn) {
    SCOPED_TRACE(turn);
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(0.37 * turn, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    TriangleSurface s = pair;
    for (Vec3& p : s.points) {
      p = R * p;
    }
    TetrahedralizeOptions o;
    o.targetEdgeLength = 3.0;
    const TetrahedralizeResult meshed = tetrahedralizeSurface(s, o);
    EXPECT_EQ(meshed.repairs.mergedBodies, 1);
    EXPECT_GT(meshed.tetCount, 100);
  }
}
