#pragma once
/// @file EulerTour.h
/// @brief Closed Euler tours without crossovers on the trimmed lattice (paper Section 3.2,
/// Fig. 15), in linear time instead of Fleury's O(n²).
///
/// At every vertex the incident edges are ordered by angle in the tangent plane of the nozzle
/// direction (the layer normal). A transition system pairs them: (e0 e1)(e2 e3)… in that cyclic
/// order, i.e. the path turns at a crossing instead of going straight through (non-crossing
/// pairs). Following the transitions splits the edges into closed circuits. Two circuits that
/// meet at a degree-4 vertex are merged by switching it to the other non-crossing pairing
/// (e1 e2)(e3 e0): re-pairing the four ends of two different closed trails always joins them
/// into one, and the union-find over circuit ids tracks which circuits are already joined, so
/// one pass over the vertices leaves one circuit per connected piece (Kotzig's A-trail
/// construction for 4-regular plane graphs). O(E log d) overall (sorting d edges per vertex).
/// Vertices of degree 6 or more (irregular lattice vertices) keep their first pairing and are
/// counted; a piece may then need more than one tour.
#include "lattice/LatticeInfill.h"

#include <vector>

namespace geolattice {

struct EulerTours {
  std::vector<std::vector<int>> vertices;  ///< per tour: closed vertex sequence (first == last)
  std::vector<std::vector<int>> edges;  ///< per tour: edge ids in order (vertices[t][i] -> [i+1])
  std::vector<int> subgraph;            ///< per tour: the sub-graph it belongs to
  int switches = 0;                     ///< transitions switched to merge circuits
  int highDegreeVertices = 0;           ///< degree >= 6: kept unswitched
};

/// Tours over the edges with kept[e] != 0 (all edges if kept is empty); uses points, normals,
/// edges and edgeSubgraph of g. Throws GeoLatticeError for an odd-degree vertex (naming it and
/// its degree: trim first), inconsistent sizes or a zero normal at a vertex of degree >= 4.
EulerTours nonCrossingEulerTours(const LatticeGraph& g, const std::vector<char>& kept);

/// Independent check used by tests and the planner's report: for every vertex passed more than
/// once by the same tour, do two passes (in-edge, out-edge) interleave in the cyclic order
/// around it? Returns the number of such crossing pairs (0 for tours from nonCrossingEulerTours).
int countTourCrossovers(const LatticeGraph& g, const EulerTours& tours);

}  // namespace geolattice
