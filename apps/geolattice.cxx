// geolattice: command-line front end. It builds the same VTK pipeline as the ParaView plugin and
// the pvpython scripts (reader -> placement -> tetrahedralization -> geodesic fields -> ...)
// and writes every stage's output plus report.json into the output directory.
#include "JsonWriter.h"
#include "OutputFiles.h"

#include "common/Error.h"
#include "CliOptions.h"
#include "ErrorCapture.h"
#include "SequenceCsv.h"
#include "ToolpathOutput.h"
#include "VerifyCommand.h"
#include "vtkGLArrayNames.h"
#include "vtkGLCollisionVerifier.h"
#include "vtkGLCurvedLayerSlicer.h"
#include "vtkGLGeodesicDistanceFields.h"
#include "vtkGLLatticeInfill.h"
#include "vtkGLMeshReader.h"
#include "vtkGLOverhangAnalysis.h"
#include "vtkGLPlaceOnPlatform.h"
#include "vtkGLPrintSequencer.h"
#include "vtkGLSkeletonTree.h"
#include "vtkGLTetrahedralizeSurface.h"
#include "vtkGLToolpathPlanner.h"
#include "vtkGLGCodeWriter.h"
#include "vtkGLURScriptWriter.h"
#include "vtkGLWaypointCsvWriter.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWriter.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace gl = geolattice;
using Clock = std::chrono::steady_clock;

constexpr const char* kStages[] = {"mesh",     "gdf",      "layers", "lattice",
                                   "sequence", "toolpath", "program"};
constexpr const char* kScriptFile = "print_part.script";  // + print_part_1.script, ... when split
constexpr const char* kGCodeFile = "toolpath.gcode";
constexpr const char* kWaypointFile = "waypoints.csv";
constexpr const char* kStrategies[] = {"lpt", "dpt", "a4",
                                       "best"};  // = vtkGLPrintSequencer::Strategy 0..3

const char* kUsage =
    R"(geolattice - multi-axis support-free printing with lattice infill (GeoLattice )" GEOLATTICE_VERSION
    R"()

Usage:
  geolattice run MODEL -o OUTDIR [options]
  geolattice verify OUTDIR [nozzle options] [--allow-unavoidable]
  geolattice --help | --version

MODEL is a closed triangle surface (.stl .obj .ply .vtp .off) or a tet mesh (.vtu .tet .node
.ele; a tet mesh skips meshing). Outputs in OUTDIR: tets.vtu (the tet mesh), fields.vtu (tets
with Gamma, Alpha, Beta), layers.vtp (curved layers, cell array LayerId), overhang.vtp (the
part's surface with the overhang angles of planar and curved slicing), lattice.vtp (the lattice
infill graph of every layer: line cells with EdgeKind, LayerId, SubgraphId and, after the
sequence stage, PrintOrder), skeleton.vtp (one node per connected sub-graph, tree edges, point
array PrintOrder), sequence.vtp (the printing order as a polyline through the sub-graphs' start
points), sequence.csv (order, sub-graph, layer, start and end point, retraction), collisions.vtp
(the first nozzle collisions found by the verifier), toolpath.vtp (the printing path: points in
printing order with Normals = nozzle axis, Thickness, Width, Extrusion, FeedRate, MoveKind
(0 print, 1 support perimeter, 2 air), LayerId, SubgraphId, PathIndex, PointIndex; one polyline
per run of one kind), toolpath.pvd with toolpath/step_NNNN.vtp (the print replay: open
toolpath.pvd in ParaView and press Play; step k holds everything printed up to progress
k/steps), toolpath_collisions.vtp (the verifier on the toolpath, every point a nozzle station,
only printed points as material), print_part.script (the URScript program of the robot cell: a
UR5/UR5e holds the part under a fixed nozzle; split at air moves into print_part_1.script,
print_part_2.script, ... below --max-script-bytes, run one after the other), toolpath.gcode
(5-axis G-code for an A-C or B-C tilting-rotary table), waypoints.csv (x,y,z,nx,ny,nz,e,kind,layer
per toolpath point), report.json (per stage: seconds, counts, results). Files are written to a
temporary name first, so nothing partial is left behind on failure.

`verify OUTDIR` re-checks with the independent collision verifier the newer of toolpath.vtp
(every point at its own time) and lattice.vtp (sub-graphs at their PrintOrder), nozzle from
report.json unless given; exit status 0 when collision-free, 3 when the nozzle hits earlier
material (with --allow-unavoidable: only when an order could have avoided it).

