#pragma once
/// @file SparseCholesky.h
/// @brief Factor-once, solve-many sparse symmetric positive-definite solver with a choice of
/// back end, so the GDF stage factors each matrix once and reuses it (docs/performance.md has the
/// measured comparison; CHOLMOD is the default).
///
/// Data flow: A (lower triangle read) -> symbolic analysis (fill-reducing ordering + symbolic
/// factor; CHOLMOD only: kept and shared between solvers whose matrices have the same pattern)
/// -> numeric factorization -> solve(b) any number of times.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>

namespace geolattice {

enum class CholeskyBackend {
  Cholmod,  ///< SuiteSparse CHOLMOD LL^T, supernodal or simplicial (CHOLMOD's choice by flops/nnz)
  EigenLDLT,  ///< Eigen::SimplicialLDLT with AMD ordering (no external library)
};

/// @class SparseCholesky
/// @brief Factorization of one SPD matrix A (only its lower triangle is read).
///
/// With CHOLMOD, the ordering (CHOLMOD's default strategy: AMD, and METIS too when AMD's fill is
/// high, keeping the better) and the symbolic factor are computed once per sparsity pattern and
/// reused: by later factorize() calls on a matrix with the same pattern, and by other solvers
/// given it through shareAnalysis(). The Eigen back end analyses every matrix itself.
/// Distinct SparseCholesky objects may factorize and solve concurrently.
class SparseCholesky {
public:
  explicit SparseCholesky(CholeskyBackend backend = CholeskyBackend::Cholmod);
  ~SparseCholesky();
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;

  /// Factors A (square, #rows x #rows, compressed or not); throws GeoLatticeError (naming
  /// `what`) if A is not positive definite or not square. Reuses the symbolic analysis if it
  /// was made for exactly A's sparsity pattern, else analyses A first.
  void factorize(const Eigen::SparseMatrix<double>& A, const char* what);
  /// Makes this solver use `other`'s symbolic analysis (if it has one and both use CHOLMOD), so
  /// factorize() of a matrix with the same pattern skips the ordering. Keeps any factorization.
  void shareAnalysis(const SparseCholesky& other);
  /// True if a symbolic analysis is held (CHOLMOD only).
  bool hasAnalysis() const;
  /// CHOLMOD's estimates from the symbolic analysis: floating-point operations of a numeric
  /// factorization and non-zeros of the factor (0 without an analysis, and for Eigen).
  double factorFlops() const;
  double factorNonZeros() const;
  /// Computes and keeps the symbolic analysis of A's pattern (CHOLMOD; nothing for Eigen) unless
  /// it is held already, so that other solvers can shareAnalysis() before factorizing.
  void analyze(const Eigen::SparseMatrix<double>& A, const char* what);
  /// x = A^{-1} b (b has #rows entries). Requires a successful factorize(). Not reentrant:
  /// one object solves in one thread at a time (CHOLMOD keeps its workspace per object).
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// X = A^{-1} B for all columns of B (#rows x k) at once, faster than k solve() calls.
  Eigen::MatrixXd solveColumns(const Eigen::MatrixXd& B) const;
  bool factorized() const;
  CholeskyBackend backend() const { return backend_; }

private:
  struct Analysis;
  struct Impl;
  CholeskyBackend backend_;
  std::unique_ptr<Impl> impl_;
};

/// @class SingleThreadedBlas
/// @brief Holds OpenBLAS to one thread while at least one guard lives (process-wide, counted),
/// and gives it back its thread count after the last. For code that runs CHOLMOD factorizations
/// or supernodal solves on several threads at once: each calling a multi-threaded OpenBLAS
/// oversubscribes the cores and its threads spin (measured: two 1M-tet factorizations side by
/// side 14.3 s, 6.5 s with one BLAS thread each). The setting is process-wide: BLAS calls of
/// other threads made while a guard lives run on one thread too. Another BLAS (reference BLAS,
/// single-threaded) is left as it is.
class SingleThreadedBlas {
public:
  SingleThreadedBlas();
  ~SingleThreadedBlas();
  SingleThreadedBlas(const SingleThreadedBlas&) = delete;
  SingleThreadedBlas& operator=(const SingleThreadedBlas&) = delete;
  /// OpenBLAS's thread count now (0 if the BLAS is not OpenBLAS).
  static int currentThreads();
};

/// Factors A into `a` and B into `b` at the same time, one on the calling thread and one on a
/// second thread, with the BLAS held to one thread while both run (when it is OpenBLAS: its
/// threads would spin against each other). B must have A's sparsity pattern (`b` then shares
/// `a`'s analysis). On 2 cores two 1M-tet factorizations take 6.5 s this way instead of 8.9 s one
/// after the other (docs/performance.md). Throws as factorize() does, after both have ended
/// (A's error if both fail).
void factorizeTogether(SparseCholesky& a, const Eigen::SparseMatrix<double>& A, const char* whatA,
                       SparseCholesky& b, const Eigen::SparseMatrix<double>& B, const char* whatB);

}  // namespace geolattice
