/**
 * @class   vtkGLOverhangAnalysis
 * @brief   Overhang angles of a part's boundary under planar and curved-layer slicing.
 *
 * For every boundary face of the tet grid (outward), the overhang angle θ between the nozzle
 * orientation d and the outward face normal n, θ = acos(d · n) (paper Section 2.2, Fig. 7;
 * core/overhang/OverhangAnalysis.h): for planar 2.5-axis slicing d = +z, for curved layers d is
 * the nozzle axis of the face's tet (`GammaGradient`, the unit ∇γ). A face with θ above
 * ThresholdAngle needs support (Fig. 8 shows both for the Y model). Faces whose three vertices
 * are base vertices (`HeatSource` = 1) rest on the platform: they are left out of both fractions
 * and their area is reported separately.
 *
 * Input:  vtkUnstructuredGrid of tetrahedra (mm) with cell array `GammaGradient` (3 components)
 *         and point array `HeatSource` (non-zero = base vertex): the output of
 *         vtkGLGeodesicDistanceFields.
 * Output: vtkPolyData of the boundary surface (triangles, outward; only the points they use,
 *         renumbered), with
 *   - cell data `OverhangPlanar`, `OverhangCurved` (θ in degrees, [0, 180]; 90° for a face of
 *     zero area), `OnBase` (uint8, 1 = on the platform), and the input's cell arrays of the tet
 *     each face belongs to (e.g. `GammaGradient`, the nozzle axis);
 *   - point data: the input's point arrays (`Gamma`, `Alpha`, `Beta`, `HeatSource`, ...);
 *   - field data: the input's field data plus `OverhangPlanarFraction` and
 *     `OverhangCurvedFraction` (area with θ > threshold / area off the base, in [0, 1]),
 *     `OverhangThresholdDeg`, `OverhangBaseArea` and `OverhangTotalArea` (all boundary faces,
 *     base included; mm²).
 * Parameters: ThresholdAngle (degrees, default 135, in (90, 180]).
 * Errors (a missing or malformed GammaGradient / HeatSource array, non-tet cells, a threshold
 * outside (90, 180], non-unit directions) are reported with vtkErrorMacro and give an empty
 * output.
 */
#ifndef vtkGLOverhangAnalysis_h
#define vtkGLOverhangAnalysis_h

#include "GeoLatticeFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class GEOLATTICEFILTERS_EXPORT vtkGLOverhangAnalysis : public vtkPolyDataAlgorithm {
public:
  static vtkGLOverhangAnalysis* New();
  vtkTypeMacro(vtkGLOverhangAnalysis, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Overhang angle above which a face needs support (degrees, default 135, valid range
  /// (90, 180]). Not clamped: the lower bound is open, and a value outside the range is
  /// reported as an error instead of being silently changed.
  vtkSetMacro(ThresholdAngle, double);
  vtkGetMacro(ThresholdAngle, double);
  ///@}

protected:
  vtkGLOverhangAnalysis();
  ~vtkGLOverhangAnalysis() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double ThresholdAngle;

private:
  vtkGLOverhangAnalysis(const vtkGLOverhangAnalysis&) = delete;
  void operator=(const vtkGLOverhangAnalysis&) = delete;
};

#endif