Options:
  -o, --output DIR        output directory (created if missing)                     [required]
  --until STAGE           last stage: mesh | gdf | layers | lattice | sequence | toolpath |
                          program                                                    [program]
 Model placement (models come in arbitrary units; GeoLattice works in millimetres):
  --scale F               uniform scale factor applied to the model                  [1]
  --fit-size MM           scale so the largest bounding-box side is MM (replaces --scale) [off]
  --no-center             keep x and y as they are (default: bounding box centred on x = y = 0)
                          The base is always moved to the platform, z = 0.
 Tetrahedral meshing (TetGen):
  --edge-length MM        target tet edge length; 0 = automatic (see --target-tets)  [0]
  --target-tets N         tet count the automatic edge length aims at                [75000]
  --radius-edge R         TetGen radius-edge ratio bound (quality; 1.414 = sqrt 2)   [1.414]
 Geodesic distance fields (heat method, paper Eqs. 1-5):
  --base MODE             base (heat source): lowest | faces                         [lowest]
                          lowest: vertices within --base-tolerance of the lowest z;
                          faces: vertices of boundary faces facing down within --base-angle
  --base-tolerance MM     height band above the lowest point that is the base        [0.05]
  --base-angle DEG        max angle between a base face's outward normal and -z      [10]
  --time-factor F         heat time t = F * h^2 (h = mean edge length)               [4]
  --reference X,Y,Z       reference vector r of Eq. 3 (sets the lattice directions)  [1,0,0]
  --solver NAME           cholmod | eigen (sparse Cholesky back end)                 [cholmod]
 Curved layers (iso-surfaces of Gamma):
  --layer-interval MM     γ distance between layers (nominal layer thickness)        [0.6]
  --first-layer MM        γ of the first layer                      [= --layer-interval]
  --overhang-threshold DEG  overhang angle above which a surface needs support       [135]
 Lattice infill (iso-lines of Alpha and Beta on each layer, paper Algorithm 1):
  --lattice-width MM      distance between lattice lines, both directions            [4]
  --alpha-width MM        distance between α lines (overrides --lattice-width)
  --beta-width MM         distance between β lines (overrides --lattice-width)
  --alpha-phase MM        offset of the α levels                                     [0]
  --beta-phase MM         offset of the β levels                                     [0]
  --min-subgraph MM       drop connected lattice pieces shorter than this            [0]
 Printing sequence (skeleton tree, paper Section 3.1) and collision check:
  --strategy NAME         lpt | dpt | a4 | best (best = rollout of a4, never worse)  [best]
  --nozzle-angle DEG      half-angle NA of the nozzle's bounding cone, in (0, 90)    [45]
  --nozzle-length MM      cone length; above it the holder (0 = cone only)           [0]
  --holder-radius MM      radius of the holder cylinder above the nozzle length      [0]
  --tip-clearance MM      ignore material at most this high above the nozzle tip     [0.1]
  --tip-face-radius MM    ignore material this close to the tip (under the nozzle's
                          flat face, which presses the bead)                          [0.5]
  --sample-spacing MM     spacing of the material samples tested for collisions      [1]
 Toolpath (paper Section 3.2: Euler tours, thickness Eq. 15, extrusion Eq. 14, air moves):
  --path-width MM         path (bead) width w                                        [0.6]
  --filament-diameter MM  raw filament diameter; Eq. 14 uses the radius r_m = MM / 2 [1.75]
  --flow MU               flow correction mu of Eq. 14, in (0, 1]                    [0.95]
  --print-speed MM/S      nozzle feed rate of print moves                            [10]
  --air-speed MM/S        nozzle feed rate of air moves                              [50]
  --thickness-cap L       layer thickness capped at L x the layer interval (Eq. 15)  [1.5]
  --max-turn DEG          largest nozzle axis change between points (rotation steps) [5]
  --max-segment MM        subdivide longer path segments (0 = never)                 [1]
  --max-tilt DEG          largest tilt of the nozzle axis off the layer normal where
                          the normal would hit earlier material (0 = never tilt)     [15]
  --tilt-blend MM         path length over which such a tilt fades out               [5]
  --safe-margin MM        margin of the safe box air moves travel on (Fig. 18)       [5]
  --lift MM               lift along the axis for a hop onto an upper sub-graph      [2]
  --retraction MM         filament retracted before each air move, primed after it   [1]
  --tooth-length MM       support perimeter tooth length along trimmed edges, 0 = 2w [0]
  --no-perimeter          no support perimeter where boundary edges were trimmed
  --replay-steps N        step files of the print replay (toolpath.pvd); fewer for
                          long paths (all steps together <= ~2 million points);
                          0 = no replay files                                        [50]
 Programs (paper Section 4: the robot holds the part, the nozzle is fixed; robot cell in metres
 in the robot base frame, toolpath mm scaled by 0.001):
  --robot NAME            ur5 | ur5e                                                 [ur5]
  --nozzle-tip X,Y,Z      nozzle tip position (m)                           [0,-0.4,0.3]
  --nozzle-axis X,Y,Z     nozzle body direction from the tip into the nozzle    [0,0,1]
  --part-offset M         the platform plate M metres in front of the flange, part z
                          along the flange z (TCP = p[0,0,M,0,0,0])                  [0.04]
  --part-on-flange X,Y,Z,RX,RY,RZ  the part (platform) frame on the flange as a URScript
                          pose (m, rotation vector in rad); replaces --part-offset
  --max-script-bytes N    split the program into files below N bytes, at air moves
                          (UR controllers reject very large scripts)              [4000000]
  --speed-factor F        fraction of the joint speed limits used, in (0, 1]         [0.5]
  --max-filament-rate MM/S  filament rate at analog output 0 level 1 (10 V)          [5]
  --max-blend M           largest movel blend radius (m)                          [0.0005]
  --max-joint-step DEG    largest joint change between points; the joint path is
                          re-planned around larger ones, any left is an error        [20]
  --allow-unreachable     write the program even if points are unreachable (the robot
                          holds still there; for simulation). Default: error, no program
  --gcode KIN             5-axis G-code table kinematics: ac | bc | none              [ac]
  --gcode-pivot X,Y,Z     machine position of the rotary axes' intersection (mm)  [0,0,0]
  --gcode-offset X,Y,Z    part frame origin relative to the rotary centre (mm)    [0,0,0]
  --tilt-limits MIN,MAX   limits of the tilt axis A or B (degrees)             [-120,120]
 Output:
  -q, --quiet             no progress lines on stdout

Progress goes to stdout. Exit status: 0 on success; 1 on an error (one line on stderr naming
the problem); 2 on bad usage (one line on stderr); 3 (verify only) on a collision.
)";

struct Options {
  std::string model;
  std::string outDir;
  std::string until = "program";
  double scale = 1.0;
  double fitSize = 0.0;
  bool center = true;
  double edgeLength = 0.0;
  double targetTets = 75000;
  double radiusEdge = 1.414;
  std::string base = "lowest";
  double baseTolerance = 0.05;
  double baseAngle = 10.0;
  double timeFactor = 4.0;
  double reference[3] = {1, 0, 0};
  std::string solver = "cholmod";
  double layerInterval = 0.6;
  double firstLayer = -1;  // < 0: equal to layerInterval
  double overhangThreshold = 135.0;
  double latticeWidth = 4.0;
  double alphaWidth = -1;  // < 0: latticeWidth
  double betaWidth = -1;
  double alphaPhase = 0;
  double betaPhase = 0;
  double minSubgraph = 0;
  std::string strategy = "best";
  geolattice::NozzleOptions nozzle;
  geolattice::ToolpathCliOptions toolpath;
  geolattice::ProgramCliOptions program;
  bool quiet = false;
};

