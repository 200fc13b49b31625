#include "toolpath/SupportPerimeter.h"

#include "common/Error.h"
#include "common/GridHash.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace geolattice {
namespace {

/// The boundary edges of the lattice in a uniform grid of cells as large as the farthest a ray
/// is cast (a hash of the cells an edge's box overlaps), to find the far side of a layer region.
class BoundaryGrid {
public:
  BoundaryGrid(const LatticeGraph& g, const std::vector<char>& isBoundary, double cell)
      : g_(g), cell_(cell) {
    for (size_t e = 0; e < g.edges.size(); ++e) {
      if (isBoundary[e]) {
        const Vec3 &a = g.points[g.edges[e][0]], &b = g.points[g.edges[e][1]];
        forEachGridCell(a.cwiseMin(b), a.cwiseMax(b), cell_,
                        [&](uint64_t key) { cells_[key].push_back(static_cast<int>(e)); });
      }
    }
  }

  /// How far the ray from boundary vertex v along `inward` (unit, in the layer's tangent plane at
  /// v, normal n) runs inside the region of `subgraph` before it crosses another boundary edge
  /// of that sub-graph: the crossing is found in the tangent plane, for edges within `reach` of v
  /// and within half of it off that plane. `reach` when nothing is crossed.
  double clearance(int v, int subgraph, const Vec3& inward, const Vec3& n, double reach) const {
    const Vec3& b = g_.points[v];
    const Vec3 across = n.cross(inward);  // the third axis of the frame (inward, across, n)
    double nearest = reach;
    const Vec3 end = b + reach * inward;
    forEachGridCell(b.cwiseMin(end), b.cwiseMax(end), cell_, [&](uint64_t key) {
      const auto cell = cells_.find(key);
      if (cell == cells_.end()) {
        return;
      }
      for (const int e : cell->second) {
        const int p = g_.edges[e][0], q = g_.edges[e][1];
        if (p == v || q == v || g_.edgeSubgraph[e] != subgraph) {
          continue;
        }
        const Vec3 dp = g_.points[p] - b, dq = g_.points[q] - b;
        const double vp = dp.dot(across), vq = dq.dot(across);
        if ((vp > 0) == (vq > 0) || vp == vq) {
          continue;  // the edge does not cross the ray's line
        }
        const double t = vp / (vp - vq);
        const Vec3 x = dp + t * (dq - dp);
        const double along = x.dot(inward);
        if (along > 0 && along < nearest && std::abs(x.dot(n)) < 0.5 * reach) {
          nearest = along;
        }
      }
    });
    return nearest;
  }

private:
  const LatticeGraph& g_;
  double cell_;
  std::unordered_map<uint64_t, std::vector<int>> cells_;
};

}  // namespace

