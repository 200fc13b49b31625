#include "lattice/LatticeInfill.h"

#include "common/Error.h"
#include "common/ParallelFor.h"
#include "common/UnionFind.h"
#include "common/WorkLimit.h"
#include "lattice/LatticeLevels.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>

namespace geolattice {

namespace {

constexpr int kAlpha = 0;
constexpr int kBeta = 1;
// LayerGraph::onMeshEdge of vertices that are not edge points.
constexpr int kTriangleInterior = -1;
constexpr int kLayerPoint = -2;

/// Index of the first level > x.
int firstAbove(const std::vector<double>& levels, double x) {
  return static_cast<int>(std::upper_bound(levels.begin(), levels.end(), x) - levels.begin());
}
/// Index of the first level >= x.
int firstAtOrAbove(const std::vector<double>& levels, double x) {
  return static_cast<int>(std::lower_bound(levels.begin(), levels.end(), x) - levels.begin());
}
/// Index of the level equal to x, or -1.
int exactLevel(const std::vector<double>& levels, double x) {
  const int k = firstAtOrAbove(levels, x);
  return k < static_cast<int>(levels.size()) && levels[k] == x ? k : -1;
}

Vec3 unitOrZero(const Vec3& v) {
  const double n = v.norm();
  return n > 0 ? Vec3(v / n) : Vec3::Zero();
}

/// The graph of one layer, with vertex and sub-graph ids local to the layer.
struct LayerGraph {
  std::vector<Vec3> points, normals;
  std::vector<double> alpha, beta;
  std::vector<int> alphaLevel, betaLevel;
  std::vector<int>
      onMeshEdge;  ///< layer-mesh edge of an edge point, kTriangleInterior or kLayerPoint
  std::vector<LatticeVertexKind> kind;
  std::vector<int> degree, subgraph;
  std::vector<std::array<int, 2>> edges;
  std::vector<LatticeEdgeKind> edgeKind;
  std::vector<int> edgeLevel, edgeSubgraph;
  std::vector<LatticeSubgraph> subgraphs;
  LatticeStatistics stats;

  int addVertex(const Vec3& p, const Vec3& n, double a, double b, int ka, int kb, int meshEdge) {
    points.push_back(p);
    normals.push_back(n);
    alpha.push_back(a);
    beta.push_back(b);
    alphaLevel.push_back(ka);
    betaLevel.push_back(kb);
    onMeshEdge.push_back(meshEdge);
    return static_cast<int>(points.size()) - 1;
  }
  void addEdge(int u, int v, LatticeEdgeKind k, int level) {
    edges.push_back({u, v});
    edgeKind.push_back(k);
    edgeLevel.push_back(level);
  }
};

/// A unique edge of a layer mesh, a < b (layer-local point ids); parameters t run from a to b.
struct MeshEdge {
  int a = 0, b = 0;
  int count = 0;                     ///< triangles using it (1 = layer boundary)
  int tri[2] = {-1, -1};             ///< layer-local triangles
  int side[2] = {-1, -1};            ///< side s of the triangle: corners s -> s+1
  int pointBegin = 0, pointEnd = 0;  ///< isoline points on the edge, sorted by t (CSR)
  int firstLevel[2] = {0, 0};        ///< level index of the edge's first point per field
  int rankBegin[2] = {0,
                      0};  ///< per field: rank of level firstLevel + i at rankOf[f][rankBegin + i]
  bool diagonal = false;   ///< joins layer points on disjoint tet edges (a quad diagonal)
};

/// Segment end point: its vertex and its place on the triangle boundary cycle.
struct Endpoint {
  int corner = -1;  ///< 0..2 for an exact hit at a corner, else -1
  int vertex = -1;  ///< layer graph vertex
  int slot = 0;     ///< 2i: corner i; 2i+1: inside side i (corners i -> i+1)
  int rank = 0;     ///< order inside the side, in the triangle's traversal direction
};

bool before(const Endpoint& x, const Endpoint& y) {
  return x.slot != y.slot ? x.slot < y.slot : x.rank < y.rank;
}

struct Segment {
  int field = 0, level = 0;
  Endpoint end[2];
  int alongSide = -1;  ///< side the segment lies on (both ends exact corner hits), else -1
};

struct Split {
  int segment;
  double key;  ///< order along the segment from end[0] to end[1]
  int vertex;
};

/// Builds the lattice graph of one layer (see the header for the algorithm).
class LayerBuilder {
public:
  LayerBuilder(const CurvedLayers& layers, int layer, const std::vector<double>* levels[2],
               const LatticeOptions& options)
      : layers_(layers), layer_(layer), options_(options) {
    levels_[0] = levels[0];
    levels_[1] = levels[1];
    p0_ = layers.layerPointOffset[layer];
    np_ = layers.layerPointOffset[layer + 1] - p0_;
    t0_ = layers.layerTriangleOffset[layer];
    nt_ = layers.layerTriangleOffset[layer + 1] - t0_;
  }

  LayerGraph build() {
    buildEdges();
    buildEdgePoints();
    meshVertex_.assign(np_, -1);
    for (int t = 0; t < nt_; ++t) {
      processTriangle(t);
    }
    addBoundaryEdges();
    removeDuplicateEdges();
    if (options_.mergeQuadDiagonalPoints && !layers_.sourceEdge.empty()) {
      mergeDiagonalPoints();
    }
    compact(std::vector<char>(g_.edges.size(), 1));
    classify();
    findSubgraphs();
    g_.onMeshEdge.clear();
    return std::move(g_);
  }

private:
  double field(int f, int v) const {
    return f == kAlpha ? layers_.alpha[p0_ + v] : layers_.beta[p0_ + v];
  }
  int corner(int t, int i) const { return layers_.triangles[t0_ + t][i] - p0_; }

