/**
 * @class   vtkGLAutoOrient
 * @brief   Turns the part so that it prints best: which side faces the build plate.
 *
 * core/orient/AutoOrient.h. With Orient = Auto the filter samples candidate down directions (a
 * Fibonacci sphere of SphereCandidates, the normals of the HullCandidates largest convex-hull
 * facets, and the part as placed), scores each with the real stages on one coarse tet mesh of
 * about EvaluationTets tets (layers every EvaluationLayerInterval mm, a lattice of
 * EvaluationLatticeWidth mm, the paper's A4 order and the independent collision verifier with the
 * nozzle and the build plate) and picks the best by a lexicographic objective: base contact area
 * at least MinBaseArea, then the fewest colliding stations, forced steps, overhang, layers. With
 * Orient = Keep (the default, as desktop slicers do) the part passes unchanged.
 *
 * Input:  vtkPolyData, the placed part (GL Place On Platform): a closed triangle surface in mm.
 * Output port 0 (Oriented Surface): the part rotated so its chosen side is down, standing on
 *   z = 0 with its x/y centre kept; point and cell data passed. Field data: `OrientMode`
 *   ("keep" or "auto"), and with Auto `OrientUp` (3: the part's direction, as it came in, that
 *   now points up), `OrientRotation` (9, row major: input -> output), `OrientCandidates`,
 *   `OrientSeconds`, `OrientBefore` and `OrientAfter` (colliding stations as placed and chosen),
 *   `OrientEvaluationTets`.
 * Output port 1 (Candidates): with Auto, one vertex per candidate at centre + radius × its up
 *   direction (a sphere around the part), point data `OrientRank` (0 = chosen),
 *   `CollidingStations`, `PlateStations`, `ForcedSteps`, `BaseArea` (mm²), `OverhangFraction`,
 *   `LayerCount`, `Feasible` (1: enough base area and evaluated), `Evaluated`, `OrientUp` (3),
 *   `CollisionStations`, `OrientSeconds`, `OrientSource` (string: keep, hull or sphere, and the
 *   error of a stage that failed on it).
 * Parameters: Orient (default 0 = Keep), the nozzle (vtkGLNozzle, shared), MinBaseArea (mm²,
 *   default 10), SphereCandidates (default 100), HullCandidates (default 24), EvaluationTets
 *   (default 15000), EvaluationLayerInterval (mm, default 1.5), EvaluationLatticeWidth (mm,
 *   default 8), NumberOfThreads (default 0 = all cores).
 * Errors (an empty or open surface, bad parameters, no candidate with the base area: the message
 * names the largest area found) are reported with vtkErrorMacro; RequestData returns 0.
 */
#ifndef vtkGLAutoOrient_h
#define vtkGLAutoOrient_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLNozzleAlgorithm.h"

class GEOLATTICEFILTERS_EXPORT vtkGLAutoOrient : public vtkGLNozzleAlgorithm {
public:
  static vtkGLAutoOrient* New();
  vtkTypeMacro(vtkGLAutoOrient, vtkGLNozzleAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Values of Orient.
  enum Modes { KEEP = 0, AUTO = 1 };

  ///@{
  /// Keep the placement (default 0 = Keep) or search the best orientation (1 = Auto).
  vtkSetClampMacro(Orient, int, KEEP, AUTO);
  vtkGetMacro(Orient, int);
  ///@}

  ///@{
  /// Contact area with the plate an orientation needs (mm², default 10, >= 0).
  vtkSetMacro(MinBaseArea, double);
  vtkGetMacro(MinBaseArea, double);
  ///@}

  ///@{
  /// Candidate directions from a uniform sphere sample (default 100, >= 0).
  vtkSetMacro(SphereCandidates, int);
  vtkGetMacro(SphereCandidates, int);
  ///@}

  ///@{
  /// Candidate directions from the largest convex-hull facets (default 24, >= 0).
  vtkSetMacro(HullCandidates, int);
  vtkGetMacro(HullCandidates, int);
  ///@}

  ///@{
  /// Tets of the coarse evaluation mesh (default 15000, >= 100).
  vtkSetMacro(EvaluationTets, int);
  vtkGetMacro(EvaluationTets, int);
  ///@}

  ///@{
  /// Layer interval of the evaluation (mm, default 1.5, > 0).
  vtkSetMacro(EvaluationLayerInterval, double);
  vtkGetMacro(EvaluationLayerInterval, double);
  ///@}

  ///@{
  /// Lattice width of the evaluation (mm, default 8, > 0).
  vtkSetMacro(EvaluationLatticeWidth, double);
  vtkGetMacro(EvaluationLatticeWidth, double);
  ///@}

  ///@{
  /// Candidates evaluated in parallel (default 0 = all cores).
  vtkSetClampMacro(NumberOfThreads, int, 0, 256);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

protected:
  vtkGLAutoOrient();
  ~vtkGLAutoOrient() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Orient;
  double MinBaseArea;
  int SphereCandidates;
  int HullCandidates;
  int EvaluationTets;
  double EvaluationLayerInterval;
  double EvaluationLatticeWidth;
  int NumberOfThreads;

private:
  vtkGLAutoOrient(const vtkGLAutoOrient&) = delete;
  void operator=(const vtkGLAutoOrient&) = delete;
};

#endif
