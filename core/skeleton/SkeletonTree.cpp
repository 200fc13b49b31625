#include "skeleton/SkeletonTree.h"

#include "common/Error.h"
#include "common/Progress.h"
#include "common/UnionFind.h"
#include "mesh/TetMeshTopology.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

namespace geolattice {

namespace {

/// Barycentric coordinates of x in tet t; the smallest one tells how far inside x is.
double minBarycentric(const TetMesh& mesh, int t, const Vec3& x) {
  const auto& q = mesh.tets[t];
  const Vec3 &a = mesh.points[q[0]], &b = mesh.points[q[1]], &c = mesh.points[q[2]],
             &d = mesh.points[q[3]];
  const double vol = signedTetVolume(a, b, c, d);
  if (vol == 0) {
    return -std::numeric_limits<double>::infinity();
  }
  const double l0 = signedTetVolume(x, b, c, d) / vol, l1 = signedTetVolume(a, x, c, d) / vol,
               l2 = signedTetVolume(a, b, x, d) / vol, l3 = signedTetVolume(a, b, c, x) / vol;
  return std::min({l0, l1, l2, l3});
}

}  // namespace

SkeletonTree buildSkeletonTree(const TetMesh& mesh, const Eigen::VectorXd& gamma,
                               const std::vector<double>& phi,
                               const std::vector<SkeletonAnchor>& anchors,
                               const SkeletonTreeOptions& options) {
  const int T = static_cast<int>(mesh.tets.size());
  const int L = static_cast<int>(phi.size());
  const int K = static_cast<int>(anchors.size());
  if (T == 0) {
    throw GeoLatticeError("skeleton tree: the tet mesh is empty");
  }
  if (gamma.size() != static_cast<Eigen::Index>(mesh.points.size())) {
    throw GeoLatticeError("skeleton tree: gamma needs one value per tet-mesh point");
  }
  if (K == 0) {
    throw GeoLatticeError("skeleton tree: the lattice has no sub-graph");
  }
  for (int l = 0; l + 1 < L; ++l) {
    if (!(phi[l] < phi[l + 1])) {
      throw GeoLatticeError("skeleton tree: layer values must be strictly ascending");
    }
  }
  for (const SkeletonAnchor& a : anchors) {
    if (a.layer < 0 || a.layer >= L) {
      throw GeoLatticeError("skeleton tree: a sub-graph's layer is out of range");
    }
  }

  const ProgressReporter progress(options.progress, options.shouldAbort, "skeleton tree");
  progress.report(0.0);

  // γ range of each tet; slabs s = [phi[s], phi[s+1]], s = 0..L-2, met by the tet.
  std::vector<double> gmin(T), gmax(T);
  std::vector<int> slabBegin(T), slabEnd(T), elementOffset(T + 1, 0);
  for (int t = 0; t < T; ++t) {
    const auto& q = mesh.tets[t];
    gmin[t] = std::min({gamma[q[0]], gamma[q[1]], gamma[q[2]], gamma[q[3]]});
    gmax[t] = std::max({gamma[q[0]], gamma[q[1]], gamma[q[2]], gamma[q[3]]});
    // first s with phi[s+1] >= gmin; last s with phi[s] <= gmax.
    slabBegin[t] = L < 2 ? 0
                         : static_cast<int>(std::lower_bound(phi.begin() + 1, phi.end(), gmin[t]) -
                                            (phi.begin() + 1));
    slabEnd[t] =
        L < 2 ? 0
              : std::min(L - 1, static_cast<int>(std::upper_bound(phi.begin(), phi.end(), gmax[t]) -
                                                 phi.begin()));
    slabEnd[t] = std::max(slabEnd[t], slabBegin[t]);
    elementOffset[t + 1] = elementOffset[t] + (slabEnd[t] - slabBegin[t]);
  }
  auto element = [&](int t, int s) {
    return s >= slabBegin[t] && s < slabEnd[t] ? elementOffset[t] + (s - slabBegin[t]) : -1;
  };

  progress.report(0.05);

  // Pieces of face-adjacent tets touch iff the shared face meets the slab.
  UnionFind pieces(elementOffset[T]);
  std::unique_ptr<TetMeshTopology> ownTopology;
  if (options.topology && static_cast<int>(options.topology->neighbors().size()) != T) {
    throw GeoLatticeError("skeleton tree: the given tet adjacency is of another mesh (" +
                          std::to_string(options.topology->neighbors().size()) +
                          " tets, the mesh " + std::to_string(T) + ")");
  }
  if (!options.topology) {
    ownTopology = std::make_unique<TetMeshTopology>(mesh);
  }
  const TetMeshTopology& topology = options.topology ? *options.topology : *ownTopology;
  progress.report(0.35);
  const ProgressReporter unionProgress = progress.part(0.35, 0.65);
  for (int t = 0; t < T; ++t) {
    unionProgress.loop(t, T);
    const auto& q = mesh.tets[t];
    for (int k = 0; k < 4; ++k) {
      const int u = topology.neighbor(t, k);
      if (u <= t) {
        continue;
      }
      double fmin = std::numeric_limits<double>::infinity(), fmax = -fmin;
      for (int i = 0; i < 4; ++i) {
        if (i != k) {
          fmin = std::min(fmin, gamma[q[i]]);
          fmax = std::max(fmax, gamma[q[i]]);
        }
      }
      for (int s = std::max(slabBegin[t], slabBegin[u]); s < std::min(slabEnd[t], slabEnd[u]);
           ++s) {
        if (fmin <= phi[s + 1] && fmax >= phi[s]) {
          pieces.unite(element(t, s), element(u, s));
        }
      }
    }
  }

  progress.report(0.65);

  // Locate each anchor in a tet whose γ range contains its layer value: among the tets of
  // that layer whose bounding box contains it, the one it is deepest inside.
  std::vector<int> layerTetOffset(L + 1, 0), layerTets;
  auto layerRange = [&](int t) {
    const int lo =
        static_cast<int>(std::lower_bound(phi.begin(), phi.end(), gmin[t]) - phi.begin());
    const int hi =
        static_cast<int>(std::upper_bound(phi.begin(), phi.end(), gmax[t]) - phi.begin());
    return std::make_pair(lo, hi);  // layers [lo, hi) have gmin <= phi <= gmax
  };
  for (int t = 0; t < T; ++t) {
    const auto [lo, hi] = layerRange(t);
    for (int l = lo; l < hi; ++l) {
      ++layerTetOffset[l + 1];
    }
  }
  for (int l = 0; l < L; ++l) {
    layerTetOffset[l + 1] += layerTetOffset[l];
  }
  layerTets.resize(layerTetOffset[L]);
  {
    std::vector<int> next(layerTetOffset.begin(), layerTetOffset.end() - 1);
    for (int t = 0; t < T; ++t) {
      const auto [lo, hi] = layerRange(t);
      for (int l = lo; l < hi; ++l) {
        layerTets[next[l]++] = t;
      }
    }
  }
  progress.report(0.7);
  const ProgressReporter anchorProgress = progress.part(0.7, 0.95);
  std::vector<int> anchorTet(K, -1);
  for (int k = 0; k < K; ++k) {
    anchorProgress.loop(k, K);
    const Vec3& x = anchors[k].point;
    double best = -std::numeric_limits<double>::infinity();
    for (int i = layerTetOffset[anchors[k].layer]; i < layerTetOffset[anchors[k].layer + 1]; ++i) {
      const int t = layerTets[i];
      const auto& q = mesh.tets[t];
      Vec3 lo = mesh.points[q[0]], hi = lo;
      for (int j = 1; j < 4; ++j) {
        lo = lo.cwiseMin(mesh.points[q[j]]);
        hi = hi.cwiseMax(mesh.points[q[j]]);
      }
      const Vec3 pad = 1e-6 * (hi - lo) + Vec3::Constant(1e-9);
      if ((x.array() < (lo - pad).array()).any() || (x.array() > (hi + pad).array()).any()) {
        continue;
      }
      const double b = minBarycentric(mesh, t, x);
      if (b > best) {
        best = b;
        anchorTet[k] = t;
      }
    }
    if (anchorTet[k] < 0 || best < -1e-6) {
      std::ostringstream s;
      s << "skeleton tree: sub-graph " << k << " (layer " << anchors[k].layer
        << ") lies in no tet of the mesh whose gamma range contains the layer value; are the "
           "lattice and the tet mesh"
           " from the same part?";
      throw GeoLatticeError(s.str());
    }
  }

  progress.report(0.95);

  std::vector<int> label;
  SkeletonTree tree;
  tree.slabComponents = pieces.labels(label);
  tree.layerValues = phi;
  tree.nodes.resize(K);
  for (int k = 0; k < K; ++k) {
    tree.nodes[k].layer = anchors[k].layer;
  }
  // Per slab s: component of each node of layer s (above it) and of layer s+1 (below it).
  std::vector<std::pair<long long, int>> below, above;  // (component, node)
  for (int k = 0; k < K; ++k) {
    const int t = anchorTet[k], l = anchors[k].layer;
    if (l + 1 < L) {
      below.push_back({label[element(t, l)], k});  // node sits under slab l
    }
    if (l >= 1) {
      above.push_back({label[element(t, l - 1)], k});  // node sits over slab l-1
    }
  }
  std::sort(below.begin(), below.end());
  std::sort(above.begin(), above.end());
  for (size_t i = 0, j = 0; i < below.size();) {
    size_t i2 = i;
    while (i2 < below.size() && below[i2].first == below[i].first) {
      ++i2;
    }
    while (j < above.size() && above[j].first < below[i].first) {
      ++j;
    }
    for (size_t j2 = j; j2 < above.size() && above[j2].first == below[i].first; ++j2) {
      for (size_t a = i; a < i2; ++a) {
        tree.edges.push_back({below[a].second, above[j2].second});
      }
    }
    i = i2;
  }
  linkSkeletonEdges(tree);
  progress.report(1.0);
  return tree;
}

void linkSkeletonEdges(SkeletonTree& tree) {
  std::sort(tree.edges.begin(), tree.edges.end());
  for (SkeletonNode& n : tree.nodes) {
    n.lower.clear();
    n.upper.clear();
  }
  for (const auto& e : tree.edges) {
    tree.nodes[e[0]].upper.push_back(e[1]);
    tree.nodes[e[1]].lower.push_back(e[0]);
  }
  int firstLayer = std::numeric_limits<int>::max();
  for (const SkeletonNode& n : tree.nodes) {
    firstLayer = std::min(firstLayer, n.layer);
  }
  tree.roots = tree.floatingNodes = tree.mergeNodes = tree.splitNodes = 0;
  for (SkeletonNode& n : tree.nodes) {
    std::sort(n.lower.begin(), n.lower.end());
    std::sort(n.upper.begin(), n.upper.end());
    tree.roots += n.lower.empty();
    tree.floatingNodes += n.lower.empty() && n.layer > firstLayer;
    tree.mergeNodes += n.lower.size() > 1;
    tree.splitNodes += n.upper.size() > 1;
  }
}

SkeletonTree buildSkeletonTree(const TetMesh& mesh, const Eigen::VectorXd& gamma,
                               const LatticeGraph& lattice, const SkeletonTreeOptions& options) {
  const int K = static_cast<int>(lattice.subgraphs.size());
  if (K == 0) {
    throw GeoLatticeError("skeleton tree: the lattice has no sub-graph");
  }
  // Anchor: the vertex of each sub-graph nearest to its centroid (any vertex would do).
  std::vector<SkeletonAnchor> anchors(K);
  std::vector<double> bestDistance(K, std::numeric_limits<double>::infinity());
  for (size_t v = 0; v < lattice.points.size(); ++v) {
    const int s = lattice.vertexSubgraph[v];
    if (s < 0 || s >= K) {
      continue;
    }
    const double d = (lattice.points[v] - lattice.subgraphs[s].centroid).squaredNorm();
    if (d < bestDistance[s]) {
      bestDistance[s] = d;
      anchors[s].point = lattice.points[v];
    }
  }
  for (int s = 0; s < K; ++s) {
    if (!std::isfinite(bestDistance[s])) {
      throw GeoLatticeError("skeleton tree: a lattice sub-graph has no vertex");
    }
    anchors[s].layer = lattice.subgraphs[s].layer;
  }
  SkeletonTree tree = buildSkeletonTree(mesh, gamma, lattice.layerValues, anchors, options);
  for (int s = 0; s < K; ++s) {
    tree.nodes[s].indexInLayer = lattice.subgraphs[s].indexInLayer;
    tree.nodes[s].centroid = lattice.subgraphs[s].centroid;
    tree.nodes[s].length = lattice.subgraphs[s].length;
  }
  return tree;
}

SkeletonAncestry::SkeletonAncestry(const SkeletonTree& tree) {
  const int K = static_cast<int>(tree.nodes.size());
  const size_t words = (static_cast<size_t>(K) + 63) / 64;
  bits_.assign(K, std::vector<unsigned long long>(words, 0));
  std::vector<int> byLayer(K);
  for (int k = 0; k < K; ++k) {
    byLayer[k] = k;
  }
  std::stable_sort(byLayer.begin(), byLayer.end(),
                   [&](int a, int b) { return tree.nodes[a].layer < tree.nodes[b].layer; });
  for (int b : byLayer) {  // lower nodes are one layer down, so they are complete already
    for (int a : tree.nodes[b].lower) {
      for (size_t w = 0; w < words; ++w) {
        bits_[b][w] |= bits_[a][w];
      }
      bits_[b][a >> 6] |= 1ull << (a & 63);
    }
  }
}

void validateSkeletonTree(const SkeletonTree& tree) {
  const int K = static_cast<int>(tree.nodes.size());
  if (K == 0) {
    throw GeoLatticeError("skeleton tree is empty");
  }
  std::vector<std::vector<int>> lower(K), upper(K);
  for (const auto& e : tree.edges) {
    if (e[0] < 0 || e[1] < 0 || e[0] >= K || e[1] >= K) {
      throw GeoLatticeError("skeleton tree: an edge refers to a missing node");
    }
    // Edges join consecutive layers upwards: then the graph is acyclic by construction.
    if (tree.nodes[e[1]].layer != tree.nodes[e[0]].layer + 1) {
      std::ostringstream s;
      s << "skeleton tree: cyclic or missing adjacency: edge " << e[0] << " - " << e[1]
        << " joins layers " << tree.nodes[e[0]].layer << " and " << tree.nodes[e[1]].layer
        << " (must be consecutive, lower first)";
      throw GeoLatticeError(s.str());
    }
    upper[e[0]].push_back(e[1]);
    lower[e[1]].push_back(e[0]);
  }
  for (int k = 0; k < K; ++k) {
    std::sort(lower[k].begin(), lower[k].end());
    std::sort(upper[k].begin(), upper[k].end());
    if (lower[k] != tree.nodes[k].lower || upper[k] != tree.nodes[k].upper) {
      std::ostringstream s;
      s << "skeleton tree: the lower/upper lists of node " << k << " do not match the edges";
      throw GeoLatticeError(s.str());
    }
  }
}

}  // namespace geolattice
