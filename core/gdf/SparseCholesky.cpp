#include "gdf/SparseCholesky.h"

#include "common/Error.h"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

#include <string>

namespace geolattice {

struct SparseCholesky::Impl {
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> cholmod;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt;
  bool ok = false;
};

SparseCholesky::SparseCholesky(CholeskyBackend backend) : backend_(backend), impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

void SparseCholesky::factorize(const Eigen::SparseMatrix<double>& A, const char* what) {
  impl_->ok = false;
  Eigen::ComputationInfo info;
  if (backend_ == CholeskyBackend::Cholmod) {
    impl_->cholmod.compute(A);
    info = impl_->cholmod.info();
  } else {
    impl_->ldlt.compute(A);
    info = impl_->ldlt.info();
    // LDLT "succeeds" on indefinite matrices; require a positive diagonal.
    if (info == Eigen::Success && (impl_->ldlt.vectorD().array() <= 0).any()) {
      info = Eigen::NumericalIssue;
    }
  }
  if (info != Eigen::Success) {
    throw GeoLatticeError(std::string("factorization of the ") + what +
                          " matrix failed: it is not positive definite (is the mesh connected and non-degenerate?)");
  }
  impl_->ok = true;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const {
  if (!impl_->ok) {
    throw GeoLatticeError("SparseCholesky::solve called before a successful factorize");
  }
  if (backend_ == CholeskyBackend::Cholmod) {
    return impl_->cholmod.solve(b);
  }
  return impl_->ldlt.solve(b);
}

bool SparseCholesky::factorized() const { return impl_->ok; }

} // namespace geolattice
