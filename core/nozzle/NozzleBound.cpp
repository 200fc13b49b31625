#include "nozzle/NozzleBound.h"

#include <algorithm>
#include <cmath>

namespace geolattice {

using Vec = Eigen::Vector3d;

NozzleBound::NozzleBound(double angleRad, double reachMm, double clearanceMm, double apexOffsetMm,
                         const NozzleVolume* profile)
    : sinAngle(std::sin(angleRad)),
      cosAngle(std::cos(angleRad)),
      halfSpaceOrMore(angleRad >= M_PI / 2),
      reach(reachMm),
      clearance(clearanceMm),
      apexOffset(apexOffsetMm),
      volume(profile) {}

NozzleBound::NozzleBound(const NozzleModel& model, const NozzleVolume& v)
    : NozzleBound(model.boundingHalfAngleRad(), model.reach(), model.tipClearance,
                  model.boundingApexOffset(), model.printhead ? &v : nullptr) {}

bool NozzleBound::mayTouch(const Vec& c, double rho) const {
  const Vec v = c - tip;
  const double h = v.dot(axis);
  if (h + rho <= clearance) {
    return false;  // the whole ball is at or below the tip plane
  }
  const double v2 = v.squaredNorm();
  if (v2 > (rho + reach) * (rho + reach)) {
    return false;  // beyond the end of the nozzle
  }
  const double r = std::sqrt(std::max(0.0, v2 - h * h));
  if (volume && !volume->mayContainBall(h, r, rho)) {
    return false;  // outside the printhead's profile
  }
  if (halfSpaceOrMore) {
    return true;
  }
  const double ha = h + apexOffset;  // height above the bounding cone's apex
  if (r * cosAngle <= ha * sinAngle) {
    return true;  // centre inside the bounding cone
  }
  const double along = r * sinAngle + ha * cosAngle;
  const double distance = along <= 0 ? std::sqrt(r * r + ha * ha) : r * cosAngle - ha * sinAngle;
  return distance <= rho;
}

}  // namespace geolattice
