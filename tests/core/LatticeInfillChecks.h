#pragma once
// Checks shared by the lattice graph tests: structure (degrees, kinds, sub-graphs, boundary
// loops, duplicate vertices) and geometry (vertices on the layer surface, isolines at their
// level, no two edges of a layer meeting except at a shared vertex). Each check recomputes what
// it verifies from the graph's edges or from the input layers, independently of the builder.
#include "common/SegmentDistance.h"
#include "lattice/LatticeInfill.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace geolattice::testing {

struct StructureReport {
  int irregularVertices = 0;  ///< degree != 4/3/2 for crossing/boundary hit/other
  int oddBoundaryHitSubgraphs = 0;
  int duplicateVertices = 0;  ///< two vertices of a layer closer than the tolerance
  int zeroLengthEdges = 0;
  int crossings = 0;
  int boundaryHits = 0;
};

/// Degrees and kinds recomputed from the edges, sub-graph ids against a BFS, even boundary-hit
/// counts per sub-graph, boundary loops against the boundary edges, duplicate positions.
inline StructureReport checkStructure(const LatticeGraph& g, double tolerance) {
  StructureReport r;
  const int V = static_cast<int>(g.points.size());
  const int E = static_cast<int>(g.edges.size());
  const int L = static_cast<int>(g.layerValues.size());
  EXPECT_EQ(g.layerVertexOffset.back(), V);
  EXPECT_EQ(g.layerEdgeOffset.back(), E);
  EXPECT_EQ(g.layerSubgraphOffset.back(), static_cast<int>(g.subgraphs.size()));
  std::vector<std::array<int, 3>> kindCount(V, {0, 0, 0});
  std::vector<std::vector<int>> adjacency(V);
  for (int e = 0; e < E; ++e) {
    const auto [a, b] = g.edges[e];
    EXPECT_NE(a, b);
    EXPECT_EQ(g.vertexLayer[a], g.edgeLayer[e]);
    EXPECT_EQ(g.vertexLayer[b], g.edgeLayer[e]);
    EXPECT_EQ(g.vertexSubgraph[a], g.edgeSubgraph[e]);
    EXPECT_EQ(g.vertexSubgraph[b], g.edgeSubgraph[e]);
    ++kindCount[a][static_cast<int>(g.edgeKind[e])];
    ++kindCount[b][static_cast<int>(g.edgeKind[e])];
    adjacency[a].push_back(b);
    adjacency[b].push_back(a);
    if ((g.points[a] - g.points[b]).norm() <= tolerance) {
      ++r.zeroLengthEdges;
    }
  }
  for (int v = 0; v < V; ++v) {
    const auto& c = kindCount[v];
    const int degree = c[0] + c[1] + c[2];
    EXPECT_EQ(degree, g.degree[v]) << "vertex " << v;
    EXPECT_GT(degree, 0) << "isolated vertex " << v;
    LatticeVertexKind kind;
    if (c[2] > 0) {
      kind = c[0] + c[1] > 0 ? LatticeVertexKind::BoundaryHit : LatticeVertexKind::Boundary;
    } else {
      kind = c[0] > 0 && c[1] > 0 ? LatticeVertexKind::Crossing : LatticeVertexKind::IsolinePoint;
    }
    EXPECT_EQ(kind, g.vertexKind[v]) << "vertex " << v;
    const int expected = kind == LatticeVertexKind::Crossing      ? 4
                         : kind == LatticeVertexKind::BoundaryHit ? 3
                                                                  : 2;
    r.irregularVertices += degree != expected;
    r.crossings += kind == LatticeVertexKind::Crossing;
    r.boundaryHits += kind == LatticeVertexKind::BoundaryHit;
  }
  // Sub-graphs: connected (BFS from the first vertex reaches exactly the sub-graph's vertices).
  std::vector<int> seen(V, 0);
  std::vector<int> hits(g.subgraphs.size(), 0), vertexCount(g.subgraphs.size(), 0);
  for (int v = 0; v < V; ++v) {
    ++vertexCount[g.vertexSubgraph[v]];
    hits[g.vertexSubgraph[v]] += g.vertexKind[v] == LatticeVertexKind::BoundaryHit;
  }
  for (size_t s = 0; s < g.subgraphs.size(); ++s) {
    const LatticeSubgraph& sg = g.subgraphs[s];
    EXPECT_EQ(sg.id, static_cast<int>(s));
    EXPECT_EQ(sg.vertexCount, vertexCount[s]);
    EXPECT_EQ(sg.boundaryHitCount, hits[s]);
    r.oddBoundaryHitSubgraphs += hits[s] % 2;
    EXPECT_GE(static_cast<int>(s), g.layerSubgraphOffset[sg.layer]);
    EXPECT_LT(static_cast<int>(s), g.layerSubgraphOffset[sg.layer + 1]);
  }
  for (int v0 = 0; v0 < V; ++v0) {
    if (seen[v0]) {
      continue;
    }
    std::vector<int> stack{v0};
    seen[v0] = 1;
    int reached = 0;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      ++reached;
      EXPECT_EQ(g.vertexSubgraph[v], g.vertexSubgraph[v0]);
      for (int w : adjacency[v]) {
        if (!seen[w]) {
          seen[w] = 1;
          stack.push_back(w);
        }
      }
    }
    EXPECT_EQ(reached, vertexCount[g.vertexSubgraph[v0]])
        << "sub-graph " << g.vertexSubgraph[v0] << " is not connected";
  }
  // Boundary loops: closed, made of boundary edges, each boundary edge exactly once.
  std::map<std::pair<int, int>, int> boundaryUse;
  for (int e = 0; e < E; ++e) {
    if (g.edgeKind[e] == LatticeEdgeKind::Boundary) {
      boundaryUse[{std::min(g.edges[e][0], g.edges[e][1]),
                   std::max(g.edges[e][0], g.edges[e][1])}] = 0;
    }
  }
  for (const LatticeSubgraph& sg : g.subgraphs) {
    for (const LatticeBoundaryLoop& loop : sg.boundaryLoops) {
      EXPECT_TRUE(loop.closed);
      const size_t n = loop.vertices.size();
      for (size_t i = 0; i < n; ++i) {
        const int a = loop.vertices[i], b = loop.vertices[(i + 1) % n];
        EXPECT_EQ(g.vertexSubgraph[a], sg.id);
        auto it = boundaryUse.find({std::min(a, b), std::max(a, b)});
        if (it == boundaryUse.end()) {
          ADD_FAILURE() << "loop step " << a << " -> " << b << " is not a boundary edge";
        } else {
          ++it->second;
        }
      }
    }
  }
  for (const auto& [edge, uses] : boundaryUse) {
    EXPECT_EQ(uses, 1) << "boundary edge " << edge.first << "-" << edge.second;
  }
  // Duplicate positions inside a layer: sweep along x.
  for (int l = 0; l < L; ++l) {
    std::vector<int> order(g.layerVertexOffset[l + 1] - g.layerVertexOffset[l]);
    std::iota(order.begin(), order.end(), g.layerVertexOffset[l]);
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return g.points[a].x() < g.points[b].x(); });
    for (size_t i = 0; i < order.size(); ++i) {
      for (size_t j = i + 1;
           j < order.size() && g.points[order[j]].x() - g.points[order[i]].x() <= tolerance; ++j) {
        r.duplicateVertices += (g.points[order[j]] - g.points[order[i]]).norm() <= tolerance;
      }
    }
  }
  return r;
}

