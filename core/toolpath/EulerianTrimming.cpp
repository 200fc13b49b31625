#include "toolpath/EulerianTrimming.h"

#include "common/Error.h"
#include "common/UnionFind.h"

#include <algorithm>
#include <limits>
#include <queue>
#include <sstream>

namespace geolattice {

namespace {

/// Edges of one sub-graph with local incidence lists.
struct Subgraph {
  std::vector<int> edges;                        ///< global edge ids
  std::vector<int> vertices;                     ///< global vertex ids
  std::vector<std::vector<int>> incident;        ///< per local vertex: local edge ids
  const std::vector<int>* localOfAll = nullptr;  ///< global vertex -> local id in its sub-graph
  int local(int v) const { return (*localOfAll)[v]; }
};

/// A boundary loop cut at its odd vertices: chains of local edge ids.
struct Loop {
  std::vector<std::vector<int>> chains;
  std::vector<double> chainLength;
  bool oddCount = false;
};

int componentsOfKept(const Subgraph& s, const LatticeGraph& g, const std::vector<char>& keptLocal) {
  UnionFind uf(static_cast<int>(s.vertices.size()));
  std::vector<char> touched(s.vertices.size(), 0);
  for (size_t e = 0; e < s.edges.size(); ++e) {
    if (keptLocal[e]) {
      const auto& ge = g.edges[s.edges[e]];
      uf.unite(s.local(ge[0]), s.local(ge[1]));
      touched[s.local(ge[0])] = touched[s.local(ge[1])] = 1;
    }
  }
  int count = 0;
  for (size_t v = 0; v < s.vertices.size(); ++v) {
    count += touched[v] && uf.find(static_cast<int>(v)) == static_cast<int>(v);
  }
  return count;
}

}  // namespace

namespace {

/// Calls f(a, b) for every edge (a, b) not longer than tolerance; returns how many.
template <class F>
int forEachShortEdge(const LatticeGraph& g, double tolerance, F&& f) {
  const size_t V = g.points.size();
  int count = 0;
  for (const auto& [a, b] : g.edges) {
    if (a < 0 || b < 0 || a >= static_cast<int>(V) || b >= static_cast<int>(V)) {
      throw GeoLatticeError("edge contraction: an edge refers to a missing vertex");
    }
    if ((g.points[a] - g.points[b]).norm() <= tolerance) {
      f(a, b);
      ++count;
    }
  }
  return count;
}

}  // namespace

int countShortEdges(const LatticeGraph& g, double tolerance) {
  return forEachShortEdge(g, tolerance, [](int, int) {});
}

int contractShortEdges(LatticeGraph& g, double tolerance, std::vector<int>* edgeValues) {
  const size_t V = g.points.size(), E = g.edges.size();
  UnionFind uf(static_cast<int>(V));
  const int contracted = forEachShortEdge(g, tolerance, [&](int a, int b) { uf.unite(a, b); });
  if (contracted == 0) {
    return 0;
  }
  size_t out = 0;
  auto keepIf = [](auto& v, const std::vector<char>& keep) {
    if (v.size() != keep.size()) {
      return;
    }
    size_t j = 0;
    for (size_t i = 0; i < keep.size(); ++i) {
      if (keep[i]) {
        v[j++] = v[i];
      }
    }
    v.resize(j);
  };
  std::vector<char> keep(E, 1);
  for (size_t e = 0; e < E; ++e) {
    auto& ed = g.edges[e];
    ed = {uf.find(ed[0]), uf.find(ed[1])};
    keep[e] = ed[0] != ed[1];
    out += keep[e];
  }
  keepIf(g.edgeKind, keep);
  keepIf(g.edgeLevel, keep);
  keepIf(g.edgeLayer, keep);
  keepIf(g.edgeSubgraph, keep);
  keepIf(g.edges, keep);
  if (edgeValues) {
    keepIf(*edgeValues, keep);
  }
  // Degrees of the merged vertices.
  if (g.degree.size() == V) {
    std::fill(g.degree.begin(), g.degree.end(), 0);
    for (const auto& ed : g.edges) {
      ++g.degree[ed[0]];
      ++g.degree[ed[1]];
    }
  }
  return contracted;
}

TrimResult trimToEulerian(const LatticeGraph& g) {
  const size_t V = g.points.size(), E = g.edges.size(), K = g.subgraphs.size();
  if (g.edgeKind.size() != E || g.edgeSubgraph.size() != E || g.vertexSubgraph.size() != V) {
    throw GeoLatticeError("Eulerian trimming: lattice arrays do not match its edges and vertices");
  }
  TrimResult r;
  r.kept.assign(E, 1);
  r.componentCount.assign(K, 0);

  // Group edges and vertices by sub-graph.
  std::vector<Subgraph> subs(K);
  std::vector<int> localOf(V, -1);
  for (size_t e = 0; e < E; ++e) {
    const int s = g.edgeSubgraph[e];
    const auto [a, b] = g.edges[e];
    if (s < 0 || s >= static_cast<int>(K) || a < 0 || b < 0 || a >= static_cast<int>(V) ||
        b >= static_cast<int>(V)) {
      throw GeoLatticeError("Eulerian trimming: an edge has no valid sub-graph or vertex");
    }
    if (!((g.points[a] - g.points[b]).norm() > 0)) {
      std::ostringstream m;
      m << "Eulerian trimming: lattice edge " << e << " has zero length";
      throw GeoLatticeError(m.str());
    }
    subs[s].edges.push_back(static_cast<int>(e));
  }
  for (size_t k = 0; k < K; ++k) {
    Subgraph& s = subs[k];
    s.localOfAll = &localOf;
    for (int e : s.edges) {
      for (int v : g.edges[e]) {
        if (localOf[v] < 0) {
          localOf[v] = static_cast<int>(s.vertices.size());
          s.vertices.push_back(v);
        } else if (localOf[v] >= static_cast<int>(s.vertices.size()) ||
                   s.vertices[localOf[v]] != v) {
          throw GeoLatticeError("Eulerian trimming: a vertex is shared by two sub-graphs");
        }
      }
    }
    s.incident.assign(s.vertices.size(), {});
    for (size_t i = 0; i < s.edges.size(); ++i) {
      for (int v : g.edges[s.edges[i]]) {
        s.incident[localOf[v]].push_back(static_cast<int>(i));
      }
    }
  }

  for (size_t k = 0; k < K; ++k) {
    Subgraph& s = subs[k];
    const int n = static_cast<int>(s.vertices.size());
    const int m = static_cast<int>(s.edges.size());
    auto other = [&](int le, int lv) {
      const auto& ge = g.edges[s.edges[le]];
      return s.local(ge[0]) == lv ? s.local(ge[1]) : s.local(ge[0]);
    };
    auto isBoundary = [&](int le) {
      return g.edgeKind[s.edges[le]] == LatticeEdgeKind::Boundary;
    };
    auto length = [&](int le) {
      const auto& ge = g.edges[s.edges[le]];
      return (g.points[ge[0]] - g.points[ge[1]]).norm();
    };
    std::vector<int> degree(n);
    for (int v = 0; v < n; ++v) {
      degree[v] = static_cast<int>(s.incident[v].size());
    }

    // Boundary loops as edge cycles, cut into chains at odd vertices.
    std::vector<Loop> loops;
    std::vector<char> usedB(m, 0);
    for (int e0 = 0; e0 < m; ++e0) {
      if (usedB[e0] || !isBoundary(e0)) {
        continue;
      }
      std::vector<int> cycle;     // local edges in order
      std::vector<int> atVertex;  // vertex at the start of each edge
      int v = s.local(g.edges[s.edges[e0]][0]);
      int e = e0;
      const int start = v;
      bool closed = false;
      while (e >= 0 && !usedB[e]) {
        usedB[e] = 1;
        cycle.push_back(e);
        atVertex.push_back(v);
        v = other(e, v);
        if (v == start) {
          closed = true;
          break;
        }
        int next = -1;
        for (int f : s.incident[v]) {
          if (!usedB[f] && isBoundary(f)) {
            next = f;
            break;
          }
        }
        e = next;
      }
      Loop loop;
      // Rotate so the loop starts at an odd vertex, then cut at every odd vertex.
      int firstOdd = -1;
      int oddCount = 0;
      for (size_t i = 0; i < cycle.size(); ++i) {
        if (degree[atVertex[i]] % 2 == 1) {
          ++oddCount;
          if (firstOdd < 0) {
            firstOdd = static_cast<int>(i);
          }
        }
      }
      if (!closed || firstOdd < 0) {
        continue;  // nothing to fix by chains (open chains are left to the T-join)
      }
      loop.oddCount = oddCount % 2 == 1;
      std::vector<int> chain;
      double len = 0;
      for (size_t j = 0; j < cycle.size(); ++j) {
        const size_t i = (firstOdd + j) % cycle.size();
        if (j > 0 && degree[atVertex[i]] % 2 == 1) {
          loop.chains.push_back(chain);
          loop.chainLength.push_back(len);
          chain.clear();
          len = 0;
        }
        chain.push_back(cycle[i]);
        len += length(cycle[i]);
      }
      loop.chains.push_back(chain);
      loop.chainLength.push_back(len);
      r.oddLoops += loop.oddCount;
      loops.push_back(std::move(loop));
    }

    // Candidate deletions: per even loop, parity 0 or 1.
    std::vector<int> evenLoops;
    for (size_t i = 0; i < loops.size(); ++i) {
      if (!loops[i].oddCount && loops[i].chains.size() >= 2) {
        evenLoops.push_back(static_cast<int>(i));
      }
    }
    auto apply = [&](unsigned long long mask, std::vector<char>& keep, double& deleted) {
      keep.assign(m, 1);
      deleted = 0;
      for (size_t j = 0; j < evenLoops.size(); ++j) {
        const Loop& loop = loops[evenLoops[j]];
        const size_t parity = (mask >> j) & 1ull;
        for (size_t c = parity; c < loop.chains.size(); c += 2) {
          for (int le : loop.chains[c]) {
            keep[le] = 0;
          }
          deleted += loop.chainLength[c];
        }
      }
    };
    std::vector<char> best, trial;
    double bestDeleted = std::numeric_limits<double>::infinity();
    int bestComponents = std::numeric_limits<int>::max();
    auto consider = [&](unsigned long long mask) {
      double deleted = 0;
      apply(mask, trial, deleted);
      const int c = componentsOfKept(s, g, trial);
      if (c < bestComponents || (c == bestComponents && deleted < bestDeleted)) {
        bestComponents = c;
        bestDeleted = deleted;
        best = trial;
      }
    };
    if (evenLoops.size() <= 8) {
      for (unsigned long long mask = 0; mask < (1ull << evenLoops.size()); ++mask) {
        consider(mask);
      }
    } else {  // loop by loop: flip a loop's parity when that helps
      unsigned long long mask = 0;
      consider(mask);
      for (size_t j = 0; j < evenLoops.size(); ++j) {
        const int before = bestComponents;
        const double beforeDeleted = bestDeleted;
        consider(mask | (1ull << (j % 64)));
        if (bestComponents < before || (bestComponents == before && bestDeleted < beforeDeleted)) {
          mask |= 1ull << (j % 64);
        }
      }
    }
    if (best.empty()) {
      best.assign(m, 1);
    }

    // Remaining odd vertices (odd loops, open boundary chains, irregular vertices): T-join by
    // shortest paths (BFS in edges) inside the kept graph, deleting the path edges.
    std::vector<int> deg(n, 0);
    for (int le = 0; le < m; ++le) {
      if (best[le]) {
        for (int v : g.edges[s.edges[le]]) {
          ++deg[s.local(v)];
        }
      }
    }
    for (int a = 0; a < n; ++a) {
      if (deg[a] % 2 == 0) {
        continue;
      }
      std::vector<int> via(n, -2);
      std::queue<int> q;
      q.push(a);
      via[a] = -1;
      int target = -1;
      while (!q.empty() && target < 0) {
        const int v = q.front();
        q.pop();
        for (int le : s.incident[v]) {
          if (!best[le])
            continue;
          const int w = other(le, v);
          if (via[w] != -2)
            continue;
          via[w] = le;
          if (deg[w] % 2 == 1) {
            target = w;
            break;
          }
          q.push(w);
        }
      }
      if (target < 0) {
        continue;  // no partner in this piece (cannot happen in a graph: odd vertices pair up)
      }
      for (int v = target; v != a;) {
        const int le = via[v];
        best[le] = 0;
        ++r.tJoinEdges;
        const int w = other(le, v);
        --deg[v];
        --deg[w];
        v = w;
      }
    }

    for (int le = 0; le < m; ++le) {
      if (!best[le]) {
        r.kept[s.edges[le]] = 0;
        if (isBoundary(le)) {
          ++r.trimmedEdges;
          r.trimmedLength += length(le);
        }
      }
    }
    r.componentCount[k] = componentsOfKept(s, g, best);
    r.splitSubgraphs += r.componentCount[k] > 1;
  }
  return r;
}

}  // namespace geolattice
