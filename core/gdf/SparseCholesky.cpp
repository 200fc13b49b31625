#include "gdf/SparseCholesky.h"

#include "common/Error.h"

#include <Eigen/SparseCholesky>
#include <cholmod.h>

#include <dlfcn.h>

#include <algorithm>
#include <future>
#include <mutex>
#include <string>
#include <vector>

namespace geolattice {

namespace {

void startCholmod(cholmod_common& c) {
  cholmod_start(&c);
  c.print = 0;                  // core never prints; failures are reported through status
  c.supernodal = CHOLMOD_AUTO;  // supernodal when flops/nnz(L) >= 40, simplicial below
  c.final_ll = 1;               // simplicial LL^T, not LDL^T: LDL^T would accept indefinite A
  c.final_asis = 1;             // keep the factor as computed (no conversion after factorizing)
  c.quick_return_if_not_posdef = 1;
}

/// Read-only CHOLMOD view of a compressed column-major matrix (no copy). stype -1: CHOLMOD reads
/// the lower triangle only.
cholmod_sparse viewLower(const Eigen::SparseMatrix<double>& A) {
  cholmod_sparse s{};
  s.nrow = static_cast<size_t>(A.rows());
  s.ncol = static_cast<size_t>(A.cols());
  s.nzmax = static_cast<size_t>(A.nonZeros());
  s.p = const_cast<int*>(A.outerIndexPtr());
  s.i = const_cast<int*>(A.innerIndexPtr());
  s.x = const_cast<double*>(A.valuePtr());
  s.stype = -1;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;  // Eigen keeps the row indices of each compressed column sorted
  s.packed = 1;
  return s;
}

cholmod_dense viewDense(const double* data, Eigen::Index rows, Eigen::Index cols) {
  cholmod_dense d{};
  d.nrow = static_cast<size_t>(rows);
  d.ncol = static_cast<size_t>(cols);
  d.nzmax = static_cast<size_t>(rows * cols);
  d.d = static_cast<size_t>(rows);
  d.x = const_cast<double*>(data);
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

/// Runs CHOLMOD's numeric factorization with its OpenMP loops on one thread. Debian's CHOLMOD
/// asks for 4 OpenMP threads in the supernodal assembly loops whatever the core count; on this
/// project's 2-core machines those threads (plus OpenBLAS's) oversubscribe the cores and spin,
/// and one thread factors the 66k-tet bunny's matrices about twice as fast (docs/performance.md).
/// A host `teams` region with thread_limit(1) caps the thread count of the parallel regions
/// inside it for this call only (OpenMP 5.0); the BLAS keeps its own threads. The body is C
/// code, so nothing is thrown out of the OpenMP region.
void factorizeWithOneOpenMPThread(cholmod_sparse* A, cholmod_factor* L, cholmod_common* common) {
#pragma omp teams num_teams(1) thread_limit(1)
  cholmod_factorize(A, L, common);
}

/// A in compressed storage: A itself, or `copy` made from it.
const Eigen::SparseMatrix<double>& compressed(const Eigen::SparseMatrix<double>& A,
                                              Eigen::SparseMatrix<double>& copy) {
  if (A.isCompressed()) {
    return A;
  }
  copy = A;
  copy.makeCompressed();
  return copy;
}

std::string cholmodStatus(int status) {
  switch (status) {
    case CHOLMOD_OUT_OF_MEMORY:
      return "out of memory";
    case CHOLMOD_TOO_LARGE:
      return "matrix too large";
    case CHOLMOD_INVALID:
      return "invalid input";
    default:
      return "CHOLMOD status " + std::to_string(status);
  }
}

}  // namespace

/// Ordering and symbolic factor of one sparsity pattern (immutable once built, shared).
struct SparseCholesky::Analysis {
  cholmod_common common;
  cholmod_factor* symbolic = nullptr;
  std::vector<int> outer, inner;  ///< the pattern analysed (compressed column storage)

  Analysis() { startCholmod(common); }
  ~Analysis() {
    cholmod_free_factor(&symbolic, &common);
    cholmod_finish(&common);
  }
  Analysis(const Analysis&) = delete;
  Analysis& operator=(const Analysis&) = delete;

  bool matches(const Eigen::SparseMatrix<double>& A) const {
    const size_t n = static_cast<size_t>(A.cols());
    return outer.size() == n + 1 && inner.size() == static_cast<size_t>(A.nonZeros()) &&
           std::equal(outer.begin(), outer.end(), A.outerIndexPtr()) &&
           std::equal(inner.begin(), inner.end(), A.innerIndexPtr());
  }
};

struct SparseCholesky::Impl {
  cholmod_common common;
  cholmod_factor* factor = nullptr;
  std::shared_ptr<const Analysis> analysis;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt;
  bool ok = false;