using geolattice::parseNumber;
using geolattice::UsageError;

Options parseArguments(int argc, char** argv) {
  Options o;
  if (argc < 2) {
    throw UsageError("missing command (try --help)");
  }
  const std::string command = argv[1];
  if (command != "run") {
    throw UsageError("unknown command '" + command + "' (try --help)");
  }
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        throw UsageError(arg + " needs a value");
      }
      return argv[++i];
    };
    if (arg == "-o" || arg == "--output")
      o.outDir = value();
    else if (arg == "--until")
      o.until = value();
    else if (arg == "--scale")
      o.scale = parseNumber(arg, value());
    else if (arg == "--fit-size")
      o.fitSize = parseNumber(arg, value());
    else if (arg == "--no-center")
      o.center = false;
    else if (arg == "--edge-length")
      o.edgeLength = parseNumber(arg, value());
    else if (arg == "--target-tets")
      o.targetTets = parseNumber(arg, value());
    else if (arg == "--radius-edge")
      o.radiusEdge = parseNumber(arg, value());
    else if (arg == "--base")
      o.base = value();
    else if (arg == "--base-tolerance")
      o.baseTolerance = parseNumber(arg, value());
    else if (arg == "--base-angle")
      o.baseAngle = parseNumber(arg, value());
    else if (arg == "--time-factor")
      o.timeFactor = parseNumber(arg, value());
    else if (arg == "--reference") {
      std::stringstream ss(value());
      std::string part;
      int k = 0;
      while (std::getline(ss, part, ',')) {
        if (k == 3) {
          throw UsageError("--reference expects X,Y,Z");
        }
        o.reference[k++] = parseNumber("--reference", part);
      }
      if (k != 3) {
        throw UsageError("--reference expects X,Y,Z");
      }
    } else if (arg == "--solver")
      o.solver = value();
    else if (arg == "--layer-interval")
      o.layerInterval = parseNumber(arg, value());
    else if (arg == "--first-layer")
      o.firstLayer = parseNumber(arg, value());
    else if (arg == "--overhang-threshold")
      o.overhangThreshold = parseNumber(arg, value());
    else if (arg == "--lattice-width")
      o.latticeWidth = parseNumber(arg, value());
    else if (arg == "--alpha-width")
      o.alphaWidth = parseNumber(arg, value());
    else if (arg == "--beta-width")
      o.betaWidth = parseNumber(arg, value());
    else if (arg == "--alpha-phase")
      o.alphaPhase = parseNumber(arg, value());
    else if (arg == "--beta-phase")
      o.betaPhase = parseNumber(arg, value());
    else if (arg == "--min-subgraph")
      o.minSubgraph = parseNumber(arg, value());
    else if (arg == "--strategy")
      o.strategy = value();
    else if (o.nozzle.parse(arg, value)) {
    } else if (o.toolpath.parse(arg, value)) {
    } else if (o.program.parse(arg, value)) {
    } else if (arg == "-q" || arg == "--quiet")
      o.quiet = true;
    else if (!arg.empty() && arg[0] == '-')
      throw UsageError("unknown option " + arg);
    else if (o.model.empty())
      o.model = arg;
    else
      throw UsageError("unexpected argument '" + arg + "'");
  }
  if (o.model.empty()) {
    throw UsageError("missing MODEL");
  }
  if (o.outDir.empty()) {
    throw UsageError("missing -o OUTDIR");
  }
  if (std::find(std::begin(kStages), std::end(kStages), o.until) == std::end(kStages)) {
    throw UsageError(
        "--until must be one of: mesh, gdf, layers, lattice, sequence, toolpath, program (got '" +
        o.until + "')");
  }
  if (std::find(std::begin(kStrategies), std::end(kStrategies), o.strategy) ==
      std::end(kStrategies)) {
    throw UsageError("--strategy must be one of: lpt, dpt, a4, best (got '" + o.strategy + "')");
  }
  if (o.base != "lowest" && o.base != "faces") {
    throw UsageError("--base must be lowest or faces (got '" + o.base + "')");
  }
  if (o.solver != "cholmod" && o.solver != "eigen") {
    throw UsageError("--solver must be cholmod or eigen (got '" + o.solver + "')");
  }
  if (o.firstLayer < 0) {
    o.firstLayer = o.layerInterval;
  }
  if (o.alphaWidth < 0) {
    o.alphaWidth = o.latticeWidth;
  }
  if (o.betaWidth < 0) {
    o.betaWidth = o.latticeWidth;
  }
  // Parameter ranges are checked by the filters themselves, with the same messages as in ParaView.
  return o;
}

/// Swallows VTK's console output; the messages that matter reach the CLI through ErrorCapture.
class SilentOutputWindow : public vtkOutputWindow {
public:
  static SilentOutputWindow* New() { return new SilentOutputWindow; }
  vtkTypeMacro(SilentOutputWindow, vtkOutputWindow);
  void DisplayText(const char*) override {}
};

/// While alive, prints " 25%", " 50%", " 75%" on the current stage line as the progress events of
/// `algorithm` pass them (the long stages; nothing when disabled, e.g. with -q).
class ProgressPrinter {
public:
  ProgressPrinter(vtkAlgorithm* algorithm, bool enabled)
      : Algorithm(enabled ? algorithm : nullptr) {
    if (this->Algorithm) {
      this->Command->SetClientData(&this->Next);
      this->Command->SetCallback([](vtkObject*, unsigned long, void* client, void* call) {
        int& next = *static_cast<int*>(client);
        const double p = call ? *static_cast<double*>(call) : 0.0;
        for (; next <= 3 && p >= 0.25 * next; ++next) {
          std::cout << " " << 25 * next << "%" << std::flush;
        }
      });
      this->Tag = this->Algorithm->AddObserver(vtkCommand::ProgressEvent, this->Command);
    }
  }
  ~ProgressPrinter() {
    if (this->Algorithm) {
      this->Algorithm->RemoveObserver(this->Tag);
    }
  }
  ProgressPrinter(const ProgressPrinter&) = delete;
  ProgressPrinter& operator=(const ProgressPrinter&) = delete;

private:
  vtkAlgorithm* Algorithm;
  vtkNew<vtkCallbackCommand> Command;
  unsigned long Tag = 0;
  int Next = 1;  ///< the next quarter to print
};