  void buildEdges() {
    // Bucket the 3 nt half-edges by their smaller point (CSR), then group equal larger points.
    std::vector<int> offset(np_ + 1, 0);
    for (int t = 0; t < nt_; ++t) {
      for (int s = 0; s < 3; ++s) {
        ++offset[std::min(corner(t, s), corner(t, (s + 1) % 3)) + 1];
      }
    }
    std::partial_sum(offset.begin(), offset.end(), offset.begin());
    std::vector<std::pair<int, int>> bucket(3 *
                                            static_cast<size_t>(nt_));  // (larger point, half-edge)
    std::vector<int> cursor(offset.begin(), offset.end() - 1);
    for (int t = 0; t < nt_; ++t) {
      for (int s = 0; s < 3; ++s) {
        const int u = corner(t, s), v = corner(t, (s + 1) % 3);
        bucket[cursor[std::min(u, v)]++] = {std::max(u, v), 3 * t + s};
      }
    }
    triEdge_.assign(3 * static_cast<size_t>(nt_), -1);
    for (int a = 0; a < np_; ++a) {
      std::sort(bucket.begin() + offset[a], bucket.begin() + offset[a + 1]);
      for (int i = offset[a]; i < offset[a + 1];) {
        int j = i;
        while (j < offset[a + 1] && bucket[j].first == bucket[i].first) {
          ++j;
        }
        if (j - i > 2) {
          throw GeoLatticeError("layer " + std::to_string(layers_.layerIndex[layer_]) +
                                " is not edge-manifold: its edge (" + std::to_string(p0_ + a) +
                                ", " + std::to_string(p0_ + bucket[i].first) + ") is used by " +
                                std::to_string(j - i) + " triangles");
        }
        MeshEdge e;
        e.a = a;
        e.b = bucket[i].first;
        e.count = j - i;
        for (int k = i; k < j; ++k) {
          e.tri[k - i] = bucket[k].second / 3;
          e.side[k - i] = bucket[k].second % 3;
          triEdge_[bucket[k].second] = static_cast<int>(edges_.size());
        }
        if (!layers_.sourceEdge.empty()) {
          const auto& ea = layers_.sourceEdge[p0_ + e.a];
          const auto& eb = layers_.sourceEdge[p0_ + e.b];
          e.diagonal = ea[0] != ea[1] && eb[0] != eb[1] && ea[0] != eb[0] && ea[0] != eb[1] &&
                       ea[1] != eb[0] && ea[1] != eb[1];
        }
        edges_.push_back(e);
        i = j;
      }
    }
  }

  /// Isoline points strictly inside each edge (Eqs. 6-9), one vertex each; an α- and a β-point
  /// with the same parameter become one vertex.
  void buildEdgePoints() {
    struct Entry {
      double t;
      int k[2];
    };
    std::vector<Entry> list[2], merged;
    for (size_t ei = 0; ei < edges_.size(); ++ei) {
      MeshEdge& e = edges_[ei];
      for (int f = 0; f < 2; ++f) {
        const std::vector<double>& lv = *levels_[f];
        const double fa = field(f, e.a), fb = field(f, e.b);
        const int k0 = firstAbove(lv, std::min(fa, fb));
        const int k1 = firstAtOrAbove(lv, std::max(fa, fb));  // levels in (min, max)
        list[f].clear();
        for (int k = k0; k < k1; ++k) {
          list[f].push_back(
              {(lv[k] - fa) / (fb - fa), {f == kAlpha ? k : -1, f == kBeta ? k : -1}});
        }
        if (fa > fb) {
          std::reverse(list[f].begin(), list[f].end());  // ascending t
        }
        e.firstLevel[f] = k0;
        e.rankBegin[f] = static_cast<int>(rankOf_[f].size());
        rankOf_[f].resize(rankOf_[f].size() + list[f].size());
      }
      merged.clear();
      size_t i = 0, j = 0;
      while (i < list[0].size() || j < list[1].size()) {
        if (j == list[1].size() || (i < list[0].size() && list[0][i].t < list[1][j].t)) {
          merged.push_back(list[0][i++]);
        } else if (i == list[0].size() || list[1][j].t < list[0][i].t) {
          merged.push_back(list[1][j++]);
        } else {  // same parameter: one vertex on both isolines (a crossing on the edge)
          merged.push_back({list[0][i].t, {list[0][i].k[0], list[1][j].k[1]}});
          ++i;
          ++j;
          ++g_.stats.edgeCrossings;
        }
      }
      e.pointBegin = static_cast<int>(edgePointVertex_.size());
      const Vec3& pa = layers_.points[p0_ + e.a];
      const Vec3& pb = layers_.points[p0_ + e.b];
      const Vec3& na = layers_.normals[p0_ + e.a];
      const Vec3& nb = layers_.normals[p0_ + e.b];
      for (size_t r = 0; r < merged.size(); ++r) {
        const Entry& m = merged[r];
        const double t = m.t;
        const double a = m.k[0] >= 0 ? (*levels_[0])[m.k[0]]
                                     : (1 - t) * field(kAlpha, e.a) + t * field(kAlpha, e.b);
        const double b = m.k[1] >= 0 ? (*levels_[1])[m.k[1]]
                                     : (1 - t) * field(kBeta, e.a) + t * field(kBeta, e.b);
        const int v = g_.addVertex((1 - t) * pa + t * pb, unitOrZero((1 - t) * na + t * nb), a, b,
                                   m.k[0], m.k[1], static_cast<int>(ei));
        edgePointVertex_.push_back(v);
        for (int f = 0; f < 2; ++f) {
          if (m.k[f] >= 0) {
            rankOf_[f][e.rankBegin[f] + (m.k[f] - e.firstLevel[f])] = static_cast<int>(r);
          }
        }
      }
      e.pointEnd = static_cast<int>(edgePointVertex_.size());
    }
  }

