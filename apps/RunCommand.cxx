#include "RunCommand.h"

#include "CliOptions.h"
#include "ErrorCapture.h"
#include "Interrupt.h"
#include "OutputFiles.h"
#include "OrientationCsv.h"
#include "SequenceCsv.h"
#include "StageReports.h"
#include "ToolpathOutput.h"

#include "GLPrintPipeline.h"
#include "common/Error.h"
#include "vtkGLArrayNames.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataSet.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkWriter.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <iostream>
#include <sstream>

namespace geolattice {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// While alive, prints " 25%", " 50%", " 75%" on the current stage line as the progress events of
/// `algorithm` pass them (nothing when disabled, e.g. with -q).
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

/// A stage that failed: report.json names it, stderr gets "STAGE: message".
struct StageError : GeoLatticeError {
  StageError(const std::string& stage, const std::string& message)
      : GeoLatticeError(stage + ": " + message), Stage(stage), Message(message) {}
  std::string Stage, Message;
};

class Run {
public:
  GLPrintPipeline P;
  RunOptions R;

  int Execute() {
    this->Files = OutputRecord(R.outDir);
    this->Report["geolattice_version"] = GEOLATTICE_VERSION;
    this->Report["model"] = R.model;
    prepareOutputDirectory(R.outDir);
    const InterruptHandler interrupt;
    try {
      const int status = this->Stages();
      this->Finish(status);
      return status;
    } catch (const StageError& e) {
      if (InterruptHandler::Interrupted()) {
        this->Report["failed"] = {{"stage", e.Stage}, {"message", "interrupted (Ctrl-C)"}};
        this->Finish(kExitInterrupted);
        std::cerr << "geolattice: interrupted: the " << e.Stage
                  << " stage was stopped by Ctrl-C (report.json names it)\n";
        return kExitInterrupted;
      }
      this->Report["failed"] = {{"stage", e.Stage}, {"message", withFlagNames(e.Message)}};
      this->Finish(kExitError);
      throw GeoLatticeError(e.Stage + ": " + withFlagNames(e.Message));
    }
  }

private:
  int Stages() {
    const bool tetMesh = vtkGLMeshReader::IsTetMeshFile(R.model.c_str());
    P.SetTetMeshInput(tetMesh);
    P.Reader->SetFileName(R.model.c_str());
    if (R.allowCollisions) {
      P.ScriptWriter->SetAllowCollisions(true);
      P.GCodeWriter->SetAllowCollisions(true);
      P.WaypointWriter->SetAllowCollisions(true);
    }

    this->CheckParameters();
    vtkDataObject* placed = this->Update("input", P.Placement, {P.Reader, P.Placement});
    Json& input = this->Section("input");
    input["file"] = R.model;
    reportInput(placed, tetMesh, input);
    if (!R.quiet && input.contains("size_mm")) {
      std::cout << "geolattice: the part is " << input["size_mm"][0].get<double>() << " x "
                << input["size_mm"][1].get<double>() << " x " << input["size_mm"][2].get<double>()
                << " mm (x y z, as placed)\n";
    }

    if (!tetMesh) {
      if (P.Orientation->GetOrient() == vtkGLAutoOrient::AUTO) {  // Keep: it passes the part on
        placed = this->Update("orient", P.Orientation);
        reportOrientation(placed, this->Section("orient"));
        this->Write(P.Orientation->GetOutputDataObject(1), "orientation.vtp");
        this->WriteFile("orientation.csv", [&](const std::string& path) {
          writeOrientationCsv(vtkPolyData::SafeDownCast(P.Orientation->GetOutputDataObject(1)),
                              path);
        });
      }
    } else if (P.Orientation->GetOrient() == vtkGLAutoOrient::AUTO) {
      throw UsageError("--orient auto needs a surface model: " + R.model +
                       " is a tet mesh (orient its boundary surface, e.g. exported as .stl)");
    }
    vtkDataObject* tets = placed;
    if (!tetMesh) {
      tets = this->Update("mesh", P.Tetrahedralize);
    } else {
      this->LastSeconds = 0;
    }
    reportMesh(tets, !tetMesh, this->Section("mesh"));
    this->Write(tets, "tets.vtu");
    if (R.until == "mesh") {
      return kExitOk;
    }

    vtkDataObject* fields = this->Update("gdf", P.GeodesicFields);
    reportFields(fields, this->Section("gdf"));
    this->Write(fields, "fields.vtu");
    if (R.until == "gdf") {
      return kExitOk;
    }

    vtkDataObject* layers = this->Update("layers", P.Slicer);
    reportLayers(P, layers, this->Section("layers"));
    this->Write(layers, "layers.vtp");
    vtkDataObject* surface = this->Update("overhang", P.OverhangAnalysis);
    reportOverhang(surface, this->Section("overhang"));
    this->Write(surface, "overhang.vtp");
    if (R.until == "layers") {
      return kExitOk;
    }

    vtkDataObject* graph = this->Update("lattice", P.LatticeInfill);
    reportLattice(P, graph, this->Section("lattice"));
    this->Write(graph, "lattice.vtp");
    if (R.until == "lattice") {
      return kExitOk;
    }

    vtkDataObject* tree = this->Update("skeleton", P.SkeletonTree);
    reportSkeleton(tree, this->Section("skeleton"));
    this->Update("sequence", P.Sequencer);
    Json& sequence = this->Section("sequence");
    vtkDataObject* sequenced = P.Sequencer->GetOutputDataObject(0);
    vtkDataObject* collisions = this->Update("verify", P.SequenceVerifier);
    sequence["verify_seconds"] = this->LastSeconds;
    reportSequence(P, sequenced, sequence);
    sequence["subgraphs"] = vtkDataSet::SafeDownCast(tree)->GetNumberOfPoints();
    reportCollisions(collisions, sequence);
    this->Write(sequenced, "lattice.vtp");
    this->Write(P.Sequencer->GetOutputDataObject(1), "skeleton.vtp");
    this->Write(P.Sequencer->GetOutputDataObject(2), "sequence.vtp");
    this->Write(collisions, "collisions.vtp");
    this->WriteFile("sequence.csv", [&](const std::string& path) {
      writeSequenceCsv(vtkPolyData::SafeDownCast(sequenced),
                       vtkPolyData::SafeDownCast(P.Sequencer->GetOutputDataObject(2)), path);
    });
    if (R.until == "sequence") {
      return kExitOk;
    }

    vtkDataObject* toolpath = this->Update("toolpath", P.Planner);
    Json& path = this->Section("toolpath");
    vtkDataObject* pathCollisions = this->Update("verify toolpath", P.ToolpathVerifier);
    path["verify_seconds"] = this->LastSeconds;
    reportToolpath(P, toolpath, path);
    reportCollisions(pathCollisions, path);
    this->Write(toolpath, "toolpath.vtp");
    this->Write(pathCollisions, "toolpath_collisions.vtp");
    const int steps =
        replayStepCount(vtkDataSet::SafeDownCast(toolpath)->GetNumberOfPoints(), R.replaySteps);
    path["replay_steps"] = steps;
    const auto replayStart = Clock::now();
    for (const std::string& f : writeToolpathReplay(P.Planner, R.outDir, steps)) {
      if (f.find('*') == std::string::npos) {
        this->Files.add(f, secondsSince(replayStart));
      }
    }
    for (int k = 1; k <= steps; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "toolpath/step_%04d.vtp", k);
      this->Files.add((fs::path(R.outDir) / name).string(), 0.0);
    }
    if (R.until == "toolpath") {
      return kExitOk;
    }
    return this->Programs(pathCollisions);
  }