/// The stages that can take long enough for a percentage on their line.
bool isLongStage(const std::string& stage) {
  return stage == "mesh" || stage == "gdf" || stage == "lattice" || stage == "sequence" ||
         stage == "toolpath";
}

double fieldValue(vtkDataObject* data, const char* name, int component = 0) {
  vtkDataArray* a = vtkDataArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
  return a && a->GetNumberOfTuples() > component ? a->GetTuple1(component) : 0.0;
}

class Pipeline {
public:
  explicit Pipeline(const Options& o) : Opt(o) {}

  int Run() {
    gl::prepareOutputDirectory(Opt.outDir);
    gl::JsonObject report;
    report.set("geolattice_version", GEOLATTICE_VERSION);
    report.set("model", Opt.model);
    const bool isTetMesh = vtkGLMeshReader::IsTetMeshFile(Opt.model.c_str());

    // Stage: read + place on the platform.
    vtkNew<vtkGLMeshReader> reader;
    reader->SetFileName(Opt.model.c_str());
    vtkNew<vtkGLPlaceOnPlatform> place;
    place->SetInputConnection(reader->GetOutputPort());
    place->SetScale(Opt.scale);
    place->SetFitSize(Opt.fitSize);
    place->SetCenterXY(Opt.center);
    vtkDataObject* placed = this->Execute("input", {reader, place}, place);
    {
      auto& s = report.object("input");
      s.set("seconds", this->LastSeconds);
      s.set("file", Opt.model);
      s.set("points",
            static_cast<long long>(vtkDataSet::SafeDownCast(placed)->GetNumberOfPoints()));
      s.set(isTetMesh ? "tets" : "triangles",
            static_cast<long long>(vtkDataSet::SafeDownCast(placed)->GetNumberOfCells()));
      s.set("scale", fieldValue(placed, gl::arrays::PlacementScale));
      s.set("translation",
            std::vector<double>{fieldValue(placed, gl::arrays::PlacementTranslation, 0),
                                fieldValue(placed, gl::arrays::PlacementTranslation, 1),
                                fieldValue(placed, gl::arrays::PlacementTranslation, 2)});
      double b[6];
      vtkDataSet::SafeDownCast(placed)->GetBounds(b);
      s.set("size_mm", std::vector<double>{b[1] - b[0], b[3] - b[2], b[5] - b[4]});
    }

    // Stage: tetrahedral mesh (skipped for tet-mesh input).
    vtkAlgorithm* tetSource = place;
    vtkNew<vtkGLTetrahedralizeSurface> tetrahedralize;
    {
      auto& s = report.object("mesh");
      vtkDataObject* tets = nullptr;
      if (isTetMesh) {
        tets = placed;
        s.set("seconds", 0.0);
        s.set("meshed", false);
      } else {
        tetrahedralize->SetInputConnection(place->GetOutputPort());
        tetrahedralize->SetTargetEdgeLength(Opt.edgeLength);
        tetrahedralize->SetRadiusEdgeRatio(Opt.radiusEdge);
        tetrahedralize->SetTargetTetCount(static_cast<int>(std::min(Opt.targetTets, 2e9)));
        tets = this->Execute("mesh", {tetrahedralize}, tetrahedralize);
        tetSource = tetrahedralize;
        s.set("seconds", this->LastSeconds);
        s.set("meshed", true);
        s.set("target_edge_length_mm", fieldValue(tets, gl::arrays::TargetEdgeLength));
        s.set("mean_edge_length_mm", fieldValue(tets, gl::arrays::MeanEdgeLength));
      }
      s.set("points", static_cast<long long>(vtkDataSet::SafeDownCast(tets)->GetNumberOfPoints()));
      s.set("tets", static_cast<long long>(vtkDataSet::SafeDownCast(tets)->GetNumberOfCells()));
      this->Write(tets, "tets.vtu");
    }
    if (Opt.until == "mesh") {
      return this->Finish(report);
    }

    // Stage: geodesic distance fields.
    vtkNew<vtkGLGeodesicDistanceFields> gdf;
    gdf->SetInputConnection(tetSource->GetOutputPort());
    gdf->SetSourceMode(Opt.base == "faces" ? vtkGLGeodesicDistanceFields::DOWNWARD_FACES
                                           : vtkGLGeodesicDistanceFields::LOWEST_Z);
    gdf->SetBaseTolerance(Opt.baseTolerance);
    gdf->SetBaseFaceAngle(Opt.baseAngle);
    gdf->SetTimeFactor(Opt.timeFactor);
    gdf->SetReferenceVector(Opt.reference);
    gdf->SetUseCholmod(Opt.solver == "cholmod");
    vtkDataObject* fields = this->Execute("gdf", {gdf}, gdf);
    {
      auto& s = report.object("gdf");
      s.set("seconds", this->LastSeconds);
      s.set("points",
            static_cast<long long>(vtkDataSet::SafeDownCast(fields)->GetNumberOfPoints()));
      s.set("tets", static_cast<long long>(vtkDataSet::SafeDownCast(fields)->GetNumberOfCells()));
      s.set("sources", static_cast<long long>(fieldValue(fields, gl::arrays::SourceCount)));
      s.set("gamma_max", fieldValue(fields, gl::arrays::GammaRange, 1));
      s.set("alpha_max", fieldValue(fields, gl::arrays::AlphaRange, 1));
      s.set("beta_max", fieldValue(fields, gl::arrays::BetaRange, 1));
      s.set("assembly_seconds", fieldValue(fields, gl::arrays::GdfTimings, 0));
      s.set("factorization_seconds", fieldValue(fields, gl::arrays::GdfTimings, 1));
      s.set("solve_seconds", fieldValue(fields, gl::arrays::GdfTimings, 2));
      s.set("reference_fallback_tets",
            static_cast<long long>(fieldValue(fields, gl::arrays::ReferenceFallbackTets)));
      auto& o = s.object("orthogonality_deviation_deg");
      o.set("alpha_gamma_median", fieldValue(fields, gl::arrays::OrthogonalityDeg, 0));
      o.set("alpha_gamma_p95", fieldValue(fields, gl::arrays::OrthogonalityDeg, 1));
      o.set("beta_gamma_median", fieldValue(fields, gl::arrays::OrthogonalityDeg, 2));
      o.set("beta_gamma_p95", fieldValue(fields, gl::arrays::OrthogonalityDeg, 3));
      this->Write(fields, "fields.vtu");
    }
    if (Opt.until == "gdf") {
      return this->Finish(report);
    }

    // Stage: curved layers.
    vtkNew<vtkGLCurvedLayerSlicer> slicer;
    slicer->SetInputConnection(gdf->GetOutputPort());
    slicer->SetLayerInterval(Opt.layerInterval);
    slicer->SetFirstLayerOffset(Opt.firstLayer);
    vtkDataObject* layers = this->Execute("layers", {slicer}, slicer);
    {
      auto& s = report.object("layers");
      s.set("seconds", this->LastSeconds);
      vtkFieldData* fd = layers->GetFieldData();
      const vtkIdType count = fd->GetArray(gl::arrays::LayerValues)->GetNumberOfTuples();
      s.set("count", static_cast<long long>(count));
      s.set("interval", Opt.layerInterval);
      s.set("first_layer", Opt.firstLayer);
      s.set("points",
            static_cast<long long>(vtkDataSet::SafeDownCast(layers)->GetNumberOfPoints()));
      s.set("triangles",
            static_cast<long long>(vtkDataSet::SafeDownCast(layers)->GetNumberOfCells()));
      double range[2];
      fd->GetArray(gl::arrays::LayerComponents)->GetRange(range);
      s.set("components_max", static_cast<long long>(range[1]));
      auto nanRange = [fd](const char* name, bool wantMin) {
        vtkDataArray* a = fd->GetArray(name);
        double best = wantMin ? std::numeric_limits<double>::infinity()
                              : -std::numeric_limits<double>::infinity();
        for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i) {
          const double v = a->GetTuple1(i);
          if (!std::isnan(v)) {
            best = wantMin ? std::min(best, v) : std::max(best, v);
          }
        }
        return best;
      };
      auto& spacing = s.object("spacing_mm");
      spacing.set("min", nanRange(gl::arrays::LayerSpacingMin, true));
      spacing.set("mean_min", nanRange(gl::arrays::LayerSpacingMean, true));
      spacing.set("mean_max", nanRange(gl::arrays::LayerSpacingMean, false));
      spacing.set("max", nanRange(gl::arrays::LayerSpacingMax, false));
      this->Write(layers, "layers.vtp");
    }