  /// The one vertex of layer point v (exact hits of both fields and the boundary share it).
  int meshVertex(int v) {
    if (meshVertex_[v] < 0) {
      const int p = p0_ + v;
      meshVertex_[v] = g_.addVertex(layers_.points[p], layers_.normals[p], layers_.alpha[p],
                                    layers_.beta[p], exactLevel(*levels_[0], layers_.alpha[p]),
                                    exactLevel(*levels_[1], layers_.beta[p]), kLayerPoint);
    }
    return meshVertex_[v];
  }

  /// End point of the level-k isoline of field f on side s of triangle t; `upper` is the corner
  /// of the side with f >= level.
  Endpoint endpoint(int t, int s, int f, int k, int upper, double value) {
    Endpoint p;
    if (value == (*levels_[f])[k]) {
      p.corner = upper;
      p.slot = 2 * upper;
      return p;  // vertex assigned once the segment is kept
    }
    const MeshEdge& e = edges_[triEdge_[3 * t + s]];
    const int r = rankOf_[f][e.rankBegin[f] + (k - e.firstLevel[f])];
    const bool forward = corner(t, s) == e.a;
    p.vertex = edgePointVertex_[e.pointBegin + r];
    p.slot = 2 * s + 1;
    p.rank = forward ? r : (e.pointEnd - e.pointBegin - 1 - r);
    return p;
  }

