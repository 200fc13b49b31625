#include "VerifyCommand.h"

#include "CliOptions.h"
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
#include <regex>
#include <sstream>
#include <string>

namespace geolattice {

namespace {

/// The nozzle a run used, from the "sequence" section of its report.json (missing keys keep
/// the defaults).
void readNozzleFromReport(const std::filesystem::path& report, NozzleOptions& n) {
  std::ifstream in(report);
  if (!in) {
    return;
  }
  std::stringstream text;
  text << in.rdbuf();
  const std::string json = text.str();
  const size_t section = json.find("\"sequence\"");
  if (section == std::string::npos) {
    return;
  }
  const std::string tail = json.substr(section);
  auto read = [&tail](const char* key, double& value) {
    const std::regex re(std::string("\"") + key + "\"\\s*:\\s*([-+0-9.eE]+)");
    std::smatch m;
    if (std::regex_search(tail, m, re)) {
      value = std::stod(m[1]);
    }
  };
  read("nozzle_angle_deg", n.angle);
  read("nozzle_length_mm", n.length);
  read("holder_radius_mm", n.holderRadius);
  read("tip_clearance_mm", n.tipClearance);
  read("tip_face_radius_mm", n.tipFaceRadius);
  read("sample_spacing_mm", n.sampleSpacing);
}

double fieldNumber(vtkDataObject* data, const char* name) {
  vtkDataArray* a = vtkDataArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
  return a && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0) : 0.0;
}

}  // namespace

int runVerifyCommand(int argc, char** argv) {
  std::string dir;
  bool allowUnavoidable = false, quiet = false;
  NozzleOptions cli, nozzle;
  std::vector<std::string> given;  // nozzle flags given on the command line override the report
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        throw UsageError(arg + " needs a value");
      }
      return argv[++i];
    };
    if (arg == "--allow-unavoidable")
      allowUnavoidable = true;
    else if (arg == "-q" || arg == "--quiet")
      quiet = true;
    else if (cli.parse(arg, value))
      given.push_back(arg);
    else if (!arg.empty() && arg[0] == '-')
      throw UsageError("unknown option " + arg);
    else if (dir.empty())
      dir = arg;
    else
      throw UsageError("unexpected argument '" + arg + "'");
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
  readNozzleFromReport(std::filesystem::path(dir) / "report.json", nozzle);
  for (const std::string& flag : given) {
    if (flag == "--nozzle-angle")
      nozzle.angle = cli.angle;
    if (flag == "--nozzle-length")
      nozzle.length = cli.length;
    if (flag == "--holder-radius")
      nozzle.holderRadius = cli.holderRadius;
    if (flag == "--tip-clearance")
      nozzle.tipClearance = cli.tipClearance;
    if (flag == "--tip-face-radius")
      nozzle.tipFaceRadius = cli.tipFaceRadius;
    if (flag == "--sample-spacing")
      nozzle.sampleSpacing = cli.sampleSpacing;
  }

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
  nozzle.apply(verifier.Get());
  ErrorCapture errors;
  errors.Watch(verifier);
  verifier->Update();
  if (!errors.Message.empty()) {
    throw GeoLatticeError("verify: " + errors.Message);
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
              << ": " << stations << " nozzle stations, nozzle angle " << nozzle.angle << " deg";
    if (nozzle.length > 0) {
      std::cout << ", length " << nozzle.length << " mm, holder radius " << nozzle.holderRadius
                << " mm";
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
