#include "gdf/GeodesicDistanceFields.h"

#include "common/Error.h"
#include "common/Progress.h"
#include "common/UnionFind.h"
#include "mesh/TetMeshTopology.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <sstream>
#include <chrono>
#include <cmath>
#include <future>
#include <limits>
#include <numeric>
#include <queue>
#include <string>

namespace geolattice {

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Vertex components of the mesh by union-find over tet vertices.
int vertexComponents(const TetMesh& mesh, std::vector<int>& component) {
  UnionFind sets(static_cast<int>(mesh.points.size()));
  for (const auto& t : mesh.tets) {
    for (int k = 1; k < 4; ++k) {
      sets.unite(t[0], t[k]);
    }
  }
  return sets.labels(component);
}

/// Lower triangle of the symmetric K with every diagonal entry stored (first in its column,
/// 0 if K has none). The heat, pinned and Dirichlet matrices all use this one pattern, so
/// CHOLMOD orders and analyses it once (SparseCholesky::shareAnalysis).
SparseMatrix lowerWithDiagonal(const SparseMatrix& K) {
  const int n = static_cast<int>(K.cols());
  std::vector<int> outer(static_cast<size_t>(n) + 1, 0);
  std::vector<int> inner;
  std::vector<double> values;
  inner.reserve(static_cast<size_t>(K.nonZeros() / 2 + n));
  values.reserve(inner.capacity());
  for (int c = 0; c < n; ++c) {
    inner.push_back(c);
    values.push_back(0.0);
    for (SparseMatrix::InnerIterator it(K, c); it; ++it) {
      if (it.row() == c) {
        values.back() = it.value();
      } else if (it.row() > c) {
        inner.push_back(static_cast<int>(it.row()));
        values.push_back(it.value());
      }
    }
    outer[c + 1] = static_cast<int>(inner.size());
  }
  SparseMatrix L = Eigen::Map<const SparseMatrix>(n, n, static_cast<Eigen::Index>(inner.size()),
                                                  outer.data(), inner.data(), values.data());
  return L;
}

/// In place on a lowerWithDiagonal() matrix: rows and columns with fixed[i] become those of a
/// positive multiple of the identity (entries kept as explicit zeros, so the pattern does not
/// change). Solving with b_i = 0 on those rows gives x_i = 0 exactly and the other entries
/// of x solve the principal sub-system of the free rows: the Dirichlet / pinned problem.
void fixRows(SparseMatrix& L, const std::vector<char>& fixed) {
  const int n = static_cast<int>(L.cols());
  const int* outer = L.outerIndexPtr();
  const int* inner = L.innerIndexPtr();
  double* values = L.valuePtr();
  for (int c = 0; c < n; ++c) {
    const int begin = outer[c];
    if (fixed[c]) {
      values[begin] = values[begin] > 0 ? values[begin] : 1.0;  // keep K's scale on the diagonal
      std::fill(values + begin + 1, values + outer[c + 1], 0.0);
    } else {
      for (int k = begin + 1; k < outer[c + 1]; ++k) {
        if (fixed[inner[k]]) {
          values[k] = 0.0;
        }
      }
    }
  }
}

std::vector<char> indexMask(size_t n, const std::vector<int>& indices) {
  std::vector<char> mask(n, 0);
  for (int i : indices) {
    mask[i] = 1;
  }
  return mask;
}

/// Gives every tet with valid[t] == 0 a unit vector from its already-valid face neighbours
/// (breadth first, so the gaps fill from their rims), projected orthogonal to normal[t] when a
/// normal field is given. Returns the number of tets still invalid (isolated regions).
int fillFromNeighbours(std::vector<Vec3>& field, std::vector<char>& valid,
                       const TetMeshTopology& topology, const std::vector<Vec3>* normal) {
  const int nt = static_cast<int>(field.size());
  std::queue<int> queue;
  std::vector<char> queued(nt, 0);
  auto pushInvalidNeighbours = [&](int t) {
    for (int k = 0; k < 4; ++k) {
      const int n = topology.neighbor(t, k);
      if (n >= 0 && !valid[n] && !queued[n]) {
        queued[n] = 1;
        queue.push(n);
      }
    }
  };
  for (int t = 0; t < nt; ++t) {
    if (valid[t]) {
      pushInvalidNeighbours(t);
    }
  }
  int remaining = static_cast<int>(std::count(valid.begin(), valid.end(), 0));
  while (!queue.empty()) {
    const int t = queue.front();
    queue.pop();
    Vec3 sum = Vec3::Zero();
    for (int k = 0; k < 4; ++k) {
      const int n = topology.neighbor(t, k);
      if (n >= 0 && valid[n]) {
        sum += field[n];
      }
    }
    if (normal) {
      sum -= sum.dot((*normal)[t]) * (*normal)[t];
    }
    if (sum.norm() > 1e-12) {
      field[t] = sum.normalized();
      valid[t] = 1;
      --remaining;
      pushInvalidNeighbours(t);
    }
  }
  return remaining;
}

double angleDeviationDeg(const Vec3& a, const Vec3& b) {
  const double na = a.norm(), nb = b.norm();
  if (na == 0 || nb == 0) {
    return 90.0;
  }
  const double c = std::clamp(a.dot(b) / (na * nb), -1.0, 1.0);
  return std::abs(90.0 - std::acos(c) * 180.0 / M_PI);
}

double percentile(std::vector<double> values, double q) {
  if (values.empty()) {
    return 0;
  }
  const size_t k = std::min(values.size() - 1,
                            static_cast<size_t>(q * static_cast<double>(values.size() - 1) + 0.5));
  std::nth_element(values.begin(), values.begin() + static_cast<long>(k), values.end());
  return values[k];
}

}  // namespace

