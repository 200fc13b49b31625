#include "nozzle/Printhead.h"

#include "common/Error.h"
#include "mesh/CgalSurfaceMesh.h"
#include "mesh/SurfaceCheck.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>

#include <cmath>
#include <sstream>

namespace geolattice {

namespace {

using K = cgal::Kernel;
using Mesh = cgal::SurfaceMesh;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(4);
  s << v;
  return s.str();
}

/// Squared distance from the z axis.
double radial2(const Vec3& p) {
  return p.x() * p.x() + p.y() * p.y();
}

/// The point of segment ab at height z (a and b on either side of it, or on it).
Vec3 atHeight(const Vec3& a, const Vec3& b, double z) {
  const double dz = b.z() - a.z();
  const double t = dz != 0 ? std::clamp((z - a.z()) / dz, 0.0, 1.0) : 0.0;
  return a + t * (b - a);
}

}  // namespace

Printhead::Printhead(const TriangleSurface& mesh, const std::string& name) : name_(name) {
  const std::string what = "printhead " + name + ": ";
  SurfaceCheckReport check;
  try {
    check = requireClosedManifold(mesh);
  } catch (const GeoLatticeError& e) {
    throw GeoLatticeError(what + e.what() +
                          " (a printhead must be one closed, edge-manifold triangle mesh: export "
                          "it as a solid body from your CAD tool)");
  }
  triangles_ = check.triangleCount;
  volume_ = std::abs(check.signedVolume);

  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3& p : mesh.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double size = (hi - lo).maxCoeff();
  if (size < 1.0 || size > 2000.0) {
    throw GeoLatticeError(what + "it is " + fmt(size) +
                          " mm across; a printhead is given in millimetres (1 mm - 2 m)" +
                          (size < 1.0 ? ": was it exported in metres?" : ""));
  }
  const Mesh solid = cgal::toSurfaceMesh(mesh, what + "CGAL");
  if (CGAL::Polygon_mesh_processing::does_self_intersect(solid)) {
    throw GeoLatticeError(what +
                          "the mesh intersects itself; repair it (or export the printhead as "
                          "one solid body) so that its inside is well defined");
  }

  // The tip: the lowest point, on the axis at the origin.
  const double tolerance = std::max(1e-3, 1e-5 * size);
  if (std::abs(lo.z()) > tolerance) {
    throw GeoLatticeError(what + "its lowest point is at z = " + fmt(lo.z()) +
                          " mm; the tip (the centre of the orifice face) must be at the origin "
                          "with the nozzle axis along +z, up into the printhead");
  }
  const Tree tree(faces(solid).first, faces(solid).second, solid);
  const double tipDistance = std::sqrt(tree.squared_distance(K::Point_3(0, 0, 0)));
  if (tipDistance > tolerance) {
    throw GeoLatticeError(what + "the origin is " + fmt(tipDistance) +
                          " mm from its surface; the tip (the centre of the orifice face) must be "
                          "at the origin with the nozzle axis along +z");
  }
  height_ = hi.z();
  const CGAL::Side_of_triangle_mesh<Mesh, K> inside(solid);
  const double probe = std::min(0.05, 0.01 * height_);
  if (inside(K::Point_3(0, 0, probe)) != CGAL::ON_BOUNDED_SIDE) {
    throw GeoLatticeError(what +
                          "the nozzle axis (+z from the tip at the origin) does not enter "
                          "the printhead; the axis must point from the tip up into it");
  }

  // Height profile: per bin, the largest distance from the axis over the closed slab.
  const int bins =
      std::max(1, std::min(kProfileBins, static_cast<int>(std::ceil(height_ / 0.005))));
  bin_ = height_ / bins;
  invBin_ = 1.0 / bin_;
  std::vector<double> r2(bins, 0.0);
  for (const auto& t : mesh.triangles) {
    const Vec3 v[3] = {mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]};
    const double zLo = std::min({v[0].z(), v[1].z(), v[2].z()});
    const double zHi = std::max({v[0].z(), v[1].z(), v[2].z()});
    const int k0 = std::clamp(static_cast<int>(std::floor(zLo * invBin_)), 0, bins - 1);
    const int k1 = std::clamp(static_cast<int>(std::floor(zHi * invBin_)), 0, bins - 1);
    for (int k = k0; k <= k1; ++k) {
      const double s0 = k * bin_, s1 = (k + 1) * bin_;
      double best = 0;
      for (int i = 0; i < 3; ++i) {
        const Vec3& a = v[i];
        const Vec3& b = v[(i + 1) % 3];
        if (a.z() >= s0 && a.z() <= s1) {
          best = std::max(best, radial2(a));
        }
        for (double s : {s0, s1}) {  // where the edge crosses a slab plane
          if ((a.z() - s) * (b.z() - s) <= 0 && a.z() != b.z()) {
            best = std::max(best, radial2(atHeight(a, b, s)));
          }
        }
      }
      r2[k] = std::max(r2[k], best);
    }
  }
  radius_.resize(bins);
  for (int k = 0; k < bins; ++k) {
    radius_[k] = std::sqrt(r2[k]);
    maxRadius_ = std::max(maxRadius_, radius_[k]);
    reach_ = std::max(reach_, std::hypot((k + 1) * bin_, radius_[k]));
  }
  faceRadius_ = radius_[0];
  radiusMax_ = RangeMax(radius_);

  // Bounding cone: the apex offset a (from a few candidates) whose cone is narrowest 10 mm up;
  // the half-angle covers every bin from its lower height.
  double bestWidth = std::numeric_limits<double>::infinity();
  for (double a : {0.0, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0}) {
    double angle = 0;
    for (int k = 0; k < bins; ++k) {
      angle = std::max(angle, std::atan2(radius_[k], k * bin_ + a));
    }
    const double width = (10.0 + a) * std::tan(std::min(angle, 0.5 * M_PI - 1e-9));
    if (width < bestWidth) {
      bestWidth = width;
      apexOffset_ = a;
      boundAngle_ = angle;
    }
  }

  // Clear angles by distance from the tip: bin k holds points at distance in
  // [k bin, |((k + 1) bin, R_k)|] at angles up to atan2(R_k, k bin).
  angleBin_ = std::max(bin_, reach_ / 2048);
  clearAngle_.assign(static_cast<size_t>(std::ceil(reach_ / angleBin_)) + 1, 0.0);
  for (int k = 0; k < bins; ++k) {
    if (radius_[k] <= 0) {
      continue;
    }
    const double angle = std::atan2(radius_[k], k * bin_);
    const int j0 = static_cast<int>(k * bin_ / angleBin_);
    const int j1 = std::min(static_cast<int>(clearAngle_.size()) - 1,
                            static_cast<int>(std::hypot((k + 1) * bin_, radius_[k]) / angleBin_));
    for (int j = j0; j <= j1; ++j) {
      clearAngle_[j] = std::max(clearAngle_[j], angle);
    }
  }
  clearAngleMax_ = RangeMax(clearAngle_);
  std::vector<double> negCos(clearAngle_.size());
  for (size_t j = 0; j < negCos.size(); ++j) {
    negCos[j] = -std::cos(clearAngle_[j]);
  }
  negCosClearMax_ = RangeMax(negCos);
}

double Printhead::maxClearAngleBetween(double rho0, double rho1) const {
  rho0 = std::max(rho0, 0.0);
  rho1 = std::min(rho1, reach_);
  if (!(rho0 <= rho1)) {
    return 0.0;
  }
  return clearAngleMax_(static_cast<int>(rho0 / angleBin_), static_cast<int>(rho1 / angleBin_));
}

double Printhead::clearAngleAt(double rho) const {
  if (!(rho >= 0) || rho > reach_) {
    return 0.0;
  }
  const int j =
      std::min(static_cast<int>(rho / angleBin_), static_cast<int>(clearAngle_.size()) - 1);
  return clearAngle_[j];
}

}  // namespace geolattice