  void processTriangle(int t) {
    segments_.clear();
    splits_.clear();
    const int c[3] = {corner(t, 0), corner(t, 1), corner(t, 2)};
    for (int f = 0; f < 2; ++f) {
      const std::vector<double>& lv = *levels_[f];
      const double v[3] = {field(f, c[0]), field(f, c[1]), field(f, c[2])};
      const int k0 = firstAbove(lv, std::min({v[0], v[1], v[2]}));
      const int k1 = firstAbove(lv, std::max({v[0], v[1], v[2]}));  // levels in (min, max]
      for (int k = k0; k < k1; ++k) {
        const double level = lv[k];
        const bool above[3] = {v[0] >= level, v[1] >= level, v[2] >= level};
        const int lone = above[0] == above[1] ? 2 : (above[0] == above[2] ? 1 : 0);
        // The sides at the lone corner: s1 = (lone+2)%3 ends at it, s2 = lone starts at it.
        const int s1 = (lone + 2) % 3, s2 = lone;
        const int other1 = (lone + 2) % 3, other2 = (lone + 1) % 3;
        const int upper1 = above[lone] ? lone : other1;
        const int upper2 = above[lone] ? lone : other2;
        Segment seg;
        seg.field = f;
        seg.level = k;
        seg.end[0] = endpoint(t, s1, f, k, upper1, v[upper1]);
        seg.end[1] = endpoint(t, s2, f, k, upper2, v[upper2]);
        if (seg.end[0].corner >= 0 && seg.end[0].corner == seg.end[1].corner) {
          ++g_.stats.touchingSegments;  // the isoline touches the layer at one point
          continue;
        }
        if (seg.end[0].corner >= 0 && seg.end[1].corner >= 0) {
          // Along side (lone+1)%3, the third corner below.
          const int side = (lone + 1) % 3;
          const MeshEdge& e = edges_[triEdge_[3 * t + side]];
          if (e.count == 1) {
            ++g_.stats.boundarySegments;  // coincides with the layer boundary
            continue;
          }
          const int nt = e.tri[0] == t ? e.tri[1] : e.tri[0];
          const int ns = e.tri[0] == t ? e.side[1] : e.side[0];
          if (field(f, corner(nt, (ns + 2) % 3)) < level) {
            ++g_.stats
                  .ridgeSegments;  // emitted by both triangles: the field touches the level from below
            continue;
          }
          seg.alongSide = side;
        }
        for (Endpoint& p : seg.end) {
          if (p.corner >= 0) {
            p.vertex = meshVertex(c[p.corner]);
          }
        }
        segments_.push_back(seg);
      }
    }
    // Crossings of α- and β-segments (Eqs. 10-11).
    const int n = static_cast<int>(segments_.size());
    for (int i = 0; i < n; ++i) {
      if (segments_[i].field != kAlpha) {
        continue;
      }
      for (int j = 0; j < n; ++j) {
        if (segments_[j].field != kBeta) {
          continue;
        }
        const Segment& A = segments_[i];
        const Segment& B = segments_[j];
        if (A.end[0].vertex == B.end[0].vertex || A.end[0].vertex == B.end[1].vertex ||
            A.end[1].vertex == B.end[0].vertex || A.end[1].vertex == B.end[1].vertex) {
          continue;  // they meet at a shared end point (lines cross at most once)
        }
        const bool forwardA = before(A.end[0], A.end[1]);
        const Endpoint& lo = forwardA ? A.end[0] : A.end[1];
        const Endpoint& hi = forwardA ? A.end[1] : A.end[0];
        const bool in0 = before(lo, B.end[0]) && before(B.end[0], hi);
        const bool in1 = before(lo, B.end[1]) && before(B.end[1], hi);
        if (in0 == in1) {
          continue;
        }
        if (A.alongSide >= 0 || B.alongSide >= 0) {
          // One segment lies on a side; the other ends inside that side: that end is the crossing.
          const bool alongA = A.alongSide >= 0;
          const Segment& S = alongA ? A : B;
          const Segment& O = alongA ? B : A;
          const Endpoint* hit = nullptr;
          for (const Endpoint& p : O.end) {
            if (p.slot == 2 * S.alongSide + 1) {
              hit = &p;
            }
          }
          if (!hit) {
            continue;  // cannot happen for linear fields; keep the segments unsplit
          }
          const double key = S.end[0].corner == S.alongSide ? hit->rank : -hit->rank;
          splits_.push_back({alongA ? i : j, key, hit->vertex});
          // The point is on S's isoline too (S's field is constant on that side).
          (S.field == kAlpha ? g_.alphaLevel : g_.betaLevel)[hit->vertex] = S.level;
          (S.field == kAlpha ? g_.alpha : g_.beta)[hit->vertex] = (*levels_[S.field])[S.level];
          continue;
        }
        const int a0 = A.end[0].vertex, a1 = A.end[1].vertex;
        const int b0 = B.end[0].vertex, b1 = B.end[1].vertex;
        const double levelA = (*levels_[kAlpha])[A.level], levelB = (*levels_[kBeta])[B.level];
        const double d = g_.beta[a1] - g_.beta[a0];
        const double s = std::clamp(d != 0 ? (levelB - g_.beta[a0]) / d : 0.5, 0.0, 1.0);  // Eq. 11
        const int x = g_.addVertex((1 - s) * g_.points[a0] + s * g_.points[a1],
                                   unitOrZero((1 - s) * g_.normals[a0] + s * g_.normals[a1]),
                                   levelA, levelB, A.level, B.level, kTriangleInterior);
        splits_.push_back({i, (d >= 0 ? 1.0 : -1.0) * B.level, x});
        splits_.push_back({j, (g_.alpha[b1] >= g_.alpha[b0] ? 1.0 : -1.0) * A.level, x});
      }
    }
    std::sort(splits_.begin(), splits_.end(), [](const Split& x, const Split& y) {
      return x.segment != y.segment ? x.segment < y.segment : x.key < y.key;
    });
    size_t next = 0;
    for (int i = 0; i < n; ++i) {
      const Segment& S = segments_[i];
      const LatticeEdgeKind kind =
          S.field == kAlpha ? LatticeEdgeKind::Alpha : LatticeEdgeKind::Beta;
      int prev = S.end[0].vertex;
      for (; next < splits_.size() && splits_[next].segment == i; ++next) {
        g_.addEdge(prev, splits_[next].vertex, kind, S.level);
        prev = splits_[next].vertex;
      }
      g_.addEdge(prev, S.end[1].vertex, kind, S.level);
    }
  }

  /// The layer boundary (Eqs. 12-13), split at the isoline points on it, in triangle order.
  void addBoundaryEdges() {
    for (const MeshEdge& e : edges_) {
      if (e.count != 1) {
        continue;
      }
      const int s = e.side[0];
      const bool forward = corner(e.tri[0], s) == e.a;
      int prev = meshVertex(forward ? e.a : e.b);
      const int n = e.pointEnd - e.pointBegin;
      for (int r = 0; r < n; ++r) {
        const int v = edgePointVertex_[e.pointBegin + (forward ? r : n - 1 - r)];
        g_.addEdge(prev, v, LatticeEdgeKind::Boundary, -1);
        prev = v;
      }
      g_.addEdge(prev, meshVertex(forward ? e.b : e.a), LatticeEdgeKind::Boundary, -1);
    }
  }

  void removeDuplicateEdges() {
    std::vector<int> order(g_.edges.size());
    std::iota(order.begin(), order.end(), 0);
    auto key = [&](int e) {
      return std::make_pair(std::min(g_.edges[e][0], g_.edges[e][1]),
                            std::max(g_.edges[e][0], g_.edges[e][1]));
    };
    std::sort(order.begin(), order.end(),
              [&](int x, int y) { return key(x) != key(y) ? key(x) < key(y) : x < y; });
    std::vector<char> keep(g_.edges.size(), 1);
    for (size_t i = 1; i < order.size(); ++i) {
      if (key(order[i]) == key(order[i - 1])) {
        keep[order[i]] = 0;
        ++g_.stats.duplicateEdges;
      }
    }
    compactEdges(keep);
  }

  void compactEdges(const std::vector<char>& keep) {
    size_t w = 0;
    for (size_t e = 0; e < g_.edges.size(); ++e) {
      if (keep[e]) {
        g_.edges[w] = g_.edges[e];
        g_.edgeKind[w] = g_.edgeKind[e];
        g_.edgeLevel[w] = g_.edgeLevel[e];
        ++w;
      }
    }
    g_.edges.resize(w);
    g_.edgeKind.resize(w);
    g_.edgeLevel.resize(w);
  }

