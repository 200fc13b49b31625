#include "slicer/CurvedLayerSlicer.h"

#include "common/Error.h"
#include "mesh/TetMeshCheck.h"
#include "common/Progress.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace geolattice {

namespace {

constexpr int kTetEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

/// Local edge index of the tet edge (i, j), i != j.
int localEdge(int i, int j) {
  if (i > j) {
    std::swap(i, j);
  }
  static constexpr int table[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};
  return table[i][j];
}

/// Gradient of the linear interpolant of f over tet (p0..p3).
Vec3 linearGradient(const TetMesh& mesh, const std::array<int, 4>& t, const Eigen::VectorXd& f,
                    double* volume) {
  const Vec3& p0 = mesh.points[t[0]];
  Eigen::Matrix3d edges;
  edges.row(0) = (mesh.points[t[1]] - p0).transpose();
  edges.row(1) = (mesh.points[t[2]] - p0).transpose();
  edges.row(2) = (mesh.points[t[3]] - p0).transpose();
  const double det = edges.determinant();
  if (volume) {
    *volume = std::abs(det) / 6.0;
  }
  if (det == 0) {
    return Vec3::Zero();
  }
  const Vec3 df(f[t[1]] - f[t[0]], f[t[2]] - f[t[0]], f[t[3]] - f[t[0]]);
  return edges.partialPivLu().solve(df);
}

/// Unique edges of the mesh (a < b), in (a, b) order, and, per tet, the id of each of its six
/// local edges. A counting sort on a, then a short sort of each vertex's list on b: linear in
/// the tets (a full sort of the 6 #T edge records took 1.1 s of the 1M-tet slicing).
void uniqueEdges(const TetMesh& mesh, std::vector<std::array<int, 2>>& edges,
                 std::vector<std::array<int, 6>>& tetEdges) {
  struct Rec {
    int b, slot;
  };
  const size_t nv = mesh.points.size();
  std::vector<int> start(nv + 1, 0);
  for (const auto& tet : mesh.tets) {
    for (const auto& e : kTetEdges) {
      ++start[std::min(tet[e[0]], tet[e[1]]) + 1];
    }
  }
  for (size_t v = 0; v < nv; ++v) {
    start[v + 1] += start[v];
  }
  std::vector<Rec> recs(6 * mesh.tets.size());
  {
    std::vector<int> cursor(start.begin(), start.end() - 1);
    for (size_t t = 0; t < mesh.tets.size(); ++t) {
      for (int k = 0; k < 6; ++k) {
        const int a = mesh.tets[t][kTetEdges[k][0]], b = mesh.tets[t][kTetEdges[k][1]];
        recs[cursor[std::min(a, b)]++] = {std::max(a, b), static_cast<int>(6 * t + k)};
      }
    }
  }
  tetEdges.resize(mesh.tets.size());
  edges.clear();
  for (size_t a = 0; a < nv; ++a) {
    const auto begin = recs.begin() + start[a], end = recs.begin() + start[a + 1];
    std::sort(begin, end, [](const Rec& x, const Rec& y) { return x.b < y.b; });
    for (auto it = begin; it != end; ++it) {
      if (it == begin || it->b != (it - 1)->b) {
        edges.push_back({static_cast<int>(a), it->b});
      }
      tetEdges[it->slot / 6][it->slot % 6] = static_cast<int>(edges.size() - 1);
    }
  }
}

void validate(const TetMesh& mesh, const Eigen::VectorXd& gamma, const Eigen::VectorXd& alpha,
              const Eigen::VectorXd& beta, const std::vector<Vec3>& normals,
              const SlicerOptions& o) {
  if (mesh.tets.empty() || mesh.points.empty()) {
    throw GeoLatticeError("empty mesh: nothing to slice");
  }
  const auto n = static_cast<Eigen::Index>(mesh.points.size());
  if (gamma.size() != n || alpha.size() != n || beta.size() != n ||
      static_cast<Eigen::Index>(normals.size()) != n) {
    throw GeoLatticeError("slicer fields must have one value per mesh vertex (" +
                          std::to_string(n) + ")");
  }
  if (!gamma.allFinite()) {
    throw GeoLatticeError("γ has non-finite values");
  }
  requireTetVertexIndicesInRange(mesh);  // uniqueEdges writes by vertex index
  o.validate();
}

}  // namespace

