#ifndef GLPrintPipeline_h
#define GLPrintPipeline_h
/**
 * @file GLPrintPipeline.h
 * @brief The whole GeoLattice pipeline, wired once: the command-line tool (apps/) and the filter
 * tests build it from here; pvpython/geolattice_pipeline.py builds the same proxies in the same
 * order (tests/pvpython/test_pipeline_description.py compares the two descriptions).
 *
 *   Reader -> Place -> Orient -> Pedestal -> Mesh (the three skipped for a tet-mesh input) -> Fields
 *          -> Layers -> Lattice
 *          -> Skeleton (+ Fields) -> Sequence -> Toolpath -> the program writers
 *   Overhang on Fields; SequenceVerify on Sequence; ToolpathVerify and Replay on Toolpath;
 *   Summary on Toolpath and ToolpathVerify.
 *
 * Every filter keeps its own defaults (taken from the core options structs); the pipeline only
 * connects them and gives the sequencer, both verifiers and the planner one shared nozzle
 * (vtkGLNozzle). Construction only wires; nothing runs until a stage is updated.
 */
#ifndef __VTK_WRAP__

#include "GeoLatticeFiltersModule.h"
#include "vtkGLAutoOrient.h"
#include "vtkGLCollisionVerifier.h"
#include "vtkGLCurvedLayerSlicer.h"
#include "vtkGLGCodeWriter.h"
#include "vtkGLGeodesicDistanceFields.h"
#include "vtkGLLatticeInfill.h"
#include "vtkGLMeshReader.h"
#include "vtkGLNozzle.h"
#include "vtkGLOverhangAnalysis.h"
#include "vtkGLPedestal.h"
#include "vtkGLPlaceOnPlatform.h"
#include "vtkGLPrintSequencer.h"
#include "vtkGLPrintSummary.h"
#include "vtkGLSkeletonTree.h"
#include "vtkGLTetrahedralizeSurface.h"
#include "vtkGLToolpathPlanner.h"
#include "vtkGLToolpathReplay.h"
#include "vtkGLURScriptWriter.h"
#include "vtkGLWaypointCsvWriter.h"

#include <vtkNew.h>

#include <functional>
#include <vector>

class vtkAlgorithm;

class GEOLATTICEFILTERS_EXPORT GLPrintPipeline {
public:
  /// The stages in pipeline order (a CLI `--until` names one of the first group).
  enum Stage {
    Read,
    Place,
    Orient,
    Raise,  ///< the pedestal (vtkGLPedestal; Height 0 passes the part through)
    Mesh,
    Fields,
    Layers,
    Overhang,
    Lattice,
    Skeleton,
    Sequence,
    SequenceVerify,
    Toolpath,
    ToolpathVerify,
    Summary,  ///< the numbers a slicer shows (vtkGLPrintSummary on Toolpath + ToolpathVerify)
    Replay,   ///< the print replay of the toolpath (vtkGLToolpathReplay)
    NumberOfStages
  };

  /// Wires every filter. With tetMeshInput the Orient, Raise and Mesh stages are skipped: the placed tet
  /// mesh goes straight to Fields (and Skeleton).
  explicit GLPrintPipeline(bool tetMeshInput = false);
  GLPrintPipeline(const GLPrintPipeline&) = delete;
  GLPrintPipeline& operator=(const GLPrintPipeline&) = delete;

  /// Rewires for a tet-mesh input (true) or a surface (false).
  void SetTetMeshInput(bool tetMeshInput);
  bool GetTetMeshInput() const { return this->TetMeshInput; }

  /// The pedestal, as the CLI's --pedestal and GL Print Part's Pedestal Height ask for it: mm < 0
  /// = automatic (the orientation search stands a part on a pedestal of its default height where
  /// that helps; none with Orient Keep), 0 = never, mm > 0 = always that tall (the search scores
  /// every candidate on it). Sets the orientation's Pedestal mode and height and the pedestal's
  /// Height; the getter reads them back (-1 for automatic).
  void SetPedestalRequest(double mm);
  double GetPedestalRequest();

  /// Gives the orientation search's refinement the print's resolution and order: the slicer's
  /// layer interval, the lattice's (smaller) width, the sequencer's strategy and the planner's
  /// largest axis tilt. Call after
  /// setting parameters, before updating; it modifies nothing when they already match or the
  /// orientation is Keep (then a print setting re-runs no orientation).
  void MatchOrientationToPrint();

