#pragma once
/// @file SubgraphSplitting.h
/// @brief The printing order of sub-graph pieces (issue 14, "sub-graph splitting"): where two
/// sub-graphs block each other, one is cut along the lattice into pieces that can be ordered.
///
/// Mutual blocking: i has material inside the nozzle swept over j (i in PCG(j): i must come after
/// j) and j inside the nozzle swept over i (j in PCG(i): j after i). No order of whole
/// sub-graphs avoids it (the sequencer's forced steps). But usually different parts of i are
/// involved: the stations of i that see j's material (they must come before j) and the material
/// of i that j's stations see (it must come after j). When those two sets are disjoint, i is cut
/// between them: every edge of i goes with the nearer of the two sets (its midpoint's distance),
/// and each connected part of either side becomes a piece — cut at lattice vertices, which then
/// belong to the pieces on both sides. The order "the part before, j, the part after" is then
/// possible. Pieces are new nodes of the skeleton with the sub-graph's lower and upper nodes
/// (Criterion 1 for each piece as for the whole), the material is sampled per piece, and the
/// potential collisions and the order are computed again; this repeats for a few rounds while
/// forced steps remain and something can be cut (it stops early when a round made things worse),
/// and the round with the fewest forced steps wins (no split at all when splitting does not
/// reduce them). Pieces of one sub-graph are not ordered by their potential collisions with each
/// other (a whole sub-graph is not tested against itself either). The toolpath prints a piece as the runs
/// of its sub-graph's Euler tour that lie in it (toolpath/ToolpathPlanner.h).
#include "sequence/PotentialCollisions.h"
#include "sequence/PrintMaterial.h"
#include "sequence/PrintSequencer.h"
#include "skeleton/SkeletonTree.h"

#include <vector>

namespace geolattice {

struct SplitOptions {
  /// Split-and-reorder rounds while forced steps remain (0 = never split, the default: on the
  /// bundled models the cuts found so far remove few forced steps and add retractions; see
  /// docs/performance.md, "Sub-graph splitting").
  int maxRounds = 0;
  /// Throws GeoLatticeError naming a bad option.
  void validate() const;
};

struct PieceSequence {
  std::vector<int> edgePiece;      ///< per lattice edge: its piece (-1 for an edge without one)
  std::vector<int> pieceSubgraph;  ///< per piece: the sub-graph it is part of (piece k < K: k)
  SkeletonTree tree;               ///< the skeleton over the pieces
  MaterialSamples material;        ///< samples grouped by piece
  PotentialCollisions pcg;         ///< over the pieces
  PrintSequence sequence;          ///< the order of the pieces
  int forcedStepsBefore = 0;       ///< forced steps of the order of whole sub-graphs
  int splitSubgraphs = 0;          ///< sub-graphs printed as more than one piece
  int rounds = 0;                  ///< rounds that cut something
};

/// The potential collisions and the order (as PotentialCollisions.h and PrintSequencer.h), with
/// the splitting above. Without forced steps (or with maxRounds 0) the pieces are the
/// sub-graphs and the result is that of computePotentialCollisions + sequencePrint. The order's
/// strategy must use the PCG (a4 or best). Throws GeoLatticeError as those two do.
PieceSequence sequencePieces(const LatticeGraph& lattice, const SkeletonTree& tree,
                             double sampleSpacing, const NozzleModel& nozzle,
                             const PotentialCollisionOptions& pcgOptions,
                             const SequenceOptions& sequenceOptions, const SplitOptions& options);

}  // namespace geolattice
