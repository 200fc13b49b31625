#include "gdf/GeodesicDistanceFields.h"

#include "common/Error.h"
#include "mesh/TetMeshTopology.h"

#include <algorithm>
#include <chrono>
#include <cmath>
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
  std::vector<int> parent(mesh.points.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while (parent[v] != v) {
      parent[v] = parent[parent[v]];
      v = parent[v];
    }
    return v;
  };
  for (const auto& t : mesh.tets) {
    for (int k = 1; k < 4; ++k) {
      const int a = find(t[0]), b = find(t[k]);
      if (a != b) {
        parent[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  component.assign(mesh.points.size(), -1);
  std::vector<int> label(mesh.points.size(), -1);
  int count = 0;
  for (size_t v = 0; v < mesh.points.size(); ++v) {
    const int r = find(static_cast<int>(v));
    if (label[r] < 0) {
      label[r] = count++;
    }
    component[v] = label[r];
  }
  return count;
}

/// The principal sub-matrix of A on the rows/columns with keep[i]; reduced[i] maps old -> new.
SparseMatrix restrictMatrix(const SparseMatrix& A, const std::vector<int>& reduced, int n) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(A.nonZeros());
  for (int c = 0; c < A.outerSize(); ++c) {
    if (reduced[c] < 0) {
      continue;
    }
    for (SparseMatrix::InnerIterator it(A, c); it; ++it) {
      if (reduced[it.row()] >= 0 && it.row() >= c) { // lower triangle is all the solvers read
        triplets.emplace_back(reduced[it.row()], reduced[c], it.value());
      }
    }
  }
  SparseMatrix R(n, n);
  R.setFromTriplets(triplets.begin(), triplets.end());
  R.makeCompressed();
  return R;
}

/// Reduced index map for "all vertices except `fixed`"; returns the reduced size.
int freeIndexMap(size_t nv, const std::vector<int>& fixed, std::vector<int>& reduced) {
  reduced.assign(nv, 0);
  for (int f : fixed) {
    reduced[f] = -1;
  }
  int n = 0;
  for (size_t i = 0; i < nv; ++i) {
    if (reduced[i] == 0) {
      reduced[i] = n++;
    }
  }
  return n;
}

/// Solves K x = b with x = 0 on the removed vertices, given the factorization of the reduced K.
Eigen::VectorXd solveReduced(const SparseCholesky& solver, const std::vector<int>& reduced, int n,
                             const Eigen::VectorXd& b) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  if (n == 0) {
    return x;
  }
  Eigen::VectorXd rb(n);
  for (Eigen::Index i = 0; i < b.size(); ++i) {
    if (reduced[i] >= 0) {
      rb[reduced[i]] = b[i];
    }
  }
  const Eigen::VectorXd rx = solver.solve(rb);
  for (Eigen::Index i = 0; i < b.size(); ++i) {
    if (reduced[i] >= 0) {
      x[i] = rx[reduced[i]];
    }
  }
  return x;
}

/// Gives every tet with valid[t] == 0 a unit vector from its already-valid face neighbours
/// (breadth first, so the gaps fill from their rims), projected orthogonal to normal[t] when a
/// normal field is given. Returns the number of tets still invalid (isolated regions).
int fillFromNeighbours(std::vector<Vec3>& field, std::vector<char>& valid, const TetMeshTopology& topology,
                       const std::vector<Vec3>* normal) {
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
  const size_t k = std::min(values.size() - 1, static_cast<size_t>(q * static_cast<double>(values.size() - 1) + 0.5));
  std::nth_element(values.begin(), values.begin() + static_cast<long>(k), values.end());
  return values[k];
}

void validate(const GeodesicFieldOptions& o) {
  if (!(o.timeFactor > 0) || !std::isfinite(o.timeFactor)) {
    throw GeoLatticeError("heat time factor must be > 0 (got " + std::to_string(o.timeFactor) + ")");
  }
  if (!(o.reference.norm() > 0) || !o.reference.allFinite()) {
    throw GeoLatticeError("reference vector r must be non-zero and finite");
  }
  if (!(o.referenceParallelDeg >= 0 && o.referenceParallelDeg < 90)) {
    throw GeoLatticeError("reference parallel angle must be in [0, 90) degrees (got " +
                          std::to_string(o.referenceParallelDeg) + ")");
  }
}

} // namespace

