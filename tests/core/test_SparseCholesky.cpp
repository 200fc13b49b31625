// SparseCholesky: both back ends, the shared CHOLMOD analysis, multi-column solves, bad input.
#include "common/Error.h"
#include "gdf/SparseCholesky.h"

#include "../common/ErrorOf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace geolattice;
using SpMat = Eigen::SparseMatrix<double>;

namespace {

/// 5-point Laplacian of an m x m grid plus shift * I (SPD for shift > 0), full symmetric storage.
SpMat gridMatrix(int m, double shift) {
  std::vector<Eigen::Triplet<double>> t;
  auto id = [m](int i, int j) {
    return i * m + j;
  };
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) {
      t.emplace_back(id(i, j), id(i, j), 4.0 + shift);
      if (i + 1 < m) {
        t.emplace_back(id(i, j), id(i + 1, j), -1.0);
        t.emplace_back(id(i + 1, j), id(i, j), -1.0);
      }
      if (j + 1 < m) {
        t.emplace_back(id(i, j), id(i, j + 1), -1.0);
        t.emplace_back(id(i, j + 1), id(i, j), -1.0);
      }
    }
  }
  SpMat A(m * m, m * m);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

double relativeResidual(const SpMat& A, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  return (A * x - b).norm() / b.norm();
}

class SparseCholeskyBackends : public ::testing::TestWithParam<CholeskyBackend> {};

}  // namespace

TEST_P(SparseCholeskyBackends, SolvesAnSpdSystemFromItsLowerTriangle) {
  const SpMat A = gridMatrix(30, 0.01);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 2.0);
  SparseCholesky solver(GetParam());
  EXPECT_FALSE(solver.factorized());
  const SpMat lower = A.triangularView<Eigen::Lower>();  // only the lower triangle is read
  solver.factorize(lower, "grid");
  ASSERT_TRUE(solver.factorized());
  EXPECT_LT(relativeResidual(A, solver.solve(b), b), 1e-12);
  // The full symmetric matrix gives the same solution.
  SparseCholesky full(GetParam());
  full.factorize(A, "grid");
  EXPECT_LT((full.solve(b) - solver.solve(b)).lpNorm<Eigen::Infinity>(), 1e-12);
}

TEST_P(SparseCholeskyBackends, SolveColumnsMatchesSingleSolves) {
  const SpMat A = gridMatrix(20, 0.5);
  SparseCholesky solver(GetParam());
  solver.factorize(A, "grid");
  Eigen::MatrixXd B(A.rows(), 3);
  B.col(0) = Eigen::VectorXd::LinSpaced(A.rows(), 0.0, 1.0);
  B.col(1) = Eigen::VectorXd::Ones(A.rows());
  B.col(2) = Eigen::VectorXd::LinSpaced(A.rows(), 3.0, -7.0);
  const Eigen::MatrixXd X = solver.solveColumns(B);
  ASSERT_EQ(X.rows(), A.rows());
  ASSERT_EQ(X.cols(), 3);
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT((X.col(k) - solver.solve(B.col(k))).lpNorm<Eigen::Infinity>(), 1e-13) << k;
    EXPECT_LT(relativeResidual(A, X.col(k), B.col(k)), 1e-12) << k;
  }
}

