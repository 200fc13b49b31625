/**
 * @class   vtkGLAutoOrient
 * @brief   Turns the part so that it prints best: which side faces the build plate.
 *
 * core/orient/AutoOrient.h. With Orient = Auto the filter samples candidate down directions (a
 * Fibonacci sphere of SphereCandidates, the normals of the HullCandidates largest convex-hull
 * facets, and the part as placed), scores each with the real stages on one coarse tet mesh of
 * about EvaluationTets tets (layers every EvaluationLayerInterval mm, a lattice of
 * EvaluationLatticeWidth mm, the paper's A4 order and the independent collision verifier with the
 * nozzle and the build plate), scores the best RefineCandidates of them and the part as placed
 * again at the printing resolution (RefineLayerInterval, RefineLatticeWidth), and picks the best
 * by a lexicographic objective: base contact area at least MinBaseArea, then the fewest colliding
 * stations, forced steps, no pedestal, overhang, layers. With Pedestal = When It Helps (the
 * default) a direction whose part cannot stand on the plate, or whose nozzle meets the plate, is
 * also tried on a pedestal PedestalHeight mm tall reaching PedestalContactHeight mm into the part
 * (core/pedestal/Pedestal.h; GL Pedestal downstream builds it). With Orient = Keep (the default,
 * as desktop slicers do) the part passes unchanged.
 *
 * Input:  vtkPolyData, the placed part (GL Place On Platform): a closed triangle surface in mm.
 * Output port 0 (Oriented Surface): the part rotated so its chosen side is down, standing on
 *   z = 0 with its x/y centre kept; point and cell data passed. Field data: `OrientMode`
 *   ("keep" or "auto"), and with Auto `OrientUp` (3: the part's direction, as it came in, that
 *   now points up), `OrientRotation` (9, row major: input -> output), `OrientCandidates`,
 *   `OrientSeconds`, `OrientBefore` and `OrientAfter` (colliding stations as placed and chosen, at
 *   the printing resolution when refined), `OrientEvaluationTets`, `OrientEvaluationScale` (the
 *   factor on every evaluation's layer interval, lattice width and samples: 1, or for a part of
 *   more than 200,000 mm³ sqrt(volume / 200,000), core evaluationScale), `OrientRefined`, and
 *   `OrientPedestalHeight` / `OrientPedestalContactHeight` (mm: the pedestal chosen, 0 = none),
 *   `OrientChosenRank` (the candidate shown: CandidateRank, clamped), and `MergedBodies` where
 *   bodies of the input that touch along a face (welded by the reader) were merged into their
 *   union before the search (core mergeTouchingBodies: the output is that union), and
 *   `DuplicateTriangles` / `ReorientedTriangles` / `DegenerateTrianglesRemoved` /
 *   `WeldedVertices` where triangles repeating another one were dropped, triangles flipped
 *   against their neighbours turned, degenerate ones removed or vertices welded across a seam
 *   as wide as rounding (core/mesh/SurfaceRepair.h).
 * Output port 1 (Candidates): with Auto, one vertex per candidate at centre + radius × its up
 *   direction (a sphere around the part), point data `OrientRank` (0 = chosen),
 *   `CollidingStations`, `PlateStations`, `ForcedSteps`, `BaseArea` (mm²), `OverhangFraction`,
 *   `LayerCount`, `Feasible` (1: enough base area and evaluated), `Evaluated`, `OrientUp` (3),
 *   `CollisionStations`, `OrientSeconds`, `Pedestal` (mm; such candidates sit on a sphere 15 %
 *   larger), `Refined`, `CoarseCollidingStations`, `OrientSource` (string: keep, hull or sphere,
 *   and the error of a stage that failed on it).
 * Parameters: Orient (default 0 = Keep), the nozzle (vtkGLNozzle, shared), MinBaseArea (mm²,
 *   default 10), MaxHeight (mm, default 0 = none: sides taller than it rank after those that
 *   fit and collide as little; the command line sets the robot cell's tallest part when it
 *   writes the program),
 *   SphereCandidates (default 100), HullCandidates (default 24), EvaluationTets
 *   (default 15000), EvaluationLayerInterval (mm, default 1.5), EvaluationLatticeWidth (mm,
 *   default 8), Pedestal (0 = Never, 1 = When It Helps (default), 2 = Always), PedestalHeight (mm,
 *   default 10), PedestalContactHeight (mm, default 1), RefineCandidates (default 4),
 *   RefineLayerInterval (mm, default 0.6), RefineLatticeWidth (mm, default 4), RefineStrategy
 *   (0 LPT .. 3 Best, default 3 = the sequencer's), MaxAxisTilt (degrees, default 30 = the
 *   toolpath planner's), NumberOfThreads (default 0 = all cores). Defaults from core (OrientOptions).
 * Errors (an empty or open surface, bad parameters, no candidate with the base area: the message
 * names the largest area found) are reported with vtkErrorMacro; RequestData returns 0.
 */
#ifndef vtkGLAutoOrient_h
#define vtkGLAutoOrient_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLOptionMacros.h"
#include "vtkGLNozzleAlgorithm.h"

#include "orient/AutoOrient.h"  // OrientOptions: the parameters and their defaults