void GeodesicFieldOptions::validate() const {
  if (!(this->timeFactor > 0) || !std::isfinite(this->timeFactor)) {
    throw GeoLatticeError("heat time factor must be > 0 (got " + std::to_string(this->timeFactor) +
                          ")");
  }
  if (!(this->reference.norm() > 0) || !this->reference.allFinite()) {
    throw GeoLatticeError("reference vector r must be non-zero and finite");
  }
  if (!(this->referenceParallelDeg >= 0 && this->referenceParallelDeg < 90)) {
    throw GeoLatticeError("reference parallel angle must be in [0, 90) degrees (got " +
                          std::to_string(this->referenceParallelDeg) + ")");
  }
}

GeodesicDistanceFields::GeodesicDistanceFields(TetMesh mesh, const GeodesicFieldOptions& options)
    : mesh_(std::move(mesh)),
      options_(options),
      heat_(options.backend),
      pinnedLaplacian_(options.backend),
      dirichletLaplacian_(options.backend) {
  options_.validate();
  const ProgressReporter progress(options_.progress, options_.shouldAbort,
                                  "geodesic distance fields");
  progress.report(0.0);
  auto start = Clock::now();
  ops_ = buildTetOperators(mesh_);  // also checks the vertex indices the topology relies on
  // The tet adjacency is needed only by solve() and by callers; build it on a second thread
  // while this one assembles and factors. (If this constructor throws, the future's
  // destructor waits for the thread before the members go.)
  std::future<void> topologyDone = std::async(
      std::launch::async, [this] { topology_ = std::make_unique<TetMeshTopology>(mesh_); });
  componentCount_ = vertexComponents(mesh_, component_);
  // The pinned vertex of a component is its lowest one: a base vertex in the default source
  // selection, so that the Dirichlet γ can reuse the pinned factor (prepareDirichlet).
  pinned_.assign(componentCount_, -1);
  for (size_t v = 0; v < component_.size(); ++v) {
    int& p = pinned_[component_[v]];
    if (p < 0 || mesh_.points[v].z() < mesh_.points[p].z()) {
      p = static_cast<int>(v);
    }
  }
  heatTime_ = options_.timeFactor * ops_.meanEdgeLength * ops_.meanEdgeLength;
  // All three matrices share the pattern of K's lower triangle (see lowerWithDiagonal).
  SparseMatrix heatMatrix = lowerWithDiagonal(ops_.stiffness);
  SparseMatrix pinnedK = heatMatrix;
  fixRows(pinnedK, indexMask(mesh_.points.size(), pinned_));
  // Eq. 1 multiplied by V: (V + t K) u = V u0, symmetric positive definite.
  {
    double* values = heatMatrix.valuePtr();
    for (Eigen::Index k = 0; k < heatMatrix.nonZeros(); ++k) {
      values[k] = heatTime_ * values[k];
    }
    for (Eigen::Index c = 0; c < heatMatrix.cols(); ++c) {
      values[heatMatrix.outerIndexPtr()[c]] += ops_.vertexVolumes[c];  // diagonal: first in column
    }
  }
  setupTimings_.assembly = secondsSince(start);
  progress.report(0.15);

  start = Clock::now();
  if (options_.factorTogether) {
    factorizeTogether(heat_, heatMatrix, "heat (V + tK)", pinnedLaplacian_, pinnedK,
                      "pinned Laplacian");
  } else {
    heat_.factorize(heatMatrix, "heat (V + tK)");
    progress.report(0.55);
    pinnedLaplacian_.shareAnalysis(heat_);
    pinnedLaplacian_.factorize(pinnedK, "pinned Laplacian");
  }
  dirichletLaplacian_.shareAnalysis(heat_);
  setupTimings_.factorization = secondsSince(start);
  progress.report(0.95);

  start = Clock::now();
  topologyDone.get();
  setupTimings_.assembly += secondsSince(start);
  progress.report(1.0);
}