void SlicerOptions::validate() const {
  if (!(this->interval > 0) || !std::isfinite(this->interval)) {
    throw GeoLatticeError("layer interval must be > 0 mm (got " + std::to_string(this->interval) +
                          ")");
  }
  if (!(this->firstLayerOffset > 0) || !std::isfinite(this->firstLayerOffset)) {
    throw GeoLatticeError("first layer offset must be > 0 mm (got " +
                          std::to_string(this->firstLayerOffset) + ")");
  }
  requireValidWorkLimit(this->maxElements, "the layer size limit");
  if (this->firstLayer < 0 || (this->lastLayer >= 0 && this->lastLayer < this->firstLayer)) {
    throw GeoLatticeError("invalid layer range [" + std::to_string(this->firstLayer) + ", " +
                          std::to_string(this->lastLayer) + "]");
  }
}

int layerCount(double gammaMax, const SlicerOptions& o) {
  if (!(o.interval > 0) || gammaMax < o.firstLayerOffset) {
    return 0;
  }
  int n = static_cast<int>(std::floor((gammaMax - o.firstLayerOffset) / o.interval)) + 1;
  // Guard the floor against rounding: φ_{n-1} <= γ_max < φ_n with φ computed as layerValue().
  while (n > 0 && layerValue(n - 1, o) > gammaMax) {
    --n;
  }
  while (layerValue(n, o) <= gammaMax) {
    ++n;
  }
  return n;
}

std::vector<Vec3> vertexGradientDirections(const TetMesh& mesh, const Eigen::VectorXd& f) {
  std::vector<Vec3> sum(mesh.points.size(), Vec3::Zero());
  for (const auto& t : mesh.tets) {
    double volume = 0;
    const Vec3 g = linearGradient(mesh, t, f, &volume);
    for (int v : t) {
      sum[v] += volume * g;
    }
  }
  for (Vec3& s : sum) {
    const double len = s.norm();
    s = len > 0 ? Vec3(s / len) : Vec3::Zero();
  }
  return sum;
}

