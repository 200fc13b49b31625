#pragma once
/// @file SparseCholesky.h
/// @brief Factor-once, solve-many sparse symmetric positive-definite solver with a choice of
/// back end, so the GDF stage factors each matrix once and reuses it (docs/performance.md has the
/// measured comparison; CHOLMOD's supernodal factorization is the default).
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>

namespace geolattice {

enum class CholeskyBackend {
  Cholmod,     ///< SuiteSparse CHOLMOD, supernodal LL^T (default)
  EigenLDLT,   ///< Eigen::SimplicialLDLT with AMD ordering (no external library)
};

/// @class SparseCholesky
/// @brief Factorization of one SPD matrix A (only its lower triangle is read).
class SparseCholesky {
public:
  explicit SparseCholesky(CholeskyBackend backend = CholeskyBackend::Cholmod);
  ~SparseCholesky();
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;

  /// Factors A; throws GeoLatticeError (naming `what`) if A is not positive definite.
  void factorize(const Eigen::SparseMatrix<double>& A, const char* what);
  /// x = A^{-1} b. Requires a successful factorize().
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  bool factorized() const;
  CholeskyBackend backend() const { return backend_; }

private:
  struct Impl;
  CholeskyBackend backend_;
  std::unique_ptr<Impl> impl_;
};

} // namespace geolattice
