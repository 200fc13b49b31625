#pragma once
/// @file GridHash.h
/// @brief Cells of a uniform grid, keyed for a hash map: the spatial index of the searches that
/// only ask what lies within a short distance (the seam weld of mesh/SurfaceRepair.h, the far
/// side of a layer region in toolpath/SupportPerimeter.h). Cells as large as that distance: a
/// query visits the few cells its box overlaps.
#include <Eigen/Core>

#include <cstdint>

namespace geolattice {

/// The integer cell of p in a grid of cubes of side `cell` (> 0) with a corner at the origin.
inline Eigen::Vector3i gridCell(const Eigen::Vector3d& p, double cell) {
  return (p / cell).array().floor().cast<int>();
}

/// A hash key of a cell (the primes of Teschner et al. 2003). Distinct cells may share a key:
/// what a key holds are candidates to test, not answers.
inline uint64_t gridCellKey(const Eigen::Vector3i& c) {
  return (static_cast<uint64_t>(static_cast<uint32_t>(c.x())) * 73856093u) ^
         (static_cast<uint64_t>(static_cast<uint32_t>(c.y())) * 19349663u) ^
         (static_cast<uint64_t>(static_cast<uint32_t>(c.z())) * 83492791u);
}

/// Calls f(key) for every cell the box [lo, hi] overlaps.
template <class F>
void forEachGridCell(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double cell, F&& f) {
  const Eigen::Vector3i a = gridCell(lo, cell), z = gridCell(hi, cell);
  for (int i = a.x(); i <= z.x(); ++i) {
    for (int j = a.y(); j <= z.y(); ++j) {
      for (int k = a.z(); k <= z.z(); ++k) {
        f(gridCellKey(Eigen::Vector3i(i, j, k)));
      }
    }
  }
}

}  // namespace geolattice