  /// Incident edges of every vertex (CSR).
  void incidence(std::vector<int>& offset, std::vector<int>& list) const {
    const size_t nv = g_.points.size();
    offset.assign(nv + 1, 0);
    for (const auto& e : g_.edges) {
      ++offset[e[0] + 1];
      ++offset[e[1] + 1];
    }
    std::partial_sum(offset.begin(), offset.end(), offset.begin());
    list.resize(offset[nv]);
    std::vector<int> cursor(offset.begin(), offset.end() - 1);
    for (size_t e = 0; e < g_.edges.size(); ++e) {
      list[cursor[g_.edges[e][0]]++] = static_cast<int>(e);
      list[cursor[g_.edges[e][1]]++] = static_cast<int>(e);
    }
  }

  /// Removes degree-2 isoline points on quad diagonals, joining their two edges (the isoline is
  /// straight across the quad, so the joined edge passes through the removed point).
  void mergeDiagonalPoints() {
    std::vector<int> offset, list;
    incidence(offset, list);
    std::vector<char> keep(g_.edges.size(), 1);
    for (size_t v = 0; v < g_.points.size(); ++v) {
      const int me = g_.onMeshEdge[v];
      if (me < 0 || !edges_[me].diagonal || (g_.alphaLevel[v] >= 0) == (g_.betaLevel[v] >= 0)) {
        continue;
      }
      int inc[2], n = 0;
      for (int i = offset[v]; i < offset[v + 1]; ++i) {
        if (keep[list[i]]) {
          if (n < 2) {
            inc[n] = list[i];
          }
          ++n;
        }
      }
      if (n != 2 || g_.edgeKind[inc[0]] != g_.edgeKind[inc[1]]) {
        continue;
      }
      const int e1 = inc[0], e2 = inc[1];
      const int x = g_.edges[e1][0] == static_cast<int>(v) ? g_.edges[e1][1] : g_.edges[e1][0];
      const int y = g_.edges[e2][0] == static_cast<int>(v) ? g_.edges[e2][1] : g_.edges[e2][0];
      if (x == y) {
        continue;
      }
      // Keep the direction of e1 (x -> v becomes x -> y; v -> x becomes y -> x).
      g_.edges[e1] = g_.edges[e1][0] == static_cast<int>(v) ? std::array<int, 2>{y, x}
                                                            : std::array<int, 2>{x, y};
      keep[e2] = 0;
      for (int i = offset[y]; i < offset[y + 1]; ++i) {
        if (list[i] == e2) {
          list[i] = e1;
        }
      }
      ++g_.stats.mergedDiagonalPoints;
    }
    compactEdges(keep);
  }

  /// Keeps the edges with keep[e] and the vertices they use (order preserved).
  void compact(const std::vector<char>& keep) {
    compactEdges(keep);
    std::vector<int> newId(g_.points.size(), -1);
    for (const auto& e : g_.edges) {
      newId[e[0]] = newId[e[1]] = 0;
    }
    int n = 0;
    for (size_t v = 0; v < g_.points.size(); ++v) {
      if (newId[v] >= 0) {
        newId[v] = n;
        g_.points[n] = g_.points[v];
        g_.normals[n] = g_.normals[v];
        g_.alpha[n] = g_.alpha[v];
        g_.beta[n] = g_.beta[v];
        g_.alphaLevel[n] = g_.alphaLevel[v];
        g_.betaLevel[n] = g_.betaLevel[v];
        g_.onMeshEdge[n] = g_.onMeshEdge[v];
        if (!g_.subgraph.empty()) {
          g_.subgraph[n] = g_.subgraph[v];
          g_.kind[n] = g_.kind[v];
          g_.degree[n] = g_.degree[v];
        }
        ++n;
      }
    }
    for (auto* a : {&g_.alphaLevel, &g_.betaLevel, &g_.onMeshEdge}) {
      a->resize(n);
    }
    g_.points.resize(n);
    g_.normals.resize(n);
    g_.alpha.resize(n);
    g_.beta.resize(n);
    if (!g_.subgraph.empty()) {
      g_.subgraph.resize(n);
      g_.kind.resize(n);
      g_.degree.resize(n);
    }
    for (auto& e : g_.edges) {
      e = {newId[e[0]], newId[e[1]]};
    }
  }

  /// Vertex kinds from the kinds of the incident edges; degree rule check.
  void classify() {
    const size_t nv = g_.points.size();
    std::vector<std::array<int, 3>> count(nv, {0, 0, 0});
    for (size_t e = 0; e < g_.edges.size(); ++e) {
      for (int v : g_.edges[e]) {
        ++count[v][static_cast<int>(g_.edgeKind[e])];
      }
    }
    g_.kind.resize(nv);
    g_.degree.resize(nv);
    for (size_t v = 0; v < nv; ++v) {
      const auto& c = count[v];
      g_.degree[v] = c[0] + c[1] + c[2];
      if (c[2] > 0) {
        g_.kind[v] = c[0] + c[1] > 0 ? LatticeVertexKind::BoundaryHit : LatticeVertexKind::Boundary;
      } else {
        g_.kind[v] =
            c[0] > 0 && c[1] > 0 ? LatticeVertexKind::Crossing : LatticeVertexKind::IsolinePoint;
      }
    }
  }

