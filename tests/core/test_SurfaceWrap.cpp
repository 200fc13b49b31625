// The alpha wrap (core/mesh/SurfaceWrap.h) turns a surface no other repair takes (facets
// crossing each other, a hole, a non-manifold edge, a duplicate triangle) into a closed
// 2-manifold without self-intersections, an offset of the part: its volume and bounds grow by
// about the offset, no more.
#include "common/Error.h"
#include "mesh/AnalyticShapes.h"
#include "mesh/CgalSurfaceMesh.h"
#include "mesh/SurfaceCheck.h"
#include "mesh/SurfaceWrap.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <gtest/gtest.h>

using namespace geolattice;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

/// `b` appended to `a` (no shared points).
void append(TriangleSurface& a, const TriangleSurface& b, const Vec3& shift) {
  const int base = static_cast<int>(a.points.size());
  for (const Vec3& p : b.points) {
    a.points.push_back(p + shift);
  }
  for (const auto& t : b.triangles) {
    a.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
}

}  // namespace

TEST(SurfaceWrap, ADefectiveSoupBecomesAClosedManifoldOffsetOfThePart) {
  // Two 20 mm boxes overlapping by 10 mm in x (their facets cross), a triangle of the first
  // removed (a hole), one of the second repeated (three triangles on an edge, and a duplicate).
  TriangleSurface soup = boxSurface(Vec3(20, 20, 20), 2.0);
  append(soup, boxSurface(Vec3(20, 20, 20), 2.0), Vec3(10, 0, 0));
  soup.triangles.erase(soup.triangles.begin() + 7);
  soup.triangles.push_back(soup.triangles.back());
  ASSERT_FALSE(checkSurface(soup).isClosedManifold());

  const double alpha = 0.5;
  const SurfaceWrapResult r = wrapSurface(soup, alpha, 40e6);
  EXPECT_NEAR(r.offset, alpha / 30, 1e-12);
  EXPECT_EQ(r.triangles, static_cast<int>(soup.triangles.size()));
  EXPECT_GT(r.inputTriangles, 0);
  const SurfaceCheckReport check = checkSurface(soup);
  EXPECT_TRUE(check.isClosedManifold());
  EXPECT_GT(check.signedVolume, 0);  // outward
  const cgal::SurfaceMesh mesh = cgal::toSurfaceMesh(soup, "wrap");
  EXPECT_FALSE(PMP::does_self_intersect(mesh));
  // The union is 30 x 20 x 20 = 12,000 mm³; the wrap lies outside it within the offset (and
  // alpha's rounding of the edges, which takes volume away).
  const double volume = PMP::volume(mesh);
  EXPECT_GT(volume, 12000 * 0.99);
  EXPECT_LT(volume, (30 + 2 * r.offset) * (20 + 2 * r.offset) * (20 + 2 * r.offset));
  Eigen::AlignedBox3d box;
  for (const Vec3& p : soup.points) {
    box.extend(p);
  }
  EXPECT_NEAR(box.min().x(), 0 - r.offset, 0.05);
  EXPECT_NEAR(box.max().x(), 30 + r.offset, 0.05);
  EXPECT_NEAR(box.max().z(), 20 + r.offset, 0.05);
}

TEST(SurfaceWrap, BadInput) {
  TriangleSurface box = boxSurface(Vec3(10, 10, 10), 5.0);
  EXPECT_THROW(wrapSurface(box, 0.0, 40e6), GeoLatticeError);
  EXPECT_THROW(wrapSurface(box, -1.0, 40e6), GeoLatticeError);
  TriangleSurface empty;
  EXPECT_THROW(wrapSurface(empty, 0.5, 40e6), GeoLatticeError);
  // 600 mm² at 1 µm: ~1.4e9 triangles, refused before any work, naming the way out.
  try {
    wrapSurface(box, 0.001, 40e6);
    ADD_FAILURE() << "a wrap of a billion triangles was not refused";
  } catch (const GeoLatticeError& e) {
    EXPECT_NE(std::string(e.what()).find("--wrap"), std::string::npos) << e.what();
  }
  EXPECT_EQ(box.triangles.size(), boxSurface(Vec3(10, 10, 10), 5.0).triangles.size());
  // In a part scaled 1000 times when placed (metres to mm), the message speaks in mm of it.
  try {
    wrapSurface(box, 0.001, 40e6, 1000.0);
    ADD_FAILURE() << "a wrap of a billion triangles was not refused";
  } catch (const GeoLatticeError& e) {
    EXPECT_NE(std::string(e.what()).find("600000000 mm^2 of surface at a resolution of 1 mm"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(wrapSurface(box, 1.0, 40e6, 0.0), GeoLatticeError);
}