    // Overhang of the part's surface, planar (nozzle +z) against curved (nozzle ∇γ).
    vtkNew<vtkGLOverhangAnalysis> overhang;
    overhang->SetInputConnection(gdf->GetOutputPort());
    overhang->SetThresholdAngle(Opt.overhangThreshold);
    vtkDataObject* surface = this->Execute("overhang", {overhang}, overhang);
    {
      auto& s = report.object("overhang");
      s.set("seconds", this->LastSeconds);
      s.set("threshold_deg", fieldValue(surface, gl::arrays::OverhangThresholdDeg));
      s.set("planar_fraction", fieldValue(surface, gl::arrays::OverhangPlanarFraction));
      s.set("curved_fraction", fieldValue(surface, gl::arrays::OverhangCurvedFraction));
      s.set("surface_area_mm2", fieldValue(surface, gl::arrays::OverhangTotalArea));
      s.set("base_area_mm2", fieldValue(surface, gl::arrays::OverhangBaseArea));
      this->Write(surface, "overhang.vtp");
    }
    if (Opt.until == "layers") {
      return this->Finish(report);
    }

    // Stage: lattice infill on every layer.
    vtkNew<vtkGLLatticeInfill> lattice;
    lattice->SetInputConnection(slicer->GetOutputPort(0));
    lattice->SetAlphaWidth(Opt.alphaWidth);
    lattice->SetBetaWidth(Opt.betaWidth);
    lattice->SetAlphaPhase(Opt.alphaPhase);
    lattice->SetBetaPhase(Opt.betaPhase);
    lattice->SetMinimumSubgraphLength(Opt.minSubgraph);
    vtkDataObject* graph = this->Execute("lattice", {lattice}, lattice, /*allowEmpty=*/true);
    {
      auto& s = report.object("lattice");
      s.set("seconds", this->LastSeconds);
      s.set("alpha_width", Opt.alphaWidth);
      s.set("beta_width", Opt.betaWidth);
      auto count = [graph](const char* name) {
        return static_cast<long long>(fieldValue(graph, name));
      };
      s.set("vertices", count(gl::arrays::LatticeVertices));
      s.set("edges", count(gl::arrays::LatticeEdges));
      s.set("subgraphs", count(gl::arrays::LatticeSubgraphs));
      s.set("crossings", count(gl::arrays::LatticeCrossings));
      s.set("boundary_hits", count(gl::arrays::LatticeBoundaryHits));
      s.set("isoline_edges", count(gl::arrays::LatticeIsolineEdges));
      s.set("dropped_subgraphs", count(gl::arrays::LatticeDroppedSubgraphs));
      s.set("irregular_vertices", count(gl::arrays::LatticeIrregularVertices));
      this->Write(graph, "lattice.vtp");
    }
    if (Opt.until == "lattice") {
      return this->Finish(report);
    }