/// Closest point of triangle abc to p, as barycentric weights (Ericson, Real-Time Collision Detection 5.1.5).
inline Vec3 closestBarycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0)
    return {1, 0, 0};
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3)
    return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6)
    return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denom = 1 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {1 - v - w, v, w};
}

/// Uniform grid of boxes (cell size h) for neighbour queries.
class BoxGrid {
public:
  BoxGrid(const Vec3& origin, double h) : origin_(origin), h_(h) {}
  void insert(int id, const Vec3& lo, const Vec3& hi) {
    const auto a = cell(lo), b = cell(hi);
    for (long i = a[0]; i <= b[0]; ++i)
      for (long j = a[1]; j <= b[1]; ++j)
        for (long k = a[2]; k <= b[2]; ++k)
          cells_[key(i, j, k)].push_back(id);
  }
  const std::vector<int>& at(const Vec3& p) const {
    static const std::vector<int> none;
    const auto c = cell(p);
    auto it = cells_.find(key(c[0], c[1], c[2]));
    return it == cells_.end() ? none : it->second;
  }
  const std::unordered_map<long long, std::vector<int>>& cells() const { return cells_; }

private:
  std::array<long, 3> cell(const Vec3& p) const {
    return {static_cast<long>(std::floor((p.x() - origin_.x()) / h_)),
            static_cast<long>(std::floor((p.y() - origin_.y()) / h_)),
            static_cast<long>(std::floor((p.z() - origin_.z()) / h_))};
  }
  static long long key(long i, long j, long k) { return (i * 1000003LL + j) * 1000033LL + k; }
  Vec3 origin_;
  double h_;
  std::unordered_map<long long, std::vector<int>> cells_;
};

