#pragma once
/// @file NozzleModel.h
/// @brief The nozzle volume used for collision tests (paper Section 3.1, Fig. 13a): its
/// bounding cone with half-angle NA about the nozzle axis (the layer normal at the tip), apex at
/// the tip, optionally cut at the nozzle length L above which the holder is a cylinder of
/// radius R about the same axis (unbounded upwards). With L = ∞ it is the paper's cone.
///
/// In coordinates of a tip p and unit axis n, a point x with h = (x - p)·n and
/// r = |x - p - h n| is inside iff h > tipClearance and
///   (h <= L and r < h tan NA)  or  (h > L and r < R).
/// tipClearance (>= 0, default 0.1 mm) ignores material level with the tip: the nozzle's flat
/// face rides on the layer being printed, so beads of the same layer next to the tip (their tops
/// within a fraction of a layer of the tip, e.g. where the path passes a crossing the second
/// time) are not obstacles. 0 makes every point above the tip plane count.
#include <cmath>
#include <limits>

namespace geolattice {

struct NozzleModel {
  double halfAngleDeg = 45.0;   ///< NA, in (0, 90) degrees
  double length = std::numeric_limits<double>::infinity();  ///< L (mm, > 0), ∞ = cone only
  double holderRadius = 0.0;    ///< R (mm, >= 0), used when length is finite; 0 = no holder
  double tipClearance = 0.1;    ///< material with h <= this is ignored (mm, >= 0)

  /// Throws GeoLatticeError naming the bad parameter.
  void validate() const;
  /// Half-angle of a cone with the same apex and axis that contains the whole nozzle volume:
  /// max(NA, atan(R / L)). Used for conservative bounds only.
  double boundingHalfAngleRad() const;
  /// Distance from the tip beyond which nothing is inside: L / cos NA for a finite nozzle
  /// without holder (holderRadius 0), else ∞.
  double reach() const;
};

} // namespace geolattice
