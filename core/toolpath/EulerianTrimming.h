#pragma once
/// @file EulerianTrimming.h
/// @brief Eulerian trimming of the lattice sub-graphs (paper Section 3.2, Fig. 14b): delete
/// boundary edges so that every vertex has even degree and each sub-graph has a closed Euler
/// tour.
///
/// Along each boundary loop of a sub-graph the odd vertices (the boundary hits of degree 3)
/// v_1, v_2, … cut the loop into chains; deleting every second chain makes each of them even.
/// Of the two parities per loop, the one that keeps the sub-graph connected is taken (ties: the
/// one that deletes less length); with several loops the combinations are searched (all of them
/// up to 8 loops, else loop by loop). A loop with an odd number of odd vertices (an isoline from
/// the outer boundary to a hole) cannot be fixed by its own chains: the remaining odd vertices
/// are paired by shortest paths inside the sub-graph (a T-join) whose edges are deleted. If
/// no choice keeps a sub-graph connected, it is printed as several tours and counted in
/// splitSubgraphs. O(E) per sub-graph and tried combination.
#include "lattice/LatticeInfill.h"

#include <vector>

namespace geolattice {

struct TrimResult {
  std::vector<char> kept;           ///< #E 1 = edge stays in the printed graph
  std::vector<int> componentCount;  ///< per sub-graph: connected pieces after trimming (1 normally)
  int trimmedEdges = 0;             ///< boundary edges deleted
  double trimmedLength = 0;         ///< their length (mm)
  int tJoinEdges = 0;               ///< edges deleted by the odd-loop fallback
  int splitSubgraphs = 0;           ///< sub-graphs left in more than one piece
  int oddLoops = 0;                 ///< boundary loops with an odd number of odd vertices
};

/// Documented repair before trimming: contracts edges not longer than `tolerance` (mm). The
/// lattice can hold such edges where an α/β crossing falls exactly on a layer-mesh edge that
/// also carries one of the isoline points (e.g. lattice levels aligned with a structured mesh's
/// diagonals): the crossing and the isoline point are then two vertices at one position.
/// Contracting merges them (degrees 4 + 2 - 2 = 4) and removes the edge from every per-edge
/// array of g; vertex arrays keep their size (the merged vertex keeps its edges, the other is
/// left without edges). `edgeValues` (optional, one per edge, e.g. the pieces of split
/// sub-graphs) is compacted with the edges. Returns the number of contracted edges.
int contractShortEdges(LatticeGraph& g, double tolerance, std::vector<int>* edgeValues = nullptr);
/// The edges contractShortEdges would contract (none changed), so a caller copies the lattice
/// only when there are some. Throws GeoLatticeError for an edge that refers to a missing vertex.
int countShortEdges(const LatticeGraph& g, double tolerance);

/// Trims every sub-graph of g. Needs edges, edgeKind, edgeSubgraph, vertexSubgraph, points and
/// subgraphs. Throws GeoLatticeError for inconsistent arrays or a zero-length edge.
TrimResult trimToEulerian(const LatticeGraph& g);

}  // namespace geolattice
