#include "sequence/PrintMaterial.h"

#include "common/Error.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace geolattice {

MaterialSamples sampleLatticeMaterial(const LatticeGraph& g, double spacing) {
  return sampleLatticeMaterial(g, spacing, g.edgeSubgraph, static_cast<int>(g.subgraphs.size()));
}

MaterialSamples sampleLatticeMaterial(const LatticeGraph& g, double spacing,
                                      const std::vector<int>& edgeGroup, int K) {
  if (!(spacing > 0) || !std::isfinite(spacing)) {
    std::ostringstream s;
    s << "sample spacing must be > 0 mm (got " << spacing << ")";
    throw GeoLatticeError(s.str());
  }
  const size_t V = g.points.size(), E = g.edges.size();
  if (g.normals.size() != V || g.vertexSubgraph.size() != V || g.edgeSubgraph.size() != E ||
      edgeGroup.size() != E) {
    throw GeoLatticeError(
        "lattice arrays do not match its points and edges (normals, sub-graph ids)");
  }
  auto checkGroup = [K](int s) {
    if (s >= K) {
      throw GeoLatticeError("lattice sub-graph id out of range");
    }
  };
  // The groups of each vertex: those of its edges, or its sub-graph's when it has none.
  std::vector<std::vector<int>> vertexGroups(V);
  std::vector<int> interior(E, 0);
  for (size_t e = 0; e < E; ++e) {
    const auto [a, b] = g.edges[e];
    if (a < 0 || b < 0 || a >= static_cast<int>(V) || b >= static_cast<int>(V)) {
      throw GeoLatticeError("lattice edge refers to a missing vertex");
    }
    checkGroup(g.edgeSubgraph[e]);
    checkGroup(edgeGroup[e]);
    const int s = edgeGroup[e];
    if (g.edgeSubgraph[e] < 0 || s < 0) {
      continue;
    }
    for (int v : {a, b}) {
      if (std::find(vertexGroups[v].begin(), vertexGroups[v].end(), s) == vertexGroups[v].end()) {
        vertexGroups[v].push_back(s);
      }
    }
    const double len = (g.points[b] - g.points[a]).norm();
    interior[e] = std::max(0, static_cast<int>(std::ceil(len / spacing)) - 1);
  }
  for (size_t v = 0; v < V; ++v) {
    checkGroup(g.vertexSubgraph[v]);
    if (vertexGroups[v].empty() && g.vertexSubgraph[v] >= 0) {
      vertexGroups[v].push_back(g.vertexSubgraph[v]);
    }
  }
  // Count per group, then fill in place (samples grouped, vertices first, then edge interiors).
  std::vector<int> count(K + 1, 0);
  for (size_t v = 0; v < V; ++v) {
    for (int s : vertexGroups[v]) {
      ++count[s + 1];
    }
  }
  for (size_t e = 0; e < E; ++e) {
    if (g.edgeSubgraph[e] >= 0 && edgeGroup[e] >= 0) {
      count[edgeGroup[e] + 1] += interior[e];
    }
  }
  MaterialSamples m;
  m.offset.assign(K + 1, 0);
  for (int s = 0; s < K; ++s) {
    m.offset[s + 1] = m.offset[s] + count[s + 1];
  }
  const size_t S = m.offset[K];
  m.points.resize(S);
  m.normals.resize(S);
  m.subgraph.resize(S);
  std::vector<int> next(m.offset.begin(), m.offset.end() - 1);
  const Vec3 up(0, 0, 1);
  for (size_t v = 0; v < V; ++v) {
    for (int s : vertexGroups[v]) {
      const int k = next[s]++;
      m.points[k] = g.points[v];
      m.normals[k] = unitOr(g.normals[v], up);
      m.subgraph[k] = s;
    }
  }
  for (size_t e = 0; e < E; ++e) {
    const int s = edgeGroup[e];
    if (g.edgeSubgraph[e] < 0 || s < 0) {
      continue;
    }
    const auto [a, b] = g.edges[e];
    for (int i = 1; i <= interior[e]; ++i) {
      const double t = static_cast<double>(i) / (interior[e] + 1);
      const int k = next[s]++;
      m.points[k] = (1 - t) * g.points[a] + t * g.points[b];
      m.normals[k] = unitOr((1 - t) * g.normals[a] + t * g.normals[b], unitOr(g.normals[a], up));
      m.subgraph[k] = s;
    }
  }
  return m;
}

}  // namespace geolattice
