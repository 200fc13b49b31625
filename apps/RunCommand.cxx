#include "RunCommand.h"
#include "RunSession.h"

#include "BaseContactReport.h"
#include "CliOptions.h"
#include "CrashReport.h"
#include "ErrorCapture.h"
#include "Interrupt.h"
#include "OutputFiles.h"
#include "OrientationCsv.h"
#include "SequenceCsv.h"
#include "ReferenceFallbackNote.h"
#include "SetUpTriesReport.h"
#include "SurfaceRepairReport.h"
#include "StageReports.h"
#include "ToolpathOutput.h"

#include "GLPrintPipeline.h"
#include "common/Error.h"
#include "sequence/PrintSequencer.h"
#include "tetrahedralize/TetrahedralizeSurface.h"
#include "vtkGLArrayNames.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataSet.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkWriter.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <iostream>
#include <sstream>
#include <utility>

namespace geolattice {

namespace {

namespace fs = std::filesystem;

/// `geolattice run`: the stages one after the other on the session's pipeline.
class Run : public RunSession {
public:
  int Execute() {
    this->Files = OutputRecord(R.outDir);
    this->Report["geolattice_version"] = GEOLATTICE_VERSION;
    this->Report["model"] = R.model;
    prepareOutputDirectory(R.outDir);
    const InterruptHandler interrupt;
    try {
      const int status = this->Stages();
      if (!this->SmallBaseWarning.empty()) {  // not before an error's one line
        std::cerr << this->SmallBaseWarning;
      }
      this->Finish(status);
      return status;
    } catch (const StageError& e) {
      this->HoldNotes(false);  // the notes of the set-up that failed, before its error
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
    } catch (...) {
      this->HoldNotes(false);
      throw;
    }
  }

private:
  /// The stages, the search for a printable set-up where the toolpath collides (--orient auto),
  /// then the robot program.
  int Stages() {
    // The notes are said once the set-up is final: those of a set-up that another one replaces
    // (FindAPrintableSetUp) would describe a mesh that is not printed.
    this->HoldNotes(true);
    // The robot program is a gate of the set-up when it is written (the orientation search
    // ranks sides too tall for the cell last; --orient auto then tries other orientations where
    // the robot cannot follow the toolpath).
    P.RobotGate = R.until == "program";
    if (const std::optional<int> done = this->StagesThroughToolpath()) {
      this->HoldNotes(false);
      return *done;  // --until stopped earlier
    }
    this->FindAPrintableSetUp();
    this->HoldNotes(false);
    if (R.until == "toolpath") {
      return kExitOk;
    }
    return runProgramStage(*this, P.ToolpathVerifier->GetOutputDataObject(0));
  }