  void findSubgraphs() {
    const int nv = static_cast<int>(g_.points.size());
    UnionFind sets(nv);
    for (const auto& e : g_.edges) {
      sets.unite(e[0], e[1]);
    }
    std::vector<int> comp;  // components numbered by their first vertex
    const int nc = sets.labels(comp);
    std::vector<double> length(nc, 0.0);
    for (const auto& e : g_.edges) {
      length[comp[e[0]]] += (g_.points[e[1]] - g_.points[e[0]]).norm();
    }
    std::vector<int> newComp(nc, -1);
    int kept = 0;
    for (int c = 0; c < nc; ++c) {
      if (length[c] < options_.minimumSubgraphLength) {
        ++g_.stats.droppedSubgraphs;
        g_.stats.droppedLength += length[c];
      } else {
        newComp[c] = kept++;
      }
    }
    g_.subgraph.resize(nv);
    for (int v = 0; v < nv; ++v) {
      g_.subgraph[v] = newComp[comp[v]];
    }
    if (kept < nc) {
      std::vector<char> keep(g_.edges.size());
      for (size_t e = 0; e < g_.edges.size(); ++e) {
        keep[e] = g_.subgraph[g_.edges[e][0]] >= 0;
      }
      compact(keep);
    }
    // Statistics per sub-graph.
    g_.subgraphs.assign(kept, LatticeSubgraph{});
    for (int c = 0; c < kept; ++c) {
      g_.subgraphs[c].indexInLayer = c;
    }
    g_.edgeSubgraph.resize(g_.edges.size());
    for (size_t v = 0; v < g_.points.size(); ++v) {
      LatticeSubgraph& s = g_.subgraphs[g_.subgraph[v]];
      ++s.vertexCount;
      if (g_.kind[v] == LatticeVertexKind::Crossing) {
        ++s.crossingCount;
        ++g_.stats.crossings;
      } else if (g_.kind[v] == LatticeVertexKind::BoundaryHit) {
        ++s.boundaryHitCount;
        ++g_.stats.boundaryHits;
      }
      const int expected = g_.kind[v] == LatticeVertexKind::Crossing      ? 4
                           : g_.kind[v] == LatticeVertexKind::BoundaryHit ? 3
                                                                          : 2;
      if (g_.degree[v] != expected) {
        ++g_.stats.irregularVertices;
      }
      if (g_.kind[v] == LatticeVertexKind::Crossing && g_.onMeshEdge[v] == kLayerPoint) {
        ++g_.stats.pointCrossings;
      }
    }
    for (size_t e = 0; e < g_.edges.size(); ++e) {
      const int c = g_.subgraph[g_.edges[e][0]];
      g_.edgeSubgraph[e] = c;
      LatticeSubgraph& s = g_.subgraphs[c];
      ++s.edgeCount;
      if (g_.edgeKind[e] != LatticeEdgeKind::Boundary) {
        ++s.isolineEdgeCount;
        ++g_.stats.isolineEdges;
      }
      const Vec3& p = g_.points[g_.edges[e][0]];
      const Vec3& q = g_.points[g_.edges[e][1]];
      const double len = (q - p).norm();
      s.length += len;
      s.centroid += len * 0.5 * (p + q);
    }
    for (size_t c = 0; c < g_.subgraphs.size(); ++c) {
      LatticeSubgraph& s = g_.subgraphs[c];
      if (s.length > 0) {
        s.centroid /= s.length;
      }
    }
    boundaryLoops();
  }

  /// Walks the boundary edges of each sub-graph into loops, following the triangle orientation
  /// where possible.
  void boundaryLoops() {
    std::vector<int> offset, list;
    incidence(offset, list);
    std::vector<char> used(g_.edges.size(), 0);
    for (size_t e0 = 0; e0 < g_.edges.size(); ++e0) {
      if (used[e0] || g_.edgeKind[e0] != LatticeEdgeKind::Boundary) {
        continue;
      }
      used[e0] = 1;
      LatticeBoundaryLoop loop;
      const int start = g_.edges[e0][0];
      int cur = g_.edges[e0][1];
      loop.vertices.push_back(start);
      while (cur != start) {
        loop.vertices.push_back(cur);
        int next = -1;
        for (int i = offset[cur]; i < offset[cur + 1]; ++i) {
          const int e = list[i];
          if (!used[e] && g_.edgeKind[e] == LatticeEdgeKind::Boundary &&
              (next < 0 || (g_.edges[e][0] == cur && g_.edges[next][0] != cur))) {
            next = e;
          }
        }
        if (next < 0) {
          loop.closed = false;
          ++g_.stats.openBoundaryChains;
          break;
        }
        used[next] = 1;
        cur = g_.edges[next][0] == cur ? g_.edges[next][1] : g_.edges[next][0];
      }
      g_.subgraphs[g_.subgraph[start]].boundaryLoops.push_back(std::move(loop));
    }
  }

