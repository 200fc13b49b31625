#include "nozzle/BuildPlate.h"

#include "common/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace geolattice {

void BuildPlate::validate() const {
  if (!(margin >= 0) || !std::isfinite(margin) || !(thickness > 0) || !std::isfinite(thickness) ||
      !(spacing > 0) || !std::isfinite(spacing)) {
    std::ostringstream s;
    s << "build plate: margin must be >= 0 mm (got " << margin << "), thickness > 0 mm (got "
      << thickness << ") and sample spacing > 0 mm (got " << spacing << ")";
    throw GeoLatticeError(s.str());
  }
}

namespace {

void footprint(const std::vector<Vec3>& part, double margin, Vec3& lo, Vec3& hi) {
  lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (const Vec3& p : part) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  lo.x() -= margin;
  lo.y() -= margin;
  hi.x() += margin;
  hi.y() += margin;
}

}  // namespace

std::vector<Vec3> buildPlateSamples(const BuildPlate& plate, const std::vector<Vec3>& part) {
  std::vector<Vec3> samples;
  if (!plate.enabled || part.empty()) {
    return samples;
  }
  plate.validate();
  Vec3 lo, hi;
  footprint(part, plate.margin, lo, hi);
  const int nx = std::max(1, static_cast<int>(std::ceil((hi.x() - lo.x()) / plate.spacing)));
  const int ny = std::max(1, static_cast<int>(std::ceil((hi.y() - lo.y()) / plate.spacing)));
  const int nz = std::max(1, static_cast<int>(std::ceil(plate.thickness / plate.spacing)));
  const double dx = (hi.x() - lo.x()) / nx, dy = (hi.y() - lo.y()) / ny;
  const double dz = plate.thickness / nz;
  samples.reserve(static_cast<size_t>(nx + 1) * (ny + 1) + 2 * (nx + ny) * nz);
  for (int i = 0; i <= nx; ++i) {  // top face
    for (int j = 0; j <= ny; ++j) {
      samples.emplace_back(lo.x() + i * dx, lo.y() + j * dy, 0.0);
    }
  }
  for (int k = 1; k <= nz; ++k) {  // the four sides, below the top edge
    const double z = -k * dz;
    for (int i = 0; i <= nx; ++i) {
      samples.emplace_back(lo.x() + i * dx, lo.y(), z);
      samples.emplace_back(lo.x() + i * dx, hi.y(), z);
    }
    for (int j = 1; j < ny; ++j) {
      samples.emplace_back(lo.x(), lo.y() + j * dy, z);
      samples.emplace_back(hi.x(), lo.y() + j * dy, z);
    }
  }
  return samples;
}

bool tipInsidePlate(const BuildPlate& plate, const Vec3& lo, const Vec3& hi, const Vec3& p) {
  return plate.enabled && p.z() < 0 && p.z() > -plate.thickness && p.x() > lo.x() - plate.margin &&
         p.x() < hi.x() + plate.margin && p.y() > lo.y() - plate.margin &&
         p.y() < hi.y() + plate.margin;
}

}  // namespace geolattice
