// Closing the holes of an open surface (core/mesh/HoleFilling.h): holes cut into a box whose
// volume is known; a closed surface passes unchanged; a non-manifold one is refused.
#include "common/Error.h"
#include "mesh/AnalyticShapes.h"
#include "mesh/HoleFilling.h"
#include "mesh/SurfaceCheck.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace geolattice;

namespace {

/// The triangles of `s` whose three corners satisfy `inside`, removed.
TriangleSurface withHole(TriangleSurface s, const std::function<bool(const Vec3&)>& inside) {
  std::vector<std::array<int, 3>> kept;
  for (const auto& t : s.triangles) {
    if (!(inside(s.points[t[0]]) && inside(s.points[t[1]]) && inside(s.points[t[2]]))) {
      kept.push_back(t);
    }
  }
  EXPECT_LT(kept.size(), s.triangles.size());
  s.triangles = kept;
  return s;
}

}  // namespace

TEST(HoleFilling, HolesInABoxAreClosedFlat) {
  // A 10 mm box (2 mm triangles) with a 4 x 4 mm hole in its top and one in a side.
  const TriangleSurface box = boxSurface({10, 10, 10}, 2.0);
  TriangleSurface open = withHole(box, [](const Vec3& p) {
    return p.z() > 10 - 1e-9 && p.x() > 2.9 && p.x() < 7.1 && p.y() > 2.9 && p.y() < 7.1;
  });
  open = withHole(open, [](const Vec3& p) {
    return p.x() < 1e-9 && p.y() > 2.9 && p.y() < 7.1 && p.z() > 2.9 && p.z() < 7.1;
  });
  const SurfaceCheckReport before = checkSurface(open);
  ASSERT_GT(before.boundaryEdges, 0);
  const HoleFillingResult r = fillHoles(open);
  EXPECT_EQ(r.holes, 2);
  EXPECT_GT(r.addedTriangles, 0);
  const SurfaceCheckReport after = requireClosedManifold(open);
  // A flat rim in a flat face: the faired patch is flat, the box whole again.
  EXPECT_NEAR(after.signedVolume, 1000.0, 1e-6);
  for (const Vec3& p : open.points) {
    EXPECT_TRUE(p.minCoeff() > -1e-9 && p.maxCoeff() < 10 + 1e-9) << p.transpose();
  }
}

TEST(HoleFilling, AClosedSurfaceIsLeftAsItIs) {
  TriangleSurface box = boxSurface({10, 10, 10}, 2.0);
  const TriangleSurface before = box;
  const HoleFillingResult r = fillHoles(box);
  EXPECT_EQ(r.holes, 0);
  EXPECT_EQ(box.triangles, before.triangles);
  EXPECT_EQ(box.points.size(), before.points.size());
}

TEST(HoleFilling, ANonManifoldSurfaceIsRefused) {
  TriangleSurface box = boxSurface({10, 10, 10}, 2.0);
  box.points.push_back(Vec3(5, 5, 20));
  const auto t = box.triangles[0];
  box.triangles.push_back({t[0], t[1], static_cast<int>(box.points.size()) - 1});  // a fin
  EXPECT_THROW(fillHoles(box), GeoLatticeError);
}
