#include "placement/PlaceOnPlatform.h"

#include "common/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace geolattice {

void PlacementOptions::validate() const {
  // Negated comparisons also catch NaN.
  if (!(scale > 0.0) || !std::isfinite(scale)) {
    std::ostringstream m;
    m << "Scale must be > 0 (and finite), got " << scale;
    throw GeoLatticeError(m.str());
  }
  if (!(fitSize >= 0.0) || !std::isfinite(fitSize)) {
    std::ostringstream m;
    m << "FitSize must be >= 0 mm (0 = off), got " << fitSize;
    throw GeoLatticeError(m.str());
  }
  if (!(wrap >= 0.0) || !std::isfinite(wrap)) {
    std::ostringstream m;
    m << "Wrap must be >= 0 mm (0 = off), got " << wrap;
    throw GeoLatticeError(m.str());
  }
}

Placement placeOnPlatform(const Vec3& lo, const Vec3& hi, const PlacementOptions& options) {
  options.validate();
  if (!lo.allFinite() || !hi.allFinite()) {
    throw GeoLatticeError("the model's bounding box is not finite (NaN or infinite coordinates)");
  }
  const Vec3 extent = hi - lo;
  const double largest = extent.maxCoeff();
  Placement p;
  p.scale = options.scale;
  if (options.fitSize > 0.0) {
    if (!(largest > 0.0)) {
      throw GeoLatticeError(
          "FitSize needs a model with extent: its bounding box is a single point");
    }
    p.scale = options.fitSize / largest;
  }
  p.size = p.scale * extent;
  const double placed = p.size.maxCoeff();
  if (!(placed >= kMinPartSizeMm) || !(placed <= kMaxPartSizeMm)) {
    std::ostringstream m;
    m << "the part is " << placed << " mm across after scaling (" << extent.x() << " x "
      << extent.y() << " x " << extent.z() << " model units x Scale " << p.scale
      << "); a printable part is " << kMinPartSizeMm << " mm to " << kMaxPartSizeMm << " mm";
    if (placed > 0 && placed < kMinPartSizeMm) {
      const bool metres = placed < 2.0;  // 0.05 across: most likely metres
      m << " - is the file in " << (metres ? "metres" : "centimetres or inches") << "? use Scale "
        << (metres ? 1000 : 10) << " or FitSize MM";
    } else if (placed > kMaxPartSizeMm) {
      m << " - is the file in micrometres, or are its coordinates far from the origin? use "
           "Scale or FitSize MM";
    } else {
      m << " - it is flat or a single point";
    }
    throw GeoLatticeError(m.str());
  }
  const Vec3 centre = 0.5 * (lo + hi);
  p.translation = Vec3(options.centerXY ? -(p.scale * centre.x()) : 0.0,
                       options.centerXY ? -(p.scale * centre.y()) : 0.0, -(p.scale * lo.z()));
  return p;
}

std::vector<int> baseContactFaces(const TriangleSurface& surface, const Eigen::Matrix3d& R,
                                  double contactHeight) {
  // A closed surface whose triangles all face inward (a common export error; meshing turns it
  // outward later) has a negative enclosed volume: its outward normals are the opposite of the
  // triangles' (R is a rotation, so the sign does not depend on it).
  double sixVolume = 0;
  for (const auto& t : surface.triangles) {
    sixVolume += surface.points[t[0]].dot(surface.points[t[1]].cross(surface.points[t[2]]));
  }
  const double outward = sixVolume < 0 ? -1.0 : 1.0;
  double zmin = std::numeric_limits<double>::infinity();
  std::vector<double> z(surface.points.size());
  for (size_t i = 0; i < z.size(); ++i) {
    z[i] = R.row(2).dot(surface.points[i]);
    zmin = std::min(zmin, z[i]);
  }
  const double cosMax = std::cos(30 * M_PI / 180.0);
  std::vector<int> faces;
  for (size_t f = 0; f < surface.triangles.size(); ++f) {
    const auto& t = surface.triangles[f];
    if (z[t[0]] - zmin > contactHeight || z[t[1]] - zmin > contactHeight ||
        z[t[2]] - zmin > contactHeight) {
      continue;
    }
    const Vec3 cross = (R * (surface.points[t[1]] - surface.points[t[0]]))
                           .cross(R * (surface.points[t[2]] - surface.points[t[0]]));
    const double twice = cross.norm();
    if (twice > 0 && -outward * cross.z() / twice >= cosMax) {
      faces.push_back(static_cast<int>(f));
    }
  }
  return faces;
}

}  // namespace geolattice
