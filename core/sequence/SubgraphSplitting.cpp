#include "sequence/SubgraphSplitting.h"

#include "common/Error.h"
#include "common/UnionFind.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

namespace geolattice {

namespace {

/// Samples of piece `victim` that are stations with material of `partner` inside their nozzle
/// (`seeing`), and samples of `victim` inside the nozzle at a station of `partner` (`seen`).
void blockingSamples(const MaterialSamples& m, const NozzleVolume& nozzle, int victim, int partner,
                     std::vector<Vec3>& seeing, std::vector<Vec3>& seen, bool& overlap) {
  overlap = false;
  for (int s = m.offset[victim]; s < m.offset[victim + 1]; ++s) {
    bool sees = false, isSeen = false;
    for (int q = m.offset[partner]; q < m.offset[partner + 1] && !(sees && isSeen); ++q) {
      sees = sees || nozzle.contains(m.points[s], m.normals[s], m.points[q]);
      isSeen = isSeen || nozzle.contains(m.points[q], m.normals[q], m.points[s]);
    }
    if (sees) {
      seeing.push_back(m.points[s]);
    }
    if (isSeen) {
      seen.push_back(m.points[s]);
    }
    overlap = overlap || (sees && isSeen);
  }
}

double nearest(const std::vector<Vec3>& points, const Vec3& x) {
  double best = std::numeric_limits<double>::infinity();
  for (const Vec3& p : points) {
    best = std::min(best, (p - x).squaredNorm());
  }
  return best;
}

void insertSorted(std::vector<int>& list, int value) {
  list.insert(std::upper_bound(list.begin(), list.end(), value), value);
}

/// Cuts piece `victim` between its samples that see `partner` and those `partner` sees. Returns
/// false (nothing changed) when either set is empty, they overlap, or the cut leaves one piece.
/// `touch`: a lower or upper node within this distance of a piece supports it or rests on it.
bool cutPiece(const LatticeGraph& g, const MaterialSamples& m, const NozzleVolume& nozzle,
              double touch, int victim, int partner, std::vector<int>& edgePiece,
              std::vector<int>& pieceSubgraph, SkeletonTree& tree) {
  std::vector<Vec3> seeing, seen;
  bool overlap = false;
  blockingSamples(m, nozzle, victim, partner, seeing, seen, overlap);
  if (seeing.empty() || seen.empty() || overlap) {
    return false;
  }
  std::vector<int> edges;
  for (size_t e = 0; e < edgePiece.size(); ++e) {
    if (edgePiece[e] == victim) {
      edges.push_back(static_cast<int>(e));
    }
  }
  // Side of each edge: the nearer of the two sets (its midpoint's distance).
  std::vector<char> side(edges.size());
  for (size_t i = 0; i < edges.size(); ++i) {
    const auto [a, b] = g.edges[edges[i]];
    const Vec3 mid = 0.5 * (g.points[a] + g.points[b]);
    side[i] = nearest(seen, mid) < nearest(seeing, mid);
  }
  // Connected parts of each side (edges joined at their vertices).
  UnionFind parts(static_cast<int>(edges.size()));
  for (int s = 0; s < 2; ++s) {
    std::vector<int> firstAt(g.points.size(), -1);
    for (size_t i = 0; i < edges.size(); ++i) {
      if (side[i] != s) {
        continue;
      }
      for (int v : g.edges[edges[i]]) {
        if (firstAt[v] < 0) {
          firstAt[v] = static_cast<int>(i);
        } else {
          parts.unite(firstAt[v], static_cast<int>(i));
        }
      }
    }
  }
  std::vector<int> pieceOfPart(edges.size(), -1);
  std::vector<int> pieces;  // the victim first, then the new ones
  for (size_t i = 0; i < edges.size(); ++i) {
    const int root = parts.find(static_cast<int>(i));
    if (pieceOfPart[root] < 0) {
      pieceOfPart[root] =
          pieces.empty() ? victim : static_cast<int>(pieceSubgraph.size() + pieces.size() - 1);
      pieces.push_back(pieceOfPart[root]);
    }
    edgePiece[edges[i]] = pieceOfPart[root];
  }
  if (pieces.size() < 2) {
    return false;
  }
  // The new pieces are skeleton nodes on the victim's layer. Each keeps only the lower and upper
  // nodes it touches (Criterion 1 for the material that really supports it, or that it
  // supports), and the nearest of them when it touches none: a piece must not wait for an
  // upper node's support elsewhere on the layer.
  const SkeletonNode node = tree.nodes[victim];
  for (size_t p = 1; p < pieces.size(); ++p) {
    pieceSubgraph.push_back(pieceSubgraph[victim]);
    tree.nodes.push_back(node);
  }
  std::vector<std::vector<Vec3>> piecePoints(pieces.size());
  for (int e : edges) {
    const size_t k = std::find(pieces.begin(), pieces.end(), edgePiece[e]) - pieces.begin();
    const auto [a, b] = g.edges[e];
    piecePoints[k].push_back(g.points[a]);
    piecePoints[k].push_back(0.5 * (g.points[a] + g.points[b]));
    piecePoints[k].push_back(g.points[b]);
  }
  auto distanceTo = [&](size_t k, int other) {
    double best = std::numeric_limits<double>::infinity();
    for (int q = m.offset[other]; q < m.offset[other + 1]; ++q) {
      best = std::min(best, nearest(piecePoints[k], m.points[q]));
    }
    return std::sqrt(best);
  };
  auto relink = [&](const std::vector<int>& neighbours, bool lower) {
    for (int n : neighbours) {
      std::vector<int>& back = lower ? tree.nodes[n].upper : tree.nodes[n].lower;
      back.erase(std::remove(back.begin(), back.end(), victim), back.end());
    }
    for (size_t k = 0; k < pieces.size(); ++k) {
      std::vector<int>& mine = lower ? tree.nodes[pieces[k]].lower : tree.nodes[pieces[k]].upper;
      mine.clear();
      int closest = -1;
      double closestDistance = std::numeric_limits<double>::infinity();
      for (int n : neighbours) {
        const double d = distanceTo(k, n);
        if (d <= touch) {
          mine.push_back(n);
        }
        if (d < closestDistance) {
          closestDistance = d;
          closest = n;
        }
      }
      if (mine.empty() && closest >= 0) {
        mine.push_back(closest);
      }
      for (int n : mine) {
        insertSorted(lower ? tree.nodes[n].upper : tree.nodes[n].lower, pieces[k]);
      }
    }
  };
  relink(node.lower, true);
  relink(node.upper, false);
  tree.edges.clear();
  for (size_t n = 0; n < tree.nodes.size(); ++n) {
    for (int u : tree.nodes[n].upper) {
      tree.edges.push_back({static_cast<int>(n), u});
    }
  }
  std::sort(tree.edges.begin(), tree.edges.end());
  // Length and centroid per piece.
  for (int p : pieces) {
    tree.nodes[p].length = 0;
    tree.nodes[p].centroid = Vec3::Zero();
  }
  for (int e : edges) {
    const auto [a, b] = g.edges[e];
    const double len = (g.points[b] - g.points[a]).norm();
    SkeletonNode& n = tree.nodes[edgePiece[e]];
    n.length += len;
    n.centroid += len * 0.5 * (g.points[a] + g.points[b]);
  }
  for (int p : pieces) {
    SkeletonNode& n = tree.nodes[p];
    n.centroid = n.length > 0 ? Vec3(n.centroid / n.length) : Vec3(g.points[g.edges[edges[0]][0]]);
  }
  return true;
}

}  // namespace

void SplitOptions::validate() const {
  if (maxRounds < 0 || maxRounds > 100) {
    throw GeoLatticeError("sub-graph splitting: the rounds must be in [0, 100] (got " +
                          std::to_string(maxRounds) + ")");
  }
}

PieceSequence sequencePieces(const LatticeGraph& g, const SkeletonTree& tree, double spacing,
                             const NozzleModel& nozzle, const PotentialCollisionOptions& pcgOptions,
                             const SequenceOptions& sequenceOptions, const SplitOptions& options) {
  options.validate();
  if (sequenceOptions.strategy != SequenceStrategy::Greedy &&
      sequenceOptions.strategy != SequenceStrategy::Rollout) {
    throw GeoLatticeError("sub-graph splitting needs an order that uses the PCG (a4 or best)");
  }
  const int K = static_cast<int>(g.subgraphs.size());
  if (static_cast<int>(tree.nodes.size()) != K) {
    throw GeoLatticeError("sub-graph splitting: the skeleton does not match the lattice");
  }
  PieceSequence state;
  state.edgePiece = g.edgeSubgraph;
  state.pieceSubgraph.resize(K);
  for (int k = 0; k < K; ++k) {
    state.pieceSubgraph[k] = k;
  }
  state.tree = tree;
  const NozzleVolume volume(nozzle);
  // Adjacent layers touch within about a layer's spacing (plus the samples' own spacing).
  double layerGap = 0;
  for (size_t l = 1; l < tree.layerValues.size(); ++l) {
    layerGap = std::max(layerGap, tree.layerValues[l] - tree.layerValues[l - 1]);
  }
  const double touch = 2.0 * layerGap + spacing;
  PieceSequence best;
  // Progress is reported by the first round only (later rounds would run it backwards).
  PotentialCollisionOptions pcgLater = pcgOptions;
  SequenceOptions sequenceLater = sequenceOptions;
  pcgLater.progress = nullptr;
  sequenceLater.progress = nullptr;
  for (int round = 0;; ++round) {
    const int P = static_cast<int>(state.pieceSubgraph.size());
    state.material = sampleLatticeMaterial(g, spacing, state.edgePiece, P);
    state.pcg = computePotentialCollisions(state.material, nozzle, round ? pcgLater : pcgOptions);
    // Pieces of one sub-graph are not ordered by their potential collisions, as a whole
    // sub-graph is not tested against itself: the toolpath's axis clearance handles what lies
    // inside one sub-graph, and cutting must not turn that into forced steps.
    for (int i = 0; i < P; ++i) {
      std::vector<int>& list = state.pcg.pcg[i];
      const auto same = [&](int j) {
        return state.pieceSubgraph[j] == state.pieceSubgraph[i];
      };
      state.pcg.pairs -= std::count_if(list.begin(), list.end(), same);
      list.erase(std::remove_if(list.begin(), list.end(), same), list.end());
    }
    state.sequence = sequencePrint(state.tree, state.material, &state.pcg,
                                   round ? sequenceLater : sequenceOptions);
    if (round == 0) {
      state.forcedStepsBefore = state.sequence.forcedSteps;
      best = state;
    } else if (state.sequence.forcedSteps < best.sequence.forcedSteps) {
      best = state;
    }
    // Done: nothing forced, the rounds used up, or this round's cuts made things worse (more
    // cuts rarely undo that, and each round costs a PCG).
    if (state.sequence.forcedSteps == 0 || round >= options.maxRounds ||
        state.sequence.forcedSteps > best.sequence.forcedSteps) {
      break;
    }
    // Mutual pairs (neither a skeleton ancestor of the other: those Criterion 1 orders anyway);
    // each piece is cut at most once a round, the one with more material of the pair.
    const SkeletonAncestry ancestry(state.tree);
    std::set<int> touched;
    bool cut = false;
    for (int i = 0; i < P; ++i) {
      for (int j : state.pcg.pcg[i]) {
        if (j <= i || touched.count(i) || touched.count(j) || ancestry.isAncestor(i, j) ||
            ancestry.isAncestor(j, i) ||
            !std::binary_search(state.pcg.pcg[j].begin(), state.pcg.pcg[j].end(), i)) {
          continue;
        }
        const int victim = state.tree.nodes[i].length >= state.tree.nodes[j].length ? i : j;
        const int partner = victim == i ? j : i;
        // The skeleton neighbours of both: not cut again this round (their links now name new
        // pieces, whose samples come with the next round).
        std::vector<int> around;
        for (int n : {i, j}) {
          around.insert(around.end(), state.tree.nodes[n].lower.begin(),
                        state.tree.nodes[n].lower.end());
          around.insert(around.end(), state.tree.nodes[n].upper.begin(),
                        state.tree.nodes[n].upper.end());
        }
        if (std::any_of(around.begin(), around.end(), [&](int n) { return touched.count(n); })) {
          continue;  // a neighbour was cut this round
        }
        if (cutPiece(g, state.material, volume, touch, victim, partner, state.edgePiece,
                     state.pieceSubgraph, state.tree) ||
            cutPiece(g, state.material, volume, touch, partner, victim, state.edgePiece,
                     state.pieceSubgraph, state.tree)) {
          touched.insert(i);
          touched.insert(j);
          touched.insert(around.begin(), around.end());
          cut = true;
        }
      }
    }
    if (!cut) {
      break;
    }
    ++state.rounds;
    best.rounds = state.rounds;  // rounds tried, also when an earlier round stays the best
  }
  std::vector<int> pieces(K, 0);
  for (int s : best.pieceSubgraph) {
    ++pieces[s];
  }
  best.splitSubgraphs =
      static_cast<int>(std::count_if(pieces.begin(), pieces.end(), [](int n) { return n > 1; }));
  return best;
}

}  // namespace geolattice
