#include "robot/PartFloor.h"

#include <algorithm>

namespace geolattice {

PartFloor::PartFloor(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points)
    : partOnFlange_(cell.partOnFlange), scale_(cell.partScale) {
  Eigen::AlignedBox3d all;
  for (const Eigen::Vector3d& p : points) {
    all.extend(p);
  }
  // The plate: the whole path's footprint at its lowest z, there from the first point on.
  Eigen::AlignedBox3d box;
  if (!all.isEmpty()) {
    box.extend(all.min());
    box.extend(Eigen::Vector3d(all.max().x(), all.max().y(), all.min().z()));
  }
  boxes_.reserve((points.size() + kBlock - 1) / kBlock);
  for (size_t i = 0; i < points.size(); ++i) {
    box.extend(points[i]);
    if (i % kBlock == kBlock - 1 || i + 1 == points.size()) {
      boxes_.push_back(box);
    }
  }
}

double PartFloor::lowest(const Isometry& flange, size_t i) const {
  const Eigen::AlignedBox3d& box = boxes_.at(std::min(i / kBlock, boxes_.size() - 1));
  const Isometry part = flange * partOnFlange_;
  const Eigen::Vector3d centre = part * (scale_ * box.center());
  const Eigen::Vector3d half = 0.5 * scale_ * box.sizes();
  // The box's lowest corner: its centre less the half extents along the rotated z row.
  return centre.z() - part.linear().row(2).cwiseAbs().dot(half);
}

}  // namespace geolattice
