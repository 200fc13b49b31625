#pragma once
/// @file GeodesicDistanceFields.h
/// @brief The three mutually orthogonal geodesic distance fields γ, α, β on a tet mesh
/// (paper Section 2.1, Eqs. 1-5), by the heat method.
///
/// Data flow:
///   set-up (once per mesh and time factor): FEM operators K, V (TetLaplacian.h); factor the heat
///     matrix V + tK (Eq. 1 times V) and the Laplacian K with one pinned vertex per component.
///   solve(sources): heat step u (Eq. 1) -> per-tet g_γ = -∇u/|∇u| (Eq. 2) -> g_α, g_β (Eq. 3)
///     -> integrated divergences (Eq. 4) -> three Poisson solves K φ = b (Eq. 5).
///     γ uses Dirichlet γ = 0 on the sources (that factorization is cached per source set);
///     α and β use the pinned Laplacian and are shifted so their minimum is 0.
/// Sign convention: γ grows away from the base; g_γ points to increasing γ (the nozzle axis).
#include "gdf/SparseCholesky.h"
#include "gdf/TetLaplacian.h"
#include "mesh/TetMesh.h"

#include <Eigen/Cholesky>

#include <functional>
#include <memory>
#include <vector>

namespace geolattice {

class TetMeshTopology;

/// With GeodesicFieldOptions::turnReference, r is turned when more than this share of the tets
/// would take g_α from their neighbours (r within referenceParallelDeg of g_γ there).
constexpr double kReferenceTurnShare = 0.01;

/// @brief Parameters of the GDF computation.
struct GeodesicFieldOptions {
  double timeFactor = 4.0;         ///< heat time t = timeFactor * h^2, h = mean edge length (> 0)
  Vec3 reference = Vec3(1, 0, 0);  ///< r of Eq. 3 (any non-zero vector; normalised)
  double referenceParallelDeg =
      1.0;  ///< where angle(r, g_γ) < this (or > 180 - this), g_α is taken
            ///< from neighbouring tets instead of Eq. 3 (degrees, [0, 90))
  /// true (default): where r lies along g_γ in more than kReferenceTurnShare of the tets (a
  /// part whose limbs grow along r, e.g. a figure's arms along x), Eq. 3 uses instead the
  /// direction across the build direction z least along the layer normals (smallest Σ (r·g_γ)²
  /// over the tets; GeodesicFields::reference) when it lies along g_γ in fewer tets: those
  /// would take their lattice directions from their neighbours. false: r as given.
  bool turnReference = true;
  CholeskyBackend backend = CholeskyBackend::Cholmod;
  /// true (default): g_γ, and so g_α and g_β (Eq. 3), are the normalised gradient of the
  /// solved γ, so the lattice lines are orthogonal to the actual layer normals. false: the
  /// paper's choice, the normalised heat gradient of Eq. 2.
  bool directionsFromSolvedGamma = true;
  /// true (default): γ = 0 on the sources exactly (a Dirichlet Laplacian, factored once per
  /// source set). false: γ from the pinned Laplacian of α and β, shifted to start at 0 in each
  /// component (the heat method's Neumann variant): no factorization per source set, for callers
  /// that solve for many (the orientation search: one per candidate).
  bool dirichletGamma = true;
  /// true (default): the heat matrix and the pinned Laplacian are factored at the same time on
  /// two threads (factorizeTogether). false: one after the other, for callers that already run
  /// one solver per core (the orientation search, under a SingleThreadedBlas guard).
  bool factorTogether = true;
  /// Called on the calling thread with the fraction done: the constructor reports its set-up
  /// (assembly, factorizations) from 0 to 1, each solve() its own work again from 0 to 1.
  /// Optional; not part of the set-up (changing it needs no new factorization).
  std::function<void(double)> progress;
  /// Polled between those steps; true stops with a GeoLatticeError "geodesic distance fields
  /// aborted" (an aborted solve() leaves the solver usable). Optional.
  std::function<bool()> shouldAbort;
  /// Throws GeoLatticeError naming the first parameter out of its range (cheap: no data).
  void validate() const;
};

/// @brief Seconds spent in each part of the computation.
struct GeodesicFieldTimings {
  double assembly = 0;       ///< operators, topology, matrices
  double factorization = 0;  ///< heat, pinned and (if not cached) Dirichlet Laplacian, or the
                             ///< Dirichlet correction's solves with the pinned factor
  double solve = 0;          ///< heat step, vector fields, three Poisson solves
};

/// @brief Output of GeodesicDistanceFields::solve.
struct GeodesicFields {
  Eigen::VectorXd gamma;             ///< #V γ (mm), 0 on the sources
  Eigen::VectorXd alpha;             ///< #V α (mm), min 0
  Eigen::VectorXd beta;              ///< #V β (mm), min 0
  std::vector<Vec3> gammaDirection;  ///< #T unit g_γ (Eq. 2, normalised, towards increasing γ)
  std::vector<Vec3> alphaDirection;  ///< #T unit g_α (Eq. 3)
  std::vector<Vec3> betaDirection;   ///< #T unit g_β (Eq. 3)
  int referenceFallbackTets = 0;     ///< tets where r was nearly parallel to g_γ (see options)
  Vec3 reference = Vec3::Zero();     ///< the unit r Eq. 3 used (the option's, or turned)
  /// r was turned (GeodesicFieldOptions::turnReference); then the tets the given one had along
  /// g_γ.
  bool referenceTurned = false;
  int givenReferenceFallbackTets = 0;
  int zeroHeatGradientTets = 0;  ///< tets where ∇u vanished (g_γ taken from neighbours)
  /// How the Dirichlet γ was solved: true, with the pinned Laplacian's factor and a small dense
  /// correction for the other sources; false, with a factorization of its own (or not Dirichlet).
  bool dirichletFromPinned = false;
  /// Deviation from 90° (degrees) between the solved ∇α and ∇γ, and ∇β and ∇γ, over all tets:
  /// {median αγ, 95th percentile αγ, median βγ, 95th percentile βγ}.
  std::array<double, 4> orthogonalityDeviationDeg{};
  GeodesicFieldTimings timings;
};

/// @class GeodesicDistanceFields
/// @brief Factor once per mesh, then solve for any source set.
class GeodesicDistanceFields {
public:
  /// Assembles and factors; throws GeoLatticeError on a bad mesh or bad options.
  GeodesicDistanceFields(TetMesh mesh, const GeodesicFieldOptions& options = {});
  ~GeodesicDistanceFields();