CurvedLayers sliceCurvedLayers(const TetMesh& mesh, const Eigen::VectorXd& gamma,
                               const Eigen::VectorXd& alpha, const Eigen::VectorXd& beta,
                               const std::vector<Vec3>& vertexNormals,
                               const SlicerOptions& options) {
  validate(mesh, gamma, alpha, beta, vertexNormals, options);
  const ProgressReporter progress(options.progress, options.shouldAbort, "curved layer slicing");
  progress.report(0.0);
  const int total = layerCount(gamma.maxCoeff(), options);
  if (total == 0) {
    throw GeoLatticeError(
        "no layer: the first layer offset (" + std::to_string(options.firstLayerOffset) +
        " mm) is above the largest γ (" + std::to_string(gamma.maxCoeff()) + " mm)");
  }
  const int first = options.firstLayer;
  const int last = options.lastLayer < 0 ? total - 1 : std::min(options.lastLayer, total - 1);
  if (first > last) {
    throw GeoLatticeError("layer range starts at " + std::to_string(first) +
                          " but there are only " + std::to_string(total) + " layers");
  }
  const int L = last - first + 1;
  auto phi = [&](int i) {
    return layerValue(i, options);
  };
  // Smallest layer index i >= first with φ_i > x (exactly, with φ computed by phi()).
  auto firstAbove = [&](double x) {
    int i = static_cast<int>(std::floor((x - options.firstLayerOffset) / options.interval)) + 1;
    i = std::max(i, first);
    while (i > first && phi(i - 1) > x) {
      --i;
    }
    while (i <= last && phi(i) <= x) {
      ++i;
    }
    return i;
  };

  std::vector<std::array<int, 2>> edges;
  std::vector<std::array<int, 6>> tetEdges;
  uniqueEdges(mesh, edges, tetEdges);
  progress.report(0.15);

  // Points: edge crossings γ(a) < φ_i < γ(b) get slots edgeOffset[e] + (i - edgeFirst[e]);
  // vertices with γ == φ_i get one slot each.
  const int ne = static_cast<int>(edges.size());
  {
    // Count first, in 64 bits: the slots below are int, and a tiny interval would overflow them.
    long long crossings = 0;
    for (int e = 0; e < ne; ++e) {
      crossings += std::max(
          0, std::min(firstAbove(std::max(gamma[edges[e][0]], gamma[edges[e][1]])), last + 1) -
                 firstAbove(std::min(gamma[edges[e][0]], gamma[edges[e][1]])));
    }
    std::ostringstream because;
    because << "in " << L << " layers at a layer interval of " << options.interval << " mm";
    requireWithinWorkLimit(3.0 * static_cast<double>(crossings), options.maxElements,
                           "curved layer slicing", "layer points and triangles", because.str(),
                           "use a larger layer interval or raise the size limit (MaximumElements)");
  }
  std::vector<int> edgeFirst(ne), edgeOffset(ne + 1, 0);
  for (int e = 0; e < ne; ++e) {
    const double lo = std::min(gamma[edges[e][0]], gamma[edges[e][1]]);
    const double hi = std::max(gamma[edges[e][0]], gamma[edges[e][1]]);
    const int i0 = firstAbove(lo);
    const int i1 = firstAbove(hi);  // layers in [i0, i1) cross strictly: lo < φ <= hi minus φ == hi
    int count = std::max(0, std::min(i1, last + 1) - i0);
    if (count > 0 && phi(i0 + count - 1) == hi) {
      --count;  // that crossing is the vertex hit at the upper end
    }
    edgeFirst[e] = i0;
    edgeOffset[e + 1] = edgeOffset[e] + count;
  }
  const int edgePoints = edgeOffset[ne];
  std::vector<int> vertexSlot(mesh.points.size(), -1);
  std::vector<int> vertexLayer;
  int slots = edgePoints;
  for (size_t v = 0; v < mesh.points.size(); ++v) {
    const int i = firstAbove(gamma[v]) - 1;  // largest i with φ_i <= γ
    if (i >= first && i <= last && phi(i) == gamma[v]) {
      vertexSlot[v] = slots++;
    }
  }

  // Positions and interpolated fields of every slot.
  std::vector<Vec3> position(slots);
  std::vector<std::array<int, 2>> slotEdge(slots);
  std::vector<double> slotT(slots);
  std::vector<int> slotLayer(slots);
  for (int e = 0; e < ne; ++e) {
    int a = edges[e][0], b = edges[e][1];
    if (gamma[a] > gamma[b]) {
      std::swap(a, b);
    }
    for (int s = edgeOffset[e]; s < edgeOffset[e + 1]; ++s) {
      const int i = edgeFirst[e] + (s - edgeOffset[e]);
      const double t = (phi(i) - gamma[a]) / (gamma[b] - gamma[a]);
      position[s] = (1 - t) * mesh.points[a] + t * mesh.points[b];
      slotEdge[s] = {a, b};
      slotT[s] = t;
      slotLayer[s] = i - first;
    }
  }
  for (size_t v = 0; v < mesh.points.size(); ++v) {
    if (vertexSlot[v] >= 0) {
      const int s = vertexSlot[v];
      position[s] = mesh.points[v];
      slotEdge[s] = {static_cast<int>(v), static_cast<int>(v)};
      slotT[s] = 0;
      slotLayer[s] = firstAbove(gamma[v]) - 1 - first;
    }
  }

  progress.report(0.3);

  // Triangles: per tet, per crossing layer, 1 (3-1 split) or 2 (2-2 split), oriented along ∇γ.
  const ProgressReporter triangleProgress = progress.part(0.3, 0.85);
  CurvedLayers out;
  struct Tri {
    std::array<int, 3> v;
    int layer;
  };
  std::vector<Tri> tris;
  tris.reserve(2 * mesh.tets.size());
  for (size_t t = 0; t < mesh.tets.size(); ++t) {
    triangleProgress.loop(t, mesh.tets.size());
    const auto& tet = mesh.tets[t];
    double gmin = gamma[tet[0]], gmax = gmin;
    for (int k = 1; k < 4; ++k) {
      gmin = std::min(gmin, gamma[tet[k]]);
      gmax = std::max(gmax, gamma[tet[k]]);
    }
    const int i0 = firstAbove(gmin);
    const int i1 = std::min(firstAbove(gmax) - 1, last);  // layers with gmin < φ_i <= gmax
    if (i0 > i1) {
      continue;
    }
    const Vec3 grad = linearGradient(mesh, tet, gamma, nullptr);
    for (int i = i0; i <= i1; ++i) {
      const double value = phi(i);
      int above[4], below[4], na = 0, nb = 0;
      for (int k = 0; k < 4; ++k) {
        if (gamma[tet[k]] >= value) {
          above[na++] = k;
        } else {
          below[nb++] = k;
        }
      }
      // The layer point on the tet edge from local vertex lo (below) to hi (above).
      auto point = [&](int lo, int hi) {
        const int v = tet[hi];
        if (gamma[v] == value) {
          return vertexSlot[v];
        }
        const int e = tetEdges[t][localEdge(lo, hi)];
        return edgeOffset[e] + (i - edgeFirst[e]);
      };
      std::array<int, 3> tri[2];
      int count = 0;
      if (na == 1) {
        tri[count++] = {point(below[0], above[0]), point(below[1], above[0]),
                        point(below[2], above[0])};
      } else if (nb == 1) {
        tri[count++] = {point(below[0], above[0]), point(below[0], above[1]),
                        point(below[0], above[2])};
      } else if (na == 2) {
        // Quad p00 p01 p11 p10 (cyclic around the tet), split on the p00-p11 diagonal.
        const int p00 = point(below[0], above[0]), p01 = point(below[0], above[1]);
        const int p11 = point(below[1], above[1]), p10 = point(below[1], above[0]);
        tri[count++] = {p00, p01, p11};
        tri[count++] = {p00, p11, p10};
      }
      for (int c = 0; c < count; ++c) {
        auto& f = tri[c];
        if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) {
          ++out.droppedDegenerateTriangles;  // collapsed onto exact vertex hits
          continue;
        }
        const Vec3 n = (position[f[1]] - position[f[0]]).cross(position[f[2]] - position[f[0]]);
        if (n.dot(grad) < 0) {
          std::swap(f[1], f[2]);
        }
        tris.push_back({f, i - first});
      }
    }
  }

  progress.report(0.85);

  // A mesh face lying in a layer is emitted by both of its tets when both lie on the same side
  // (the layer only touches it): drop both copies. Only all-vertex-hit triangles can repeat.
  {
    std::vector<std::pair<std::array<int, 3>, size_t>> faceTris;
    for (size_t k = 0; k < tris.size(); ++k) {
      const auto& v = tris[k].v;
      if (v[0] >= edgePoints && v[1] >= edgePoints && v[2] >= edgePoints) {
        auto key = v;
        std::sort(key.begin(), key.end());
        faceTris.emplace_back(key, k);
      }
    }
    std::sort(faceTris.begin(), faceTris.end());
    std::vector<char> drop(tris.size(), 0);
    for (size_t k = 0; k + 1 < faceTris.size(); ++k) {
      if (faceTris[k].first == faceTris[k + 1].first) {
        drop[faceTris[k].second] = drop[faceTris[k + 1].second] = 1;
      }
    }
    size_t w = 0;
    for (size_t k = 0; k < tris.size(); ++k) {
      if (!drop[k]) {
        tris[w++] = tris[k];
      } else {
        ++out.droppedDuplicateFaces;
      }
    }
    tris.resize(w);
  }

  // Group triangles by layer (stable counting sort), then number points by first use.
  out.layerTriangleOffset.assign(L + 1, 0);
  for (const Tri& f : tris) {
    ++out.layerTriangleOffset[f.layer + 1];
  }
  for (int l = 0; l < L; ++l) {
    out.layerTriangleOffset[l + 1] += out.layerTriangleOffset[l];
  }
  out.triangles.resize(tris.size());
  out.triangleLayer.resize(tris.size());
  {
    std::vector<int> cursor(out.layerTriangleOffset.begin(), out.layerTriangleOffset.end() - 1);
    for (const Tri& f : tris) {
      const int k = cursor[f.layer]++;
      out.triangles[k] = f.v;
      out.triangleLayer[k] = f.layer;
    }
  }
  std::vector<int> newIndex(slots, -1);
  std::vector<int> order;
  order.reserve(slots);
  for (auto& f : out.triangles) {
    for (int& v : f) {
      if (newIndex[v] < 0) {
        newIndex[v] = static_cast<int>(order.size());
        order.push_back(v);
      }
      v = newIndex[v];
    }
  }
  const size_t np = order.size();
  out.points.resize(np);
  out.alpha.resize(np);
  out.beta.resize(np);
  out.normals.resize(np);
  out.pointLayer.resize(np);
  out.sourceEdge.resize(np);
  out.edgeParameter.resize(np);
  out.layerPointOffset.assign(L + 1, 0);
  for (size_t k = 0; k < np; ++k) {
    const int s = order[k];
    const auto [a, b] = slotEdge[s];
    const double t = slotT[s];
    out.points[k] = position[s];
    out.alpha[k] = (1 - t) * alpha[a] + t * alpha[b];
    out.beta[k] = (1 - t) * beta[a] + t * beta[b];
    const Vec3 n = (1 - t) * vertexNormals[a] + t * vertexNormals[b];
    out.normals[k] = n.norm() > 0 ? Vec3(n.normalized()) : n;
    out.pointLayer[k] = slotLayer[s];
    out.sourceEdge[k] = slotEdge[s];
    out.edgeParameter[k] = t;
    ++out.layerPointOffset[slotLayer[s] + 1];
  }
  for (int l = 0; l < L; ++l) {
    out.layerPointOffset[l + 1] += out.layerPointOffset[l];
  }
  out.layerValues.resize(L);
  out.layerIndex.resize(L);
  for (int l = 0; l < L; ++l) {
    out.layerIndex[l] = first + l;
    out.layerValues[l] = phi(first + l);
  }
  progress.report(1.0);
  return out;
}

}  // namespace geolattice
