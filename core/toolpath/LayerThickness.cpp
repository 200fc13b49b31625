#include "toolpath/LayerThickness.h"

#include "common/Error.h"
#include "common/ParallelFor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

namespace geolattice {

namespace {

/// Bounding-sphere tree over the segments of one sub-graph.
class SegmentTree {
public:
  SegmentTree(const LatticeGraph& g, std::vector<int> edges) : g_(g), edges_(std::move(edges)) {
    if (!edges_.empty()) {
      build(0, static_cast<int>(edges_.size()));
    }
  }

  /// Distance from x to the nearest segment (∞ for an empty tree).
  double nearest(const Vec3& x) const {
    double best = std::numeric_limits<double>::infinity();
    if (nodes_.empty()) {
      return best;
    }
    // Depth first on a fixed stack (no allocation per query): the tree splits at medians, so it
    // is under 32 deep and the stack holds at most one entry more than the depth.
    std::array<int, 64> stack;
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if ((x - n.centre).norm() - n.radius >= best) {
        continue;
      }
      if (n.left < 0) {
        for (int i = n.begin; i < n.end; ++i) {
          best = std::min(best, segmentDistance(x, edges_[i]));
        }
      } else {
        // Nearer child last so it is popped first.
        const Node& a = nodes_[n.left];
        const Node& b = nodes_[n.right];
        const bool leftNearer = (x - a.centre).norm() - a.radius < (x - b.centre).norm() - b.radius;
        stack[top++] = leftNearer ? n.right : n.left;
        stack[top++] = leftNearer ? n.left : n.right;
      }
    }
    return best;
  }

private:
  struct Node {
    Vec3 centre = Vec3::Zero();
    double radius = 0;
    int begin = 0, end = 0, left = -1, right = -1;
  };

  double segmentDistance(const Vec3& x, int e) const {
    const Vec3& a = g_.points[g_.edges[e][0]];
    const Vec3& b = g_.points[g_.edges[e][1]];
    const Vec3 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((x - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (x - (a + t * ab)).norm();
  }

  Vec3 mid(int e) const { return 0.5 * (g_.points[g_.edges[e][0]] + g_.points[g_.edges[e][1]]); }

  int build(int begin, int end) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (int i = begin; i < end; ++i) {
      for (int v : g_.edges[edges_[i]]) {
        lo = lo.cwiseMin(g_.points[v]);
        hi = hi.cwiseMax(g_.points[v]);
      }
    }
    const Vec3 c = 0.5 * (lo + hi);
    double r = 0;
    for (int i = begin; i < end; ++i) {
      for (int v : g_.edges[edges_[i]]) {
        r = std::max(r, (g_.points[v] - c).norm());
      }
    }
    int left = -1, right = -1;
    if (end - begin > 8) {
      int dim = 0;
      (hi - lo).maxCoeff(&dim);
      const int m = (begin + end) / 2;
      std::nth_element(edges_.begin() + begin, edges_.begin() + m, edges_.begin() + end,
                       [&](int a, int b) { return mid(a)[dim] < mid(b)[dim]; });
      left = build(begin, m);
      right = build(m, end);
    }
    nodes_[id] = {c, r, begin, end, left, right};
    return id;
  }

  const LatticeGraph& g_;
  std::vector<int> edges_;
  std::vector<Node> nodes_;
};

}  // namespace

LayerThicknessResult computeLayerThickness(const LatticeGraph& g, const SkeletonTree& tree,
                                           double lambda) {
  if (!(lambda > 0) || !std::isfinite(lambda)) {
    throw GeoLatticeError("layer thickness: the cap factor lambda must be > 0");
  }
  const int K = static_cast<int>(g.subgraphs.size());
  const int L = static_cast<int>(g.layerValues.size());
  if (static_cast<int>(tree.nodes.size()) != K) {
    throw GeoLatticeError("layer thickness: the skeleton does not match the lattice's sub-graphs");
  }
  if (L == 0) {
    throw GeoLatticeError("layer thickness: the lattice has no layer values");
  }
  std::vector<std::vector<int>> edgesOf(K);
  for (size_t e = 0; e < g.edges.size(); ++e) {
    if (g.edgeSubgraph[e] >= 0 && g.edgeSubgraph[e] < K) {
      edgesOf[g.edgeSubgraph[e]].push_back(static_cast<int>(e));
    }
  }
  // The trees and the nearest-segment queries on all cores (each is independent); the
  // statistics below in vertex order, as before.
  std::vector<std::unique_ptr<SegmentTree>> trees(K);
  parallelFor(static_cast<size_t>(K), 0, [&](size_t k, int) {
    trees[k] = std::make_unique<SegmentTree>(g, std::move(edgesOf[k]));
  });
  int firstLayer = L;
  for (const auto& s : g.subgraphs) {
    firstLayer = std::min(firstLayer, s.layer);
  }

  // Distance to the nearest segment of a sub-graph below, per vertex that has one.
  std::vector<double> below(g.points.size(), std::numeric_limits<double>::infinity());
  constexpr size_t kChunk = 4096;
  parallelFor((g.points.size() + kChunk - 1) / kChunk, 0, [&](size_t c, int) {
    for (size_t v = c * kChunk; v < std::min(g.points.size(), (c + 1) * kChunk); ++v) {
      const int s = g.vertexSubgraph[v];
      if (s >= 0 && s < K) {
        for (int lower : tree.nodes[s].lower) {
          below[v] = std::min(below[v], trees[lower]->nearest(g.points[v]));
        }
      }
    }
  });

  LayerThicknessResult r;
  r.thickness.assign(g.points.size(), 0.0);
  r.perLayer.assign(L, {});
  std::vector<double> sum(L, 0.0);
  r.deviationMin = std::numeric_limits<double>::infinity();
  r.deviationMax = -r.deviationMin;
  for (size_t v = 0; v < g.points.size(); ++v) {
    const int s = g.vertexSubgraph[v];
    if (s < 0 || s >= K) {
      continue;
    }
    const int l = g.subgraphs[s].layer;
    const double phi = l > 0 ? g.layerValues[l] - g.layerValues[l - 1] : g.layerValues[l];
    double h;
    if (l == firstLayer && tree.nodes[s].lower.empty()) {
      h = g.points[v].z();  // height above the platform (z = 0)
    } else if (tree.nodes[s].lower.empty()) {
      h = lambda * phi;
      ++r.unsupportedVertices;
    } else {
      h = below[v];
    }
    if (h > lambda * phi) {
      h = lambda * phi;
      ++r.cappedVertices;
    }
    r.thickness[v] = h;
    const double e = (h - phi) / phi;
    LayerThicknessDeviation& d = r.perLayer[l];
    d.min = d.vertices ? std::min(d.min, e) : e;
    d.max = d.vertices ? std::max(d.max, e) : e;
    sum[l] += e;
    ++d.vertices;
    r.deviationMin = std::min(r.deviationMin, e);
    r.deviationMax = std::max(r.deviationMax, e);
  }
  for (int l = 0; l < L; ++l) {
    if (r.perLayer[l].vertices > 0) {
      r.perLayer[l].mean = sum[l] / r.perLayer[l].vertices;
    }
  }
  if (!std::isfinite(r.deviationMin)) {
    r.deviationMin = r.deviationMax = 0;
  }
  return r;
}

}  // namespace geolattice
