#include "sequence/PrintSequencer.h"

#include "common/Error.h"
#include "common/Progress.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

namespace geolattice {

namespace {

/// The sample of sub-graph k nearest to x (a closed tour can start anywhere on it).
int nearestSample(const MaterialSamples& m, int k, const Vec3& x) {
  int best = m.offset[k];
  double bestDistance = std::numeric_limits<double>::infinity();
  for (int s = m.offset[k]; s < m.offset[k + 1]; ++s) {
    const double d = (m.points[s] - x).squaredNorm();
    if (d < bestDistance) {
      bestDistance = d;
      best = s;
    }
  }
  return best;
}

bool isUpperOf(const SkeletonTree& tree, int lower, int node) {
  const auto& up = tree.nodes[lower].upper;
  return std::binary_search(up.begin(), up.end(), node);
}

/// Printing state shared by all strategies: Criterion 1 via counts of unprinted lower nodes,
/// Criterion 2 via counts of unprinted nodes whose PCG contains a node.
struct SequenceState {
  const SkeletonTree* tree = nullptr;
  const MaterialSamples* material = nullptr;
  const PotentialCollisions* pcg = nullptr;
  std::vector<char> printed;
  std::vector<int> lowerLeft;   ///< unprinted lower nodes
  std::vector<int> blockedBy;   ///< unprinted nodes i != k with k in PCG(i)
  std::vector<int> ready;       ///< unprinted nodes with lowerLeft == 0 (Criterion 1)
  std::vector<int> readySince;  ///< per node: step at which it became ready (DPT)
  std::vector<int> order;
  /// per node i: the PCG entries that count for Criterion 2 (shared by rollout copies)
  std::shared_ptr<std::vector<std::vector<int>>> blocks;
  long long unavoidablePairs = 0;
  int current = -1;
  Vec3 position = Vec3::Zero();
  int retractions = 0;
  int forcedSteps = 0;
  double airLength = 0;

  void init(const SkeletonTree& t, const MaterialSamples& m, const PotentialCollisions* p) {
    tree = &t;
    material = &m;
    pcg = p;
    const int K = static_cast<int>(t.nodes.size());
    printed.assign(K, 0);
    lowerLeft.assign(K, 0);
    blockedBy.assign(K, 0);
    readySince.assign(K, -1);
    for (int k = 0; k < K; ++k) {
      lowerLeft[k] = static_cast<int>(t.nodes[k].lower.size());
      if (lowerLeft[k] == 0) {
        ready.push_back(k);
        readySince[k] = 0;
      }
    }
    blocks = std::make_shared<std::vector<std::vector<int>>>(K);
    if (p) {
      const SkeletonAncestry ancestry(t);
      for (int i = 0; i < K; ++i) {
        for (int j : p->pcg[i]) {
          if (ancestry.isAncestor(j, i)) {
            ++unavoidablePairs;
          } else {
            (*blocks)[i].push_back(j);
            ++blockedBy[j];
          }
        }
      }
    }
  }

  bool done() const { return order.size() == printed.size(); }
  bool valid(int k) const { return blockedBy[k] == 0; }

  double distanceTo(int k) const { return (tree->nodes[k].centroid - position).norm(); }

