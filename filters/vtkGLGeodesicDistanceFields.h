/**
 * @class   vtkGLGeodesicDistanceFields
 * @brief   The three mutually orthogonal geodesic distance fields γ, α, β of a tet mesh.
 *
 * Heat method on the tet mesh (paper Section 2.1, Eqs. 1-5; core/gdf/GeodesicDistanceFields.h).
 * γ is the geodesic distance to the base (the heat source); α and β have gradients orthogonal
 * to γ's, built from the reference vector r by Eq. 3. Their iso-surfaces are the curved layers
 * (γ) and the lattice lines (α, β) of the later stages.
 *
 * Input:  vtkUnstructuredGrid of linear tetrahedra (mm), positively oriented.
 * Output: the same grid with
 *   - point data `Gamma`, `Alpha`, `Beta` (mm; γ = 0 on the base, α and β start at 0) and
 *     `HeatSource` (1 on base vertices);
 *   - cell data `GammaGradient` (unit g_γ, the nozzle axis, towards increasing γ),
 *     `AlphaDirection`, `BetaDirection` (unit g_α, g_β of Eq. 3);
 *   - field data `GammaRange`, `AlphaRange`, `BetaRange` (min, max), `GdfTimings` (seconds:
 *     assembly, factorization, solve, total), `OrthogonalityDeviationDeg` (median and 95th
 *     percentile of |90° - angle| between the solved ∇α and ∇γ, then ∇β and ∇γ),
 *     `ReferenceFallbackTets`, `ReferenceUsed` (the unit r used), `GivenReferenceFallbackTets`
 *     (when TurnReference turned it: the tets ReferenceVector lay along g_γ in), `SourceCount`.
 *
 * Parameters:
 *   - SourceMode: LOWEST_Z (default; vertices within BaseTolerance mm of the lowest z),
 *     MASK_ARRAY (point array chosen with SetInputArrayToProcess(0, ...); non-zero = base),
 *     DOWNWARD_FACES (vertices of boundary faces whose outward normal is within BaseFaceAngle
 *     degrees of -z).
 *   - BaseTolerance (mm, default 0.05), BaseFaceAngle (degrees, default 10).
 *   - BaseFlatBand (mm, default 0.6): LOWEST_Z also takes the boundary faces facing down within
 *     BaseFaceAngle that lie within this height of the lowest point (a near-flat bottom that is
 *     not level starts its layers on the plate, not in a fan from its lowest patch); 0 = off.
 *   - TimeFactor: heat time t = TimeFactor * h^2, h = mean edge length (default 4).
 *   - ReferenceVector: r of Eq. 3 (default 1 0 0). ReferenceParallelAngle (degrees, default 1):
 *     where g_γ is within this angle of ±r, g_α comes from neighbouring tets (counted in
 *     `ReferenceFallbackTets`). TurnReference (default on): where r lies along g_γ in more
 *     than 1 % of the tets (a figure's arms along x), the direction across z least along the
 *     layer normals is used instead (when it lies along g_γ in fewer); off: r as given.
 *   - UseCholmod: CHOLMOD supernodal Cholesky (default) or Eigen's SimplicialLDLT.
 *
 * The matrices are factored once and kept: changing only the source selection re-solves without
 * re-assembling the heat and pinned Laplacian factorizations.
 * Errors (non-tet cells, inverted tets, empty base, bad parameters) are reported with
 * vtkErrorMacro and give an empty output.
 */
#ifndef vtkGLGeodesicDistanceFields_h
#define vtkGLGeodesicDistanceFields_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLOptionMacros.h"
#include "vtkUnstructuredGridAlgorithm.h"

#include "gdf/GeodesicDistanceFields.h"  // GeodesicFieldOptions: the parameters and their defaults

#include <memory>

