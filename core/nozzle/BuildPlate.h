#pragma once
/// @file BuildPlate.h
/// @brief The build plate as an obstacle for the nozzle: a slab of `thickness` under z = 0 that
/// covers the part's footprint (x/y bounding box) grown by `margin` on every side, moving with the
/// part (the platform frame of the toolpath). The nozzle volume must stay clear of it at every
/// station and on every air move, like printed material: the collision verifier and the toolpath's
/// axis clearance test its sample points (the top face and the four sides, every `spacing` mm)
/// with the same point-in-nozzle test as material, and a station whose tip is below the plate's
/// top inside the footprint is a plate collision by itself.
#include "mesh/TetMesh.h"

#include <vector>

namespace geolattice {

struct BuildPlate {
  bool enabled = true;     ///< false: no plate obstacle (the paper's model)
  double margin = 10.0;    ///< the plate extends this far beyond the part's footprint (mm, >= 0)
  double thickness = 5.0;  ///< slab thickness under z = 0 (mm, > 0)
  double spacing = 1.0;    ///< sample spacing on its faces (mm, > 0)

  /// Throws GeoLatticeError naming a bad parameter.
  void validate() const;
};

/// Sample points of the plate's top face (z = 0) and sides for a part whose points are `part`
/// (only their x/y extent is used); empty when the plate is disabled or the part has no points.
std::vector<Vec3> buildPlateSamples(const BuildPlate& plate, const std::vector<Vec3>& part);

/// Whether a nozzle tip at p is inside the plate (below its top face, inside the footprint grown
/// by the margin, above its bottom) for a part with the given x/y extent [lo, hi].
bool tipInsidePlate(const BuildPlate& plate, const Vec3& lo, const Vec3& hi, const Vec3& p);

}  // namespace geolattice