GeodesicDistanceFields::GeodesicDistanceFields(TetMesh mesh, const GeodesicFieldOptions& options)
    : mesh_(std::move(mesh)), options_(options), heat_(options.backend), pinnedLaplacian_(options.backend),
      dirichletLaplacian_(options.backend) {
  validate(options_);
  auto start = Clock::now();
  ops_ = buildTetOperators(mesh_);
  topology_ = std::make_unique<TetMeshTopology>(mesh_);
  componentCount_ = vertexComponents(mesh_, component_);
  pinned_.assign(componentCount_, -1);
  for (size_t v = 0; v < component_.size(); ++v) {
    if (pinned_[component_[v]] < 0) {
      pinned_[component_[v]] = static_cast<int>(v);
    }
  }
  heatTime_ = options_.timeFactor * ops_.meanEdgeLength * ops_.meanEdgeLength;
  // Eq. 1 multiplied by V: (V + t K) u = V u0, symmetric positive definite.
  SparseMatrix heatMatrix = heatTime_ * ops_.stiffness;
  for (Eigen::Index i = 0; i < heatMatrix.rows(); ++i) {
    heatMatrix.coeffRef(i, i) += ops_.vertexVolumes[i];
  }
  std::vector<int> reduced;
  const int n = freeIndexMap(mesh_.points.size(), pinned_, reduced);
  const SparseMatrix pinnedK = restrictMatrix(ops_.stiffness, reduced, n);
  setupTimings_.assembly = secondsSince(start);

  start = Clock::now();
  heat_.factorize(heatMatrix, "heat (V + tK)");
  if (n > 0) {
    pinnedLaplacian_.factorize(pinnedK, "pinned Laplacian");
  }
  setupTimings_.factorization = secondsSince(start);
}

GeodesicDistanceFields::~GeodesicDistanceFields() = default;

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
    throw GeoLatticeError("source vertex index out of range (mesh has " + std::to_string(nv) + " vertices)");
  }
  std::vector<char> componentHasSource(componentCount_, 0);
  for (int s : sources) {
    componentHasSource[component_[s]] = 1;
  }
  const int without = static_cast<int>(std::count(componentHasSource.begin(), componentHasSource.end(), 0));
  if (without > 0) {
    throw GeoLatticeError("the tet mesh has " + std::to_string(componentCount_) + " connected components and " +
                          std::to_string(without) + " of them contain no source vertex (γ is undefined there)");
  }

  GeodesicFields out;
  out.timings = setupTimings_;

  // Dirichlet Laplacian for γ: factor once per source set.
  std::vector<int> dirichletReduced;
  const int nd = freeIndexMap(nv, sources, dirichletReduced);
  if (sources != dirichletSources_ || !dirichletLaplacian_.factorized()) {
    auto start = Clock::now();
    const SparseMatrix K = restrictMatrix(ops_.stiffness, dirichletReduced, nd);
    const double t0 = secondsSince(start);
    start = Clock::now();
    dirichletSources_.clear();
    if (nd > 0) {
      dirichletLaplacian_.factorize(K, "Dirichlet Laplacian");
    }
    dirichletSources_ = sources;
    out.timings.assembly += t0;
    out.timings.factorization += secondsSince(start);
  }

  const auto start = Clock::now();
  // Eq. 1: heat step from the sources.
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nv));
  for (int s : sources) {
    rhs[s] = ops_.vertexVolumes[s];
  }
  const Eigen::VectorXd u = heat_.solve(rhs);

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
  if (out.zeroHeatGradientTets > 0 && fillFromNeighbours(out.gammaDirection, valid, *topology_, nullptr) > 0) {
    throw GeoLatticeError("the heat gradient vanished in a whole region of the mesh; increase the heat time factor");
  }

  // Eqs. 4-5 for γ: K γ = b with γ = 0 on the sources.
  out.gamma = solveReduced(dirichletLaplacian_, dirichletReduced, nd,
                           integratedDivergence(ops_, mesh_, out.gammaDirection));

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
  const Vec3 r = options_.reference.normalized();
  const double minSin = std::sin(options_.referenceParallelDeg * M_PI / 180.0);
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

  // Eqs. 4-5 for α and β with one pinned vertex per component.
  std::vector<int> pinnedReduced;
  const int np = freeIndexMap(nv, pinned_, pinnedReduced);
  out.alpha = solveReduced(pinnedLaplacian_, pinnedReduced, np, integratedDivergence(ops_, mesh_, out.alphaDirection));
  out.beta = solveReduced(pinnedLaplacian_, pinnedReduced, np, integratedDivergence(ops_, mesh_, out.betaDirection));
  // α and β are defined up to a constant per component: start each component at 0.
  for (Eigen::VectorXd* f : {&out.alpha, &out.beta}) {
    std::vector<double> minimum(componentCount_, std::numeric_limits<double>::infinity());
    for (size_t v = 0; v < nv; ++v) {
      minimum[component_[v]] = std::min(minimum[component_[v]], (*f)[v]);
    }
    for (size_t v = 0; v < nv; ++v) {
      (*f)[v] -= minimum[component_[v]];
    }
  }

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
  out.orthogonalityDeviationDeg = {percentile(devAlpha, 0.5), percentile(devAlpha, 0.95), percentile(devBeta, 0.5),
                                   percentile(devBeta, 0.95)};
  out.timings.solve = secondsSince(start);
  return out;
}

GeodesicFields computeGeodesicDistanceFields(const TetMesh& mesh, const std::vector<int>& sources,
                                             const GeodesicFieldOptions& options) {
  GeodesicDistanceFields solver(mesh, options);
  return solver.solve(sources);
}

} // namespace geolattice
