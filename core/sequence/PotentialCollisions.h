#pragma once
/// @file PotentialCollisions.h
/// @brief Potential collision sub-graphs (PCG) of each sub-graph (paper Section 3.1,
/// Algorithm 3, Fig. 13b): PCG(i) = the sub-graphs j != i with material inside the envelope
/// swept by the nozzle over sub-graph i. If j is in PCG(i), j must not be printed before i.
///
/// The paper sweeps the cone along the boundary curve of G_i, fills the ring with an advancing
/// front mesh and intersects it with every other sub-graph, O(k²·m), 154-277 s for 311
/// sub-graphs. Here the envelope is the union of the nozzle volumes at every sample point of
/// G_i (interior points included, which matters on curved layers), tested by a dual descent of
/// two bounding-sphere trees, one over G_i's nozzle stations and one over G_j's material:
/// a cluster of stations (centre c, radius ρ, axes within δ of n̄) sweeps a volume inside
/// ball(c, ρ) ⊕ cone(n̄, NA* + δ), so a material cluster farther than ρ + ρ' from that cone
/// is skipped; leaves use the exact nozzle test. The search for a pair stops at the first
/// hit, pairs are pruned at the roots, and the sub-graphs are split over threads.
#include "common/WorkLimit.h"
#include "nozzle/NozzleModel.h"
#include "sequence/PrintMaterial.h"

#include <functional>
#include <vector>

namespace geolattice {

struct PotentialCollisions {
  std::vector<std::vector<int>> pcg;  ///< per sub-graph: ascending ids j != i
  long long pairs = 0;                ///< total PCG entries
  long long leafTests = 0;            ///< exact point-in-nozzle tests performed
  double seconds = 0;
};

/// @brief Parameters of computePotentialCollisions() (the result does not depend on them).
struct PotentialCollisionOptions {
  int threads = 0;  ///< worker threads over the sub-graphs; 0 = hardware concurrency
  /// Bound against runaway work (common/WorkLimit.h): the pairs of sub-graphs, K (K - 1) / 2, are
  /// what the test costs (an infinite cone holds everything above); more is refused (> 0).
  double maxPairs = kDefaultMaxElements;
  /// Called on the calling thread with the fraction of sub-graphs done (1 at the end). Optional.
  std::function<void(double)> progress;
  /// Polled on the calling thread after each sub-graph it handles; true stops every worker and
  /// throws GeoLatticeError "potential collisions aborted". Optional.
  std::function<bool()> shouldAbort;
};

/// Throws GeoLatticeError for a bad nozzle.
PotentialCollisions computePotentialCollisions(const MaterialSamples& material,
                                               const NozzleModel& nozzle,
                                               const PotentialCollisionOptions& options);

/// threads: 0 = hardware concurrency. Throws GeoLatticeError for a bad nozzle.
PotentialCollisions computePotentialCollisions(const MaterialSamples& material,
                                               const NozzleModel& nozzle, int threads = 0);

}  // namespace geolattice