    // Stage: skeleton tree, printing order, independent collision check.
    vtkNew<vtkGLSkeletonTree> skeleton;
    skeleton->SetInputConnection(0, lattice->GetOutputPort());
    skeleton->SetInputConnection(1, gdf->GetOutputPort());
    vtkDataObject* tree = this->Execute("skeleton", {skeleton}, skeleton);
    {
      auto& s = report.object("skeleton");
      s.set("seconds", this->LastSeconds);
      s.set("nodes", static_cast<long long>(vtkDataSet::SafeDownCast(tree)->GetNumberOfPoints()));
      s.set("edges", static_cast<long long>(vtkDataSet::SafeDownCast(tree)->GetNumberOfCells()));
      s.set("roots", static_cast<long long>(fieldValue(tree, gl::arrays::SkeletonRoots)));
      s.set("split_nodes",
            static_cast<long long>(fieldValue(tree, gl::arrays::SkeletonSplitNodes)));
      s.set("merge_nodes",
            static_cast<long long>(fieldValue(tree, gl::arrays::SkeletonMergeNodes)));
      s.set("floating_nodes",
            static_cast<long long>(fieldValue(tree, gl::arrays::SkeletonFloatingNodes)));
    }
    vtkNew<vtkGLPrintSequencer> sequencer;
    sequencer->SetInputConnection(0, lattice->GetOutputPort());
    sequencer->SetInputConnection(1, skeleton->GetOutputPort());
    sequencer->SetStrategy(
        static_cast<int>(std::find(std::begin(kStrategies), std::end(kStrategies), Opt.strategy) -
                         std::begin(kStrategies)));
    Opt.nozzle.apply(sequencer.Get());
    this->Execute("sequence", {sequencer}, sequencer);
    const double sequenceSeconds = this->LastSeconds;
    vtkDataObject* sequenced = sequencer->GetOutputDataObject(0);
    vtkNew<vtkGLCollisionVerifier> verifier;
    verifier->SetInputConnection(sequencer->GetOutputPort(0));
    Opt.nozzle.apply(verifier.Get());
    vtkDataObject* collisions = this->Execute("verify", {verifier}, verifier, /*allowEmpty=*/true);
    {
      auto& s = report.object("sequence");
      s.set("seconds", sequenceSeconds);
      s.set("verify_seconds", this->LastSeconds);
      s.set("strategy", Opt.strategy);
      Opt.nozzle.report(s);
      s.set("subgraphs",
            static_cast<long long>(vtkDataSet::SafeDownCast(tree)->GetNumberOfPoints()));
      s.set("retractions",
            static_cast<long long>(fieldValue(sequenced, gl::arrays::SequenceRetractions)));
      s.set("air_length_mm", fieldValue(sequenced, gl::arrays::SequenceAirLength));
      s.set("pcg_pairs",
            static_cast<long long>(fieldValue(sequenced, gl::arrays::SequencePcgPairs)));
      s.set("pcg_seconds", fieldValue(sequenced, gl::arrays::SequencePcgSeconds));
      s.set("unavoidable_pcg_pairs",
            static_cast<long long>(fieldValue(sequenced, gl::arrays::SequenceUnavoidablePairs)));
      s.set("forced_steps",
            static_cast<long long>(fieldValue(sequenced, gl::arrays::SequenceForcedSteps)));
      gl::reportCollisions(collisions, s);
      this->Write(sequenced, "lattice.vtp");
      this->Write(sequencer->GetOutputDataObject(1), "skeleton.vtp");
      this->Write(sequencer->GetOutputDataObject(2), "sequence.vtp");
      this->Write(collisions, "collisions.vtp");
      const std::string csv = (std::filesystem::path(Opt.outDir) / "sequence.csv").string();
      gl::writeSequenceCsv(vtkPolyData::SafeDownCast(sequenced),
                           vtkPolyData::SafeDownCast(sequencer->GetOutputDataObject(2)), csv);
      this->Written.push_back(csv);
    }
    if (Opt.until == "sequence") {
      return this->Finish(report);
    }

    // Stage: toolpath (Section 3.2), its collision check (every point a station at its own time,
    // air points no material) and the print replay.
    vtkNew<vtkGLToolpathPlanner> planner;
    planner->SetInputConnection(0, sequencer->GetOutputPort(0));
    planner->SetInputConnection(1, sequencer->GetOutputPort(1));
    Opt.toolpath.apply(planner.Get());
    Opt.nozzle.applyNozzle(planner.Get());
    vtkDataObject* toolpath = this->Execute("toolpath", {planner}, planner);
    const double toolpathSeconds = this->LastSeconds;
    vtkNew<vtkGLCollisionVerifier> toolpathVerifier;
    toolpathVerifier->SetInputConnection(planner->GetOutputPort());
    toolpathVerifier->SetTimeArrayName(gl::arrays::PointIndex);
    Opt.nozzle.apply(toolpathVerifier.Get());
    vtkDataObject* toolpathCollisions =
        this->Execute("verify toolpath", {toolpathVerifier}, toolpathVerifier, /*allowEmpty=*/true);
    {
      auto& s = report.object("toolpath");
      s.set("seconds", toolpathSeconds);
      s.set("verify_seconds", this->LastSeconds);
      Opt.toolpath.report(s);
      gl::reportToolpath(toolpath, s);
      gl::reportCollisions(toolpathCollisions, s);
      this->Write(toolpath, "toolpath.vtp");
      this->Write(toolpathCollisions, "toolpath_collisions.vtp");
      const int steps = gl::replayStepCount(vtkDataSet::SafeDownCast(toolpath)->GetNumberOfPoints(),
                                            Opt.toolpath.replaySteps);
      s.set("replay_steps", steps);
      for (const std::string& path : gl::writeToolpathReplay(planner, Opt.outDir, steps)) {
        this->Written.push_back(path);
      }
    }
    if (Opt.until == "toolpath") {
      return this->Finish(report);
    }