  /// Every stage up to the toolpath's verdict, with its report section and files; the exit
  /// status when --until ends the run before it.
  std::optional<int> StagesThroughToolpath() {
    const bool tetMesh = vtkGLMeshReader::IsTetMeshFile(R.model.c_str());
    P.SetTetMeshInput(tetMesh);
    P.MatchOrientationToPrint();
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
    this->Note(wrapNote(input, P.Placement->GetWrap()));
    this->Note(filledHolesNote(input));
    if (!R.quiet && input.contains("size_mm")) {
      std::cout << "geolattice: the part is " << input["size_mm"][0].get<double>() << " x "
                << input["size_mm"][1].get<double>() << " x " << input["size_mm"][2].get<double>()
                << " mm (x y z, as placed)\n";
    }

    if (!tetMesh) {
      if (P.Orientation->GetOrient() == vtkGLAutoOrient::AUTO) {  // Keep: it passes the part on
        placed = this->Update("orient", P.Orientation);
        if (!this->BaseConsidered) {  // the part on its own base first, where that is as good
          this->BaseConsidered = true;
          if (const int rank = P.PreferTheBaseToAPedestal(); rank >= 0) {
            P.Orientation->Update();  // re-places the part (the search is cached)
            placed = P.Orientation->GetOutputDataObject(0);
            this->Section("orient")["base_first_rank"] = rank;
            if (!R.quiet) {
              std::cout << "geolattice: trying the search's candidate of rank " << rank
                        << " first: the best one's direction without its pedestal\n";
            }
          } else if (const int kept = P.PreferThePlacementToATallerPrint(); kept >= 0) {
            P.Orientation->Update();
            placed = P.Orientation->GetOutputDataObject(0);
            this->Section("orient")["placement_first_rank"] = kept;
            if (!R.quiet) {
              std::cout << "geolattice: trying the part as placed first (the search's rank " << kept
                        << "): the best one needs a pedestal or twice its layers\n";
            }
          }
        }
        reportOrientation(placed, this->Section("orient"));
        this->Section("orient")["max_height_mm"] = P.Orientation->GetMaxHeight();
        this->Write(P.Orientation->GetOutputDataObject(1), "orientation.vtp");
        this->WriteFile("orientation.csv", [&](const std::string& path) {
          writeOrientationCsv(vtkPolyData::SafeDownCast(P.Orientation->GetOutputDataObject(1)),
                              path);
        });
      }
    } else if (P.Orientation->GetOrient() == vtkGLAutoOrient::AUTO) {
      throw UsageError("--orient auto needs a surface model: " + R.model +
                       " is a tet mesh (orient its boundary surface, e.g. exported as .stl)");
    } else if (P.Pedestal->GetHeight() > 0) {
      throw UsageError("--pedestal needs a surface model: " + R.model +
                       " is a tet mesh (raise its boundary surface, e.g. exported as .stl)");
    }
    vtkDataObject* tets = placed;
    if (!tetMesh) {
      if (P.Pedestal->HeightFor(placed) > 0) {  // Height 0: it passes the part on
        vtkDataObject* raised = this->Update("pedestal", P.Pedestal);
        reportPedestal(raised, this->Section("pedestal"));
      }
      tets = this->Update("mesh", P.Tetrahedralize);
    } else {
      this->LastSeconds = 0;
    }
    reportMesh(tets, !tetMesh, this->Section("mesh"));
    if (this->Section("mesh").value("tetgen_quality_bound_dropped", false)) {
      this->Note(qualityBoundDroppedNote(this->Section("mesh").value("tets", 0)) +
                 " (report.json mesh.tetgen_quality_bound_dropped)");
    }
    for (const std::string& note :
         reportSurfaceRepairs(P.Orientation->GetOutputDataObject(0), tets, this->Section("mesh"))) {
      this->Note(note);
    }
    this->Write(tets, "tets.vtu");
    if (R.until == "mesh") {
      return kExitOk;
    }

    vtkDataObject* fields = this->Update("gdf", P.GeodesicFields);
    // The run does not solve on this mesh again (another set-up meshes again): its factors
    // would stay resident to the end (~30 MB at 75k tets, fresh pages for later stages).
    P.GeodesicFields->ReleaseSolver();
    reportFields(fields, this->Section("gdf"));
    this->Note(referenceFallbackNote(this->Report["gdf"], P.GeodesicFields->GetReferenceVector(),
                                     P.GeodesicFields->GetTurnReference()));
    this->Write(fields, "fields.vtu");
    if (R.until == "gdf") {
      return kExitOk;
    }

    vtkDataObject* layers = this->Update("layers", P.Slicer);
    reportLayers(P, layers, this->Section("layers"));
    this->Write(layers, "layers.vtp");
    vtkDataObject* surface = this->Update("overhang", P.OverhangAnalysis);
    reportOverhang(surface, this->Section("overhang"));
    this->SmallBaseWarning = reportBaseContact(P, surface, this->Section("overhang"));
    this->Write(surface, "overhang.vtp");
    if (R.until == "layers") {
      return kExitOk;
    }

    vtkDataObject* graph = this->Update("lattice", P.LatticeInfill);
    reportLattice(P, graph, this->Section("lattice"));
    if (R.until == "lattice") {
      this->Write(graph, "lattice.vtp");
      return kExitOk;
    }

    // lattice.vtp is written once, after the sequence (with each sub-graph's PrintOrder), and the
    // lattice alone only where the skeleton, the sequence or its check fails: topopt's 28 MB are
    // not compressed twice.
    auto latticeOnFailure = [&](auto&& stage) {
      try {
        return stage();
      } catch (const StageError&) {
        this->Write(graph, "lattice.vtp");
        throw;
      }
    };
    vtkDataObject* tree =
        latticeOnFailure([&] { return this->Update("skeleton", P.SkeletonTree); });
    reportSkeleton(tree, this->Section("skeleton"));
    latticeOnFailure([&] { return this->Update("sequence", P.Sequencer); });
    Json& sequence = this->Section("sequence");
    vtkDataObject* sequenced = P.Sequencer->GetOutputDataObject(0);
    vtkDataObject* collisions =
        latticeOnFailure([&] { return this->Update("verify", P.SequenceVerifier); });
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
    // The toolpath with every station's verdict (point array Collision: colour by it in ParaView).
    vtkDataObject* checkedPath = P.ToolpathVerifier->GetOutputDataObject(1);
    this->Write(checkedPath, "toolpath.vtp");
    this->Write(pathCollisions, "toolpath_collisions.vtp");
    vtkDataObject* summary = this->Update("summary", P.PrintSummary);  // before Section: its time
    reportSummary(summary, this->Section("summary"));
    const int steps =
        replayStepCount(vtkDataSet::SafeDownCast(toolpath)->GetNumberOfPoints(), R.replaySteps);
    path["replay_steps"] = steps;
    // The replay's files on a writer thread of their own, beside toolpath.vtp's, from a copy of
    // their own (VTK caches array ranges inside the arrays: two writers must not share one);
    // its seconds are on toolpath.pvd.
    const std::string pvd = (fs::path(R.outDir) / "toolpath.pvd").string();
    vtkNew<vtkPolyData> replayed;
    if (steps > 0) {
      replayed->DeepCopy(checkedPath);
    }
    std::vector<std::string> replayFiles;
    if (steps > 0) {
      replayFiles = {pvd, (fs::path(R.outDir) / "toolpath" / "empty.vtp").string()};
    }
    for (int k = 1; k <= steps; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "toolpath/step_%04d.vtp", k);
      replayFiles.push_back((fs::path(R.outDir) / name).string());
    }
    this->Post(
        steps > 0 ? pvd : "", replayFiles,
        // Moved: the job holds the copy's only reference (BackgroundWriter.h).
        [replayed = vtkSmartPointer<vtkPolyData>(std::move(replayed)), dir = R.outDir, steps] {
          writeToolpathReplay(replayed, dir, steps);  // steps 0: removes an earlier replay
        },
        true);
    return std::nullopt;
  }