  /// One orientation run through the toolpath verifier by ChooseOrientationByToolpath.
  struct OrientationTry {
    int rank = 0;             ///< the search's rank of the candidate
    bool ok = false;          ///< the stages ran (false: one failed on this candidate)
    long long colliding = 0;  ///< strict toolpath stations with the nozzle in material/plate
    long long stations = 0;   ///< stations checked
    double pedestal = 0;      ///< mm of pedestal under it
    double seconds = 0;
  };

  /// The orientation the real toolpath prints best: with Orient Auto, the search's candidates are
  /// run through the toolpath verifier in rank order, up to `tries` of them (feasible ones scored
  /// at the print's resolution) besides the part as placed (on the plate, when it can stand
  /// there), which is tried where it ranks or else last, until one is strictly collision-free; the one with the fewest
  /// colliding stations is kept (Orientation's CandidateRank; the earlier rank on a tie). The
  /// search runs once: a rank change only re-places the part. Why: the search scores sub-graph
  /// orders, not toolpaths (no axis tilts, no collision inside a sub-graph), so two close
  /// candidates can print the other way round. `starting` (optional) is called before each try
  /// after the first. Nothing is tried with Orient Keep, tries < 2 or a stop request (Ctrl-C).
  std::vector<OrientationTry> ChooseOrientationByToolpath(
      int tries, const std::function<void(const OrientationTry&)>& starting = {});

  /// Candidates ChooseOrientationByToolpath runs at most (CLI --orient-tries, GL Print Part
  /// OrientTries; 1 = the search's best only).
  int OrientationTries = 3;

  /// The filter of a stage (Mesh: the tetrahedralizer even when skipped).
  vtkAlgorithm* Filter(Stage stage);
  /// "read", "place", "orient", "pedestal", "mesh", "fields", "layers", "overhang", "lattice", "skeleton", "sequence",
  /// "sequence-verify", "toolpath", "toolpath-verify", "summary", "replay".
  static const char* StageName(Stage stage);

  /// Asks every running GeoLattice filter to stop at its next abort poll, as if its AbortExecute
  /// were set (safe to call from a signal handler: it stores a lock-free atomic). Used by the
  /// CLI for Ctrl-C; ClearStopRequest() before the next run.
  static void RequestStop();
  static void ClearStopRequest();

  vtkNew<vtkGLNozzle> Nozzle;  ///< shared by Sequence, both verifiers and Toolpath
  vtkNew<vtkGLMeshReader> Reader;
  vtkNew<vtkGLPlaceOnPlatform> Placement;
  vtkNew<vtkGLAutoOrient> Orientation;  ///< Keep by default: the part as placed
  vtkNew<vtkGLPedestal> Pedestal;       ///< the orientation search's choice, else Height (0: none)
  vtkNew<vtkGLTetrahedralizeSurface> Tetrahedralize;
  vtkNew<vtkGLGeodesicDistanceFields> GeodesicFields;
  vtkNew<vtkGLCurvedLayerSlicer> Slicer;
  vtkNew<vtkGLOverhangAnalysis> OverhangAnalysis;
  vtkNew<vtkGLLatticeInfill> LatticeInfill;
  vtkNew<vtkGLSkeletonTree> SkeletonTree;
  vtkNew<vtkGLPrintSequencer> Sequencer;
  vtkNew<vtkGLCollisionVerifier> SequenceVerifier;  ///< the order (time = PrintOrder)
  vtkNew<vtkGLToolpathPlanner> Planner;
  vtkNew<vtkGLCollisionVerifier> ToolpathVerifier;  ///< the toolpath (time = PointIndex)
  vtkNew<vtkGLPrintSummary> PrintSummary;           ///< the summary table (report.json "summary")
  vtkNew<vtkGLToolpathReplay> ToolpathReplay;       ///< the print over time (toolpath.pvd)
  vtkNew<vtkGLURScriptWriter> ScriptWriter;
  vtkNew<vtkGLGCodeWriter> GCodeWriter;
  vtkNew<vtkGLWaypointCsvWriter> WaypointWriter;

private:
  bool TetMeshInput = false;
};

#endif  // __VTK_WRAP__
#endif
