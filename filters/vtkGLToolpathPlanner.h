/**
 * @class   vtkGLToolpathPlanner
 * @brief   The printing path of the whole part: the sub-graphs in printing order, each printed
 *          as closed crossover-free Euler tours, with layer thickness, extrusion, nozzle axes
 *          and safe air moves between them (GL Toolpath Replay replays it over time).
 *
 * Paper Section 3.2 (Figs. 14-18, Eqs. 14-15), core/toolpath/ToolpathPlanner.h: zero-length
 * lattice edges are contracted, each sub-graph is trimmed to an Eulerian graph and printed as
 * closed tours that turn at every α/β crossing (no crossover); where the trimming deleted
 * boundary edges a support perimeter (offset PathWidth inside the boundary loop, jagged with
 * teeth of ToothLength along the trimmed edges, Fig. 14d) is spliced into the tour (out along a
 * connector, around, back without extrusion); the layer thickness h of a vertex is its distance
 * to the lattice of its lower skeleton node(s), capped at ThicknessCap × φ_i (Eq. 15; the height
 * above the platform on the first layer); the extrusion follows the mass conservation
 * π r_m² ΔE = μ w h̄ L (Eq. 14, r_m = FilamentDiameter / 2, μ = FlowCorrection, w = PathWidth,
 * h̄ the mean thickness of the segment's ends); the nozzle axis is the layer normal (∇γ), with
 * rotation steps inserted where it would turn by more than MaxTurnAngle between points and
 * segments subdivided to at most MaxSegmentLength; where the nozzle along ∇γ would hit material
 * printed earlier on the path (a strongly curved layer inside one sub-graph), the axis is tilted
 * by the least angle that clears it (at most MaxAxisTilt, faded over TiltBlendLength of path;
 * core/toolpath/NozzleAxisClearance.h); between
 * sub-graphs the nozzle retracts by Retraction mm of filament, moves by air (a hop of Lift mm
 * onto an upper node of the current sub-graph, else over the safe box around everything printed
 * so far grown by SafeMargin, Fig. 18) and primes again.
 *
 * Input port 0: vtkPolyData, the Sequenced Lattice output of vtkGLPrintSequencer: the lattice
 *         (line cells with cell arrays `SubgraphId`, `LayerId`, `EdgeKind` (the trimming keeps
 *         or drops boundary edges), point arrays `NozzleAxis`, `Gamma`) with field data
 *         `SequenceOrder` (sub-graph id per position), which is the printing order used. Its
 *         field data `SkeletonEdges` is passed to the output.
 * Input port 1: vtkPolyData, the skeleton of the same lattice: the output of vtkGLSkeletonTree or
 *         the Sequenced Skeleton output of vtkGLPrintSequencer (point data `LayerId`, `NodeId`).
 * Output: vtkPolyData with one point per toolpath point in printing order and one polyline cell
 *   per continuous run of moves of the same kind on the same path and sub-graph (a piece of a
 *   tour, a support perimeter, an air move), consecutive cells sharing their end point: renders
 *   with few cells and can be tubed, thresholded and coloured by cell MoveKind without
 *   interpolation across kinds.
 *   - point data (the move that ends at the point; the first point is the start, MoveKind Air):
 *     `NozzleAxis` (3 components: unit nozzle axis; not the active normals, which ParaView would light the lines with), `Thickness` (h, mm, 0 on air
 *     moves), `Width` (w, mm, 0 on air moves and on the way back from a perimeter, which does
 *     not extrude), `Extrusion` (cumulative filament E, mm, after the retractions and primes),
 *     `FeedRate` (mm/s), `MoveKind` (int: 0 print, 1 perimeter, 2 air; geolattice::movekind),
 *     `LayerId` (the lattice's LayerId, -1 on air moves), `SubgraphId` (-1 on air moves),
 *     `PathIndex` (int: the tour; air moves carry the next one), `PointIndex` (int: 0..N-1, the
 *     print time for vtkGLCollisionVerifier with TimeArrayName PointIndex), `AxisTilt` (degrees
 *     between the nozzle axis and the layer normal ∇γ);
 *   - cell data of each run: `MoveKind`, `PathIndex`, `LayerId`, `SubgraphId`;
 *   - field data: `ToolpathPrintLength` (lattice), `ToolpathPerimeterLength`, `ToolpathAirLength`
 *     (mm), `ToolpathPerimeterLoops`, `ToolpathPerimeterTeeth`, `ToolpathRetractions`,
 *     `ToolpathTours`, `ToolpathCrossings` (self-crossings of the tours, 0 expected),
 *     `ToolpathSplitSubgraphs` (sub-graphs printed as more than one tour),
 *     `ToolpathContractedEdges`, `ToolpathTrimmedEdges`, `ToolpathTrimmedLength` (mm),
 *     `ToolpathFilament` (mm), `ToolpathFilamentDiameter` (mm, the parameter),
 *     `ToolpathVolume` (mm³), `ToolpathThicknessDeviation` (2 values:
 *     min and max of e = (h - φ)/φ), `ToolpathThicknessDeviationPerLayer` (3 components min,
 *     mean, max per lattice layer 0..L-1), `ToolpathCappedVertices`,
 *     `ToolpathUnsupportedVertices`, `ToolpathRotationSteps`, `ToolpathSubdivisionPoints`,
 *     `ToolpathCollidingStations` (along ∇γ), `ToolpathTiltedStations`,
 *     `ToolpathUnclearedStations`, `ToolpathMaxAxisTilt` (degrees), `ToolpathReplannedHops`
 *     (hops onto an upper node that collided and went over the safe box),
 *     `ToolpathAlignedTransitions` (transitions whose air stations collided, built again along
 *     their stations' final axes), `ToolpathReorderedTours` (tours printed from another start or
 *     the other way round because fewer of their stations collide so) and
 *     `ToolpathUnclearedBeforeReorder` (the stations colliding before that), `ToolpathSeconds` (planning wall time) and `SkeletonEdges` from input 0; always of the whole toolpath.
 * No time: the output is always the whole toolpath (GL Toolpath Replay adds the print replay's
 *   time steps).
 * Parameters: PathWidth (w, mm, default 0.6, > 0), FilamentDiameter (mm, default 1.75, > 0; the
 *   core takes the radius r_m = diameter / 2), FlowCorrection (μ, default 0.95, in (0, 1]),
 *   PrintFeedRate (f_p, mm/s, default 10, > 0), AirFeedRate (mm/s, default 50, > 0),
 *   ThicknessCap (λ of Eq. 15, default 1.5, > 0), MaxTurnAngle (degrees, default 5, > 0),
 *   SafeMargin (mm, default 5, >= 0), Lift (mm, default 2, > 0), Retraction (mm of filament,
 *   default 1, >= 0), SupportPerimeter (default on), ToothLength (l, mm, default 0 = 2 PathWidth,
 *   >= 0), MaxSegmentLength (mm, default 1, >= 0; 0 = no subdivision), MaximumElements (default
 *   40e6: more estimated stations is refused before planning), the nozzle (vtkGLNozzle,
 *   shared with the sequencer and the verifier),
 *   MaxAxisTilt (degrees, default 30, in [0, 60]; 0 = axis ∇γ everywhere), TiltBlendLength (mm,
 *   default 5, >= 0).
 * Errors (an empty lattice or skeleton, missing arrays (EdgeKind included), no SequenceOrder
 * ("run GL Print Sequencer first"), an order that is not a permutation of the sub-graphs, a
 * skeleton that does not match the lattice, a bad parameter, or what the core rejects, e.g. odd
 * vertices left after trimming) are reported with vtkErrorMacro and give an empty output.
 */