GeodesicDistanceFields::~GeodesicDistanceFields() = default;

void GeodesicDistanceFields::setReference(const Vec3& reference) {
  if (!(reference.norm() > 0) || !reference.allFinite()) {
    throw GeoLatticeError("reference vector r must be non-zero and finite");
  }
  options_.reference = reference;
}

void GeodesicDistanceFields::startComponentsAtZero(Eigen::VectorXd& f) const {
  std::vector<double> minimum(componentCount_, std::numeric_limits<double>::infinity());
  for (Eigen::Index v = 0; v < f.size(); ++v) {
    minimum[component_[v]] = std::min(minimum[component_[v]], f[v]);
  }
  for (Eigen::Index v = 0; v < f.size(); ++v) {
    f[v] -= minimum[component_[v]];
  }
}

void GeodesicDistanceFields::prepareDirichlet(const std::vector<int>& sources,
                                              const std::vector<char>& isSource,
                                              GeodesicFieldTimings& timings) {
  auto start = Clock::now();
  DirichletCorrection& c = dirichletCorrection_;
  auto clear = [&c] {  // (the LLT keeps its last factor, unused while inactive)
    c.active = false;
    c.constrained.clear();
    c.Z.resize(0, 0);
  };
  clear();
  // K_D (source rows and columns identity) differs from the pinned K_P only in the rows and
  // columns of the m sources that are not pinned, if every pinned vertex is a source. Then
  // K_D x = b is K_P x + E λ = b with E^T x = 0 (E: those sources' identity columns; λ their
  // reactions): x = y - Z λ with y = K_P^-1 b, Z = K_P^-1 E and (E^T Z) λ = E^T y. That costs m
  // solves with the pinned factor instead of a factorization: taken when m * (4 flops per factor
  // non-zero) is below half the factorization's flops, and Z stays under kMaxCorrectionEntries.
  constexpr double kMaxCorrectionEntries = 2e7;  // 160 MB of Z (solved 16 columns at a time)
  const bool pinnedAreSources =
      std::all_of(pinned_.begin(), pinned_.end(), [&](int p) { return isSource[p] != 0; });
  if (pinnedAreSources) {
    const std::vector<char> isPinned = indexMask(mesh_.points.size(), pinned_);
    for (int s : sources) {
      if (!isPinned[s]) {
        c.constrained.push_back(s);
      }
    }
  }
  const double n = static_cast<double>(mesh_.points.size());
  const double m = static_cast<double>(c.constrained.size());
  const double flops = pinnedLaplacian_.factorFlops();
  if (pinnedAreSources && flops > 0 && 4.0 * m * pinnedLaplacian_.factorNonZeros() < 0.5 * flops &&
      n * m <= kMaxCorrectionEntries) {
    const Eigen::Index mi = static_cast<Eigen::Index>(c.constrained.size());
    const Eigen::Index ni = static_cast<Eigen::Index>(n);
    // Z in blocks of columns, so that E and the solver's result stay small beside Z.
    constexpr Eigen::Index kBlock = 16;
    c.Z.resize(ni, mi);
    for (Eigen::Index k0 = 0; k0 < mi; k0 += kBlock) {
      const Eigen::Index w = std::min(kBlock, mi - k0);
      Eigen::MatrixXd E = Eigen::MatrixXd::Zero(ni, w);
      for (Eigen::Index k = 0; k < w; ++k) {
        E(c.constrained[k0 + k], k) = 1.0;
      }
      c.Z.middleCols(k0, w) = pinnedLaplacian_.solveColumns(E);
    }
    Eigen::MatrixXd capacitance(mi, mi);
    for (Eigen::Index i = 0; i < mi; ++i) {
      capacitance.row(i) = c.Z.row(c.constrained[i]);
    }
    c.capacitance.compute(0.5 * (capacitance + capacitance.transpose()));
    if (c.capacitance.info() == Eigen::Success) {
      c.active = true;
      timings.factorization += secondsSince(start);
      return;
    }
    clear();  // not positive definite to rounding: factor K_D instead
  }
  SparseMatrix K = lowerWithDiagonal(ops_.stiffness);
  fixRows(K, isSource);
  timings.assembly += secondsSince(start);
  start = Clock::now();
  dirichletLaplacian_.factorize(K, "Dirichlet Laplacian");  // the heat matrix's ordering
  timings.factorization += secondsSince(start);
}

