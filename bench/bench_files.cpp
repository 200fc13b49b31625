// The VTK XML files the CLI writes: a toolpath-sized polydata (points, a polyline, the toolpath's
// arrays) through filters/GLXMLFileWriter, with its buffered base64 stream (Arg 1) and with VTK's
// own encoder (Arg 0), binary inline mode, LZ4 (the CLI's settings). Results: docs/performance.md.
#include "GLXMLFileWriter.h"

#include <benchmark/benchmark.h>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

namespace {

/// n points along a helix-like path with the toolpath's point arrays: 3 + 6 doubles and 4 ints.
vtkNew<vtkPolyData> toolpathLike(int n) {
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  points->SetDataType(VTK_DOUBLE);  // as the toolpath's points
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(n);
  vtkNew<vtkDoubleArray> axis;
  axis->SetName("NozzleAxis");
  axis->SetNumberOfComponents(3);
  poly->GetPointData()->AddArray(axis);
  const char* scalars[] = {"Thickness", "Width", "Extrusion", "FeedRate", "AxisTilt"};
  for (const char* name : scalars) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfTuples(n);
    poly->GetPointData()->AddArray(a);
  }
  const char* ints[] = {"MoveKind", "LayerId", "SubgraphId", "PointIndex"};
  for (const char* name : ints) {
    vtkNew<vtkIntArray> a;
    a->SetName(name);
    a->SetNumberOfTuples(n);
    poly->GetPointData()->AddArray(a);
  }
  for (int i = 0; i < n; ++i) {
    const double t = 0.002 * i;
    points->InsertNextPoint(40 * std::cos(t) + 0.1 * std::sin(37 * t), 40 * std::sin(t),
                            0.6 * std::floor(t / 6.283));
    axis->InsertNextTuple3(0.1 * std::sin(t), 0.1 * std::cos(3 * t), 1.0);
    lines->InsertCellPoint(i);
    for (int k = 0; k < 5; ++k) {
      poly->GetPointData()->GetArray(scalars[k])->SetComponent(i, 0, 0.6 + 0.01 * std::sin(k * t));
    }
    const int values[] = {i % 40 == 0 ? 2 : 1, static_cast<int>(t / 6.283), i / 900, i};
    for (int k = 0; k < 4; ++k) {
      poly->GetPointData()->GetArray(ints[k])->SetComponent(i, 0, values[k]);
    }
  }
  poly->SetPoints(points);
  poly->SetLines(lines);
  return poly;
}

void BM_WriteToolpathFile(benchmark::State& state) {
  static vtkNew<vtkPolyData> poly = toolpathLike(465000);  // topopt's toolpath: 464,593 points
  const std::string file =
      (std::filesystem::temp_directory_path() / "geolattice-bench-toolpath.vtp").string();
  for (auto _ : state) {
    if (!geolattice::writeXmlDataFile(poly, file, state.range(0) != 0)) {
      state.SkipWithError("could not write the file");
      break;
    }
  }
  state.counters["MB"] = static_cast<double>(std::filesystem::file_size(file)) / 1e6;
  std::remove(file.c_str());
}
BENCHMARK(BM_WriteToolpathFile)->ArgName("buffered")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