  /// The program stage behind its gates: a colliding toolpath (unless --allow-collisions),
  /// unreachable points (unless --allow-unreachable) or a joint flip/limit stop it before any
  /// program file is written; the report records which gate stopped what.
  int Programs(vtkDataObject* pathCollisions) {
    Json& s = this->Section("program");
    Json& gates = this->Report["gates"];
    const long long stations =
        static_cast<long long>(fieldValue(pathCollisions, arrays::CollisionStations));
    const long long colliding =
        static_cast<long long>(fieldValue(pathCollisions, arrays::CollisionViolatingStations));
    if (colliding > 0) {
      std::ostringstream line;
      line << "toolpath collides at " << colliding << " of " << stations << " stations ("
           << (100.0 * static_cast<double>(colliding) / std::max<long long>(stations, 1)) << " %)";
      if (pathCollisions->GetFieldData()->GetArray(arrays::CollisionLayerRange)) {
        line << ", layers " << fieldValue(pathCollisions, arrays::CollisionLayerRange, 0) << "-"
             << fieldValue(pathCollisions, arrays::CollisionLayerRange, 1);
      }
      line << ": see toolpath_collisions.vtp";
      gates["collision"] = {{"passed", false},
                            {"colliding_stations", colliding},
                            {"stations", stations},
                            {"overridden", R.allowCollisions}};
      if (!R.allowCollisions) {
        gates["collision"]["stopped"] = {"program"};
        this->GateLine(line.str() + "; no program written (--allow-collisions writes it anyway)");
        s["written"] = false;
        return kExitCollisionGate;
      }
      this->GateLine(line.str() + "; programs written anyway (--allow-collisions)", true);
    } else {
      gates["collision"] = {{"passed", true}, {"stations", stations}};
    }

    if (!R.quiet) {
      std::cout << "geolattice: program ..." << std::flush;
    }
    const auto start = Clock::now();
    const std::string dir = R.outDir;
    vtkGLURScriptWriter* script = P.ScriptWriter;
    script->SetFileName((fs::path(dir) / "print_part.script").string().c_str());
    const std::string scriptError = this->RunWriter(script, !R.quiet);
    reportScript(P, s);
    const double scriptSeconds = secondsSince(start);
    if (!scriptError.empty()) {
      if (!R.quiet) {
        std::cout << " stopped\n";
      }
      if (script->GetUnreachableCount() > 0 && !script->GetAllowUnreachable()) {
        gates["reachability"] = {
            {"passed", false},
            {"unreachable", static_cast<long long>(script->GetUnreachableCount())},
            {"stopped", {"program"}}};
        this->GateLine("program: " + withFlagNames(scriptError));
        return kExitUnreachableGate;
      }
      if (script->GetLargeJointSteps() > 0) {
        gates["joints"] = {{"passed", false},
                           {"large_steps", static_cast<long long>(script->GetLargeJointSteps())},
                           {"max_step_deg", script->GetMaxJointStepDeg()},
                           {"stopped", {"program"}}};
        this->GateLine("program: " + withFlagNames(scriptError));
        return kExitJointGate;
      }
      throw StageError("program", scriptError);
    }
    gates["reachability"] = {
        {"passed", script->GetUnreachableCount() == 0},
        {"unreachable", static_cast<long long>(script->GetUnreachableCount())}};
    gates["joints"] = {{"passed", true}, {"max_step_deg", script->GetMaxJointStepDeg()}};
    if (script->GetUnreachableCount() > 0) {
      std::cerr << "geolattice: warning: " << script->GetUnreachableCount() << " of "
                << script->GetNumberOfWaypoints()
                << " toolpath points are unreachable: the program was written anyway "
                   "(--allow-unreachable)\n";
    }

    Json& g = s["gcode"];
    std::vector<std::string> programFiles;
    for (int k = 0; k < script->GetNumberOfFilesWritten(); ++k) {
      programFiles.push_back(script->GetFileWritten(k));
    }
    const std::string gcodePath = (fs::path(dir) / "toolpath.gcode").string();
    std::string gcodeSkipped;
    double gcodeSeconds = 0;
    if (!R.gcode) {
      g = {{"kinematics", "none"}};
    } else {
      g["kinematics"] = P.GCodeWriter->GetKinematics() ? "bc" : "ac";
      P.GCodeWriter->SetFileName(gcodePath.c_str());
      const auto t0 = Clock::now();
      const std::string error = this->RunWriter(P.GCodeWriter);
      gcodeSeconds = secondsSince(t0);
      if (!error.empty() && P.GCodeWriter->GetOutOfLimitsCount() > 0) {
        // The table cannot tilt far enough for some points (axes pointing down under an
        // overhang): no G-code, but the robot program stays valid; the report names the points.
        g["written"] = false;
        g["error"] = error;
        g["out_of_limits"] = static_cast<long long>(P.GCodeWriter->GetOutOfLimitsCount());
        gcodeSkipped = error;
      } else if (!error.empty()) {
        RemoveFiles(programFiles);
        if (!R.quiet) {
          std::cout << " failed\n";
        }
        throw StageError("program", error + " (--tilt-limits, or --gcode none)");
      } else {
        g["written"] = true;
        g["file"] = "toolpath.gcode";
        reportGCode(P, g);
        programFiles.push_back(gcodePath);
      }
    }

    const std::string csvPath = (fs::path(dir) / "waypoints.csv").string();
    P.WaypointWriter->SetFileName(csvPath.c_str());
    const auto t1 = Clock::now();
    const std::string csvError = this->RunWriter(P.WaypointWriter);
    if (!csvError.empty()) {
      RemoveFiles(programFiles);
      if (!R.quiet) {
        std::cout << " failed\n";
      }
      throw StageError("program", csvError);
    }
    for (int k = 0; k < script->GetNumberOfFilesWritten(); ++k) {
      this->Files.add(script->GetFileWritten(k), scriptSeconds / script->GetNumberOfFilesWritten());
    }
    if (R.gcode && gcodeSkipped.empty()) {
      this->Files.add(gcodePath, gcodeSeconds);
    }
    this->Files.add(csvPath, secondsSince(t1));
    if (!gcodeSkipped.empty()) {
      std::cout << "geolattice: warning: no G-code written: " << gcodeSkipped << "\n";
    }
    s["csv"] = "waypoints.csv";
    s["csv_rows"] = static_cast<long long>(P.WaypointWriter->GetNumberOfRows());
    s["written"] = true;
    s["seconds"] = secondsSince(start);
    if (!R.quiet) {
      std::cout << " done (" << secondsSince(start) << " s)\n";
    }
    return kExitOk;
  }

