#include "toolpath/EulerTour.h"

#include "common/Error.h"
#include "common/UnionFind.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace geolattice {

namespace {

/// Half-edge "end" ids: 2e + side, side 0 at edges[e][0], side 1 at edges[e][1].
inline int endVertex(const LatticeGraph& g, int end) {
  return g.edges[end >> 1][end & 1];
}
inline int otherEnd(int end) {
  return end ^ 1;
}

/// Ends at each vertex sorted by angle about the vertex normal.
struct VertexStar {
  std::vector<int> offset;  ///< #V + 1
  std::vector<int> ends;    ///< grouped by vertex, in cyclic order
};

VertexStar buildStars(const LatticeGraph& g, const std::vector<char>& kept) {
  const int V = static_cast<int>(g.points.size());
  const int E = static_cast<int>(g.edges.size());
  VertexStar s;
  s.offset.assign(V + 1, 0);
  for (int e = 0; e < E; ++e) {
    if (kept.empty() || kept[e]) {
      ++s.offset[g.edges[e][0] + 1];
      ++s.offset[g.edges[e][1] + 1];
    }
  }
  for (int v = 0; v < V; ++v) {
    s.offset[v + 1] += s.offset[v];
  }
  s.ends.resize(s.offset[V]);
  std::vector<int> next(s.offset.begin(), s.offset.end() - 1);
  for (int e = 0; e < E; ++e) {
    if (kept.empty() || kept[e]) {
      s.ends[next[g.edges[e][0]]++] = 2 * e;
      s.ends[next[g.edges[e][1]]++] = 2 * e + 1;
    }
  }
  std::vector<std::pair<double, int>> tmp;
  for (int v = 0; v < V; ++v) {
    const int d = s.offset[v + 1] - s.offset[v];
    if (d % 2 == 1) {
      std::ostringstream m;
      m << "Euler tour: vertex " << v << " has odd degree " << d << " after trimming";
      throw GeoLatticeError(m.str());
    }
    if (d < 4) {
      continue;  // degree 2: one pairing, no order needed
    }
    const Vec3& n = g.normals[v];
    if (!(n.norm() > 0)) {
      std::ostringstream m;
      m << "Euler tour: vertex " << v << " of degree " << d << " has no normal";
      throw GeoLatticeError(m.str());
    }
    const Vec3 axis = n.normalized();
    const Vec3 u = axis.unitOrthogonal();
    const Vec3 w = axis.cross(u);
    tmp.clear();
    for (int i = s.offset[v]; i < s.offset[v + 1]; ++i) {
      const Vec3 d3 = g.points[endVertex(g, otherEnd(s.ends[i]))] - g.points[v];
      tmp.push_back({std::atan2(d3.dot(w), d3.dot(u)), s.ends[i]});
    }
    std::sort(tmp.begin(), tmp.end());
    for (int i = 0; i < d; ++i) {
      s.ends[s.offset[v] + i] = tmp[i].second;
    }
  }
  return s;
}

/// Follows transitions from the end `start` (leaving its vertex along its edge) until back.
template <class Visit>
void traceCircuit(const std::vector<int>& partner, int start, Visit visit) {
  int end = start;
  do {
    visit(end);                    // traverse edge end>>1 from end's vertex to the other end
    end = partner[otherEnd(end)];  // arrive at the other end, leave by its partner
  } while (end != start);
}

}  // namespace

