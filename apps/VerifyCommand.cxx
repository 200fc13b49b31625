#include "VerifyCommand.h"

#include "CliOptions.h"
#include "GLPrintPipeline.h"
#include "ErrorCapture.h"
#include "common/Error.h"
#include "vtkGLArrayNames.h"
#include "vtkGLCollisionVerifier.h"

#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <vtkExecutive.h>
#include <sstream>
#include <string>

namespace geolattice {

namespace {

/// The nozzle a run used, from the "sequence" section of its report.json (missing keys keep
/// the defaults).
void readNozzleFromReport(const std::filesystem::path& report, GLPrintPipeline& p) {
  std::ifstream in(report);
  if (!in) {
    return;
  }
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!json.is_object() || !json.contains("sequence") || !json["sequence"].is_object()) {
    return;
  }
  const nlohmann::json& s = json["sequence"];
  auto read = [&s](const char* key, auto setter) {
    if (s.contains(key) && s[key].is_number()) {
      setter(s[key].get<double>());
    }
  };
  vtkGLNozzle* n = p.Nozzle;
  read("nozzle_angle_deg", [n](double v) { n->SetNozzleAngle(v); });
  read("nozzle_length_mm", [n](double v) { n->SetNozzleLength(v); });
  read("holder_radius_mm", [n](double v) { n->SetHolderRadius(v); });
  read("tip_clearance_mm", [n](double v) { n->SetTipClearance(v); });
  read("holder_length_mm", [n](double v) { n->SetHolderLength(v); });
  read("tip_face_radius_mm", [n](double v) { n->SetTipFaceRadius(v); });
  read("face_contact_mm", [n](double v) { n->SetFaceContact(v); });
  read("plate_margin_mm", [n](double v) { n->SetPlateMargin(v); });
  read("plate_thickness_mm", [n](double v) { n->SetPlateThickness(v); });
  if (s.contains("build_plate") && s["build_plate"].is_boolean()) {
    n->SetBuildPlate(s["build_plate"].get<bool>());
  }
  if (s.contains("printhead") && s["printhead"].is_object() && s["printhead"].contains("file") &&
      s["printhead"]["file"].is_string()) {
    n->SetPrintheadFile(s["printhead"]["file"].get<std::string>().c_str());
  }
  read("sample_spacing_mm", [&p](double v) { p.Sequencer->SetSampleSpacing(v); });
}

/// The run options that describe the nozzle (and the sample spacing): verify takes those.
const CliOption* nozzleOption(const std::string& flag) {
  for (const CliOption& o : runOptionTable()) {
    if (flag == o.flag && (o.property.rfind("GLNozzle.", 0) == 0 || flag == "--sample-spacing")) {
      return &o;
    }
  }
  return nullptr;
}

double fieldNumber(vtkDataObject* data, const char* name) {
  vtkDataArray* a = vtkDataArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
  return a && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0) : 0.0;
}

}  // namespace

