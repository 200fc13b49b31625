#pragma once
/// @file PartFloor.h
/// @brief The part the robot holds, against the floor the robot stands on (base z = 0): how
/// low does the part reach at a flange pose, as printed up to a toolpath point?
///
/// The part is modelled by the axis-aligned box (part frame) of the toolpath printed so far,
/// with the plate under it: the footprint of the whole toolpath at its lowest z (the plate's
/// own size is not known to the robot stage; a larger plate is the user's cell to check). The
/// boxes are kept per block of kBlock points, each holding the block's last point, so a point
/// is checked with at most kBlock - 1 points printed after it: memory O(N / kBlock), each query
/// O(1). A box is conservative for the material inside it; the floor check is a bound, not a
/// contact test.
#include "robot/RobotCell.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace geolattice {

class PartFloor {
public:
  static constexpr size_t kBlock = 64;

  /// `points`: the toolpath in part units (cell.partScale converts them to metres).
  PartFloor(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points);

  /// Height (m, base frame z) of the lowest point of the part printed up to point i when the
  /// flange is at `flange` (base frame).
  double lowest(const Isometry& flange, size_t i) const;

private:
  Isometry partOnFlange_;
  double scale_ = 1;
  std::vector<Eigen::AlignedBox3d> boxes_;  ///< per block, part units
};

}  // namespace geolattice