  /// Checks the parameters of every stage the run will reach before the first one runs: VTK's
  /// information pass visits every filter upstream of the last ones, and each filter checks its
  /// own parameters there (filters/vtkGLRequest.h). Milliseconds, not minutes of meshing.
  void CheckParameters() {
    std::vector<vtkAlgorithm*> last = {P.Tetrahedralize};
    if (P.GetTetMeshInput()) {
      last = {P.Placement};
    }
    const std::string& u = R.until;
    if (u != "mesh") {
      last = {P.GeodesicFields};
    }
    if (u != "mesh" && u != "gdf") {
      last = {P.Slicer, P.OverhangAnalysis};
    }
    if (u == "lattice") {
      last.push_back(P.LatticeInfill);
    } else if (u == "sequence") {
      last.push_back(P.SequenceVerifier);
    } else if (u == "toolpath") {
      last.push_back(P.ToolpathVerifier);
    } else if (u.empty() || u == "program") {
      last.insert(last.end(), {P.ToolpathVerifier, P.ScriptWriter, P.WaypointWriter});
      if (R.gcode) {
        last.push_back(P.GCodeWriter);
      }
    }
    ErrorCapture errors;
    for (int s = 0; s < GLPrintPipeline::NumberOfStages; ++s) {
      errors.Watch(P.Filter(static_cast<GLPrintPipeline::Stage>(s)));
    }
    for (vtkAlgorithm* a : {static_cast<vtkAlgorithm*>(P.ScriptWriter.Get()),
                            static_cast<vtkAlgorithm*>(P.GCodeWriter.Get()),
                            static_cast<vtkAlgorithm*>(P.WaypointWriter.Get())}) {
      errors.Watch(a);
    }
    for (vtkAlgorithm* a : last) {
      if (!a->GetExecutive()->UpdateInformation() || !errors.Message.empty()) {
        throw StageError("parameters", errors.Message.empty()
                                           ? std::string(a->GetClassName()) + " failed"
                                           : errors.Message);
      }
    }
  }