struct GeometryReport {
  double maxSurfaceDistance = 0;  ///< vertex to its layer's triangles (mm)
  double maxLevelError = 0;  ///< |α - level| (|β - level|) interpolated at isoline vertices (mm)
  int intersectingEdgePairs =
      0;  ///< edges of a layer closer than the tolerance without a shared vertex
  double minSeparation =
      std::numeric_limits<double>::infinity();  ///< of edge pairs without a shared vertex
};

/// Geometry against the input layers. tolerance: distance below which two edges count as meeting.
inline GeometryReport checkGeometry(const LatticeGraph& g, const CurvedLayers& layers,
                                    double tolerance) {
  GeometryReport r;
  const int L = static_cast<int>(g.layerValues.size());
  for (int l = 0; l < L; ++l) {
    // Triangles of the layer in a grid; cell size ~ 2 x mean triangle extent.
    const int t0 = layers.layerTriangleOffset[l], t1 = layers.layerTriangleOffset[l + 1];
    if (t0 == t1) {
      EXPECT_EQ(g.layerVertexOffset[l], g.layerVertexOffset[l + 1]);
      continue;
    }
    double extent = 0;
    Vec3 lo = Vec3::Constant(1e300);
    for (int t = t0; t < t1; ++t) {
      const auto& f = layers.triangles[t];
      extent += (layers.points[f[1]] - layers.points[f[0]]).norm();
      for (int v : f)
        lo = lo.cwiseMin(layers.points[v]);
    }
    const double h = 2 * extent / (t1 - t0);
    BoxGrid triangles(lo, h);
    for (int t = t0; t < t1; ++t) {
      const auto& f = layers.triangles[t];
      Vec3 a = layers.points[f[0]], b = a;
      for (int v : f) {
        a = a.cwiseMin(layers.points[v]);
        b = b.cwiseMax(layers.points[v]);
      }
      triangles.insert(t, a - Vec3::Constant(tolerance), b + Vec3::Constant(tolerance));
    }
    for (int v = g.layerVertexOffset[l]; v < g.layerVertexOffset[l + 1]; ++v) {
      double best = std::numeric_limits<double>::infinity(), alphaAt = 0, betaAt = 0;
      for (int t : triangles.at(g.points[v])) {
        const auto& f = layers.triangles[t];
        const Vec3 w = closestBarycentric(g.points[v], layers.points[f[0]], layers.points[f[1]],
                                          layers.points[f[2]]);
        const Vec3 q =
            w[0] * layers.points[f[0]] + w[1] * layers.points[f[1]] + w[2] * layers.points[f[2]];
        const double d = (q - g.points[v]).norm();
        if (d < best) {
          best = d;
          alphaAt =
              w[0] * layers.alpha[f[0]] + w[1] * layers.alpha[f[1]] + w[2] * layers.alpha[f[2]];
          betaAt = w[0] * layers.beta[f[0]] + w[1] * layers.beta[f[1]] + w[2] * layers.beta[f[2]];
        }
      }
      r.maxSurfaceDistance = std::max(r.maxSurfaceDistance, best);
      if (g.alphaLevel[v] >= 0) {
        r.maxLevelError =
            std::max(r.maxLevelError, std::abs(alphaAt - g.alphaLevels[g.alphaLevel[v]]));
      }
      if (g.betaLevel[v] >= 0) {
        r.maxLevelError =
            std::max(r.maxLevelError, std::abs(betaAt - g.betaLevels[g.betaLevel[v]]));
      }
    }
    // Edge pairs without a shared vertex must stay apart.
    BoxGrid edges(lo, h);
    for (int e = g.layerEdgeOffset[l]; e < g.layerEdgeOffset[l + 1]; ++e) {
      const Vec3& a = g.points[g.edges[e][0]];
      const Vec3& b = g.points[g.edges[e][1]];
      edges.insert(e, a.cwiseMin(b) - Vec3::Constant(tolerance),
                   a.cwiseMax(b) + Vec3::Constant(tolerance));
    }
    std::vector<std::pair<int, int>> pairs;
    for (const auto& [key, list] : edges.cells()) {
      for (size_t i = 0; i < list.size(); ++i) {
        for (size_t j = i + 1; j < list.size(); ++j) {
          pairs.emplace_back(std::min(list[i], list[j]), std::max(list[i], list[j]));
        }
      }
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    for (const auto& [e, f] : pairs) {
      const auto& E1 = g.edges[e];
      const auto& E2 = g.edges[f];
      if (E1[0] == E2[0] || E1[0] == E2[1] || E1[1] == E2[0] || E1[1] == E2[1]) {
        continue;
      }
      const double d =
          segmentDistance(g.points[E1[0]], g.points[E1[1]], g.points[E2[0]], g.points[E2[1]]);
      r.minSeparation = std::min(r.minSeparation, d);
      if (d <= tolerance) {
        ++r.intersectingEdgePairs;
      }
    }
  }
  return r;
}

}  // namespace geolattice::testing