EulerTours nonCrossingEulerTours(const LatticeGraph& g, const std::vector<char>& kept) {
  const int E = static_cast<int>(g.edges.size());
  if (g.normals.size() != g.points.size() || g.edgeSubgraph.size() != g.edges.size() ||
      (!kept.empty() && kept.size() != g.edges.size())) {
    throw GeoLatticeError("Euler tour: lattice arrays do not match its edges and vertices");
  }
  const VertexStar star = buildStars(g, kept);
  const int V = static_cast<int>(g.points.size());
  std::vector<int> partner(2 * E, -1);
  auto pairUp = [&](int a, int b) {
    partner[a] = b;
    partner[b] = a;
  };
  for (int v = 0; v < V; ++v) {
    for (int i = star.offset[v]; i + 1 < star.offset[v + 1]; i += 2) {
      pairUp(star.ends[i], star.ends[i + 1]);  // (e0 e1)(e2 e3)…: turn, never go straight
    }
  }
  // Circuits of the initial transition system.
  std::vector<int> circuit(E, -1);
  int circuits = 0;
  for (int e = 0; e < E; ++e) {
    if ((kept.empty() || kept[e]) && circuit[e] < 0) {
      traceCircuit(partner, 2 * e, [&](int end) { circuit[end >> 1] = circuits; });
      ++circuits;
    }
  }
  // Merge circuits at degree-4 vertices by switching to the other non-crossing pairing.
  EulerTours out;
  UnionFind joined(std::max(circuits, 1));
  for (int v = 0; v < V; ++v) {
    const int d = star.offset[v + 1] - star.offset[v];
    if (d >= 6) {
      ++out.highDegreeVertices;
      continue;
    }
    if (d != 4) {
      continue;
    }
    const int* h = &star.ends[star.offset[v]];
    const int c0 = joined.find(circuit[h[0] >> 1]), c2 = joined.find(circuit[h[2] >> 1]);
    if (c0 != c2) {
      pairUp(h[1], h[2]);
      pairUp(h[3], h[0]);
      joined.unite(c0, c2);
      ++out.switches;
    }
  }
  // Final tours.
  std::vector<char> done(E, 0);
  for (int e = 0; e < E; ++e) {
    if ((!kept.empty() && !kept[e]) || done[e]) {
      continue;
    }
    std::vector<int> verts{g.edges[e][0]}, edges;
    traceCircuit(partner, 2 * e, [&](int end) {
      done[end >> 1] = 1;
      edges.push_back(end >> 1);
      verts.push_back(endVertex(g, otherEnd(end)));
    });
    out.vertices.push_back(std::move(verts));
    out.edges.push_back(std::move(edges));
    out.subgraph.push_back(g.edgeSubgraph[e]);
  }
  return out;
}

int countTourCrossovers(const LatticeGraph& g, const EulerTours& tours) {
  int crossings = 0;
  for (size_t t = 0; t < tours.edges.size(); ++t) {
    const auto& vs = tours.vertices[t];
    const auto& es = tours.edges[t];
    const size_t n = es.size();
    // Passes through each vertex: (incoming edge, outgoing edge) around the closed tour.
    std::vector<std::pair<int, std::pair<int, int>>> passes;  // vertex, (in, out)
    for (size_t i = 0; i < n; ++i) {
      passes.push_back({vs[i], {es[(i + n - 1) % n], es[i]}});
    }
    std::sort(passes.begin(), passes.end());
    for (size_t i = 0; i < passes.size();) {
      size_t j = i;
      while (j < passes.size() && passes[j].first == passes[i].first) {
        ++j;
      }
      if (j - i >= 2) {
        const int v = passes[i].first;
        const Vec3 axis = g.normals[v].normalized();
        const Vec3 u = axis.unitOrthogonal(), w = axis.cross(u);
        auto angle = [&](int e) {
          const int o = g.edges[e][0] == v ? g.edges[e][1] : g.edges[e][0];
          const Vec3 d = g.points[o] - g.points[v];
          return std::atan2(d.dot(w), d.dot(u));
        };
        auto between = [](double a, double lo,
                          double hi) {  // a strictly inside the arc lo -> hi (ccw)
          const double twoPi = 2 * M_PI;
          auto norm = [&](double x) {
            return std::fmod(std::fmod(x, twoPi) + twoPi, twoPi);
          };
          return norm(a - lo) > 0 && norm(a - lo) < norm(hi - lo);
        };
        for (size_t a = i; a < j; ++a) {
          for (size_t b = a + 1; b < j; ++b) {
            const double a0 = angle(passes[a].second.first), a1 = angle(passes[a].second.second);
            const double b0 = angle(passes[b].second.first), b1 = angle(passes[b].second.second);
            // Chords (a0 a1) and (b0 b1) cross iff exactly one end of b lies on each side.
            crossings += between(b0, a0, a1) != between(b1, a0, a1);
          }
        }
      }
      i = j;
    }
  }
  return crossings;
}

}  // namespace geolattice
