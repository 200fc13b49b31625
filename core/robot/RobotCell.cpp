#include "robot/RobotCell.h"

#include "common/Error.h"
#include "common/Rotation.h"

#include <cmath>

namespace geolattice {

void RobotCell::validate() const {
  if (!nozzleTip.allFinite() || !nozzleAxis.allFinite() ||
      std::abs(nozzleAxis.norm() - 1.0) > 1e-9) {
    throw GeoLatticeError(
        "robot cell: the nozzle tip must be finite and the nozzle axis a unit vector");
  }
  if (!(partScale > 0) || !std::isfinite(partScale) || !partOnFlange.matrix().allFinite()) {
    throw GeoLatticeError(
        "robot cell: the part scale must be > 0 and the part-on-flange transform finite");
  }
}

Isometry RobotCell::flangePose(const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                               double psi) const {
  const Eigen::Matrix3d align = rotationBetween(n, nozzleAxis);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(psi, nozzleAxis).toRotationMatrix() * align;
  Isometry part = Isometry::Identity();
  part.linear() = r;
  part.translation() = nozzleTip - r * (partScale * p);
  return part * partOnFlange.inverse();
}

}  // namespace geolattice
