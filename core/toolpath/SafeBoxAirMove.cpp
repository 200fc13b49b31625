#include "toolpath/SafeBoxAirMove.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geolattice {

namespace {

/// Where the ray x + t·d (t >= 0) leaves the box (x inside). The bottom of the box is the
/// platform side: a ray heading down is stopped at the side faces or, failing that, its
/// horizontal exit, so the tip never goes below the box.
Vec3 exitPoint(const Vec3& x, const Vec3& d, const Eigen::AlignedBox3d& box) {
  double t = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (d[k] > 1e-12) {
      t = std::min(t, (box.max()[k] - x[k]) / d[k]);
    } else if (d[k] < -1e-12 && k < 2) {
      t = std::min(t, (box.min()[k] - x[k]) / d[k]);
    }
  }
  if (!std::isfinite(t)) {  // straight down: go up instead
    return Vec3(x.x(), x.y(), box.max().z());
  }
  Vec3 p = x + std::max(t, 0.0) * d;
  p.z() = std::max(p.z(), x.z());  // never below the start
  return p;
}

}  // namespace

std::vector<AirWaypoint> safeBoxAirMove(const Vec3& from, const Vec3& fromAxis, const Vec3& to,
                                        const Vec3& toAxis, const Eigen::AlignedBox3d& box) {
  const Vec3 na = fromAxis.normalized(), nb = toAxis.normalized();
  const Vec3 a1 = exitPoint(from, na, box);
  const Vec3 b1 = exitPoint(to, nb, box);
  const double top = box.max().z();
  const Vec3 a2(a1.x(), a1.y(), top), b2(b1.x(), b1.y(), top);
  std::vector<AirWaypoint> w;
  // On the top face the nozzle points straight up, so its body stays above the box while it
  // turns; on the way up and down the axis turns between the exit direction (out of the box)
  // and +z, both of which point away from the box.
  w.push_back({a1, na});
  w.push_back({a2, Vec3::UnitZ()});
  w.push_back({b2, Vec3::UnitZ()});
  w.push_back({b1, nb});
  w.push_back({to, nb});
  return w;
}

std::vector<AirWaypoint> liftAirMove(const Vec3& from, const Vec3& fromAxis, const Vec3& to,
                                     const Vec3& toAxis, double lift) {
  const Vec3 na = fromAxis.normalized(), nb = toAxis.normalized();
  return {{from + lift * na, na}, {to + lift * nb, nb}, {to, nb}};
}

}  // namespace geolattice
