// The program stage of `geolattice run`: the safety gates, then the URScript program, the
// G-code and the waypoint CSV (all or none of them).
#include "CrashReport.h"
#include "RunCommand.h"
#include "RunSession.h"

#include "vtkGLArrayNames.h"

#include <vtkDataObject.h>
#include <vtkFieldData.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace geolattice {

namespace fs = std::filesystem;

namespace {

/// " (the best candidate on a H mm pedestal: N colliding stations)" when the orientation tries
/// (report.json orient.tries) printed candidates on a pedestal (so suggesting one is no help);
/// else "".
std::string leastCollidingOnAPedestal(const Json& report) {
  const Json* best = nullptr;
  if (report.contains("orient") && report["orient"].contains("tries")) {
    for (const Json& t : report["orient"]["tries"]) {
      if (t.value("ok", false) && t.value("pedestal_mm", 0.0) > 0 &&
          (!best ||
           t.value("colliding_stations", 0LL) < (*best).value("colliding_stations", 0LL))) {
        best = &t;
      }
    }
  }
  if (!best) {
    return "";
  }
  std::ostringstream m;
  m << " (the best candidate on a " << (*best).value("pedestal_mm", 0.0)
    << " mm pedestal: " << (*best).value("colliding_stations", 0LL) << " colliding stations)";
  return m.str();
}

/// How many of the orientation tries (report.json orient.tries) had a collision-free toolpath the
/// robot could not follow.
int robotRefusedOrientations(const Json& report) {
  int refused = 0;
  if (report.contains("orient") && report["orient"].contains("tries")) {
    for (const Json& t : report["orient"]["tries"]) {
      refused += t.contains("robot_follows") && !t["robot_follows"].get<bool>() ? 1 : 0;
    }
  }
  return refused;
}

/// The tilt limit the collision stop suggests where the toolpath's limit is smaller.
constexpr double kLargerTiltDeg = 45.0;

}  // namespace