  /// With --orient auto, when the toolpath collides: other candidates of the orientation search,
  /// taller pedestals and other print orders through the toolpath verifier
  /// (GLPrintPipeline::FindAPrintableSetUp), recorded in report.json orient.tries,
  /// orient.pedestal_tries and sequence.order_tries; the stages run again, with their files and
  /// report sections, for each set-up chosen.
  void FindAPrintableSetUp() {
    setCrashStage("set-up (other orientations, pedestals, print orders)");
    auto say = [this](const std::string& text) {
      if (!R.quiet) {
        std::cout << "geolattice: " << text << "\n";
      }
    };
    auto orderName = [](int strategy) {
      return std::string(sequenceStrategyName(static_cast<SequenceStrategy>(strategy)));
    };
    GLPrintPipeline::SetUpListener listener;
    listener.orientation = [&](const GLPrintPipeline::OrientationTry& t) {
      say(std::string(t.after == "robot" ? "the robot cannot follow the toolpath"
                                         : "the toolpath collides") +
          ": trying the orientation search's candidate of rank " + std::to_string(t.rank));
    };
    listener.pedestal = [&](const GLPrintPipeline::PedestalTry& t) {
      std::ostringstream m;
      m << "the toolpath meets the build plate: trying a " << t.height << " mm pedestal";
      say(m.str());
    };
    listener.order = [&](const GLPrintPipeline::OrderTry& t) {
      say("the toolpath collides: trying the " + orderName(t.strategy) + " print order");
    };
    auto runAgain = [&](GLPrintPipeline::SetUpStep step) {
      std::ostringstream m;
      switch (step) {
        case GLPrintPipeline::SetUpStep::Orientation:
          m << "printing the candidate of rank " << P.Orientation->GetCandidateRank();
          break;
        case GLPrintPipeline::SetUpStep::Pedestal:
          m << "printing on the " << P.Pedestal->HeightFor(P.Orientation->GetOutputDataObject(0))
            << " mm pedestal";
          break;
        case GLPrintPipeline::SetUpStep::Order: {
          const int chosen = P.Sequencer->GetStrategyOverride();
          m << "printing the " << orderName(chosen >= 0 ? chosen : P.Sequencer->GetStrategy())
            << " order";
          break;
        }
      }
      say(m.str() + (step == GLPrintPipeline::SetUpStep::Orientation
                         ? " (the first that prints, or whose toolpath collides least)"
                         : " (its toolpath collides least)"));
      // The pipeline holds the last try; its stages run again for the chosen set-up (read from
      // the cache when that was the last), their report sections anew.
      for (const char* stale : {"pedestal", "mesh", "gdf", "layers", "overhang", "lattice",
                                "skeleton", "sequence", "toolpath", "summary"}) {
        this->Report.erase(stale);
      }
      this->DropHeldNotes();  // the stages note anew for this set-up
      this->StagesThroughToolpath();
    };
    const GLPrintPipeline::SetUpTries tries = P.FindAPrintableSetUp(runAgain, listener);

    // The sections as they are (Section() would overwrite their seconds with the last stage's).
    reportSetUpTries(tries, P.Orientation->GetCandidateRank(),
                     [this](const char* name) -> Json& { return this->Report[name]; });
  }
  bool BaseConsidered = false;

  /// The part's contact below --min-base-area (BaseContactReport.h): said in report.json and,
  /// when the run ends without an error (whose one line stays alone), on stderr (even with -q: it
  /// is about the part); the run goes on (the user placed it so). The last pass's (other
  /// orientations may run).
  std::string SmallBaseWarning;

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
};

}  // namespace

int runRunCommand(int argc, char** argv) {
  auto run = std::make_unique<Run>();
  parseRunArguments(argc, argv, run->P, run->R);
  return run->Execute();
}

}  // namespace geolattice
