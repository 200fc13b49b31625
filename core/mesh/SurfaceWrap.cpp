#include "mesh/SurfaceWrap.h"

#include "common/Error.h"
#include "common/WorkLimit.h"
#include "mesh/CgalSurfaceMesh.h"

#include <CGAL/alpha_wrap_3.h>

#include <chrono>
#include <cmath>
#include <sstream>

namespace geolattice {

SurfaceWrapResult wrapSurface(TriangleSurface& surface, double alpha, double maxTriangles,
                              double mmPerUnit) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!(mmPerUnit > 0) || !std::isfinite(mmPerUnit)) {
    std::ostringstream s;
    s << "wrap: the scale must be > 0 mm per unit (got " << mmPerUnit << ")";
    throw GeoLatticeError(s.str());
  }
  if (!(alpha > 0) || !std::isfinite(alpha)) {
    std::ostringstream s;
    s << "wrap: the resolution (alpha) must be > 0 mm (got " << alpha * mmPerUnit << ")";
    throw GeoLatticeError(s.str());
  }
  requireValidWorkLimit(maxTriangles, "the wrap's size limit");
  double area = 0;
  for (const auto& t : surface.triangles) {
    const Vec3& a = surface.points[static_cast<size_t>(t[0])];
    area += 0.5 * (surface.points[static_cast<size_t>(t[1])] - a)
                      .cross(surface.points[static_cast<size_t>(t[2])] - a)
                      .norm();
  }
  if (!(area > 0)) {
    throw GeoLatticeError("wrap: the surface has no triangle with an area");
  }
  // A wrap's facets are about alpha across (equilateral-ish: area ~ 0.43 alpha² each); the
  // estimate is for the input's area, which the wrap does not exceed by much.
  const double estimate = area / (0.43 * alpha * alpha);
  std::ostringstream because;
  because << "for " << std::llround(area * mmPerUnit * mmPerUnit)
          << " mm^2 of surface at a resolution of " << alpha * mmPerUnit << " mm";
  requireWithinWorkLimit(estimate, maxTriangles, "wrap", "triangles", because.str(),
                         "use a coarser resolution (a larger --wrap)");
  std::vector<cgal::Kernel::Point_3> points;
  points.reserve(surface.points.size());
  for (const Vec3& p : surface.points) {
    points.emplace_back(p.x(), p.y(), p.z());
  }
  std::vector<std::array<size_t, 3>> faces;
  faces.reserve(surface.triangles.size());
  for (const auto& t : surface.triangles) {
    faces.push_back(
        {static_cast<size_t>(t[0]), static_cast<size_t>(t[1]), static_cast<size_t>(t[2])});
  }
  SurfaceWrapResult r;
  r.inputTriangles = static_cast<int>(surface.triangles.size());
  r.offset = alpha / 30.0;
  cgal::SurfaceMesh wrap;
  try {
    CGAL::alpha_wrap_3(points, faces, alpha, r.offset, wrap);
  } catch (const std::exception& e) {
    throw GeoLatticeError(std::string("wrap: CGAL's alpha wrap failed (") + e.what() + ")");
  }
  TriangleSurface wrapped = cgal::toTriangleSurface(wrap);
  if (wrapped.triangles.empty()) {
    throw GeoLatticeError("wrap: the wrap is empty");
  }
  surface = std::move(wrapped);
  r.triangles = static_cast<int>(surface.triangles.size());
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace geolattice
