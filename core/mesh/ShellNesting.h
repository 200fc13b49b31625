#pragma once
/// @file ShellNesting.h
/// @brief The shells of a triangle surface (triangles joined across their edges) and which lie
/// inside which; with it, the closed inner cavities of a part filled.
///
/// A hollow part (a ball with a sealed void) is one outward shell with an inward one inside it.
/// No nozzle reaches the inside of a sealed void, and the curved layers that close over its roof
/// meet from every side in a funnel that the nozzle cannot print without touching the layer's
/// other flank (a generated hollow ball, r 20 / 14 mm: 2,580 colliding stations as placed,
/// 2,287 with --orient auto; filled, it prints). The lattice infill makes the part light anyway,
/// so the usual answer is to print it solid: fillCavities removes the cavities' shells.
#include "mesh/TetMesh.h"

#include <Eigen/Geometry>

#include <vector>

namespace geolattice {

/// The shells of a surface and their nesting.
struct ShellNesting {
  int shells = 0;
  std::vector<int> shellOf;                 ///< per triangle: its shell
  std::vector<std::vector<int>> triangles;  ///< per shell: its triangles
  std::vector<double> volume6;              ///< per shell: 6 x signed volume (< 0: inward)
  std::vector<Eigen::AlignedBox3d> box;     ///< per shell: its bounding box
  /// Per shell: the shells it lies in (|winding number| 1 of one of its points, its largest
  /// triangle's centroid, whichever way they face), among those whose box holds its box.
  std::vector<std::vector<int>> inside;

  /// Shell s faces inward and lies in another shell: a cavity (SurfaceRepair's
  /// orientInvertedBodies has turned the bodies that were inside out).
  bool isCavity(int s) const { return volume6[s] < 0 && !inside[s].empty(); }
};

/// O(F) for one shell; O(F + sum over nested pairs of their triangles) otherwise.
ShellNesting nestShells(const TriangleSurface& surface);

struct CavityFilling {
  int cavities = 0;        ///< cavity shells removed
  int enclosedBodies = 0;  ///< shells inside a cavity removed with it (a body loose in a void)
  int removedTriangles = 0;
};

/// Removes every cavity's shell and every shell inside a cavity, and the points no triangle
/// uses any more: the part becomes solid where it was hollow. Expects a closed surface oriented
/// as repairSurface leaves it (mesh/SurfaceRepair.h: bodies outward, cavities inward).
CavityFilling fillCavities(TriangleSurface& surface);

}  // namespace geolattice