  /// The report section of a stage, with its seconds first.
  Json& Section(const char* name) {
    Json& s = this->Report[name];
    s["seconds"] = this->LastSeconds;
    return s;
  }

  /// Updates `last` (watching `watched`, default `last`, for errors) and returns its output.
  /// Throws StageError with the first error message when the update fails.
  vtkDataObject* Update(const char* stage, vtkAlgorithm* last,
                        std::initializer_list<vtkAlgorithm*> watched = {}) {
    if (!R.quiet) {
      std::cout << "geolattice: " << stage << " ..." << std::flush;
    }
    ErrorCapture errors;
    for (vtkAlgorithm* a : watched) {
      errors.Watch(a);
    }
    if (watched.size() == 0) {
      errors.Watch(last);
    }
    const auto start = Clock::now();
    int ok = 0;
    {
      const ProgressPrinter percent(last, !R.quiet && IsLongStage(stage));
      std::vector<vtkAlgorithm*> stageFilters(watched);
      if (stageFilters.empty()) {
        stageFilters.push_back(last);
      }
      const AbortOnInterrupt abort(stageFilters);
      ok = last->GetExecutive()->Update();
    }
    if (InterruptHandler::Interrupted()) {
      throw StageError(stage, "interrupted");
    }
    this->LastSeconds = secondsSince(start);
    if (!R.quiet) {
      std::cout << (ok && errors.Message.empty() ? " done" : " failed") << " (" << this->LastSeconds
                << " s)\n";
    }
    if (!ok || !errors.Message.empty()) {
      throw StageError(stage, errors.Message.empty() ? std::string(last->GetClassName()) + " failed"
                                                     : errors.Message);
    }
    return last->GetOutputDataObject(0);
  }