class GEOLATTICEFILTERS_EXPORT vtkGLGeodesicDistanceFields : public vtkUnstructuredGridAlgorithm {
public:
  static vtkGLGeodesicDistanceFields* New();
  vtkTypeMacro(vtkGLGeodesicDistanceFields, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SourceModes { LOWEST_Z = 0, MASK_ARRAY = 1, DOWNWARD_FACES = 2 };

  ///@{
  /// How the base (heat source) is chosen. Default LOWEST_Z.
  vtkSetClampMacro(SourceMode, int, LOWEST_Z, DOWNWARD_FACES);
  vtkGetMacro(SourceMode, int);
  ///@}

  ///@{
  /// LOWEST_Z: vertices with z <= min z + BaseTolerance are the base (mm, default 0.05).
  vtkSetMacro(BaseTolerance, double);
  vtkGetMacro(BaseTolerance, double);
  ///@}

  ///@{
  /// LOWEST_Z: also the vertices of boundary faces facing down within BaseFaceAngle whose
  /// vertices all lie within BaseFlatBand of the lowest z (mm, default 0.6; 0 = off).
  vtkSetMacro(BaseFlatBand, double);
  vtkGetMacro(BaseFlatBand, double);
  ///@}

  ///@{
  /// DOWNWARD_FACES, and LOWEST_Z's flat band: max angle between a boundary face's outward
  /// normal and -z (deg, default 10).
  vtkSetMacro(BaseFaceAngle, double);
  vtkGetMacro(BaseFaceAngle, double);
  ///@}

  ///@{
  /// Heat time t = TimeFactor * h^2 with h the mean edge length (default 4, > 0).
  vtkGLOptionMacro(TimeFactor, double, timeFactor);
  ///@}

  ///@{
  /// Reference vector r of Eq. 3 (default 1 0 0, non-zero).
  vtkSetVector3Macro(ReferenceVector, double);
  vtkGetVector3Macro(ReferenceVector, double);
  ///@}

  ///@{
  /// Angle below which r counts as parallel to g_γ (deg, default 1, in [0, 90)).
  vtkGLOptionMacro(ReferenceParallelAngle, double, referenceParallelDeg);
  ///@}

  ///@{
  /// Turn r across the build direction where it lies along g_γ in more than 1 % of the tets
  /// (default on; core/gdf/GeodesicDistanceFields.h kReferenceTurnShare).
  vtkGLOptionBooleanMacro(TurnReference, turnReference);
  ///@}

  ///@{
  /// Use CHOLMOD (default on) or Eigen's SimplicialLDLT for the factorizations.
  vtkSetMacro(UseCholmod, vtkTypeBool);
  vtkGetMacro(UseCholmod, vtkTypeBool);
  vtkBooleanMacro(UseCholmod, vtkTypeBool);
  ///@}

  /// Drops the factored solver kept for the next update (its Cholesky factors: ~30 MB at 75k
  /// tets); that update factors again. For a caller that will not change the base or the time
  /// factor on this mesh, e.g. the CLI once the fields are computed. Does not modify the filter.
  void ReleaseSolver();

  /// The stage's core options as the parameters set them (C++ only: a core type).
  VTK_WRAPEXCLUDE const geolattice::GeodesicFieldOptions& GetOptions() const {
    return this->Options;
  }

protected:
  vtkGLGeodesicDistanceFields();
  ~vtkGLGeodesicDistanceFields() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  geolattice::GeodesicFieldOptions Options;  ///< the parameters, defaults from core
  int SourceMode;
  double BaseTolerance;
  double BaseFlatBand;
  double BaseFaceAngle;
  double ReferenceVector[3];
  vtkTypeBool UseCholmod;

private:
  vtkGLGeodesicDistanceFields(const vtkGLGeodesicDistanceFields&) = delete;
  void operator=(const vtkGLGeodesicDistanceFields&) = delete;

  /// The factored solver, kept while the input mesh and the set-up parameters are unchanged.
  struct SolverCache;
  std::unique_ptr<SolverCache> Cache;
};

#endif
