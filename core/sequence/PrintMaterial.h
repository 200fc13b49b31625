#pragma once
/// @file PrintMaterial.h
/// @brief The printed material of each lattice sub-graph as sample points with nozzle
/// directions: every lattice vertex plus evenly spaced points inside longer edges. The
/// sequencer (potential collisions) and the collision verifier both test these points, so
/// their verdicts refer to the same material; each computes its own geometry.
#include "lattice/LatticeInfill.h"

#include <vector>

namespace geolattice {

/// @brief Samples grouped by sub-graph: sub-graph s owns [offset[s], offset[s+1]).
struct MaterialSamples {
  std::vector<Vec3> points;   ///< #S positions (mm)
  std::vector<Vec3> normals;  ///< #S unit nozzle axes (interpolated along edges)
  std::vector<int> subgraph;  ///< #S sub-graph id
  std::vector<int> offset;    ///< #subgraphs + 1
};

/// How densely the material is sampled (shared by the sequencer and the verifier).
struct MaterialSampling {
  double spacing = 1.0;  ///< mm between samples along an edge (> 0)
};

/// Samples the lattice: each vertex once, and ceil(len / spacing) - 1 interior points on an edge
/// of length len. Throws GeoLatticeError for spacing <= 0 or a lattice whose per-vertex or
/// per-edge arrays do not match its points. Vertices without a sub-graph (-1) are skipped.
MaterialSamples sampleLatticeMaterial(const LatticeGraph& lattice, double spacing);

/// The same samples grouped by `edgeGroup` (one group id in [0, groups) per edge, -1 for an edge
/// without a sub-graph), e.g. the pieces of split sub-graphs: an edge's interior samples go to
/// its group, a vertex is sampled once for every group among its edges (a vertex where a
/// sub-graph was cut belongs to each piece), and a vertex without edges to the group of its
/// sub-graph id. MaterialSamples::subgraph then holds the group. Throws as above, and for an
/// edgeGroup of the wrong size or with ids out of range.
MaterialSamples sampleLatticeMaterial(const LatticeGraph& lattice, double spacing,
                                      const std::vector<int>& edgeGroup, int groups);

}  // namespace geolattice