PerimeterResult supportPerimeters(const LatticeGraph& g, const std::vector<char>& kept,
                                  double offset, double toothLength) {
  if (!(offset > 0) || !(toothLength > 0) || !std::isfinite(offset) ||
      !std::isfinite(toothLength)) {
    throw GeoLatticeError("support perimeter: offset and tooth length must be > 0 mm");
  }
  const size_t V = g.points.size(), E = g.edges.size();
  if (kept.size() != E || g.edgeKind.size() != E || g.edgeSubgraph.size() != E ||
      g.normals.size() != V) {
    throw GeoLatticeError("support perimeter: lattice arrays do not match its edges and vertices");
  }
  // Incidence.
  std::vector<int> offsetOf(V + 1, 0), list(2 * E);
  for (const auto& e : g.edges) {
    ++offsetOf[e[0] + 1];
    ++offsetOf[e[1] + 1];
  }
  for (size_t v = 0; v < V; ++v) {
    offsetOf[v + 1] += offsetOf[v];
  }
  {
    std::vector<int> next(offsetOf.begin(), offsetOf.end() - 1);
    for (size_t e = 0; e < E; ++e) {
      list[next[g.edges[e][0]]++] = static_cast<int>(e);
      list[next[g.edges[e][1]]++] = static_cast<int>(e);
    }
  }
  auto isBoundary = [&](int e) {
    return g.edgeKind[e] == LatticeEdgeKind::Boundary;
  };

  std::vector<char> boundary(E, 0);
  for (size_t e = 0; e < E; ++e) {
    boundary[e] = isBoundary(static_cast<int>(e));
  }
  // A region narrower than two offsets (a sliver of a layer where it meets the surface almost
  // tangentially) gets its perimeter on its middle: offset by w, the point would lie beyond the
  // far side, outside the part (the knight: 30 perimeter points 0.3-0.59 mm outside).
  const BoundaryGrid grid(g, boundary, 2 * offset);

  PerimeterResult out;
  std::vector<char> used(E, 0);
  for (size_t e0 = 0; e0 < E; ++e0) {
    if (used[e0] || !isBoundary(static_cast<int>(e0))) {
      continue;
    }
    // Walk the loop.
    std::vector<int> loopV, loopE;
    int v = g.edges[e0][0], e = static_cast<int>(e0);
    const int start = v;
    bool closed = false;
    while (e >= 0 && !used[e]) {
      used[e] = 1;
      loopV.push_back(v);
      loopE.push_back(e);
      v = g.edges[e][0] == v ? g.edges[e][1] : g.edges[e][0];
      if (v == start) {
        closed = true;
        break;
      }
      int next = -1;
      for (int i = offsetOf[v]; i < offsetOf[v + 1]; ++i) {
        if (!used[list[i]] && isBoundary(list[i])) {
          next = list[i];
          break;
        }
      }
      e = next;
    }
    const size_t m = loopV.size();
    if (!closed || m < 3) {
      continue;
    }
    // In-layer directions and the interior side (vote of the isoline ends).
    std::vector<Vec3> d(m);
    double vote = 0;
    for (size_t i = 0; i < m; ++i) {
      const Vec3& prev = g.points[loopV[(i + m - 1) % m]];
      const Vec3& next = g.points[loopV[(i + 1) % m]];
      const Vec3 n = unitOr(g.normals[loopV[i]], Vec3::UnitZ());
      d[i] = unitOr(n.cross(next - prev), Vec3::Zero());
      for (int k = offsetOf[loopV[i]]; k < offsetOf[loopV[i] + 1]; ++k) {
        const int f = list[k];
        if (!isBoundary(f)) {
          const int o = g.edges[f][0] == loopV[i] ? g.edges[f][1] : g.edges[f][0];
          vote += d[i].dot(g.points[o] - g.points[loopV[i]]) > 0 ? 1 : -1;
        }
      }
    }
    if (vote == 0) {
      ++out.loopsWithoutIsolines;
      continue;
    }
    const double side = vote > 0 ? 1.0 : -1.0;
    const int subgraph = g.edgeSubgraph[loopE[0]];
    std::vector<double> reach(m);  // the offset at each vertex: w, or half the region's width
    for (size_t i = 0; i < m; ++i) {
      d[i] *= side;
      const Vec3 n = unitOr(g.normals[loopV[i]], Vec3::UnitZ());
      reach[i] =
          d[i].squaredNorm() > 0
              ? std::min(offset, 0.5 * grid.clearance(loopV[i], subgraph, d[i], n, 2 * offset))
              : offset;
    }
    // Start at a vertex that begins a kept edge (the tour passes it).
    size_t first = m;
    for (size_t i = 0; i < m; ++i) {
      if (kept[loopE[i]]) {
        first = i;
        break;
      }
    }
    if (first == m) {
      continue;  // fully trimmed loop: nothing of it is on the tour (does not happen: parity keeps half)
    }
    PerimeterLoop loop;
    loop.subgraph = g.edgeSubgraph[loopE[first]];
    loop.anchorVertex = loopV[first];
    auto inner = [&](size_t i) {
      return Vec3(g.points[loopV[i]] + reach[i] * d[i]);
    };
    auto add = [&](const Vec3& x, size_t i) {
      loop.points.push_back(x);
      loop.normals.push_back(unitOr(g.normals[loopV[i]], Vec3::UnitZ()));
      loop.nearVertex.push_back(loopV[i]);
    };
    add(inner(first), first);
    bool outward = false;  // phase of the zig-zag along trimmed edges
    for (size_t j = 0; j < m; ++j) {
      const size_t i = (first + j) % m, i1 = (first + j + 1) % m;
      const int edge = loopE[i];
      if (kept[edge]) {
        if (outward) {  // come back to the offset curve at the end of a tooth run
          outward = false;
        }
        add(inner(i1), i1);
        continue;
      }
      // Trimmed edge: alternate inner/outer every half tooth along it.
      const Vec3 a = g.points[loopV[i]], b = g.points[loopV[i1]];
      const Vec3 ai = inner(i), bi = inner(i1);
      const int parts =
          std::max(1, static_cast<int>(std::ceil((b - a).norm() / (0.5 * toothLength))));
      for (int k = 1; k <= parts; ++k) {
        const double t = static_cast<double>(k) / parts;
        outward = !outward;
        out.teeth += outward;
        add(outward ? Vec3((1 - t) * a + t * b) : Vec3((1 - t) * ai + t * bi), t < 0.5 ? i : i1);
      }
      if (outward && kept[loopE[i1]]) {  // leave the tooth before a kept edge
        outward = false;
        add(inner(i1), i1);
      }
    }
    if (outward) {
      add(inner(first), first);
    }
    if ((loop.points.back() - loop.points.front()).norm() > 0) {
      add(inner(first), first);
    }
    out.loops.push_back(std::move(loop));
  }
  return out;
}

}  // namespace geolattice
