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
class vtkPointData;

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
  /// largest axis tilt, and refines at least as many candidates as OrientationTries (only
  /// refined ones are tried); with RobotGate, ranks the sides too tall for the robot cell last
  /// (MaxHeight: ScriptWriter's TallestPart). Call after
  /// setting parameters, before updating; it modifies nothing when they already match or the
  /// orientation is Keep (then a print setting re-runs no orientation).
  void MatchOrientationToPrint();

  /// With Orient Auto: when the search's best candidate stands on a pedestal and the same
  /// direction without one was scored at the print's resolution (feasible, refined) within 1 % of
  /// its stations of collision-free, that one is put first (CandidateRank) and the part printed
  /// on its own base if its toolpath is collision-free (ChooseOrientationByToolpath tries the
  /// search's best next if it collides). Why: the search scores sub-graph orders with the nozzle
  /// along the layer normals; the toolpath's axis tilts clear a few hundred such stations, and a
  /// pedestal costs material and time (a 100 x 60 x 3 mm plate: 125 instead of 29 minutes).
  /// Returns the rank put first, or -1 (nothing changed). Updates the orientation search.
  int PreferTheBaseToAPedestal();

  /// With Orient Auto and OrientTries >= 2: when the search's best candidate is a much longer
  /// print than the part as placed (twice its layers, or a pedestal where the placement collided
  /// mostly with material, not the plate), and the placement stands on the plate (feasible,
  /// refined, no pedestal) but lost on colliding stations, the placement is put first
  /// (CandidateRank) and printed if its toolpath is collision-free (ChooseOrientationByToolpath
  /// tries the search's best next if it collides). Why: the search scores on a coarse mesh, and
  /// its count against the placement is often one the print does not have (three touching
  /// rings: 850 of 18,042 stations, 78 forced steps; a 120 x 120 x 2 mm plate, thinner than the
  /// coarse elements: 1,118 at the plate; 0 in each full run), while a pedestal or twice the
  /// layers make a much longer print (the plate stood on its edge on a pedestal: 204 layers
  /// instead of 5). Trying costs at most one run of the placement. Returns the rank put first,
  /// or -1 (nothing changed). Updates the orientation search.
  int PreferThePlacementToATallerPrint();

  /// One orientation run through the toolpath verifier by ChooseOrientationByToolpath.
  struct OrientationTry {
    int rank = 0;             ///< the search's rank of the candidate
    bool ok = false;          ///< the stages ran (false: one failed on this candidate)
    long long colliding = 0;  ///< strict toolpath stations with the nozzle in material/plate
    long long stations = 0;   ///< stations checked
    double pedestal = 0;      ///< mm of pedestal under it
    double seconds = 0;
    /// With RobotGate, for a collision-free toolpath: 1 the robot follows it, 0 it does not
    /// (unreachable points or joint steps above the bound left), -1 not asked.
    int robot = -1;
    long long unreachable = 0, largeSteps = 0;  ///< when asked
    double robotSeconds = 0;
    /// Why the try before this one was not printed: "collides" or "robot" ("" for the first).
    std::string after;
  };

  /// The orientation the real toolpath prints best: with Orient Auto, the current candidate (from
  /// the pipeline's outputs) and then the search's candidates are
  /// run through the toolpath verifier in rank order, up to `tries` of them (feasible ones scored
  /// at the print's resolution) besides the part as placed (on the plate, when it can stand
  /// there), which is tried where it ranks or else last, until one is strictly collision-free
  /// (and, with RobotGate, followed by the robot: RobotFollows); the one with the fewest
  /// colliding stations is kept (Orientation's CandidateRank; of equals one the robot follows,
  /// else the earlier rank). The
  /// search runs once: a rank change only re-places the part. Why: the search scores sub-graph
  /// orders, not toolpaths (no axis tilts, no collision inside a sub-graph), so two close
  /// candidates can print the other way round. `starting` (optional) is called before each try
  /// after the first. Nothing is tried with Orient Keep, tries < 2 or a stop request (Ctrl-C).
  std::vector<OrientationTry> ChooseOrientationByToolpath(
      int tries, const std::function<void(const OrientationTry&)>& starting = {});

  /// One pedestal height run through the toolpath verifier by RaisePedestalByToolpath.
  struct PedestalTry {
    double height = 0;        ///< mm
    bool ok = false;          ///< the stages ran
    long long colliding = 0;  ///< strict toolpath stations with the nozzle in material/plate
    long long plate = 0;      ///< of them, at the build plate
    long long stations = 0;   ///< stations checked
    double seconds = 0;
  };

  /// A taller pedestal where the toolpath meets the build plate, with Orient Auto and the
  /// automatic pedestal (after ChooseOrientationByToolpath): when the part stands on the search's
  /// pedestal of h mm and stations of its toolpath have the plate in the nozzle, the same
  /// orientation on pedestals of 2h and 3h mm runs through the toolpath verifier, until one has
  /// no plate station, and the height with the fewest colliding stations is kept (the
  /// pedestal's HeightOverride; the lower on a tie). Why: the search scores its pedestal at one
  /// height (10 mm by default) on a coarse mesh without axis tilts; where the lowest layers
  /// overhang far, the tilted nozzle reaches further down than that (the knight: 71 plate
  /// stations on 10 mm, none on 20). The first entry is h's own (from the current outputs).
  /// `starting` (optional) is called before each taller one. Nothing is tried otherwise (Orient
  /// Keep, a pedestal asked for or none, a tet-mesh input, no pedestal chosen, no plate station)
  /// or after a stop request (Ctrl-C).
  std::vector<PedestalTry> RaisePedestalByToolpath(
      const std::function<void(const PedestalTry&)>& starting = {});

  /// One print order run through the toolpath verifier by ChooseOrderByToolpath.
  struct OrderTry {
    int strategy = 0;         ///< vtkGLPrintSequencer::LPT .. BEST
    bool ok = false;          ///< the stages ran
    long long colliding = 0;  ///< strict toolpath stations with the nozzle in material/plate
    long long stations = 0;   ///< stations checked
    double seconds = 0;
  };

  /// The print order the real toolpath prints best, for the sequencer's Best strategy with Orient
  /// Auto (the mode that searches for a set-up that prints; after RaisePedestalByToolpath):
  /// when the toolpath of Best's order collides, the layer-priority and the depth-priority orders
  /// (LPT, DPT) run through the toolpath verifier too, until one is strictly collision-free, and
  /// the order with the fewest colliding stations is kept (the sequencer's StrategyOverride; Best
  /// on a tie). With Orient Keep the part and the order are printed as asked (and fast: each try
  /// plans a whole toolpath). Why: Best, like the paper's A4, orders whole sub-graphs by the collisions of a nozzle
  /// along their normals; where every such order collides it forces the step blocked by the
  /// fewest sub-graphs, and that can leave collisions the planner's axis tilts cannot clear
  /// where printing layer by layer leaves none (a coil over a disc: 78 colliding stations with
  /// Best's order, 0 with LPT's). The first entry is Best's own (from the current outputs).
  /// `starting` (optional) is called before each other order. Nothing is tried with Orient Keep
  /// or a tet-mesh input, for another strategy, when Best's toolpath is collision-free or
  /// collides only with the build plate (no order moves it), or after a stop request (Ctrl-C).
  std::vector<OrderTry> ChooseOrderByToolpath(
      const std::function<void(const OrderTry&)>& starting = {});

  /// The step of FindAPrintableSetUp that chose another set-up.
  enum class SetUpStep { Orientation, Pedestal, Order };
  /// What FindAPrintableSetUp tried: each list empty when its step did not run; a list of one
  /// entry is the current set-up alone (nothing else was tried).
  struct SetUpTries {
    std::vector<OrientationTry> orientations;
    std::vector<PedestalTry> pedestals;
    std::vector<OrderTry> orders;
  };
  /// Called before each other set-up FindAPrintableSetUp runs (each optional).
  struct SetUpListener {
    std::function<void(const OrientationTry&)> orientation;
    std::function<void(const PedestalTry&)> pedestal;
    std::function<void(const OrderTry&)> order;
  };

  /// The set-up the real toolpath prints (Orient Auto; the one sequence of tries for the CLI and
  /// GL Print Part): after the stages ran, while the toolpath collides (or, with RobotGate, is
  /// collision-free but the robot cannot follow it: then the orientations only),
  /// ChooseOrientationByToolpath (OrientationTries), then RaisePedestalByToolpath, then
  /// ChooseOrderByToolpath. After a step that ran another set-up, `runStages(step)` is called to
  /// bring every stage (and whatever the caller keeps of them: files, a report) to the one it
  /// chose, read from the cache when that was the last tried; it may throw, which ends the
  /// search. Nothing is tried with Orient Keep, a tet-mesh input, a collision-free toolpath or
  /// after a stop request.
  SetUpTries FindAPrintableSetUp(const std::function<void(SetUpStep)>& runStages,
                                 const SetUpListener& listener = {});

  /// Candidates ChooseOrientationByToolpath runs at most (CLI --orient-tries, GL Print Part
  /// OrientTries; 1 = the search's best only).
  int OrientationTries = 3;

  /// Whether a set-up also needs the robot to follow its toolpath (the CLI sets it when it
  /// writes the programs): FindAPrintableSetUp then asks ScriptWriter (SolveRobotPath, kept
  /// for the program) about a collision-free toolpath, and ChooseOrientationByToolpath goes on
  /// to the next candidate where the robot cannot follow it (a small mushroom as placed and
  /// as the search's best: no configuration keeps the arm off the nozzle and off the part).
  /// Set it before MatchOrientationToPrint: the search then ranks sides too tall for the cell
  /// last (a 120 mm column stands in none: it lies down).
  bool RobotGate = false;

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
  /// The toolpath verifier brought up to date: whether it ran, its colliding and checked
  /// stations (-1 when missing) and the seconds it took.
  struct ToolpathVerdict {
    bool ok = false;
    long long colliding = -1, plate = -1, stations = -1;  ///< plate: of colliding, at the plate
    double seconds = 0;
  };
  ToolpathVerdict UpdateToolpathVerdict();

  /// With RobotGate, whether the robot follows the current toolpath (ScriptWriter's
  /// SolveRobotPath; the solution is kept for the program). Fills t's robot fields.
  bool RobotFollows(OrientationTry& t);

  /// With Orient Auto: the orientation search brought up to date and its candidates' point data
  /// (one point per candidate: rank, scores, source), or null (Keep, a tet mesh, a failure).
  vtkPointData* OrientationCandidates();

  bool TetMeshInput = false;
};

#endif  // __VTK_WRAP__
#endif