namespace geolattice::testing {

/// The paper's vertex count of Eqs. 6-9 computed directly on the tet mesh: for every tet face
/// cut by a layer (PQ), the α- and β-levels strictly between the values at P and Q. The values
/// at P and Q are interpolated exactly as the slicer does (t from the lower-γ end). Exact hits
/// are not handled: use generic data.
inline long paperFacePointCount(const TetMesh& mesh, const Eigen::VectorXd& gamma,
                                const Eigen::VectorXd& alpha, const Eigen::VectorXd& beta,
                                const LatticeGraph& g) {
  std::vector<std::array<int, 3>> faces;
  for (const auto& t : mesh.tets) {
    for (int k = 0; k < 4; ++k) {
      std::array<int, 3> f{t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]};
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  auto between = [](const std::vector<double>& levels, double a, double b) {
    const double lo = std::min(a, b), hi = std::max(a, b);
    return std::lower_bound(levels.begin(), levels.end(), hi) -
           std::upper_bound(levels.begin(), levels.end(), lo);
  };
  long count = 0;
  for (const auto& f : faces) {
    for (double phi : g.layerValues) {
      const bool above[3] = {gamma[f[0]] >= phi, gamma[f[1]] >= phi, gamma[f[2]] >= phi};
      if (above[0] == above[1] && above[1] == above[2]) {
        continue;
      }
      const int lone = above[0] == above[1] ? 2 : (above[0] == above[2] ? 1 : 0);
      double a[2], b[2];
      for (int s = 0; s < 2; ++s) {
        int u = f[lone], v = f[(lone + 1 + s) % 3];
        if (gamma[u] > gamma[v])
          std::swap(u, v);
        const double t = (phi - gamma[u]) / (gamma[v] - gamma[u]);
        a[s] = (1 - t) * alpha[u] + t * alpha[v];
        b[s] = (1 - t) * beta[u] + t * beta[v];
      }
      count += between(g.alphaLevels, a[0], a[1]) + between(g.betaLevels, b[0], b[1]);
    }
  }
  return count;
}

}  // namespace geolattice::testing