Eigen::VectorXd GeodesicDistanceFields::solveDirichlet(const Eigen::VectorXd& b) const {
  const DirichletCorrection& c = dirichletCorrection_;
  if (!c.active) {
    return dirichletLaplacian_.solve(b);
  }
  Eigen::VectorXd x = pinnedLaplacian_.solve(b);  // x_p = b_p = 0 on the pinned sources
  if (!c.constrained.empty()) {
    Eigen::VectorXd yConstrained(static_cast<Eigen::Index>(c.constrained.size()));
    for (size_t i = 0; i < c.constrained.size(); ++i) {
      yConstrained[static_cast<Eigen::Index>(i)] = x[c.constrained[i]];
    }
    x -= c.Z * c.capacitance.solve(yConstrained);
  }
  return x;
}

GeodesicFields GeodesicDistanceFields::solve(const std::vector<int>& sourcesIn) {
  const size_t nv = mesh_.points.size();
  const int nt = static_cast<int>(mesh_.tets.size());
  if (sourcesIn.empty()) {
    throw GeoLatticeError("empty source set: no base vertices were selected for the γ field");
  }
  std::vector<int> sources = sourcesIn;
  std::sort(sources.begin(), sources.end());
  sources.erase(std::unique(sources.begin(), sources.end()), sources.end());
  if (sources.front() < 0 || sources.back() >= static_cast<int>(nv)) {
    throw GeoLatticeError("source vertex index out of range (mesh has " + std::to_string(nv) +
                          " vertices)");
  }
  std::vector<char> componentHasSource(componentCount_, 0);
  for (int s : sources) {
    componentHasSource[component_[s]] = 1;
  }
  const int without =
      static_cast<int>(std::count(componentHasSource.begin(), componentHasSource.end(), 0));
  if (without > 0) {
    // In the words of a print: a body with no base vertex does not stand on the plate (the
    // sources are the base), so no layer can grow into it. Name the lowest such body.
    double base = std::numeric_limits<double>::infinity();
    for (int s : sources) {
      base = std::min(base, mesh_.points[s].z());
    }
    double lowest = std::numeric_limits<double>::infinity();
    for (size_t v = 0; v < nv; ++v) {
      if (!componentHasSource[component_[v]]) {
        lowest = std::min(lowest, mesh_.points[v].z());
      }
    }
    std::ostringstream m;
    m << "the part has " << componentCount_ << " separate bodies and " << without
      << (without == 1 ? " of them does" : " of them do")
      << " not touch the base the layers grow from (no source vertex: γ is undefined there; "
         "the lowest such body starts "
      << (lowest - base)
      << " mm above the base): stand every body on the build plate, print the bodies one at a "
         "time, or let the automatic orientation look for a side on which they all stand";
    throw GeoLatticeError(m.str());
  }

  const ProgressReporter progress(options_.progress, options_.shouldAbort,
                                  "geodesic distance fields");
  progress.report(0.0);
  GeodesicFields out;
  out.timings = setupTimings_;

  // Dirichlet Laplacian for γ: set up once per source set.
  const std::vector<char> isSource = indexMask(nv, sources);
  if (options_.dirichletGamma && sources != dirichletSources_) {
    dirichletSources_.clear();  // stays clear if the set-up throws
    prepareDirichlet(sources, isSource, out.timings);
    dirichletSources_ = sources;
  }
  out.dirichletFromPinned = options_.dirichletGamma && dirichletCorrection_.active;
  progress.report(0.4);

  const auto start = Clock::now();
  // Eq. 1: heat step from the sources.
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nv));
  for (int s : sources) {
    rhs[s] = ops_.vertexVolumes[s];
  }
  const Eigen::VectorXd u = heat_.solve(rhs);
  progress.report(0.5);

  // Eq. 2: g_γ = -∇u / |∇u| (heat decreases away from the base, γ increases).
  out.gammaDirection.resize(nt);
  std::vector<char> valid(nt, 1);
  for (int t = 0; t < nt; ++t) {
    const Vec3 g = -tetGradient(ops_, mesh_, t, u);
    const double len = g.norm();
    if (len > 0 && std::isfinite(len)) {
      out.gammaDirection[t] = g / len;
    } else {
      valid[t] = 0;
      out.gammaDirection[t] = Vec3::Zero();
      ++out.zeroHeatGradientTets;
    }
  }
  if (out.zeroHeatGradientTets > 0 &&
      fillFromNeighbours(out.gammaDirection, valid, *topology_, nullptr) > 0) {
    throw GeoLatticeError(
        "the heat gradient vanished in a whole region of the mesh; increase the heat time factor");
  }

  // Eqs. 4-5 for γ: K γ = b with γ = 0 on the sources (or pinned, then shifted to start at 0).
  {
    Eigen::VectorXd b = integratedDivergence(ops_, mesh_, out.gammaDirection);
    if (options_.dirichletGamma) {
      for (int s : sources) {
        b[s] = 0;
      }
      out.gamma = solveDirichlet(b);
      for (int s : sources) {
        out.gamma[s] = 0;  // exact already up to rounding; stated for the reader
      }
    } else {
      for (int p : pinned_) {
        b[p] = 0;
      }
      out.gamma = pinnedLaplacian_.solve(b);
      startComponentsAtZero(out.gamma);
    }
  }
  progress.report(0.65);

  if (options_.directionsFromSolvedGamma) {
    // The layer normal is ∇γ of the solved field, not the raw heat gradient: near Neumann
    // boundaries (where ∇u -> 0) the heat direction is noisy while ∇γ stays smooth.
    // Where ∇γ vanishes (a tet with all four vertices on the base) the heat direction stays.
    for (int t = 0; t < nt; ++t) {
      const Vec3 g = tetGradient(ops_, mesh_, t, out.gamma);
      const double len = g.norm();
      if (len > 0 && std::isfinite(len)) {
        out.gammaDirection[t] = g / len;
      }
    }
  }

  // Eq. 3: g_α = r × g_γ / |r × g_γ|, g_β = g_α × g_γ.
  Vec3 r = options_.reference.normalized();
  const double minSin = std::sin(options_.referenceParallelDeg * M_PI / 180.0);
  auto alongGamma = [&](const Vec3& c) {  // tets where c × g_γ is too short for Eq. 3
    int n = 0;
    for (int t = 0; t < nt; ++t) {
      const double len = c.cross(out.gammaDirection[t]).norm();
      n += !(len > minSin && len > 0);
    }
    return n;
  };
  if (options_.turnReference) {
    const int given = alongGamma(r);
    if (given > kReferenceTurnShare * nt) {
      // The horizontal unit c least along the layer normals, Σ (c·g_γ)² smallest over the tets:
      // the eigenvector of the smallest eigenvalue of Σ g_xy g_xyᵀ.
      Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
      for (int t = 0; t < nt; ++t) {
        const Eigen::Vector2d g = out.gammaDirection[t].head<2>();
        m += g * g.transpose();
      }
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(m);
      const Vec3 c(eigen.eigenvectors()(0, 0), eigen.eigenvectors()(1, 0), 0.0);
      if (alongGamma(c) < given) {
        r = c.normalized();
        out.referenceTurned = true;
        out.givenReferenceFallbackTets = given;
      }
    }
  }
  out.reference = r;
  out.alphaDirection.resize(nt);
  std::fill(valid.begin(), valid.end(), 1);
  for (int t = 0; t < nt; ++t) {
    const Vec3 a = r.cross(out.gammaDirection[t]);
    const double len = a.norm();
    if (len > minSin && len > 0) {
      out.alphaDirection[t] = a / len;
    } else {
      valid[t] = 0;
      out.alphaDirection[t] = Vec3::Zero();
      ++out.referenceFallbackTets;
    }
  }
  if (out.referenceFallbackTets > 0 &&
      fillFromNeighbours(out.alphaDirection, valid, *topology_, &out.gammaDirection) > 0) {
    // Whole regions with g_γ ∥ r: use the coordinate axis least aligned with r there.
    Eigen::Index axis;
    r.cwiseAbs().minCoeff(&axis);
    const Vec3 r2 = Vec3::Unit(axis);
    for (int t = 0; t < nt; ++t) {
      if (!valid[t]) {
        out.alphaDirection[t] = r2.cross(out.gammaDirection[t]).normalized();
      }
    }
  }
  out.betaDirection.resize(nt);
  for (int t = 0; t < nt; ++t) {
    // Re-orthogonalise g_α against g_γ (propagated vectors are only projected once).
    Vec3& a = out.alphaDirection[t];
    const Vec3& g = out.gammaDirection[t];
    a = (a - a.dot(g) * g).normalized();
    out.betaDirection[t] = a.cross(g);
  }

  progress.report(0.75);

  // Eqs. 4-5 for α and β with one pinned vertex per component.
  {
    Eigen::MatrixXd b(static_cast<Eigen::Index>(nv), 2);
    b.col(0) = integratedDivergence(ops_, mesh_, out.alphaDirection);
    b.col(1) = integratedDivergence(ops_, mesh_, out.betaDirection);
    for (int p : pinned_) {
      b.row(p).setZero();
    }
    const Eigen::MatrixXd x = pinnedLaplacian_.solveColumns(b);
    out.alpha = x.col(0);
    out.beta = x.col(1);
    for (int p : pinned_) {
      out.alpha[p] = out.beta[p] = 0;
    }
  }
  // α and β are defined up to a constant per component: start each component at 0.
  startComponentsAtZero(out.alpha);
  startComponentsAtZero(out.beta);

  progress.report(0.9);

  // How orthogonal the solved fields are (the per-tet targets are orthogonal by construction).
  // Tets whose four vertices are all sources have ∇γ = 0 and are left out.
  std::vector<double> devAlpha, devBeta;
  devAlpha.reserve(nt);
  devBeta.reserve(nt);
  for (int t = 0; t < nt; ++t) {
    const Vec3 gg = tetGradient(ops_, mesh_, t, out.gamma);
    if (gg.norm() > 0) {
      devAlpha.push_back(angleDeviationDeg(tetGradient(ops_, mesh_, t, out.alpha), gg));
      devBeta.push_back(angleDeviationDeg(tetGradient(ops_, mesh_, t, out.beta), gg));
    }
  }
  out.orthogonalityDeviationDeg = {percentile(devAlpha, 0.5), percentile(devAlpha, 0.95),
                                   percentile(devBeta, 0.5), percentile(devBeta, 0.95)};
  out.timings.solve = secondsSince(start);
  progress.report(1.0);
  return out;
}

GeodesicFields computeGeodesicDistanceFields(const TetMesh& mesh, const std::vector<int>& sources,
                                             const GeodesicFieldOptions& options) {
  GeodesicDistanceFields solver(mesh, options);
  return solver.solve(sources);
}

}  // namespace geolattice