#ifndef vtkGLToolpathPlanner_h
#define vtkGLToolpathPlanner_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLOptionMacros.h"
#include "vtkGLNozzleAlgorithm.h"

#include "toolpath/ToolpathPlanner.h"  // ToolpathOptions: the parameters and their defaults
#include "vtkSmartPointer.h"           // for the cached toolpath

class GEOLATTICEFILTERS_EXPORT vtkGLToolpathPlanner : public vtkGLNozzleAlgorithm {
public:
  static vtkGLToolpathPlanner* New();
  vtkTypeMacro(vtkGLToolpathPlanner, vtkGLNozzleAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Path width w (mm, default 0.6, > 0).
  vtkGLOptionMacro(PathWidth, double, pathWidth);
  ///@}

  ///@{
  /// Filament diameter (mm, default 1.75, > 0); Eq. 14 uses the radius r_m = diameter / 2.
  vtkSetMacro(FilamentDiameter, double);
  vtkGetMacro(FilamentDiameter, double);
  ///@}

  ///@{
  /// Flow correction μ of Eq. 14 (default 0.95, in (0, 1]).
  vtkGLOptionMacro(FlowCorrection, double, flowCorrection);
  ///@}

  ///@{
  /// Nozzle feed rate f_p of print moves (mm/s, default 10, > 0).
  vtkGLOptionMacro(PrintFeedRate, double, printFeedRate);
  ///@}

  ///@{
  /// Nozzle feed rate of air moves (mm/s, default 50, > 0).
  vtkGLOptionMacro(AirFeedRate, double, airFeedRate);
  ///@}

  ///@{
  /// λ of Eq. 15: the layer thickness is capped at λ φ_i (default 1.5, > 0).
  vtkGLOptionMacro(ThicknessCap, double, thicknessCap);
  ///@}

  ///@{
  /// Largest change of the nozzle axis between consecutive points (degrees, default 5, > 0).
  vtkGLOptionMacro(MaxTurnAngle, double, maxTurnDeg);
  ///@}

  ///@{
  /// Margin of the safe box around the in-process part for air moves (mm, default 5, >= 0).
  vtkGLOptionMacro(SafeMargin, double, safeMargin);
  ///@}

  ///@{
  /// Lift along the axis for a hop onto an upper node of the current sub-graph (mm, default 2, > 0).
  vtkGLOptionMacro(Lift, double, lift);
  ///@}

  ///@{
  /// Filament retracted before each air move and primed after it (mm, default 1, >= 0).
  vtkGLOptionMacro(Retraction, double, retraction);
  ///@}

  ///@{
  /// Add the jagged support perimeter where boundary edges were trimmed (default on).
  vtkGLOptionBooleanMacro(SupportPerimeter, supportPerimeter);
  ///@}

  ///@{
  /// Tooth length l of the support perimeter along trimmed edges (mm, default 0 = 2 PathWidth, >= 0).
  vtkGLOptionMacro(ToothLength, double, toothLength);
  ///@}

  ///@{
  /// Bound against runaway work (core/common/WorkLimit.h): an output estimated to have more
  /// elements than this is refused before it is built (default 40e6, about 8 GB).
  vtkGLOptionClampMacro(MaximumElements, double, maxElements, 1.0, VTK_DOUBLE_MAX);
  ///@}

  ///@{
  /// Longest segment of the path: longer ones are subdivided (mm, default 1, >= 0; 0 = never), so
  /// that a collision check of the path's points samples it this finely.
  vtkGLOptionMacro(MaxSegmentLength, double, maxSegmentLength);
  ///@}

  ///@{
  /// Largest tilt of the nozzle axis away from the layer normal where the normal would drive the
  /// nozzle into earlier material of the path (degrees, default 30, in [0, 60]; 0 = the paper's
  /// axis ∇γ everywhere). The tilt fades out over TiltBlendLength mm of path on each side
  /// (default 5, >= 0).
  vtkGLOptionMacro(MaxAxisTilt, double, clearance.maxTiltDeg);
  vtkGLOptionMacro(TiltBlendLength, double, clearance.blendLength);
  ///@}

  /// The stage's core options as the parameters set them (C++ only: a core type).
  VTK_WRAPEXCLUDE const geolattice::ToolpathOptions& GetOptions() const { return this->Options; }

protected:
  vtkGLToolpathPlanner();
  ~vtkGLToolpathPlanner() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  geolattice::ToolpathOptions Options;  ///< the parameters, defaults from core
  double FilamentDiameter;

private:
  vtkGLToolpathPlanner(const vtkGLToolpathPlanner&) = delete;
  void operator=(const vtkGLToolpathPlanner&) = delete;
};

#endif