#include <memory>

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
  vtkGLOptionMacro(MinBaseArea, double, minBaseArea);
  ///@}

  ///@{
  /// Sides on which the part (with its pedestal) stands taller than this rank after the sides
  /// that fit and collide as little (mm, default 0 = no limit, >= 0): the robot cell's tallest part
  /// (vtkGLURScriptWriter::TallestPart), whose top layers a taller part would need below the
  /// floor.
  vtkGLOptionMacro(MaxHeight, double, maxHeight);
  ///@}

  ///@{
  /// Candidate directions from a uniform sphere sample (default 100, >= 0).
  vtkGLOptionMacro(SphereCandidates, int, sphereCandidates);
  ///@}

  ///@{
  /// Candidate directions from the largest convex-hull facets (default 24, >= 0).
  vtkGLOptionMacro(HullCandidates, int, hullCandidates);
  ///@}

  ///@{
  /// Tets of the coarse evaluation mesh (default 15000, >= 100).
  vtkGLOptionMacro(EvaluationTets, int, evaluationTets);
  ///@}

  ///@{
  /// Layer interval of the evaluation (mm, default 1.5, > 0).
  vtkGLOptionMacro(EvaluationLayerInterval, double, layerInterval);
  ///@}

  ///@{
  /// Lattice width of the evaluation (mm, default 8, > 0).
  vtkGLOptionMacro(EvaluationLatticeWidth, double, latticeWidth);
  ///@}

  /// Values of Pedestal (core PedestalChoice).
  enum PedestalModes { PEDESTAL_NEVER = 0, PEDESTAL_WHEN_IT_HELPS = 1, PEDESTAL_ALWAYS = 2 };

  ///@{
  /// Whether a candidate may stand on a pedestal (default 1 = when it helps).
  vtkGLOptionEnumMacro(Pedestal, pedestal, PEDESTAL_NEVER, PEDESTAL_ALWAYS);
  ///@}

  ///@{
  /// Height of such a pedestal (mm, default 10, in (0, 500]).
  vtkGLOptionMacro(PedestalHeight, double, pedestalHeight);
  ///@}

  ///@{
  /// How far the pedestal's column reaches up into the part (mm, default 1, in (0, 50]).
  vtkGLOptionMacro(PedestalContactHeight, double, pedestalContactHeight);
  ///@}

  ///@{
  /// Best coarse candidates scored again at the printing resolution (default 4, 0 = none).
  vtkGLOptionMacro(RefineCandidates, int, refineCandidates);
  ///@}

  ///@{
  /// The base's flat band of the scoring (mm, default 0.6 = GL Geodesic Distance Fields' Base
  /// Flat Band, >= 0): downward faces this close to the lowest point start the layers too.
  vtkGLOptionMacro(BaseFlatBand, double, baseFlatBand);
  ///@}

  ///@{
  /// Layer interval of that refinement (mm, default 0.6 = the slicer's default, > 0).
  vtkGLOptionMacro(RefineLayerInterval, double, refineLayerInterval);
  ///@}

  ///@{
  /// Lattice width of that refinement (mm, default 4 = the lattice's default, > 0).
  vtkGLOptionMacro(RefineLatticeWidth, double, refineLatticeWidth);
  ///@}

  ///@{
  /// Printing order of that refinement (0 LPT, 1 DPT, 2 A4, 3 Best = the sequencer's default).
  vtkGLOptionEnumMacro(RefineStrategy, refineStrategy, 0, 3);
  ///@}

  ///@{
  /// The toolpath's largest axis tilt off the layer normal (degrees, default 30 = the planner's
  /// MaxAxisTilt, in [0, 60]): a plate station of the part as placed whose nozzle a tilt this
  /// large towards +z lifts wholly off the plate is not counted (GL Print Part sets the
  /// planner's).
  vtkGLOptionClampMacro(MaxAxisTilt, double, maxTiltDeg, 0.0, 60.0);
  ///@}

  ///@{
  /// Which candidate the output shows: 0 (default) the best, k the k-th best (clamped to the
  /// last). Changing it re-places the part without searching again (the search is cached until
  /// the input or another parameter changes): GLPrintPipeline::ChooseOrientationByToolpath tries
  /// the next ones when the best one's toolpath collides.
  void SetCandidateRank(int rank);
  vtkGetMacro(CandidateRank, int);
  ///@}

  ///@{
  /// Candidates evaluated in parallel (default 0 = all cores).
  vtkGLOptionClampMacro(NumberOfThreads, int, threads, 0, 256);
  ///@}

  /// The stage's core options as the parameters set them (C++ only: a core type).
  VTK_WRAPEXCLUDE const geolattice::OrientOptions& GetOptions() const { return this->Options; }

protected:
  vtkGLAutoOrient();
  ~vtkGLAutoOrient() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  geolattice::OrientOptions Options;  ///< the parameters, defaults from core
  int Orient;
  int CandidateRank = 0;

private:
  struct SearchCache;
  std::unique_ptr<SearchCache> Cache;  ///< the last search, valid while nothing else changed

  vtkGLAutoOrient(const vtkGLAutoOrient&) = delete;
  void operator=(const vtkGLAutoOrient&) = delete;
};

#endif