  const CurvedLayers& layers_;
  int layer_;
  const LatticeOptions& options_;
  const std::vector<double>* levels_[2];
  int p0_ = 0, np_ = 0, t0_ = 0, nt_ = 0;
  std::vector<MeshEdge> edges_;
  std::vector<int> triEdge_;          ///< 3 nt: edge of side s of triangle t
  std::vector<int> edgePointVertex_;  ///< CSR of MeshEdge::pointBegin/End
  std::vector<int> rankOf_[2];
  std::vector<int> meshVertex_;  ///< layer point -> vertex (-1: none yet)
  std::vector<Segment> segments_;
  std::vector<Split> splits_;
  LayerGraph g_;
};

void validate(const CurvedLayers& in, const LatticeOptions& o) {
  o.validate();
  const size_t L = in.layerValues.size(), P = in.points.size(), T = in.triangles.size();
  if (in.layerIndex.size() != L || in.layerPointOffset.size() != L + 1 ||
      in.layerTriangleOffset.size() != L + 1) {
    throw GeoLatticeError("curved layers: layerIndex and the layer offsets must have " +
                          std::to_string(L) + " and " + std::to_string(L + 1) + " entries");
  }
  if (in.alpha.size() != P || in.beta.size() != P || in.normals.size() != P ||
      (!in.sourceEdge.empty() && in.sourceEdge.size() != P)) {
    throw GeoLatticeError(
        "curved layers: α, β, normals (and sourceEdge if given) need one value per point (" +
        std::to_string(P) + ")");
  }
  if (!o.widthScale.empty() && o.widthScale.size() != P) {
    throw GeoLatticeError("width scale has " + std::to_string(o.widthScale.size()) +
                          " values for " + std::to_string(P) + " layer points");
  }
  if (in.layerPointOffset[0] != 0 || in.layerTriangleOffset[0] != 0 ||
      in.layerPointOffset[L] != static_cast<int>(P) ||
      in.layerTriangleOffset[L] != static_cast<int>(T)) {
    throw GeoLatticeError(
        "curved layers: layer offsets must start at 0 and end at the point / triangle counts");
  }
  for (size_t l = 0; l < L; ++l) {
    if (in.layerPointOffset[l + 1] < in.layerPointOffset[l] ||
        in.layerTriangleOffset[l + 1] < in.layerTriangleOffset[l]) {
      throw GeoLatticeError("curved layers: decreasing offsets at layer " + std::to_string(l));
    }
  }
  for (size_t p = 0; p < P; ++p) {
    if (!std::isfinite(in.alpha[p]) || !std::isfinite(in.beta[p]) || !in.points[p].allFinite()) {
      throw GeoLatticeError("curved layers: layer point " + std::to_string(p) +
                            " has a non-finite position, α or β");
    }
  }
  for (size_t l = 0; l < L; ++l) {
    for (int t = in.layerTriangleOffset[l]; t < in.layerTriangleOffset[l + 1]; ++t) {
      const auto& f = in.triangles[t];
      for (int v : f) {
        if (v < in.layerPointOffset[l] || v >= in.layerPointOffset[l + 1]) {
          throw GeoLatticeError("curved layers: triangle " + std::to_string(t) + " of layer " +
                                std::to_string(l) + " uses point " + std::to_string(v) +
                                " outside its layer's points");
        }
      }
      if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) {
        throw GeoLatticeError("curved layers: triangle " + std::to_string(t) +
                              " uses a point twice");
      }
    }
  }
}

}  // namespace

void LatticeOptions::validate() const {
  auto positiveWidth = [](double w, const char* name) {
    if (!(w > 0) || !std::isfinite(w)) {
      throw GeoLatticeError(std::string(name) + " lattice width must be > 0 mm and finite (got " +
                            std::to_string(w) + ")");
    }
  };
  positiveWidth(this->alphaWidth, "α");
  positiveWidth(this->betaWidth, "β");
  if (!std::isfinite(this->alphaPhase) || !std::isfinite(this->betaPhase)) {
    throw GeoLatticeError("lattice phases must be finite");
  }
  if (!(this->minimumSubgraphLength >= 0) || !std::isfinite(this->minimumSubgraphLength)) {
    throw GeoLatticeError("minimum sub-graph length must be >= 0 mm (got " +
                          std::to_string(this->minimumSubgraphLength) + ")");
  }
  if (this->threads < 0) {
    throw GeoLatticeError("thread count must be >= 0 (got " + std::to_string(this->threads) + ")");
  }
  requireValidWorkLimit(this->maxElements, "the lattice size limit");
}

LatticeSizeEstimate estimateLatticeSize(const CurvedLayers& layers,
                                        const std::vector<double>& alphaLevels,
                                        const std::vector<double>& betaLevels) {
  // Levels strictly above the smallest corner value and at most the largest (an exact hit counts
  // as above, as in the builder).
  auto crossingLevels = [](const std::vector<double>& levels, double lo, double hi) {
    return static_cast<double>(std::upper_bound(levels.begin(), levels.end(), hi) -
                               std::upper_bound(levels.begin(), levels.end(), lo));
  };
  LatticeSizeEstimate e;
  for (const auto& t : layers.triangles) {
    const auto [aLo, aHi] =
        std::minmax({layers.alpha[t[0]], layers.alpha[t[1]], layers.alpha[t[2]]});
    const auto [bLo, bHi] = std::minmax({layers.beta[t[0]], layers.beta[t[1]], layers.beta[t[2]]});
    const double na = crossingLevels(alphaLevels, aLo, aHi);
    const double nb = crossingLevels(betaLevels, bLo, bHi);
    e.segments += na + nb;
    e.crossings += na * nb;
  }
  return e;
}