  Impl() { startCholmod(common); }
  ~Impl() {
    cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
};

SparseCholesky::SparseCholesky(CholeskyBackend backend)
    : backend_(backend), impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

void SparseCholesky::factorize(const Eigen::SparseMatrix<double>& Ain, const char* what) {
  impl_->ok = false;
  if (Ain.rows() != Ain.cols()) {
    throw GeoLatticeError(std::string("the ") + what + " matrix is not square (" +
                          std::to_string(Ain.rows()) + " x " + std::to_string(Ain.cols()) + ")");
  }
  Eigen::SparseMatrix<double> compressedCopy;
  const Eigen::SparseMatrix<double>& A = compressed(Ain, compressedCopy);
  if (!Eigen::Map<const Eigen::VectorXd>(A.valuePtr(), A.nonZeros()).allFinite()) {
    throw GeoLatticeError(std::string("the ") + what + " matrix contains non-finite values");
  }
  const std::string notPositiveDefinite =
      std::string("factorization of the ") + what +
      " matrix failed: it is not positive definite (is the mesh connected and non-degenerate?)";

  if (backend_ == CholeskyBackend::EigenLDLT) {
    impl_->ldlt.compute(A);
    // LDLT "succeeds" on indefinite matrices; require a positive diagonal.
    if (impl_->ldlt.info() != Eigen::Success || (impl_->ldlt.vectorD().array() <= 0).any()) {
      throw GeoLatticeError(notPositiveDefinite);
    }
    impl_->ok = true;
    return;
  }

  cholmod_sparse view = viewLower(A);
  analyze(A, what);
  // A fresh copy of the symbolic factor each time, so a failed earlier factorization leaves
  // nothing behind.
  cholmod_free_factor(&impl_->factor, &impl_->common);
  impl_->factor = cholmod_copy_factor(impl_->analysis->symbolic, &impl_->common);
  if (!impl_->factor) {
    throw GeoLatticeError(std::string("factorization of the ") + what +
                          " matrix failed: " + cholmodStatus(impl_->common.status));
  }
  factorizeWithOneOpenMPThread(&view, impl_->factor, &impl_->common);
  if (impl_->common.status == CHOLMOD_NOT_POSDEF || impl_->factor->minor < impl_->factor->n) {
    throw GeoLatticeError(notPositiveDefinite);
  }
  if (impl_->common.status < CHOLMOD_OK) {
    throw GeoLatticeError(std::string("factorization of the ") + what +
                          " matrix failed: " + cholmodStatus(impl_->common.status));
  }
  impl_->ok = true;
}

void SparseCholesky::shareAnalysis(const SparseCholesky& other) {
  if (backend_ == CholeskyBackend::Cholmod && other.backend_ == CholeskyBackend::Cholmod &&
      other.impl_->analysis) {
    impl_->analysis = other.impl_->analysis;
  }
}

void SparseCholesky::analyze(const Eigen::SparseMatrix<double>& A, const char* what) {
  if (A.rows() != A.cols()) {
    throw GeoLatticeError(std::string("the ") + what + " matrix is not square (" +
                          std::to_string(A.rows()) + " x " + std::to_string(A.cols()) + ")");
  }
  if (backend_ != CholeskyBackend::Cholmod || (impl_->analysis && impl_->analysis->matches(A))) {
    return;
  }
  Eigen::SparseMatrix<double> compressedCopy;
  const Eigen::SparseMatrix<double>& C = compressed(A, compressedCopy);
  cholmod_sparse view = viewLower(C);
  auto analysis = std::make_shared<Analysis>();
  analysis->symbolic = cholmod_analyze(&view, &analysis->common);
  if (!analysis->symbolic || analysis->common.status < CHOLMOD_OK) {
    throw GeoLatticeError(std::string("symbolic analysis of the ") + what +
                          " matrix failed: " + cholmodStatus(analysis->common.status));
  }
  analysis->outer.assign(C.outerIndexPtr(), C.outerIndexPtr() + C.cols() + 1);
  analysis->inner.assign(C.innerIndexPtr(), C.innerIndexPtr() + C.nonZeros());
  impl_->analysis = std::move(analysis);
}

double SparseCholesky::factorFlops() const {
  return impl_->analysis ? impl_->analysis->common.fl : 0.0;
}

double SparseCholesky::factorNonZeros() const {
  return impl_->analysis ? impl_->analysis->common.lnz : 0.0;
}

bool SparseCholesky::hasAnalysis() const {
  return impl_->analysis != nullptr;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const {
  return solveColumns(b);
}

Eigen::MatrixXd SparseCholesky::solveColumns(const Eigen::MatrixXd& B) const {
  if (!impl_->ok) {
    throw GeoLatticeError("SparseCholesky::solve called before a successful factorize");
  }
  if (backend_ == CholeskyBackend::EigenLDLT) {
    if (B.rows() != impl_->ldlt.rows()) {
      throw GeoLatticeError("SparseCholesky::solve: right-hand side has " +
                            std::to_string(B.rows()) + " rows, the matrix " +
                            std::to_string(impl_->ldlt.rows()));
    }
    return impl_->ldlt.solve(B);
  }
  const Eigen::Index n = static_cast<Eigen::Index>(impl_->factor->n);
  if (B.rows() != n) {
    throw GeoLatticeError("SparseCholesky::solve: right-hand side has " + std::to_string(B.rows()) +
                          " rows, the matrix " + std::to_string(n));
  }
  if (B.cols() == 0) {
    return Eigen::MatrixXd(n, 0);
  }
  cholmod_dense rhs = viewDense(B.data(), B.rows(), B.cols());
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, impl_->factor, &rhs, &impl_->common);
  if (!x) {
    throw GeoLatticeError("sparse triangular solve failed: " + cholmodStatus(impl_->common.status));
  }
  Eigen::MatrixXd X =
      Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(x->x), n, B.cols());
  cholmod_free_dense(&x, &impl_->common);
  return X;
}

bool SparseCholesky::factorized() const {
  return impl_->ok;
}

namespace {

/// OpenBLAS's thread-count functions, if the loaded BLAS is OpenBLAS (Debian's libblas.so.3
/// alternative or libopenblas.so.0); another BLAS (reference BLAS, single-threaded) has none.
struct BlasThreads {
  void (*set)(int) = nullptr;
  int (*get)() = nullptr;
  int holders = 0;  ///< live SingleThreadedBlas guards
  int saved = 1;    ///< the count before the first of them
};

std::mutex& blasMutex() {
  static std::mutex m;
  return m;
}

BlasThreads& blasThreads() {
  static BlasThreads s = [] {
    BlasThreads found;
    for (const char* library : {"libblas.so.3", "libopenblas.so.0"}) {
      void* handle = dlopen(library, RTLD_LAZY | RTLD_NOLOAD);
      if (!handle) {
        continue;
      }
      found.set = reinterpret_cast<void (*)(int)>(dlsym(handle, "openblas_set_num_threads"));
      found.get = reinterpret_cast<int (*)()>(dlsym(handle, "openblas_get_num_threads"));
      dlclose(handle);  // only drops the count taken by RTLD_NOLOAD: the library stays loaded
      if (found.set && found.get) {
        break;
      }
      found = BlasThreads{};
    }
    return found;
  }();
  return s;
}

}  // namespace

SingleThreadedBlas::SingleThreadedBlas() {
  std::lock_guard<std::mutex> lock(blasMutex());
  BlasThreads& s = blasThreads();
  if (s.holders++ == 0 && s.set && s.get) {
    s.saved = s.get();
    s.set(1);
  }
}

SingleThreadedBlas::~SingleThreadedBlas() {
  std::lock_guard<std::mutex> lock(blasMutex());
  BlasThreads& s = blasThreads();
  if (--s.holders == 0 && s.set && s.get) {
    s.set(s.saved);
  }
}

int SingleThreadedBlas::currentThreads() {
  std::lock_guard<std::mutex> lock(blasMutex());
  const BlasThreads& s = blasThreads();
  return s.get ? s.get() : 0;
}

void factorizeTogether(SparseCholesky& a, const Eigen::SparseMatrix<double>& A, const char* whatA,
                       SparseCholesky& b, const Eigen::SparseMatrix<double>& B, const char* whatB) {
  a.analyze(A, whatA);
  b.shareAnalysis(a);
  const SingleThreadedBlas blas;
  std::future<void> second =
      std::async(std::launch::async, [&b, &B, whatB] { b.factorize(B, whatB); });
  try {
    a.factorize(A, whatA);
  } catch (...) {
    second.wait();  // b and B must outlive the second thread
    throw;
  }
  second.get();
}

}  // namespace geolattice
