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

}  // namespace geolattice