LatticeGraph buildLatticeGraph(const CurvedLayers& layers, const LatticeOptions& options) {
  validate(layers, options);
  const int L = static_cast<int>(layers.layerValues.size());
  LatticeGraph out;
  out.layerValues = layers.layerValues;
  out.layerIndex = layers.layerIndex;
  // Levels Ψ^α, Ψ^β from all layer points, so that a line continues from layer to layer.
  if (!layers.points.empty()) {
    if (options.widthScale.empty()) {
      const auto [aLo, aHi] = std::minmax_element(layers.alpha.begin(), layers.alpha.end());
      const auto [bLo, bHi] = std::minmax_element(layers.beta.begin(), layers.beta.end());
      out.alphaLevels = uniformLatticeLevels(*aLo, *aHi, options.alphaWidth, options.alphaPhase);
      out.betaLevels = uniformLatticeLevels(*bLo, *bHi, options.betaWidth, options.betaPhase);
    } else {
      out.alphaLevels = gradedLatticeLevels(layers.alpha, options.widthScale, options.alphaWidth,
                                            options.alphaPhase);
      out.betaLevels = gradedLatticeLevels(layers.beta, options.widthScale, options.betaWidth,
                                           options.betaPhase);
    }
  }
  const std::vector<double>* levels[2] = {&out.alphaLevels, &out.betaLevels};
  {
    std::ostringstream because;
    because << "at line widths " << options.alphaWidth << " and " << options.betaWidth << " mm";
    requireWithinWorkLimit(estimateLatticeSize(layers, out.alphaLevels, out.betaLevels).elements(),
                           options.maxElements, "lattice infill", "vertices and edges",
                           because.str(),
                           "use wider lattice lines or raise the size limit (MaximumElements)");
  }

  // Layers are independent: workers take the next layer; the calling thread reports progress
  // and polls the abort callback after each layer finished.
  std::vector<LayerGraph> result(L);
  parallelFor(
      static_cast<size_t>(L), options.threads,
      [&](size_t l, int) {
        result[l] = LayerBuilder(layers, static_cast<int>(l), levels, options).build();
      },
      [&](size_t done) {
        if (options.progress) {
          options.progress(static_cast<double>(done) / L);
        }
        if (options.shouldAbort && options.shouldAbort()) {
          throw GeoLatticeError("lattice infill aborted");
        }
      });

  // Concatenate the layers.
  out.layerVertexOffset.assign(L + 1, 0);
  out.layerEdgeOffset.assign(L + 1, 0);
  out.layerSubgraphOffset.assign(L + 1, 0);
  for (int l = 0; l < L; ++l) {
    out.layerVertexOffset[l + 1] =
        out.layerVertexOffset[l] + static_cast<int>(result[l].points.size());
    out.layerEdgeOffset[l + 1] = out.layerEdgeOffset[l] + static_cast<int>(result[l].edges.size());
    out.layerSubgraphOffset[l + 1] =
        out.layerSubgraphOffset[l] + static_cast<int>(result[l].subgraphs.size());
  }
  const size_t V = out.layerVertexOffset[L], E = out.layerEdgeOffset[L];
  out.points.reserve(V);
  out.normals.reserve(V);
  out.edges.reserve(E);
  for (int l = 0; l < L; ++l) {
    LayerGraph& g = result[l];
    const int v0 = out.layerVertexOffset[l], s0 = out.layerSubgraphOffset[l];
    auto append = [](auto& dst, const auto& src) {
      dst.insert(dst.end(), src.begin(), src.end());
    };
    append(out.points, g.points);
    append(out.normals, g.normals);
    out.gamma.insert(out.gamma.end(), g.points.size(), layers.layerValues[l]);
    append(out.alpha, g.alpha);
    append(out.beta, g.beta);
    append(out.alphaLevel, g.alphaLevel);
    append(out.betaLevel, g.betaLevel);
    append(out.vertexKind, g.kind);
    append(out.degree, g.degree);
    out.vertexLayer.insert(out.vertexLayer.end(), g.points.size(), l);
    for (int s : g.subgraph) {
      out.vertexSubgraph.push_back(s + s0);
    }
    for (const auto& e : g.edges) {
      out.edges.push_back({e[0] + v0, e[1] + v0});
    }
    append(out.edgeKind, g.edgeKind);
    append(out.edgeLevel, g.edgeLevel);
    out.edgeLayer.insert(out.edgeLayer.end(), g.edges.size(), l);
    for (int s : g.edgeSubgraph) {
      out.edgeSubgraph.push_back(s + s0);
    }
    for (LatticeSubgraph& s : g.subgraphs) {
      s.id = s0 + s.indexInLayer;
      s.layer = l;
      for (LatticeBoundaryLoop& loop : s.boundaryLoops) {
        for (int& v : loop.vertices) {
          v += v0;
        }
      }
      out.subgraphs.push_back(std::move(s));
    }
    LatticeStatistics& a = out.stats;
    const LatticeStatistics& b = g.stats;
    a.crossings += b.crossings;
    a.boundaryHits += b.boundaryHits;
    a.isolineEdges += b.isolineEdges;
    a.irregularVertices += b.irregularVertices;
    a.droppedSubgraphs += b.droppedSubgraphs;
    a.droppedLength += b.droppedLength;
    a.touchingSegments += b.touchingSegments;
    a.boundarySegments += b.boundarySegments;
    a.ridgeSegments += b.ridgeSegments;
    a.edgeCrossings += b.edgeCrossings;
    a.pointCrossings += b.pointCrossings;
    a.duplicateEdges += b.duplicateEdges;
    a.mergedDiagonalPoints += b.mergedDiagonalPoints;
    a.openBoundaryChains += b.openBoundaryChains;
    g = LayerGraph{};  // release memory early
  }
  return out;
}

}  // namespace geolattice