    // Stage: programs (paper Section 4). The URScript program of the UR cell first (when a point
    // is unreachable nothing of this stage is written), then the 5-axis G-code and the waypoints;
    // if one of those fails, the files already written by this stage are removed again.
    {
      if (!Opt.quiet) {
        std::cout << "geolattice: program ..." << std::flush;
      }
      const auto start = Clock::now();
      const std::filesystem::path dir(Opt.outDir);
      auto& s = report.object("program");
      s.set("seconds", 0.0);  // set below; first like in the other sections
      Opt.program.report(s);

      vtkNew<vtkGLURScriptWriter> script;
      script->SetInputConnection(planner->GetOutputPort());
      Opt.program.applyScript(script.Get());
      script->SetFileName((dir / kScriptFile).string().c_str());
      const std::string scriptError =
          RunWriter(script, !Opt.quiet);  // the long writer: joints along the path
      const vtkIdType unreachable = script->GetUnreachableCount();
      std::vector<double> firstUnreachable;
      for (vtkIdType i = 0; i < std::min<vtkIdType>(unreachable, 10); ++i) {
        firstUnreachable.push_back(static_cast<double>(script->GetUnreachablePoint(i)));
      }
      std::ostringstream unreachableText;
      if (unreachable > 0) {
        unreachableText << unreachable << " of " << script->GetNumberOfWaypoints()
                        << " toolpath points are unreachable for the " << Opt.program.robot
                        << " (first:";
        for (size_t i = 0; i < firstUnreachable.size(); ++i) {
          unreachableText << (i ? ", " : " ") << static_cast<long long>(firstUnreachable[i]);
        }
        unreachableText << (unreachable > 10 ? ", ...)" : ")");
      }
      if (!scriptError.empty()) {
        if (!Opt.quiet) {
          std::cout << " failed\n";
        }
        if (unreachable > 0 && !Opt.program.allowUnreachable) {
          throw gl::GeoLatticeError("program: " + unreachableText.str() +
                                    "; nothing written: move --nozzle-tip, --part-offset or "
                                    "--part-on-flange (or --allow-unreachable)");
        }
        throw gl::GeoLatticeError("program: " + scriptError);
      }
      if (unreachable > 0) {
        std::cerr << "geolattice: warning: " << unreachableText.str()
                  << ": the program was written anyway (--allow-unreachable)\n";
      }
      std::vector<std::string> files;
      for (int k = 0; k < script->GetNumberOfFilesWritten(); ++k) {
        files.push_back(std::filesystem::path(script->GetFileWritten(k)).filename().string());
      }
      s.set("waypoints", static_cast<long long>(script->GetNumberOfWaypoints()));
      s.set("moves", static_cast<long long>(script->GetNumberOfMoves()));
      s.set("unreachable", static_cast<long long>(unreachable));
      s.set("unreachable_first", firstUnreachable);
      s.set("files", files);
      s.set("ik_branch", script->GetIKBranch());
      s.set("max_joint_step_deg", script->GetMaxJointStepDeg());
      s.set("max_tip_error_m", script->GetMaxTipError());
      s.set("max_axis_error_deg", script->GetMaxAxisErrorDeg());
      auto& singularity = s.object("min_singularity");
      singularity.set("shoulder_m", script->GetMinShoulderSingularity());
      singularity.set("elbow", script->GetMinElbowSingularity());
      singularity.set("wrist", script->GetMinWristSingularity());
      s.set("max_joint_speed_deg_s", script->GetMaxJointSpeedDegS());
      s.set("duration_s", script->GetDuration());
      s.set("max_line_length", static_cast<long long>(script->GetMaxLineLength()));
      s.set("solve_seconds", script->GetSolveSeconds());

      auto& g = s.object("gcode");
      g.set("kinematics", Opt.program.gcode);
      const std::filesystem::path gcodePath = dir / kGCodeFile;
      if (Opt.program.gcode == "none") {
        std::error_code ec;
        std::filesystem::remove(gcodePath,
                                ec);  // of an earlier run: it would not match this toolpath
      } else {
        vtkNew<vtkGLGCodeWriter> gcode;
        gcode->SetInputConnection(planner->GetOutputPort());
        Opt.program.applyGCode(gcode.Get());
        gcode->SetFileName(gcodePath.string().c_str());
        const std::string error = RunWriter(gcode);
        if (!error.empty() && gcode->GetOutOfLimitsCount() > 0) {
          // The table cannot tilt far enough for some points (axes pointing down, e.g. under an
          // overhang the curved layers print sideways): no G-code, but the robot program and the
          // rest stay valid; the report names the points.
          g.set("written", false);
          g.set("error", error);
          g.set("out_of_limits", static_cast<long long>(gcode->GetOutOfLimitsCount()));
          GCodeSkipped = error;
        } else if (!error.empty()) {
          RemoveFiles(script, {});
          if (!Opt.quiet) {
            std::cout << " failed\n";
          }
          throw gl::GeoLatticeError("program: " + error + " (--tilt-limits, or --gcode none)");
        } else {
          g.set("written", true);
          g.set("file", kGCodeFile);
          g.set("pivot_mm",
                std::vector<double>(Opt.program.gcodePivot, Opt.program.gcodePivot + 3));
          g.set("part_offset_mm",
                std::vector<double>(Opt.program.gcodeOffset, Opt.program.gcodeOffset + 3));
          g.set("tilt_limits_deg",
                std::vector<double>(Opt.program.tiltLimits, Opt.program.tiltLimits + 2));
          g.set("moves", static_cast<long long>(gcode->GetNumberOfMoves()));
          g.set("max_rotary_step_deg", gcode->GetMaxRotaryStepDeg());
          g.set("branch_flips", static_cast<long long>(gcode->GetBranchFlips()));
          g.set("max_axis_error_deg", gcode->GetMaxAxisErrorDeg());
          g.set("forced_rotary_steps", static_cast<long long>(gcode->GetForcedRotarySteps()));
        }
      }

      vtkNew<vtkGLWaypointCsvWriter> csv;
      csv->SetInputConnection(planner->GetOutputPort());
      const std::filesystem::path csvPath = dir / kWaypointFile;
      csv->SetFileName(csvPath.string().c_str());
      const std::string csvError = RunWriter(csv);
      if (!csvError.empty()) {
        RemoveFiles(script, Opt.program.gcode == "none" ? std::string() : gcodePath.string());
        if (!Opt.quiet) {
          std::cout << " failed\n";
        }
        throw gl::GeoLatticeError("program: " + csvError);
      }
      for (int k = 0; k < script->GetNumberOfFilesWritten(); ++k) {
        this->Written.push_back(script->GetFileWritten(k));
      }
      if (Opt.program.gcode != "none" && GCodeSkipped.empty()) {
        this->Written.push_back(gcodePath.string());
      }
      if (!GCodeSkipped.empty()) {
        std::error_code ec;
        std::filesystem::remove(gcodePath,
                                ec);  // of an earlier run: it would not match this toolpath
        std::cout << "geolattice: warning: no G-code written: " << GCodeSkipped << "\n";
      }
      this->Written.push_back(csvPath.string());
      s.set("csv", kWaypointFile);
      s.set("csv_rows", static_cast<long long>(csv->GetNumberOfRows()));

      const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
      s.set("seconds", seconds);
      if (!Opt.quiet) {
        std::cout << " done (" << seconds << " s)\n";
      }
    }
    return this->Finish(report);
  }