  /// Computes γ, α, β for the given source vertices (the base). Throws if sources is empty,
  /// holds an invalid index, or a connected component of the mesh contains no source.
  GeodesicFields solve(const std::vector<int>& sources);

  /// Sets the reference vector r of Eq. 3 for the next solves (not a set-up parameter: no new
  /// factorization). Throws GeoLatticeError for a zero or non-finite vector.
  void setReference(const Vec3& reference);

  const TetMesh& mesh() const { return mesh_; }
  const TetOperators& operators() const { return ops_; }
  const TetMeshTopology& topology() const { return *topology_; }
  const GeodesicFieldOptions& options() const { return options_; }
  double heatTime() const { return heatTime_; }
  int componentCount() const { return componentCount_; }
  /// Time of the constructor's work (assembly, factorization).
  const GeodesicFieldTimings& setupTimings() const { return setupTimings_; }

private:
  /// Shifts f so that its minimum in each connected component is 0.
  void startComponentsAtZero(Eigen::VectorXd& f) const;
  /// Makes the Dirichlet Laplacian of a new source set solvable: as a correction of the pinned
  /// Laplacian's factor when that is cheaper, else by factoring it.
  void prepareDirichlet(const std::vector<int>& sources, const std::vector<char>& isSource,
                        GeodesicFieldTimings& timings);
  /// K γ = b with γ = 0 on the sources (b is zero there already).
  Eigen::VectorXd solveDirichlet(const Eigen::VectorXd& b) const;

  TetMesh mesh_;
  GeodesicFieldOptions options_;
  TetOperators ops_;
  std::unique_ptr<TetMeshTopology> topology_;
  double heatTime_ = 0;
  std::vector<int> component_;  ///< #V component id
  int componentCount_ = 0;
  std::vector<int> pinned_;  ///< one pinned vertex per component
  SparseCholesky heat_;
  SparseCholesky pinnedLaplacian_;
  SparseCholesky dirichletLaplacian_;
  std::vector<int> dirichletSources_;  ///< source set the Dirichlet set-up belongs to
  /// The Dirichlet Laplacian as a correction of the pinned one (used while `active`):
  /// the sources that are not pinned, Z = K_pinned^-1 E (E: their identity columns) and the
  /// Cholesky factor of E^T Z (the capacitance matrix).
  struct DirichletCorrection {
    bool active = false;
    std::vector<int> constrained;
    Eigen::MatrixXd Z;
    Eigen::LLT<Eigen::MatrixXd> capacitance;
  } dirichletCorrection_;
  GeodesicFieldTimings setupTimings_;
};

/// One call: set-up and solve.
GeodesicFields computeGeodesicDistanceFields(const TetMesh& mesh, const std::vector<int>& sources,
                                             const GeodesicFieldOptions& options = {});

}  // namespace geolattice