int runProgramStage(RunSession& run, vtkDataObject* pathCollisions) {
  setCrashStage("program");
  GLPrintPipeline& P = run.P;
  const RunOptions& R = run.R;
  Json& s = run.Section("program");
  s["seconds"] = 0.0;  // (Section gives the last stage's) until the writers run
  Json& gates = run.Report["gates"];
  const long long stations =
      static_cast<long long>(fieldValue(pathCollisions, arrays::CollisionStations));
  const long long colliding =
      static_cast<long long>(fieldValue(pathCollisions, arrays::CollisionViolatingStations));
  if (colliding > 0) {
    std::ostringstream line;
    const long long plate =
        static_cast<long long>(fieldValue(pathCollisions, arrays::CollisionPlateStations));
    line << "toolpath collides at " << colliding << " of " << stations << " stations ("
         << std::setprecision(2)
         << (100.0 * static_cast<double>(colliding) / std::max<long long>(stations, 1))
         << std::setprecision(6) << " %";
    if (plate > 0) {
      line << ", " << plate << " of them at the build plate";
    }
    line << ")";
    if (pathCollisions->GetFieldData()->GetArray(arrays::CollisionLayerRange)) {
      line << ", layers " << fieldValue(pathCollisions, arrays::CollisionLayerRange, 0) << "-"
           << fieldValue(pathCollisions, arrays::CollisionLayerRange, 1);
    }
    line << ": see toolpath_collisions.vtp";
    // A closed void: a nozzle never gets inside to print its walls and roof from there.
    const double cavities =
        P.GetTetMeshInput()
            ? 0.0
            : fieldValue(P.Tetrahedralize->GetOutputDataObject(0), arrays::CavityRegions);
    if (cavities > 0) {
      line << "; the part has " << cavities << " closed inner "
           << (cavities == 1 ? "cavity" : "cavities")
           << " (no nozzle can enter: if the collisions are on its walls, fill it with "
              "--fill-cavities or open it)";
    }
    // What to try, cheapest first: the orientation search, then the real printhead's shape.
    std::string hint;
    if (P.Orientation->GetOrient() == vtkGLAutoOrient::KEEP) {
      hint = "--orient auto";
    }
    const char* head = P.Nozzle->GetPrintheadFile();
    if (!head || !*head) {
      hint += std::string(hint.empty() ? "" : " or ") + "--printhead FILE";
    }
    // The stations left are those no tilt within the limit clears: a larger limit may (topopt
    // auto-oriented under the cone: 13 -> 0 stations at 45°; docs/performance.md). Not where
    // the user turned the tilt off (0: the paper's axes).
    const double tiltLimit = P.Planner->GetMaxAxisTilt();
    if (tiltLimit > 0 && tiltLimit < kLargerTiltDeg) {
      hint += std::string(hint.empty() ? "" : " or ") + "--max-tilt 45";
    }
    std::string pedestalTried;  // when --orient auto printed candidates on a pedestal already
    if (plate > 0 && !P.GetTetMeshInput() &&
        P.Pedestal->HeightFor(P.Orientation->GetOutputDataObject(0)) == 0) {
      pedestalTried = leastCollidingOnAPedestal(run.Report);
      if (pedestalTried.empty()) {
        hint += std::string(hint.empty() ? "" : " or ") + "--pedestal 10";
      }
    }
    if (!hint.empty()) {
      line << "; try " << hint;
    }
    line << pedestalTried;
    gates["collision"] = {{"passed", false},
                          {"colliding_stations", colliding},
                          {"stations", stations},
                          {"overridden", R.allowCollisions}};
    if (!R.allowCollisions) {
      gates["collision"]["stopped"] = {"program"};
      run.GateLine(line.str() + "; no program written (--allow-collisions writes it anyway)");
      s["written"] = false;
      return kExitCollisionGate;
    }
    run.GateLine(line.str() + "; programs written anyway (--allow-collisions)", true);
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
  const std::string scriptError = run.RunWriter(script, !R.quiet);
  reportScript(P, s);
  const double scriptSeconds = secondsSince(start);
  s["seconds"] = scriptSeconds;  // what a gate below stops after
  if (!scriptError.empty()) {
    if (!R.quiet) {
      std::cout << " stopped\n";
    }
    // A part kept as placed: another side facing the plate turns it less far over, which often
    // suits the arm (a cap tilted 25 deg: refused as placed, printed with --orient auto).
    // Auto-oriented: how many sides the robot refused, and whether more can be tried (a
    // generated hemispherical shell: its eight best sides all start sideways right above the
    // flange, where the wrist meets the nozzle).
    std::string orientHint;
    if (P.Orientation->GetOrient() == vtkGLAutoOrient::KEEP && !P.GetTetMeshInput()) {
      orientHint = "; or try --orient auto (another side of the part facing the plate)";
    } else if (!P.GetTetMeshInput()) {
      std::ostringstream m;
      const int refused = robotRefusedOrientations(run.Report);
      if (refused > 0) {
        m << "; the robot follows none of the " << refused << " collision-free orientation"
          << (refused == 1 ? "" : "s") << " tried (report.json orient.tries)";
      }
      if (P.OrientationTries < 8) {
        m << (refused > 0 ? ": " : "; or try ")
          << "--orient-tries 8 (more of the orientation search's candidates)";
      }
      orientHint = m.str();
    }
    // Unreachable points stop the program unless allowed; a cell that reaches none of them
    // (an unreachable cell set-up: every point counted) even then.
    if (script->GetUnreachableCount() > 0 &&
        (!script->GetAllowUnreachable() ||
         script->GetUnreachableCount() == script->GetNumberOfWaypoints())) {
      gates["reachability"] = {
          {"passed", false},
          {"unreachable", static_cast<long long>(script->GetUnreachableCount())},
          {"stopped", {"program"}}};
      run.GateLine("program: " + withFlagNames(scriptError) + orientHint);
      return kExitUnreachableGate;
    }
    if (script->GetLargeJointSteps() > 0) {
      gates["joints"] = {{"passed", false},
                         {"large_steps", static_cast<long long>(script->GetLargeJointSteps())},
                         {"max_step_deg", script->GetMaxJointStepDeg()},
                         {"stopped", {"program"}}};
      run.GateLine("program: " + withFlagNames(scriptError) + orientHint);
      return kExitJointGate;
    }
    throw StageError("program", scriptError);
  }
  gates["reachability"] = {{"passed", script->GetUnreachableCount() == 0},
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
    const std::string error = run.RunWriter(P.GCodeWriter);
    gcodeSeconds = secondsSince(t0);
    if (!error.empty() && P.GCodeWriter->GetOutOfLimitsCount() > 0) {
      // The table cannot tilt far enough for some points (axes pointing down under an
      // overhang): no G-code, but the robot program stays valid; the report names the points.
      g["written"] = false;
      g["error"] = error;
      g["out_of_limits"] = static_cast<long long>(P.GCodeWriter->GetOutOfLimitsCount());
      gcodeSkipped = error;
    } else if (!error.empty()) {
      RunSession::RemoveFiles(programFiles);
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
  const std::string csvError = run.RunWriter(P.WaypointWriter);
  if (!csvError.empty()) {
    RunSession::RemoveFiles(programFiles);
    if (!R.quiet) {
      std::cout << " failed\n";
    }
    throw StageError("program", csvError);
  }
  try {
    run.WaitForFiles();  // the inspection files (written meanwhile): a program only with all of them
  } catch (...) {
    programFiles.push_back(csvPath);
    RunSession::RemoveFiles(programFiles);
    throw;
  }
  for (int k = 0; k < script->GetNumberOfFilesWritten(); ++k) {
    run.Files.add(script->GetFileWritten(k), scriptSeconds / script->GetNumberOfFilesWritten());
  }
  if (R.gcode && gcodeSkipped.empty()) {
    run.Files.add(gcodePath, gcodeSeconds);
  }
  run.Files.add(csvPath, secondsSince(t1));
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

}  // namespace geolattice
