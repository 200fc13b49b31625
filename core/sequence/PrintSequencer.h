#pragma once
/// @file PrintSequencer.h
/// @brief The printing order of the sub-graphs (paper Section 3.1, Criteria 1-2, Algorithm 4).
///
/// Strategies:
///  - LayerPriority (LPT): layer by layer; inside a layer, nearest next sub-graph.
///  - DepthPriority (DPT): along branches: an upper node of the current one whose lower nodes
///    are all printed, else the most recently enabled node (depth first); ignores collisions.
///  - Greedy (the paper's A4): candidates satisfy Criterion 1 (all lower nodes printed) and
///    Criterion 2 (in no unprinted node's PCG); prefer an upper node of the current node, else
///    the candidate nearest to the nozzle. Counters make each step O(|PCG| + candidates).
///  - Rollout (beyond the paper): at every step where the current node has no printable upper
///    node (a retraction), each of the nearest candidates is tried and the rest of the order is
///    completed by A4; the candidate whose completion costs least is taken. A rollout of a
///    sequentially consistent greedy is never worse than the greedy itself on the cost used,
///    here retractions · retractionCost + air length; the result is kept only if it is no
///    worse than A4 on retractions and on air length separately (else A4's order is returned).
///    Criterion 1 and 2 hold throughout, so it is as collision-free as A4.
/// A PCG entry j of node i where j is a skeleton ancestor of i (Criterion 1 prints j first) is a
/// collision no order avoids (a wide nozzle over a curved layer reaching the layer below); it is
/// left out of Criterion 2 and counted in unavoidablePairs, so it cannot stall the traversal.
/// If no candidate satisfies Criterion 2 (mutual PCGs: an unavoidable collision), the candidate
/// of Criterion 1 blocked by the fewest unprinted nodes is forced and counted in forcedSteps.
///
/// Metrics (until the toolpath issue gives exact air paths): every sub-graph is printed as one
/// closed tour, so it starts and ends at the same point, the sample nearest to where the nozzle
/// is. A transition to an upper node of the current node continues without retraction; any other
/// transition is a retraction. airLength sums the straight distances end -> start over all
/// transitions.
#include "sequence/PotentialCollisions.h"
#include "sequence/PrintMaterial.h"
#include "skeleton/SkeletonTree.h"

#include <functional>
#include <string>
#include <vector>

namespace geolattice {

enum class SequenceStrategy { LayerPriority = 0, DepthPriority = 1, Greedy = 2, Rollout = 3 };

/// "lpt", "dpt", "a4", "best" <-> strategy. parse throws GeoLatticeError for unknown names.
SequenceStrategy parseSequenceStrategy(const std::string& name);
const char* sequenceStrategyName(SequenceStrategy strategy);

struct SequenceOptions {
  /// Rollout ("best") by default: never worse than the paper's A4 on retractions and air length.
  SequenceStrategy strategy = SequenceStrategy::Rollout;
  int rolloutCandidates = 6;     ///< nearest candidates tried at each retraction (Rollout, >= 1)
  double retractionCost = 20.0;  ///< mm of air move one retraction is worth (Rollout, >= 0)
  /// Called on the calling thread with the fraction of the order decided. Optional.
  std::function<void(double)> progress;
  /// Polled where progress is reported; true stops with a GeoLatticeError "print sequencing
  /// aborted". Optional.
  std::function<bool()> shouldAbort;
  /// Throws GeoLatticeError naming the first parameter out of its range (cheap: no data).
  void validate() const;
};

struct PrintSequence {
  SequenceStrategy strategy = SequenceStrategy::Greedy;
  std::vector<int> order;        ///< sub-graph ids in printing order
  std::vector<int> printIndex;   ///< per sub-graph: position in order
  std::vector<Vec3> start, end;  ///< per position: first and last printed point (mm)
  std::vector<int> startSample;  ///< per position: material sample index of start
  int retractions = 0;
  double airLength = 0;            ///< mm
  int forcedSteps = 0;             ///< steps that violated Criterion 2 (no valid candidate)
  long long unavoidablePairs = 0;  ///< PCG entries that are ancestors (ignored by Criterion 2)
  double seconds = 0;
};

/// Orders the nodes of `tree`. pcg is needed by Greedy and Rollout (may be null for LPT, DPT).
/// Throws GeoLatticeError for an empty tree, material that does not match the tree, a missing
/// PCG, bad options, or a tree that fails validateSkeletonTree.
PrintSequence sequencePrint(const SkeletonTree& tree, const MaterialSamples& material,
                            const PotentialCollisions* pcg, const SequenceOptions& options = {});

/// Recomputes start/end points, retractions and air length of a given order (as described
/// above). Throws GeoLatticeError when order is not a permutation of the nodes.
void evaluateSequence(const SkeletonTree& tree, const MaterialSamples& material,
                      PrintSequence& sequence);

}  // namespace geolattice
