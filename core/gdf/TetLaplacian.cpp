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
  Eigen::AlignedBox3d box;
  for (const Vec3& p : mesh.points) {
    box.extend(p);
  }
  const double diag = box.diagonal().norm();
  const double minVolume = 1e-12 * diag * diag * diag;

  TetOperators ops;
  ops.basisGradients.resize(nt);
  ops.tetVolumes.resize(nt);
  ops.vertexVolumes = Eigen::VectorXd::Zero(nv);
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(16 * static_cast<size_t>(nt));
  for (int t = 0; t < nt; ++t) {
    const auto& tet = mesh.tets[t];
    for (int k = 0; k < 4; ++k) {
      if (tet[k] < 0 || tet[k] >= nv) {
        throw GeoLatticeError("tet " + std::to_string(t) + " refers to vertex " + std::to_string(tet[k]) +
                              " which does not exist");
      }
    }
    const Vec3& p0 = mesh.points[tet[0]];
    Eigen::Matrix3d edges;
    edges.col(0) = mesh.points[tet[1]] - p0;
    edges.col(1) = mesh.points[tet[2]] - p0;
    edges.col(2) = mesh.points[tet[3]] - p0;
    const double volume = edges.determinant() / 6.0;
    if (!(volume > minVolume)) {
      throw GeoLatticeError(std::string(volume < 0 ? "inverted" : "zero-volume") + " tet " + std::to_string(t) +
                            " (signed volume " + std::to_string(volume) + " mm^3)");
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
      for (int j = 0; j < 4; ++j) {
        triplets.emplace_back(tet[i], tet[j], volume * g[i].dot(g[j]));
      }
    }
  }
  ops.stiffness.resize(nv, nv);
  ops.stiffness.setFromTriplets(triplets.begin(), triplets.end());
  ops.stiffness.makeCompressed();

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

} // namespace geolattice
