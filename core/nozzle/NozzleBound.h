#pragma once
/// @file NozzleBound.h
/// @brief A conservative test of whether a ball can hold a point inside the nozzle at a station:
/// the spatial indices over material (the verifier's and the axis clearance's kd-tree, the
/// sequencer's bounding-sphere trees) skip whole clusters with it before the exact test
/// (NozzleVolume::contains).
#include "nozzle/NozzleModel.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

namespace geolattice {

/// Conservative reject test for a nozzle at (tip, axis): can any point of a ball be inside a cone
/// of half-angle `angle` about the axis with its apex `apexOffset` below the tip (cut at `reach`
/// from the tip, above the tip plane by more than `clearance`)? angle >= 90° keeps only the reach
/// test. With `volume` (a printhead's swept profile) the ball must also reach into that profile.
struct NozzleBound {
  NozzleBound(double angleRad, double reachMm, double clearanceMm, double apexOffsetMm = 0.0,
              const NozzleVolume* profile = nullptr);
  /// The bound of a nozzle model: its bounding cone, reach and tip clearance, and the printhead
  /// profile test through `volume` (made from the same model) when it has a printhead.
  NozzleBound(const NozzleModel& model, const NozzleVolume& volume);
  void setStation(const Eigen::Vector3d& tipPoint, const Eigen::Vector3d& unitAxis) {
    tip = tipPoint;
    axis = unitAxis;
  }
  bool mayTouch(const Eigen::Vector3d& centre, double radius) const;  // defined below (inline)

  Eigen::Vector3d tip = Eigen::Vector3d::Zero(), axis = Eigen::Vector3d::UnitZ();
  double sinAngle = 0, cosAngle = 1;
  bool halfSpaceOrMore = false;
  double reach = std::numeric_limits<double>::infinity();
  double clearance = 0;  ///< -infinity disables the tip-plane test
  double apexOffset = 0;
  const NozzleVolume* volume = nullptr;
};

// Inline: every node visit of the collision searches calls it.
inline bool NozzleBound::mayTouch(const Eigen::Vector3d& c, double rho) const {
  const Eigen::Vector3d v = c - tip;
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