  void print(int k, bool forced) {
    const int step = static_cast<int>(order.size());
    const int s = step == 0 ? material->offset[k] : nearestSample(*material, k, position);
    if (step > 0) {
      airLength += (material->points[s] - position).norm();
      retractions += !isUpperOf(*tree, current, k);
    }
    forcedSteps += forced;
    position = material->points[s];  // closed tour: it ends where it started
    current = k;
    order.push_back(k);
    printed[k] = 1;
    ready.erase(std::find(ready.begin(), ready.end(), k));
    for (int u : tree->nodes[k].upper) {
      if (--lowerLeft[u] == 0) {
        ready.push_back(u);
        readySince[u] = step + 1;
      }
    }
    for (int j : (*blocks)[k]) {
      --blockedBy[j];
    }
  }
};

/// Nearest node (by centroid) among those accepted by pred; -1 if none.
template <class Pred>
int nearestReady(const SequenceState& s, Pred pred) {
  int best = -1;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (int k : s.ready) {
    if (pred(k)) {
      const double d = s.distanceTo(k);
      if (d < bestDistance || (d == bestDistance && k < best)) {
        bestDistance = d;
        best = k;
      }
    }
  }
  return best;
}

int upperOfCurrent(const SequenceState& s, bool needValid) {
  if (s.current < 0) {
    return -1;
  }
  return nearestReady(
      s, [&](int k) { return isUpperOf(*s.tree, s.current, k) && (!needValid || s.valid(k)); });
}

/// One step of the paper's A4: upper node of the current one, else the nearest valid candidate;
/// if Criterion 2 leaves nothing, the candidate blocked by the fewest nodes (forced).
void greedyStep(SequenceState& s) {
  int next = upperOfCurrent(s, true);
  if (next < 0) {
    next = nearestReady(s, [&](int k) { return s.valid(k); });
  }
  if (next >= 0) {
    s.print(next, false);
    return;
  }
  int fewest = std::numeric_limits<int>::max();
  for (int k : s.ready) {
    fewest = std::min(fewest, s.blockedBy[k]);
  }
  s.print(nearestReady(s, [&](int k) { return s.blockedBy[k] == fewest; }), true);
}

void runLayerPriority(SequenceState& s, const ProgressReporter& progress) {
  while (!s.done()) {
    progress.loop(s.order.size(), s.printed.size());
    int lowest = std::numeric_limits<int>::max();
    for (int k : s.ready) {
      lowest = std::min(lowest, s.tree->nodes[k].layer);
    }
    // Stay in the lowest open layer; continue upwards without retraction when possible.
    int next = -1;
    if (s.current >= 0) {
      next = nearestReady(s, [&](int k) {
        return s.tree->nodes[k].layer == lowest && isUpperOf(*s.tree, s.current, k);
      });
    }
    if (next < 0) {
      next = nearestReady(s, [&](int k) { return s.tree->nodes[k].layer == lowest; });
    }
    s.print(next, false);
  }
}

void runDepthPriority(SequenceState& s, const ProgressReporter& progress) {
  while (!s.done()) {
    progress.loop(s.order.size(), s.printed.size());
    int next = upperOfCurrent(s, false);
    if (next < 0) {  // back to the most recently enabled node (depth first)
      int latest = -1;
      for (int k : s.ready) {
        latest = std::max(latest, s.readySince[k]);
      }
      next = nearestReady(s, [&](int k) { return s.readySince[k] == latest; });
    }
    s.print(next, false);
  }
}

/// progress: null for the trial completions of the rollout.
void runGreedy(SequenceState& s, const ProgressReporter* progress) {
  while (!s.done()) {
    if (progress) {
      progress->loop(s.order.size(), s.printed.size());
    }
    greedyStep(s);
  }
}

double rolloutCost(const SequenceState& s, double retractionCost) {
  // A forced step means a collision: worse than any number of retractions.
  return s.forcedSteps * 1e12 + s.retractions * retractionCost + s.airLength;
}

void runRollout(SequenceState& s, const SequenceOptions& options,
                const ProgressReporter& progress) {
  while (!s.done()) {
    progress.loop(s.order.size(), s.printed.size());
    if (upperOfCurrent(s, true) >= 0 || s.current < 0) {
      greedyStep(s);  // no retraction needed (or the very first node): nothing to decide
      continue;
    }
    // A retraction: try the nearest valid candidates, complete each with A4, keep the best.
    std::vector<std::pair<double, int>> options_;
    for (int k : s.ready) {
      if (s.valid(k)) {
        options_.push_back({s.distanceTo(k), k});
      }
    }
    if (options_.size() <= 1) {
      greedyStep(s);
      continue;
    }
    std::sort(options_.begin(), options_.end());
    options_.resize(std::min(options_.size(), static_cast<size_t>(options.rolloutCandidates)));
    int best = -1;
    double bestCost = std::numeric_limits<double>::infinity();
    for (const auto& [distance, k] : options_) {
      SequenceState trial = s;
      trial.print(k, false);
      runGreedy(trial, nullptr);
      const double cost = rolloutCost(trial, options.retractionCost);
      if (cost < bestCost) {
        bestCost = cost;
        best = k;
      }
    }
    s.print(best, false);
  }
}

}  // namespace

SequenceStrategy parseSequenceStrategy(const std::string& name) {
  if (name == "lpt")
    return SequenceStrategy::LayerPriority;
  if (name == "dpt")
    return SequenceStrategy::DepthPriority;
  if (name == "a4")
    return SequenceStrategy::Greedy;
  if (name == "best")
    return SequenceStrategy::Rollout;
  throw GeoLatticeError("unknown sequence strategy '" + name + "' (expected lpt, dpt, a4 or best)");
}

const char* sequenceStrategyName(SequenceStrategy strategy) {
  switch (strategy) {
    case SequenceStrategy::LayerPriority:
      return "lpt";
    case SequenceStrategy::DepthPriority:
      return "dpt";
    case SequenceStrategy::Greedy:
      return "a4";
    case SequenceStrategy::Rollout:
      return "best";
  }
  return "?";
}

void evaluateSequence(const SkeletonTree& tree, const MaterialSamples& m, PrintSequence& seq) {
  const int K = static_cast<int>(tree.nodes.size());
  if (static_cast<int>(seq.order.size()) != K) {
    throw GeoLatticeError("print order must list every sub-graph exactly once");
  }
  seq.printIndex.assign(K, -1);
  for (int i = 0; i < K; ++i) {
    const int k = seq.order[i];
    if (k < 0 || k >= K || seq.printIndex[k] >= 0) {
      throw GeoLatticeError("print order must list every sub-graph exactly once");
    }
    seq.printIndex[k] = i;
  }
  seq.start.assign(K, Vec3::Zero());
  seq.end.assign(K, Vec3::Zero());
  seq.startSample.assign(K, -1);
  seq.retractions = 0;
  seq.airLength = 0;
  Vec3 position = Vec3::Zero();
  for (int i = 0; i < K; ++i) {
    const int k = seq.order[i];
    const int s = i == 0 ? m.offset[k] : nearestSample(m, k, position);
    if (i > 0) {
      seq.airLength += (m.points[s] - position).norm();
      seq.retractions += !isUpperOf(tree, seq.order[i - 1], k);
    }
    seq.startSample[i] = s;
    seq.start[i] = seq.end[i] = position = m.points[s];
  }
}

void SequenceOptions::validate() const {
  if (this->rolloutCandidates < 1) {
    throw GeoLatticeError("print sequencer: rollout candidates must be >= 1 (got " +
                          std::to_string(this->rolloutCandidates) + ")");
  }
  if (!(this->retractionCost >= 0) || !std::isfinite(this->retractionCost)) {
    throw GeoLatticeError("print sequencer: the retraction cost must be >= 0 mm (got " +
                          std::to_string(this->retractionCost) + ")");
  }
}

PrintSequence sequencePrint(const SkeletonTree& tree, const MaterialSamples& m,
                            const PotentialCollisions* pcg, const SequenceOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  options.validate();
  validateSkeletonTree(tree);
  const int K = static_cast<int>(tree.nodes.size());
  if (static_cast<int>(m.offset.size()) != K + 1) {
    throw GeoLatticeError(
        "print sequencer: the material samples do not match the skeleton (one group per node)");
  }
  for (int k = 0; k < K; ++k) {
    if (m.offset[k + 1] <= m.offset[k]) {
      std::ostringstream s;
      s << "print sequencer: sub-graph " << k << " has no material";
      throw GeoLatticeError(s.str());
    }
  }
  const bool needsPcg =
      options.strategy == SequenceStrategy::Greedy || options.strategy == SequenceStrategy::Rollout;
  if (needsPcg && (!pcg || static_cast<int>(pcg->pcg.size()) != K)) {
    throw GeoLatticeError(
        "print sequencer: the a4 and best strategies need the potential collision sub-graphs of "
        "every node");
  }

  const ProgressReporter progress(options.progress, options.shouldAbort, "print sequencing");
  progress.report(0.0);
  SequenceState state;
  state.init(tree, m, needsPcg ? pcg : nullptr);
  PrintSequence seq;
  seq.strategy = options.strategy;
  switch (options.strategy) {
    case SequenceStrategy::LayerPriority:
      runLayerPriority(state, progress);
      break;
    case SequenceStrategy::DepthPriority:
      runDepthPriority(state, progress);
      break;
    case SequenceStrategy::Greedy:
      runGreedy(state, &progress);
      break;
    case SequenceStrategy::Rollout: {
      // A4 first (fast), then the rollout, which tries candidates at every retraction.
      SequenceState greedy = state;
      const ProgressReporter greedyPart = progress.part(0.0, 0.05);
      runGreedy(greedy, &greedyPart);
      runRollout(state, options, progress.part(0.05, 1.0));
      // Keep the improvement only where it is no worse on both counts.
      if (state.forcedSteps > greedy.forcedSteps || state.retractions > greedy.retractions ||
          state.airLength > greedy.airLength) {
        state = greedy;
      }
      break;
    }
  }
  seq.order = state.order;
  seq.forcedSteps = state.forcedSteps;
  seq.unavoidablePairs = state.unavoidablePairs;
  evaluateSequence(tree, m, seq);
  seq.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  progress.report(1.0);
  return seq;
}

}  // namespace geolattice