  /// The stages that can take long enough for a percentage on their line.
  static bool IsLongStage(const std::string& stage) {
    return stage == "mesh" || stage == "gdf" || stage == "lattice" || stage == "sequence" ||
           stage == "toolpath";
  }

  /// Writes with `writer` and returns the first error reported, empty on success.
  static std::string RunWriter(vtkWriter* writer, bool percent = false) {
    ErrorCapture errors;
    errors.Watch(writer);
    const ProgressPrinter printer(writer, percent);
    const AbortOnInterrupt abort({writer});
    const int ok = writer->Write();
    if (InterruptHandler::Interrupted()) {
      throw StageError("program", "interrupted");  // the writers run in the program stage
    }
    if (errors.Message.empty() && !ok) {
      errors.Message = std::string(writer->GetClassName()) + " failed";
    }
    return errors.Message;
  }

  /// Removes program files already written: a later writer of the stage failed, and the stage
  /// leaves all its files or none.
  static void RemoveFiles(const std::vector<std::string>& files) {
    std::error_code ec;
    for (const std::string& f : files) {
      fs::remove(f, ec);
    }
  }

  void GateLine(const std::string& line, bool warning = false) {
    std::cerr << "geolattice: " << (warning ? "warning: " : "stopped: ") << line << "\n";
  }

  void Write(vtkDataObject* data, const char* name) {
    const std::string path = (fs::path(R.outDir) / name).string();
    const auto start = Clock::now();
    writeVtkXml(data, path);
    this->Files.add(path, secondsSince(start));
  }

  template <class F>
  void WriteFile(const char* name, F&& write) {
    const std::string path = (fs::path(R.outDir) / name).string();
    const auto start = Clock::now();
    write(path);
    this->Files.add(path, secondsSince(start));
  }

  /// Moves the earlier run's leftovers to previous/, then writes report.json (with every file
  /// written and its seconds, and the exit status).
  void Finish(int status) {
    const std::vector<std::string> retired = this->Files.retireStaleOutputs();
    Json files = Json::array();
    for (const auto& [name, seconds] : this->Files.files()) {
      files.push_back({{"file", name}, {"seconds", seconds}});
    }
    this->Report["files"] = files;
    if (!retired.empty()) {
      this->Report["previous"] = retired;
    }
    this->Report["exit_status"] = status;
    const std::string path = (fs::path(R.outDir) / "report.json").string();
    writeAtomically(path, [this](const std::string& tmp) {
      std::ofstream out(tmp);
      out << this->Report.dump(2) << "\n";
      return static_cast<bool>(out);
    });
    if (!R.quiet) {
      std::cout << "geolattice: wrote " << this->Files.files().size() + 1 << " files in "
                << R.outDir << " (report.json lists them)";
      if (!retired.empty()) {
        std::cout << "; " << retired.size() << " files of an earlier run moved to " << R.outDir
                  << "/previous";
      }
      std::cout << "\ngeolattice: open them in ParaView (paraview " << R.outDir
                << "/toolpath.vtp) or load the plugin for the filters.\n";
    }
  }

  OutputRecord Files{""};
  Json Report = Json::object();
  double LastSeconds = 0;
};

}  // namespace

int runRunCommand(int argc, char** argv) {
  auto run = std::make_unique<Run>();
  parseRunArguments(argc, argv, run->P, run->R);
  return run->Execute();
}

}  // namespace geolattice