TEST_P(SparseCholeskyBackends, RejectsIndefiniteNonSquareAndNonFiniteMatrices) {
  SparseCholesky solver(GetParam());
  SpMat indefinite = gridMatrix(6, 0.1);
  indefinite.coeffRef(10, 10) = -3.0;
  try {
    solver.factorize(indefinite, "test-indefinite");
    FAIL() << "an indefinite matrix was accepted";
  } catch (const GeoLatticeError& e) {
    EXPECT_NE(std::string(e.what()).find("test-indefinite"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(solver.factorized());
  EXPECT_THROW(solver.solve(Eigen::VectorXd::Ones(36)), GeoLatticeError);

  EXPECT_THROW(solver.factorize(SpMat(4, 5), "rectangular"), GeoLatticeError);
  SpMat nonFinite = gridMatrix(4, 1.0);
  nonFinite.coeffRef(3, 3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(solver.factorize(nonFinite, "nan"), GeoLatticeError);

  // A good matrix after the failures factors and solves normally.
  const SpMat A = gridMatrix(6, 0.1);
  solver.factorize(A, "good");
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(36);
  EXPECT_LT(relativeResidual(A, solver.solve(b), b), 1e-12);
  EXPECT_THROW(solver.solve(Eigen::VectorXd::Ones(35)), GeoLatticeError);
}

TEST_P(SparseCholeskyBackends, FactorizedTogetherSolvesAsOneAfterTheOther) {
  const SpMat A = gridMatrix(70, 0.01);  // large enough for CHOLMOD's supernodal factor
  SpMat B = A;
  B *= 2.0;
  B.diagonal().array() += 0.5;  // same pattern, other values
  SparseCholesky a(GetParam()), b(GetParam());
  factorizeTogether(a, A, "A", b, B, "B");
  ASSERT_TRUE(a.factorized());
  ASSERT_TRUE(b.factorized());
  SparseCholesky alone(GetParam());
  alone.factorize(B, "B alone");
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(A.rows(), -2.0, 3.0);
  EXPECT_LT(relativeResidual(A, a.solve(rhs), rhs), 1e-12);
  EXPECT_LT(relativeResidual(B, b.solve(rhs), rhs), 1e-12);
  EXPECT_LT((b.solve(rhs) - alone.solve(rhs)).lpNorm<Eigen::Infinity>(),
            1e-12 * alone.solve(rhs).lpNorm<Eigen::Infinity>());

  // A failure on either thread is thrown, naming its matrix, after both have ended.
  SpMat indefinite = B;
  indefinite.coeffRef(100, 100) = -3.0;
  SparseCholesky c(GetParam()), d(GetParam());
  std::string error = expectedErrorOf(
      [&] { factorizeTogether(c, A, "first", d, indefinite, "second-indefinite"); });
  EXPECT_NE(error.find("second-indefinite"), std::string::npos) << error;
  EXPECT_FALSE(d.factorized());
  error = expectedErrorOf(
      [&] { factorizeTogether(c, indefinite, "first-indefinite", d, A, "second"); });
  EXPECT_NE(error.find("first-indefinite"), std::string::npos) << error;
  EXPECT_FALSE(c.factorized());
  EXPECT_TRUE(d.factorized());
}

TEST(SparseCholesky, TheBlasIsHeldToOneThreadWhileAGuardLivesAndGivenBackAfter) {
  const int before = SingleThreadedBlas::currentThreads();
  if (before == 0) {
    GTEST_SKIP() << "the loaded BLAS is not OpenBLAS: nothing to hold";
  }
  {
    const SingleThreadedBlas outer;
    EXPECT_EQ(SingleThreadedBlas::currentThreads(), 1);
    {
      const SingleThreadedBlas inner;  // nested (another solver's): still one
      EXPECT_EQ(SingleThreadedBlas::currentThreads(), 1);
    }
    EXPECT_EQ(SingleThreadedBlas::currentThreads(), 1);  // the outer guard still lives
  }
  EXPECT_EQ(SingleThreadedBlas::currentThreads(), before);
  const SpMat A = gridMatrix(20, 0.1);
  SparseCholesky a, b;
  factorizeTogether(a, A, "A", b, A, "B");
  EXPECT_EQ(SingleThreadedBlas::currentThreads(), before);
}

INSTANTIATE_TEST_SUITE_P(Backends, SparseCholeskyBackends,
                         ::testing::Values(CholeskyBackend::Cholmod, CholeskyBackend::EigenLDLT),
                         [](const ::testing::TestParamInfo<CholeskyBackend>& info) {
                           return info.param == CholeskyBackend::Cholmod ? "Cholmod" : "EigenLDLT";
                         });

TEST(SparseCholesky, SharedAnalysisIsReusedForTheSamePatternOnly) {
  const SpMat A = gridMatrix(25, 0.01);
  SpMat B = A;
  B *= 3.0;
  B.diagonal().array() += 1.0;  // same pattern, other values
  SparseCholesky first;
  EXPECT_FALSE(first.hasAnalysis());
  first.factorize(A, "A");
  EXPECT_TRUE(first.hasAnalysis());

  SparseCholesky second;
  second.shareAnalysis(first);
  EXPECT_TRUE(second.hasAnalysis());
  second.factorize(B, "B");
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), 1.0, 5.0);
  EXPECT_LT(relativeResidual(B, second.solve(b), b), 1e-12);
  EXPECT_LT(relativeResidual(A, first.solve(b), b), 1e-12);  // untouched by the sharing

  // A matrix with another pattern (and size) is analysed afresh.
  const SpMat C = gridMatrix(12, 0.2);
  second.factorize(C, "C");
  const Eigen::VectorXd c = Eigen::VectorXd::Ones(C.rows());
  EXPECT_LT(relativeResidual(C, second.solve(c), c), 1e-12);
  EXPECT_LT(relativeResidual(A, first.solve(b), b), 1e-12);

  // Same size, different pattern: an extra off-diagonal pair.
  SpMat D = A;
  D.coeffRef(0, A.rows() - 1) = -0.5;
  D.coeffRef(A.rows() - 1, 0) = -0.5;
  SparseCholesky third;
  third.shareAnalysis(first);
  third.factorize(D, "D");
  EXPECT_LT(relativeResidual(D, third.solve(b), b), 1e-12);

  // Sharing from / into the Eigen back end is a no-op.
  SparseCholesky eigen(CholeskyBackend::EigenLDLT);
  eigen.shareAnalysis(first);
  EXPECT_FALSE(eigen.hasAnalysis());
  eigen.factorize(B, "B");
  EXPECT_LT(relativeResidual(B, eigen.solve(b), b), 1e-12);
}

TEST(SparseCholesky, MovedSolverKeepsItsFactorization) {
  const SpMat A = gridMatrix(10, 0.3);
  SparseCholesky solver;
  solver.factorize(A, "A");
  SparseCholesky moved(std::move(solver));
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
  ASSERT_TRUE(moved.factorized());
  EXPECT_LT(relativeResidual(A, moved.solve(b), b), 1e-12);
}