private:
  /// Updates `last` (watching every algorithm of the stage for errors) and returns its output;
  /// throws with the stage name if an error was reported or the output is empty (unless
  /// allowEmpty: a lattice wider than the part is a valid, empty result).
  vtkDataObject* Execute(const char* stage, std::initializer_list<vtkAlgorithm*> algorithms,
                         vtkAlgorithm* last, bool allowEmpty = false) {
    if (!Opt.quiet) {
      std::cout << "geolattice: " << stage << " ..." << std::flush;
    }
    geolattice::ErrorCapture errors;
    for (vtkAlgorithm* a : algorithms) {
      errors.Watch(a);
    }
    const auto start = Clock::now();
    {
      const ProgressPrinter percent(last, !Opt.quiet && isLongStage(stage));
      last->Update();
    }
    this->LastSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    vtkDataSet* out = vtkDataSet::SafeDownCast(last->GetOutputDataObject(0));
    if (!Opt.quiet) {
      std::cout << (errors.Message.empty() ? " done" : " failed") << " (" << this->LastSeconds
                << " s)\n";
    }
    if (!errors.Message.empty()) {
      throw gl::GeoLatticeError(std::string(stage) + ": " + errors.Message);
    }
    if (!out || (!allowEmpty && out->GetNumberOfCells() == 0)) {
      throw gl::GeoLatticeError(std::string(stage) + ": produced an empty output");
    }
    return out;
  }

  /// Removes the program files `script` wrote (and `also`, if not empty): a later writer of the
  /// program stage failed, and the stage leaves all its files or none.
  static void RemoveFiles(vtkGLURScriptWriter* script, const std::string& also) {
    std::error_code ec;
    for (int k = 0; k < script->GetNumberOfFilesWritten(); ++k) {
      std::filesystem::remove(script->GetFileWritten(k), ec);
    }
    if (!also.empty()) {
      std::filesystem::remove(also, ec);
    }
  }

  /// Writes with `writer` (errors captured as in Execute) and returns the first error reported,
  /// empty on success. percent: print its progress on the stage line.
  static std::string RunWriter(vtkWriter* writer, bool percent = false) {
    geolattice::ErrorCapture errors;
    errors.Watch(writer);
    const ProgressPrinter printer(writer, percent);
    const int ok = writer->Write();
    if (errors.Message.empty() && !ok) {
      errors.Message = std::string(writer->GetClassName()) + " failed";
    }
    return errors.Message;
  }

  void Write(vtkDataObject* data, const char* name) {
    const std::string path = (std::filesystem::path(Opt.outDir) / name).string();
    gl::writeVtkXml(data, path);
    if (std::find(this->Written.begin(), this->Written.end(), path) == this->Written.end()) {
      this->Written.push_back(path);
    }
  }

  int Finish(gl::JsonObject& report) {
    const std::string path = (std::filesystem::path(Opt.outDir) / "report.json").string();
    gl::writeAtomically(path, [&report](const std::string& tmp) {
      std::ofstream out(tmp);
      report.write(out);
      out << "\n";
      return static_cast<bool>(out);
    });
    this->Written.push_back(path);
    if (!Opt.quiet) {
      std::cout << "geolattice: wrote";
      for (const auto& w : this->Written) {
        std::cout << " " << w;
      }
      std::cout << "\ngeolattice: open them in ParaView (paraview " << Opt.outDir
                << "/fields.vtu) or load the plugin for the filters.\n";
    }
    return 0;
  }

  const Options& Opt;
  double LastSeconds = 0;
  std::string
      GCodeSkipped;  ///< why the optional G-code was not written (empty: written or not asked for)
  std::vector<std::string> Written;
};

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
      std::cout << kUsage;
      return 0;
    }
    if (!std::strcmp(argv[i], "--version")) {
      std::cout << "geolattice " << GEOLATTICE_VERSION << "\n";
      return 0;
    }
  }
  // Errors are captured per algorithm (ErrorEvent observers) and printed once; whatever else VTK
  // would print (e.g. from readers inside a filter) goes to a silent output window.
  vtkNew<SilentOutputWindow> silent;
  vtkOutputWindow::SetInstance(silent);
  try {
    if (argc >= 2 && !std::strcmp(argv[1], "verify")) {
      return geolattice::runVerifyCommand(argc, argv);
    }
    const Options options = parseArguments(argc, argv);
    return Pipeline(options).Run();
  } catch (const UsageError& e) {
    std::cerr << "geolattice: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "geolattice: error: " << e.what() << "\n";
    return 1;
  }
}
