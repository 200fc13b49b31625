#include "nozzle/NozzleModel.h"

#include "common/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace geolattice {

void NozzleModel::validate() const {
  auto fail = [](const char* what, double v) {
    std::ostringstream s;
    s << what << " (got " << v << ")";
    throw GeoLatticeError(s.str());
  };
  if (!(halfAngleDeg > 0.0 && halfAngleDeg < 90.0)) {
    fail("nozzle angle must be in (0, 90) degrees", halfAngleDeg);
  }
  if (!(length > 0.0)) {  // infinity is allowed
    fail("nozzle length must be > 0 mm", length);
  }
  if (!(holderRadius >= 0.0) || !std::isfinite(holderRadius)) {
    fail("holder radius must be finite and >= 0 mm", holderRadius);
  }
  if (!(holderLength > 0.0)) {  // infinity is allowed
    fail("holder length must be > 0 mm", holderLength);
  }
  if (!(tipClearance >= 0.0) || !std::isfinite(tipClearance)) {
    fail("tip clearance must be finite and >= 0 mm", tipClearance);
  }
  if (!(tipFaceRadius >= 0.0) || !std::isfinite(tipFaceRadius)) {
    fail("nozzle tip face radius must be finite and >= 0 mm", tipFaceRadius);
  }
  if (!(faceContact >= 0.0) || !std::isfinite(faceContact)) {
    fail("face contact must be finite and >= 0 mm", faceContact);
  }
  if (!(printheadMarginRad >= 0.0 && printheadMarginRad < 0.5 * M_PI)) {
    fail("printhead margin must be in [0, 90) degrees", printheadMarginRad * 180.0 / M_PI);
  }
}

NozzleModel NozzleModel::widened(double marginDeg) const {
  NozzleModel wide = *this;
  if (printhead) {
    wide.printheadMarginRad = printheadMarginRad + marginDeg * M_PI / 180.0;
  } else {
    wide.halfAngleDeg = std::min(89.9, halfAngleDeg + marginDeg);
  }
  return wide;
}

double NozzleModel::boundingApexOffset() const {
  return printhead ? printhead->boundApexOffset() : 0.0;
}

double NozzleModel::boundingHalfAngleRad() const {
  if (printhead) {
    return std::min(0.5 * M_PI, printhead->boundHalfAngleRad() + printheadMarginRad);
  }
  const double cone = halfAngleDeg * M_PI / 180.0;
  if (!std::isfinite(length)) {
    return cone;
  }
  return std::max(cone, std::atan2(holderRadius, length));
}

double NozzleModel::reach() const {
  if (printhead) {
    return printhead->reach() * (1.0 + std::tan(printheadMarginRad));
  }
  if (std::isfinite(length) && holderRadius == 0.0) {
    return length / std::cos(halfAngleDeg * M_PI / 180.0);
  }
  if (std::isfinite(length) && std::isfinite(holderLength)) {
    return std::max(length / std::cos(halfAngleDeg * M_PI / 180.0),
                    std::hypot(length + holderLength, holderRadius));
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace geolattice
