#include "ToolpathOutput.h"

#include "OutputFiles.h"
#include "common/Error.h"
#include "common/ParallelFor.h"
#include "vtkGLArrayNames.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

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

std::string stepName(int k) {
  char name[32];
  std::snprintf(name, sizeof name, "step_%04d.vtp", k);
  return name;
}

/// Removes OUTDIR/toolpath/step_NNNN.vtp with NNNN > keep (and empty.vtp when keep is 0).
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
    if ((std::regex_match(name, m, pattern) && std::stoi(m[1]) > keep) ||
        (keep == 0 && name == "empty.vtp")) {
      stale.push_back(entry.path());
    }
  }
  for (const fs::path& p : stale) {
    fs::remove(p, ec);
  }
}

/// The points first..last of the toolpath (renumbered from 0) with their point data, and the
/// runs of at least two of them in each line cell with that cell's data; first > last gives no
/// points and the same arrays. The field data are copied: pieces are written on several threads,
/// and a writer caches each array's range in the array.
vtkSmartPointer<vtkPolyData> toolpathPiece(vtkPolyData* whole, vtkIdType first, vtkIdType last) {
  auto piece = vtkSmartPointer<vtkPolyData>::New();
  const vtkIdType n = std::max<vtkIdType>(0, last - first + 1);
  vtkNew<vtkPoints> points;
  points->SetDataType(whole->GetPoints()->GetDataType());
  vtkPointData* outPd = piece->GetPointData();
  outPd->CopyAllocate(whole->GetPointData(), n);
  if (n > 0) {  // one range copy per array
    points->GetData()->InsertTuples(0, n, first, whole->GetPoints()->GetData());
    outPd->CopyData(whole->GetPointData(), 0, n, first);
  }
  piece->SetPoints(points);
  vtkNew<vtkCellArray> lines;
  vtkCellData* outCd = piece->GetCellData();
  outCd->CopyAllocate(whole->GetCellData());
  std::vector<vtkIdType> run;
  auto flush = [&](vtkIdType cell) {
    if (run.size() >= 2) {
      outCd->CopyData(whole->GetCellData(), cell,
                      lines->InsertNextCell(static_cast<vtkIdType>(run.size()), run.data()));
    }
    run.clear();
  };
  auto it = vtk::TakeSmartPointer(whole->GetLines()->NewIterator());
  vtkIdType cell = whole->GetNumberOfVerts();  // cell ids count the vertices first
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell) {
    vtkIdType size = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; k < size; ++k) {
      if (ids[k] >= first && ids[k] <= last) {
        run.push_back(ids[k] - first);
      } else {
        flush(cell);
      }
    }
    flush(cell);
  }
  piece->SetLines(lines);
  vtkNew<vtkFieldData> fieldData;
  fieldData->DeepCopy(whole->GetFieldData());
  piece->SetFieldData(fieldData);
  return piece;
}

}  // namespace

int replayStepCount(long long points, int maxSteps) {
  if (maxSteps <= 0) {
    return 0;
  }
  return static_cast<int>(std::max(1LL, std::min<long long>(maxSteps, points - 1)));
}

void writeToolpathReplay(vtkPolyData* toolpath, const std::string& outDir, int steps) {
  const fs::path dir = fs::path(outDir) / "toolpath";
  const fs::path pvd = fs::path(outDir) / "toolpath.pvd";
  if (steps <= 0) {
    std::error_code ec;
    fs::remove(pvd, ec);
    removeStaleSteps(dir, 0);
    return;
  }
  if (!toolpath || toolpath->GetNumberOfPoints() == 0 || !toolpath->GetLines()) {
    throw GeoLatticeError("toolpath: no points to replay");
  }
  prepareOutputDirectory(dir.string());
  const vtkIdType last = toolpath->GetNumberOfPoints() - 1;
  // vtkGLToolpathReplay's rule: at progress p the points 0 .. round(p (N - 1)) are printed.
  auto lastPrinted = [&](int k) {
    return static_cast<vtkIdType>(std::llround(static_cast<double>(k) / steps * last));
  };
  // The steps on every core (the toolpath is only read; each piece is data of its own): the
  // replay is the last file of a run, written while the other writer has finished.
  parallelFor(static_cast<size_t>(steps) + 1, 0, [&](size_t item, int) {
    const int k = static_cast<int>(item);
    if (k == 0) {
      writeVtkXml(toolpathPiece(toolpath, 1, 0), (dir / "empty.vtp").string());
    } else {
      writeVtkXml(toolpathPiece(toolpath, lastPrinted(k - 1), lastPrinted(k)),
                  (dir / stepName(k)).string());
    }
  });
  writeAtomically(pvd.string(), [&](const std::string& tmp) {
    std::ofstream out(tmp);
    out << "<?xml version=\"1.0\"?>\n"
        << "<!-- GeoLattice print replay: at time k / " << steps
        << " the pieces 1..k of the toolpath (by point count), the other parts empty -->\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  "
           "<Collection>\n"
        << std::setprecision(10);
    for (int k = 1; k <= steps; ++k) {
      const double time = k == steps ? 1.0 : static_cast<double>(k) / steps;
      for (int j = 1; j <= steps; ++j) {
        out << "    <DataSet timestep=\"" << time << "\" group=\"\" part=\"" << j - 1
            << "\" file=\"toolpath/" << (j <= k ? stepName(j) : "empty.vtp") << "\"/>\n";
      }
    }
    out << "  </Collection>\n</VTKFile>\n";
    return static_cast<bool>(out);
  });
  removeStaleSteps(dir, steps);
}

}  // namespace geolattice
