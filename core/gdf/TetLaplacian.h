#pragma once
/// @file TetLaplacian.h
/// @brief Linear-FEM operators of a tet mesh, the set-up shared by the heat step and the three
/// Poisson solves of the GDF stage (paper Section 2.1, Eqs. 1-5).
///
/// Data flow: TetMesh -> per-tet basis gradients and volumes -> stiffness matrix K (the
/// cotangent Laplacian, sign convention: K = -L_c is positive semi-definite) and lumped vertex
/// volumes V. The gradient (Eq. 2) and integrated divergence (Eq. 4) use the same basis gradients,
/// so div(grad f) = K f holds exactly.
#include "mesh/TetMesh.h"

#include <Eigen/SparseCore>

namespace geolattice {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// @brief Per-tet FEM data and assembled matrices of a tet mesh.
struct TetOperators {
  /// basisGradients[t][k]: gradient of the hat function of local vertex k in tet t (1/mm).
  /// It is normal to the face opposite vertex k, points towards k, |.| = area/(3|T|).
  std::vector<std::array<Vec3, 4>> basisGradients;
  std::vector<double> tetVolumes;  ///< #T, |T| (mm^3), > 0
  Eigen::VectorXd vertexVolumes;   ///< #V lumped volumes, sum of |T|/4 (mm^3)
  SparseMatrix stiffness;          ///< #V x #V, K_ij = sum_T |T| grad N_i . grad N_j
  double meanEdgeLength = 0;       ///< h (mm), mean over unique edges
};

/// Assembles the operators. Throws GeoLatticeError naming the first inverted or zero-volume tet
/// (the mesh must be positively oriented) and on an empty mesh.
TetOperators buildTetOperators(const TetMesh& mesh);

/// Eq. 2: gradient of a piecewise-linear vertex field in tet t.
Vec3 tetGradient(const TetOperators& ops, const TetMesh& mesh, int t, const Eigen::VectorXd& f);

/// Eq. 4: integrated divergence b_i = sum_{T ∋ i} |T| grad N_i . g_T of a per-tet vector field,
/// so that K phi = b is the Poisson equation of Eq. 5 (phi's gradient fits g in least squares).
Eigen::VectorXd integratedDivergence(const TetOperators& ops, const TetMesh& mesh,
                                     const std::vector<Vec3>& tetField);

}  // namespace geolattice
