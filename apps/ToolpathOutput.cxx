#include "ToolpathOutput.h"

#include "OutputFiles.h"
#include "common/Error.h"
#include "vtkGLArrayNames.h"
#include "vtkGLToolpathPlanner.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <regex>

namespace geolattice {

namespace fs = std::filesystem;

namespace {

constexpr double kReplayPointBudget =
    2e6;  // points in all step files together (~70 bytes each on disk)

double fieldNumber(vtkDataObject* data, const char* name, int component = 0) {
  vtkDataArray* a = vtkDataArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
  if (!a || a->GetNumberOfValues() <= component) {
    throw GeoLatticeError(std::string("toolpath output has no field array ") + name);
  }
  return a->GetComponent(component / a->GetNumberOfComponents(),
                         component % a->GetNumberOfComponents());
}

std::string stepName(int k) {
  char name[32];
  std::snprintf(name, sizeof name, "step_%04d.vtp", k);
  return name;
}

/// Removes OUTDIR/toolpath/step_NNNN.vtp with NNNN > keep.
void removeStaleSteps(const fs::path& dir, int keep) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    return;
  }
  const std::regex pattern("step_([0-9]{4})\\.vtp");
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    std::smatch m;
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, m, pattern) && std::stoi(m[1]) > keep) {
      stale.push_back(entry.path());
    }
  }
  for (const fs::path& p : stale) {
    fs::remove(p, ec);
  }
}

}  // namespace

int replayStepCount(long long points, int maxSteps) {
  if (maxSteps <= 0) {
    return 0;
  }
  // Σ_{k=1..S} (k / S) N = N (S + 1) / 2 points in all step files.
  const double fit = 2.0 * kReplayPointBudget / std::max(1.0, static_cast<double>(points)) - 1.0;
  return std::max(1, std::min(maxSteps, static_cast<int>(std::floor(fit))));
}

std::vector<std::string> writeToolpathReplay(vtkGLToolpathPlanner* planner,
                                             const std::string& outDir, int steps) {
  const fs::path dir = fs::path(outDir) / "toolpath";
  const fs::path pvd = fs::path(outDir) / "toolpath.pvd";
  std::vector<std::string> written;
  if (steps <= 0) {
    std::error_code ec;
    fs::remove(pvd, ec);
    removeStaleSteps(dir, 0);
    return written;
  }
  prepareOutputDirectory(dir.string());
  std::vector<double> times;
  for (int k = 1; k <= steps; ++k) {
    const double p = k == steps ? 1.0 : static_cast<double>(k) / steps;
    planner->UpdateTimeStep(p);
    vtkPolyData* part = planner->GetOutput();
    if (!part || part->GetNumberOfPoints() == 0) {
      throw GeoLatticeError("toolpath: replay step " + std::to_string(k) + " is empty");
    }
    writeVtkXml(part, (dir / stepName(k)).string());
    times.push_back(p);
  }
  writeAtomically(pvd.string(), [&](const std::string& tmp) {
    std::ofstream out(tmp);
    out << "<?xml version=\"1.0\"?>\n"
        << "<!-- GeoLattice print replay: step k holds the toolpath printed up to progress k / "
        << steps << " (by point count) -->\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  "
           "<Collection>\n"
        << std::setprecision(10);
    for (int k = 1; k <= steps; ++k) {
      out << "    <DataSet timestep=\"" << times[k - 1]
          << "\" group=\"\" part=\"0\" file=\"toolpath/" << stepName(k) << "\"/>\n";
    }
    out << "  </Collection>\n</VTKFile>\n";
    return static_cast<bool>(out);
  });
  removeStaleSteps(dir, steps);
  written.push_back((dir / "step_*.vtp").string());
  written.push_back(pvd.string());
  return written;
}

void reportToolpath(vtkDataObject* toolpath, JsonObject& s) {
  auto count = [toolpath](const char* name) {
    return static_cast<long long>(fieldNumber(toolpath, name));
  };
  vtkPolyData* poly = vtkPolyData::SafeDownCast(toolpath);
  s.set("points", static_cast<long long>(poly ? poly->GetNumberOfPoints() : 0));
  s.set("cells", static_cast<long long>(poly ? poly->GetNumberOfCells() : 0));
  s.set("print_length_mm", fieldNumber(toolpath, arrays::ToolpathPrintLength));
  s.set("perimeter_length_mm", fieldNumber(toolpath, arrays::ToolpathPerimeterLength));
  s.set("air_length_mm", fieldNumber(toolpath, arrays::ToolpathAirLength));
  s.set("retractions", count(arrays::ToolpathRetractions));
  s.set("tours", count(arrays::ToolpathTours));
  s.set("crossings", count(arrays::ToolpathCrossings));
  s.set("split_subgraphs", count(arrays::ToolpathSplitSubgraphs));
  s.set("contracted_edges", count(arrays::ToolpathContractedEdges));
  s.set("trimmed_edges", count(arrays::ToolpathTrimmedEdges));
  s.set("trimmed_length_mm", fieldNumber(toolpath, arrays::ToolpathTrimmedLength));
  s.set("perimeter_loops", count(arrays::ToolpathPerimeterLoops));
  s.set("perimeter_teeth", count(arrays::ToolpathPerimeterTeeth));
  s.set("rotation_steps", count(arrays::ToolpathRotationSteps));
  s.set("subdivision_points", count(arrays::ToolpathSubdivisionPoints));
  s.set("colliding_stations_along_normal", count(arrays::ToolpathCollidingStations));
  s.set("tilted_stations", count(arrays::ToolpathTiltedStations));
  s.set("uncleared_stations", count(arrays::ToolpathUnclearedStations));
  s.set("max_axis_tilt_deg", fieldNumber(toolpath, arrays::ToolpathMaxAxisTilt));
  s.set("replanned_hops", count(arrays::ToolpathReplannedHops));
  s.set("thickness_dev_min", fieldNumber(toolpath, arrays::ToolpathThicknessDeviation, 0));
  s.set("thickness_dev_max", fieldNumber(toolpath, arrays::ToolpathThicknessDeviation, 1));
  s.set("capped_vertices", count(arrays::ToolpathCappedVertices));
  s.set("unsupported_vertices", count(arrays::ToolpathUnsupportedVertices));
  s.set("filament_mm", fieldNumber(toolpath, arrays::ToolpathFilament));
  s.set("volume_mm3", fieldNumber(toolpath, arrays::ToolpathVolume));
  s.set("planning_seconds", fieldNumber(toolpath, arrays::ToolpathSeconds));
}

}  // namespace geolattice
