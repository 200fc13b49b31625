#include "ToolpathOutput.h"

#include "OutputFiles.h"
#include "common/Error.h"
#include "vtkGLArrayNames.h"
#include "vtkGLToolpathReplay.h"

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

std::vector<std::string> writeToolpathReplay(vtkGLToolpathReplay* replay, const std::string& outDir,
                                             int steps) {
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
  replay->SetStepBy(vtkGLToolpathReplay::Points);
  replay->SetKeepUnprintedPoints(false);  // smaller files
  std::vector<double> times;
  for (int k = 1; k <= steps; ++k) {
    const double p = k == steps ? 1.0 : static_cast<double>(k) / steps;
    if (!replay->UpdateTimeStep(p)) {
      throw GeoLatticeError("toolpath: replay step " + std::to_string(k) + " failed");
    }
    vtkPolyData* part = replay->GetOutput();
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

}  // namespace geolattice
