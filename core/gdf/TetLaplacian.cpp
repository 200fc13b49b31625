#include "gdf/TetLaplacian.h"

#include "common/Error.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <string>

namespace geolattice {

TetOperators buildTetOperators(const TetMesh& mesh) {
  const int nv = static_cast<int>(mesh.points.size());
  const int nt = static_cast<int>(mesh.tets.size());
  if (nv == 0 || nt == 0) {
    throw GeoLatticeError("empty mesh: no tetrahedra to build the Laplacian on");
  }
  TetOperators ops;
  ops.basisGradients.resize(nt);
  ops.tetVolumes.resize(nt);
  ops.vertexVolumes = Eigen::VectorXd::Zero(nv);
  std::vector<int> incidenceStart(static_cast<size_t>(nv) + 1, 0);  // vertex -> tets, counted here
  for (int t = 0; t < nt; ++t) {
    const auto& tet = mesh.tets[t];
    for (int k = 0; k < 4; ++k) {
      if (tet[k] < 0 || tet[k] >= nv) {
        throw GeoLatticeError("tet " + std::to_string(t) + " refers to vertex " +
                              std::to_string(tet[k]) + " which does not exist");
      }
    }
    const Vec3& p0 = mesh.points[tet[0]];
    Eigen::Matrix3d edges;
    edges.col(0) = mesh.points[tet[1]] - p0;
    edges.col(1) = mesh.points[tet[2]] - p0;
    edges.col(2) = mesh.points[tet[3]] - p0;
    const double volume = edges.determinant() / 6.0;
    const bool flat =
        isFlatTet(p0, mesh.points[tet[1]], mesh.points[tet[2]], mesh.points[tet[3]], volume);
    if (flat || !(volume > 0)) {
      throw GeoLatticeError(std::string(flat ? "zero-volume" : "inverted") + " tet " +
                            std::to_string(t) + " (signed volume " + std::to_string(volume) +
                            " mm^3)");
    }
    // Rows of edges^{-1} are the gradients of the barycentric coordinates 1..3.
    const Eigen::Matrix3d inv = edges.inverse();
    auto& g = ops.basisGradients[t];
    g[1] = inv.row(0).transpose();
    g[2] = inv.row(1).transpose();
    g[3] = inv.row(2).transpose();
    g[0] = -(g[1] + g[2] + g[3]);
    ops.tetVolumes[t] = volume;
    for (int i = 0; i < 4; ++i) {
      ops.vertexVolumes[tet[i]] += volume / 4.0;
      ++incidenceStart[tet[i] + 1];
    }
  }

  // K column by column from the vertex -> tet incidence (tets in increasing order), straight
  // into compressed storage: the same sums in the same order as assembling 16 triplets per tet
  // with setFromTriplets, without the 16 #T triplets and the transposed copy.
  for (int v = 0; v < nv; ++v) {
    incidenceStart[v + 1] += incidenceStart[v];
  }
  std::vector<int> incidentTets(incidenceStart[nv]);
  {
    std::vector<int> fill(incidenceStart.begin(), incidenceStart.end() - 1);
    for (int t = 0; t < nt; ++t) {
      for (int k = 0; k < 4; ++k) {
        incidentTets[fill[mesh.tets[t][k]]++] = t;
      }
    }
  }
  std::vector<int> outer(static_cast<size_t>(nv) + 1, 0);
  std::vector<int> inner;
  std::vector<double> values;
  inner.reserve(15 * static_cast<size_t>(nv));
  values.reserve(15 * static_cast<size_t>(nv));
  std::vector<int> slot(nv, -1);  // row -> position in the current column, -1 if absent
  for (int c = 0; c < nv; ++c) {
    const int begin = static_cast<int>(inner.size());
    for (int k = incidenceStart[c]; k < incidenceStart[c + 1]; ++k) {
      for (int r : mesh.tets[incidentTets[k]]) {
        if (slot[r] < 0) {
          slot[r] = 0;
          inner.push_back(r);
        }
      }
    }
    std::sort(inner.begin() + begin, inner.end());
    for (int k = begin; k < static_cast<int>(inner.size()); ++k) {
      slot[inner[k]] = k;
    }
    values.resize(inner.size(), 0.0);
    for (int k = incidenceStart[c]; k < incidenceStart[c + 1]; ++k) {
      const int t = incidentTets[k];
      const auto& tet = mesh.tets[t];
      const auto& g = ops.basisGradients[t];
      const int j = static_cast<int>(std::find(tet.begin(), tet.end(), c) - tet.begin());
      for (int i = 0; i < 4; ++i) {
        values[slot[tet[i]]] += ops.tetVolumes[t] * g[i].dot(g[j]);
      }
    }
    for (int k = begin; k < static_cast<int>(inner.size()); ++k) {
      slot[inner[k]] = -1;
    }
    outer[c + 1] = static_cast<int>(inner.size());
  }
  ops.stiffness = Eigen::Map<const SparseMatrix>(nv, nv, static_cast<Eigen::Index>(inner.size()),
                                                 outer.data(), inner.data(), values.data());

  // Mean edge length over unique edges: the off-diagonal pattern of K holds each edge twice.
  double sum = 0;
  long count = 0;
  for (int c = 0; c < ops.stiffness.outerSize(); ++c) {
    for (SparseMatrix::InnerIterator it(ops.stiffness, c); it; ++it) {
      if (it.row() < it.col()) {
        sum += (mesh.points[it.row()] - mesh.points[it.col()]).norm();
        ++count;
      }
    }
  }
  ops.meanEdgeLength = count > 0 ? sum / static_cast<double>(count) : 0.0;
  return ops;
}

Vec3 tetGradient(const TetOperators& ops, const TetMesh& mesh, int t, const Eigen::VectorXd& f) {
  const auto& g = ops.basisGradients[t];
  const auto& tet = mesh.tets[t];
  return f[tet[0]] * g[0] + f[tet[1]] * g[1] + f[tet[2]] * g[2] + f[tet[3]] * g[3];
}

Eigen::VectorXd integratedDivergence(const TetOperators& ops, const TetMesh& mesh,
                                     const std::vector<Vec3>& tetField) {
  Eigen::VectorXd b = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh.points.size()));
  for (size_t t = 0; t < mesh.tets.size(); ++t) {
    for (int k = 0; k < 4; ++k) {
      b[mesh.tets[t][k]] += ops.tetVolumes[t] * ops.basisGradients[t][k].dot(tetField[t]);
    }
  }
  return b;
}

}  // namespace geolattice