int runVerifyCommand(int argc, char** argv) {
  std::string dir;
  bool allowUnavoidable = false, quiet = false;
  std::vector<std::pair<const CliOption*, std::string>> given;  // override the report's nozzle
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--allow-unavoidable") {
      allowUnavoidable = true;
    } else if (arg == "-q" || arg == "--quiet") {
      quiet = true;
    } else if (const CliOption* o = nozzleOption(arg)) {
      if (i + 1 >= argc) {
        throw UsageError(arg + " needs a value");
      }
      given.emplace_back(o, argv[++i]);
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option " + arg);
    } else if (dir.empty()) {
      dir = arg;
    } else {
      throw UsageError("unexpected argument '" + arg + "'");
    }
  }
  if (dir.empty()) {
    throw UsageError("verify: missing OUTDIR");
  }
  // The newer of toolpath.vtp (a toolpath: every point a station at its own time) and lattice.vtp
  // (sub-graphs at their PrintOrder): a later `run --until sequence` makes lattice.vtp newer.
  const std::filesystem::path latticePath = std::filesystem::path(dir) / "lattice.vtp";
  const std::filesystem::path toolpathPath = std::filesystem::path(dir) / "toolpath.vtp";
  std::error_code ec;
  const bool haveLattice = std::filesystem::is_regular_file(latticePath, ec);
  const bool haveToolpath = std::filesystem::is_regular_file(toolpathPath, ec);
  if (!haveLattice && !haveToolpath) {
    throw GeoLatticeError("verify: " + toolpathPath.string() + " and " + latticePath.string() +
                          " not found (run `geolattice run MODEL -o " + dir + "` first)");
  }
  const bool toolpath =
      haveToolpath && (!haveLattice || std::filesystem::last_write_time(toolpathPath, ec) >=
                                           std::filesystem::last_write_time(latticePath, ec));
  const std::filesystem::path checked = toolpath ? toolpathPath : latticePath;
  GLPrintPipeline settings;  // only its nozzle and sample spacing are used
  readNozzleFromReport(std::filesystem::path(dir) / "report.json", settings);
  RunOptions unused;
  for (const auto& [option, value] : given) {
    option->set(settings, unused, value);
  }
  vtkGLNozzle* nozzle = settings.Nozzle;

  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(checked.string().c_str());
  reader->Update();
  vtkPolyData* data = reader->GetOutput();
  if (!data || data->GetNumberOfCells() == 0) {
    throw GeoLatticeError("verify: " + checked.string() + " is empty or not a VTK polydata file");
  }
  if (toolpath && !data->GetPointData()->GetArray(arrays::PointIndex)) {
    throw GeoLatticeError("verify: " + checked.string() +
                          " has no PointIndex point array (not a GeoLattice toolpath)");
  }
  if (!toolpath && !data->GetCellData()->GetArray(arrays::PrintOrder)) {
    throw GeoLatticeError("verify: " + checked.string() +
                          " has no PrintOrder (run with --until sequence)");
  }
  vtkNew<vtkGLCollisionVerifier> verifier;
  verifier->SetInputData(data);
  verifier->SetTimeArrayName(toolpath ? arrays::PointIndex : arrays::PrintOrder);
  verifier->SetNozzle(nozzle);
  verifier->SetSampleSpacing(settings.Sequencer->GetSampleSpacing());
  ErrorCapture errors;
  errors.Watch(verifier);
  if (!verifier->GetExecutive()->Update() || !errors.Message.empty()) {
    throw GeoLatticeError("verify: " + (errors.Message.empty() ? "the verifier failed"
                                                               : withFlagNames(errors.Message)));
  }
  vtkPolyData* out = verifier->GetOutput();
  const long long stations = static_cast<long long>(fieldNumber(out, arrays::CollisionStations));
  const long long violating =
      static_cast<long long>(fieldNumber(out, arrays::CollisionViolatingStations));
  const long long unavoidable =
      static_cast<long long>(fieldNumber(out, arrays::CollisionUnavoidableStations));
  if (!quiet) {
    std::cout << "geolattice: verify: " << checked.filename().string()
              << (toolpath ? " (the toolpath; every point at its own time, air points no material)"
                           : " (the printing order of the sub-graphs)")
              << (haveLattice && haveToolpath ? ", the newer of toolpath.vtp and lattice.vtp" : "")
              << ": " << stations << " nozzle stations, ";
    const char* head = nozzle->GetPrintheadFile();
    if (head && *head) {
      std::cout << "printhead " << head;
    } else {
      std::cout << "nozzle angle " << nozzle->GetNozzleAngle() << " deg";
    }
    if (!(head && *head) && nozzle->GetNozzleLength() > 0) {
      std::cout << ", length " << nozzle->GetNozzleLength() << " mm, holder radius "
                << nozzle->GetHolderRadius() << " mm";
    }
    std::cout << ": ";
    if (violating == 0) {
      std::cout << "collision-free\n";
    } else {
      std::cout << violating << " stations with earlier material inside the nozzle (" << unavoidable
                << " unavoidable: material of a lower layer the order must print first)\n";
      vtkDataArray* role = out->GetPointData()->GetArray(arrays::Role);
      vtkDataArray* height = out->GetPointData()->GetArray(arrays::Height);
      vtkDataArray* radial = out->GetPointData()->GetArray(arrays::Radial);
      for (vtkIdType p = 0; role && height && radial && p + 1 < out->GetNumberOfPoints() && p < 10;
           p += 2) {
        double a[3], b[3];
        out->GetPoint(p, a);
        out->GetPoint(p + 1, b);
        std::cout << "  station (" << a[0] << ", " << a[1] << ", " << a[2] << ") obstacle (" << b[0]
                  << ", " << b[1] << ", " << b[2] << ") height " << height->GetTuple1(p)
                  << " mm, radial " << radial->GetTuple1(p) << " mm\n";
      }
    }
  }
  const bool ok = violating == 0 || (allowUnavoidable && violating == unavoidable);
  return ok ? 0 : 3;
}

}  // namespace geolattice
