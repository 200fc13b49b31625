#include "vtkGLTetrahedralizeSurface.h"

#include "GLTestDefaults.h"
#include "GLTestErrorObserver.h"
#include "GLTestProgress.h"
#include "vtkGLArrayNames.h"

#include "mesh/AnalyticShapes.h"
#include "mesh/TetMesh.h"

#include "../common/TestModels.h"

#include <gtest/gtest.h>

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>

namespace {
using geolattice::Vec3;

vtkSmartPointer<vtkPolyData> toPolyData(const geolattice::TriangleSurface& s) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const Vec3& p : s.points) {
    points->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& t : s.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  return poly;
}

double fieldValue(vtkDataObject* ds, const char* name) {
  vtkDataArray* a = ds->GetFieldData()->GetArray(name);
  EXPECT_NE(a, nullptr) << name;
  return a ? a->GetComponent(0, 0) : std::numeric_limits<double>::quiet_NaN();
}

double totalSignedVolume(vtkUnstructuredGrid* grid, int* nonPositive) {
  double total = 0.0;
  *nonPositive = 0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    grid->GetCellPoints(c, ids);
    Vec3 p[4];
    for (int k = 0; k < 4; ++k) {
      grid->GetPoint(ids->GetId(k), p[k].data());
    }
    const double v = geolattice::signedTetVolume(p[0], p[1], p[2], p[3]);
    *nonPositive += v > 0 ? 0 : 1;
    total += v;
  }
  return total;
}

struct TetRun {
  vtkSmartPointer<vtkUnstructuredGrid> Output;
  vtkSmartPointer<GLTestErrorObserver> Errors;
};

TetRun tetrahedralize(vtkPolyData* input, double edge, double ratio = 1.414) {
  vtkNew<vtkGLTetrahedralizeSurface> filter;
  TetRun run;
  run.Errors = vtkSmartPointer<GLTestErrorObserver>::New();
  run.Errors->Observe(filter);
  filter->SetInputData(input);
  filter->SetTargetEdgeLength(edge);
  filter->SetRadiusEdgeRatio(ratio);
  filter->Update();
  run.Output = filter->GetOutput();
  return run;
}

void expectEmptyWithError(const TetRun& run, const std::string& text) {
  EXPECT_TRUE(run.Errors->HasError());
  EXPECT_NE(run.Errors->Errors().find(text), std::string::npos) << run.Errors->Errors();
  EXPECT_EQ(run.Output->GetNumberOfCells(), 0);
  EXPECT_EQ(run.Output->GetNumberOfPoints(), 0);
  EXPECT_EQ(run.Output->GetFieldData()->GetNumberOfArrays(), 0);
}
}  // namespace

TEST(vtkGLTetrahedralizeSurface, BoxGivesPositiveTetsFillingTheBox) {
  auto box = toPolyData(geolattice::boxSurface(Vec3(40, 40, 60), 10.0));
  const TetRun run = tetrahedralize(box, 3.0);
  ASSERT_FALSE(run.Errors->HasError()) << run.Errors->Errors();
  vtkUnstructuredGrid* out = run.Output;
  ASSERT_GT(out->GetNumberOfCells(), 0);
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c) {
    ASSERT_EQ(out->GetCellType(c), VTK_TETRA);
  }
  int nonPositive = 0;
  EXPECT_NEAR(totalSignedVolume(out, &nonPositive), 96000.0, 1e-6 * 96000.0);
  EXPECT_EQ(nonPositive, 0);
  double bounds[6];
  out->GetBounds(bounds);
  EXPECT_NEAR(bounds[1] - bounds[0], 40.0, 1e-9);
  EXPECT_NEAR(bounds[5] - bounds[4], 60.0, 1e-9);

  EXPECT_DOUBLE_EQ(fieldValue(out, geolattice::arrays::TargetEdgeLength), 3.0);
  EXPECT_EQ(fieldValue(out, geolattice::arrays::TetCount),
            static_cast<double>(out->GetNumberOfCells()));
  const double meanEdge = fieldValue(out, geolattice::arrays::MeanEdgeLength);
  EXPECT_GT(meanEdge, 0.7 * 3.0);
  EXPECT_LT(meanEdge, 1.2 * 3.0);
  EXPECT_GE(fieldValue(out, geolattice::arrays::TetrahedralizeSeconds), 0.0);

  vtkDataArray* quality = out->GetCellData()->GetArray(geolattice::arrays::TetQuality);
  ASSERT_NE(quality, nullptr);
  ASSERT_EQ(quality->GetNumberOfTuples(), out->GetNumberOfCells());
  double range[2];
  quality->GetRange(range);
  EXPECT_GE(range[0], std::sqrt(6.0) / 4.0 - 1e-9);  // a regular tet is the best possible
  EXPECT_LE(range[1], 1.414 * 1.5);                  // TetGen's bound (box: no small input angles)
}

TEST(vtkGLTetrahedralizeSurface, BunnyFromOBJWithAutomaticEdgeLength) {
  const std::string path = testModel("bunny.obj");
  ASSERT_FALSE(path.empty()) << "bunny.obj not found in " << GEOLATTICE_TESTDATA;
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> bunny = reader->GetOutput();
  ASSERT_GT(bunny->GetNumberOfPolys(), 3000);
  // Scale to 100 mm (largest side).
  double b[6];
  bunny->GetBounds(b);
  const double scale = 100.0 / std::max({b[1] - b[0], b[3] - b[2], b[5] - b[4]});
  vtkNew<vtkPoints> scaled;
  scaled->SetDataTypeToDouble();
  for (vtkIdType i = 0; i < bunny->GetNumberOfPoints(); ++i) {
    double p[3];
    bunny->GetPoint(i, p);
    scaled->InsertNextPoint(scale * p[0], scale * p[1], scale * p[2]);
  }
  vtkNew<vtkPolyData> input;
  input->SetPoints(scaled);
  input->SetPolys(bunny->GetPolys());

  const TetRun run = tetrahedralize(input, 0.0);
  ASSERT_FALSE(run.Errors->HasError()) << run.Errors->Errors();
  const vtkIdType tets = run.Output->GetNumberOfCells();
  std::printf("[ filter bunny 100 mm auto ] %lld tets, edge %.3f mm, %.2f s\n",
              static_cast<long long>(tets),
              fieldValue(run.Output, geolattice::arrays::TargetEdgeLength),
              fieldValue(run.Output, geolattice::arrays::TetrahedralizeSeconds));
  EXPECT_GE(tets, 50000);
  EXPECT_LE(tets, 100000);
  int nonPositive = 0;
  EXPECT_GT(totalSignedVolume(run.Output, &nonPositive), 0.0);
  EXPECT_EQ(nonPositive, 0);
  EXPECT_GT(fieldValue(run.Output, geolattice::arrays::TargetEdgeLength), 0.0);
}

TEST(vtkGLTetrahedralizeSurface, OpenSurfaceGivesErrorAndEmptyOutput) {
  geolattice::TriangleSurface box = geolattice::boxSurface(Vec3(10, 10, 10), 3.0);
  box.triangles.pop_back();
  expectEmptyWithError(tetrahedralize(toPolyData(box), 2.0), "open surface: 3 boundary edges");
}

TEST(vtkGLTetrahedralizeSurface, NonManifoldSurfaceGivesError) {
  // A closed box plus a two-sided fin on one of its edges: still closed and consistently
  // oriented, but that edge is in 4 triangles.
  geolattice::TriangleSurface box = geolattice::boxSurface(Vec3(1, 1, 1), 10.0);
  const auto t = box.triangles[0];
  box.points.push_back(Vec3(-1, -1, -1));
  const int fin = static_cast<int>(box.points.size()) - 1;
  box.triangles.push_back({t[0], t[1], fin});
  box.triangles.push_back({t[1], t[0], fin});
  expectEmptyWithError(tetrahedralize(toPolyData(box), 0.5), "non-manifold surface");
}

TEST(vtkGLTetrahedralizeSurface, SelfIntersectingSurfaceGivesError) {
  geolattice::TriangleSurface box = geolattice::boxSurface(Vec3(10, 10, 10), 2.0);
  const int n = static_cast<int>(box.points.size());
  const size_t triangles = box.triangles.size();
  for (int i = 0; i < n; ++i) {
    box.points.push_back(box.points[i] + Vec3(5.3, 5.1, 4.9));
  }
  for (size_t f = 0; f < triangles; ++f) {
    const auto t = box.triangles[f];
    box.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  }
  // Two crossing boxes: one solid, their union, with a warning that says so.
  const TetRun run = tetrahedralize(toPolyData(box), 1.0);
  ASSERT_FALSE(run.Errors->HasError()) << run.Errors->Errors();
  ASSERT_GT(run.Output->GetNumberOfCells(), 0);
  vtkDataArray* merged = run.Output->GetFieldData()->GetArray(geolattice::arrays::MergedBodies);
  ASSERT_NE(merged, nullptr);
  EXPECT_EQ(merged->GetTuple1(0), 1.0);
  EXPECT_NE(run.Errors->Warnings().find("bodies of the surface touch or cross each other"),
            std::string::npos)
      << run.Errors->Warnings();
  const double union3 = 2000.0 - 4.7 * 4.9 * 5.1;  // mm^3
  int nonPositive = 0;
  EXPECT_NEAR(totalSignedVolume(run.Output, &nonPositive), union3, 1e-6 * union3);
  EXPECT_EQ(nonPositive, 0);
}

TEST(vtkGLTetrahedralizeSurface, EmptyInputGivesError) {
  vtkNew<vtkPolyData> empty;
  expectEmptyWithError(tetrahedralize(empty, 0.0), "empty surface");
}

TEST(vtkGLTetrahedralizeSurface, QuadsGiveError) {
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(1, 1, 0);
  points->InsertNextPoint(0, 1, 0);
  vtkNew<vtkCellArray> polys;
  const vtkIdType quad[4] = {0, 1, 2, 3};
  polys->InsertNextCell(4, quad);
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);
  input->SetPolys(polys);
  expectEmptyWithError(tetrahedralize(input, 0.0), "only triangles are accepted");
}

TEST(vtkGLTetrahedralizeSurface, NaNEdgeLengthGivesErrorAndFilterRecovers) {
  auto box = toPolyData(geolattice::boxSurface(Vec3(10, 10, 10), 3.0));
  expectEmptyWithError(tetrahedralize(box, std::nan("")), "target edge length must be >= 0");
  expectEmptyWithError(tetrahedralize(box, 1e-3), "is too small for a solid of");
  // Same filter object: an error, then a valid run.
  vtkNew<vtkGLTetrahedralizeSurface> filter;
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(filter);
  filter->SetInputData(box);
  filter->SetTargetEdgeLength(std::nan(""));
  filter->Update();
  EXPECT_TRUE(errors->HasError());
  EXPECT_EQ(filter->GetOutput()->GetNumberOfCells(), 0);
  errors->Clear();
  filter->SetTargetEdgeLength(2.0);
  filter->Update();
  EXPECT_FALSE(errors->HasError()) << errors->Errors();
  EXPECT_GT(filter->GetOutput()->GetNumberOfCells(), 100);
}

TEST(vtkGLTetrahedralizeSurface, ParametersOutsideTheirDomainsGiveErrors) {
  auto box = toPolyData(geolattice::boxSurface(Vec3(10, 10, 10), 3.0));
  expectEmptyWithError(tetrahedralize(box, -1.0),
                       "target edge length must be >= 0 mm (0 = automatic), got -1");
  expectEmptyWithError(tetrahedralize(box, 2.0, 0.5),
                       "radius-edge ratio must be in [1.1, 10], got 0.5");
  expectEmptyWithError(tetrahedralize(box, 2.0, 11.0), "radius-edge ratio must be in [1.1, 10]");
  vtkNew<vtkGLTetrahedralizeSurface> filter;
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(filter);
  filter->SetInputData(box);
  filter->SetTargetTetCount(10);
  filter->Update();
  EXPECT_NE(errors->Errors().find("automatic target tet count must be in [1000, 5000000], got 10"),
            std::string::npos)
      << errors->Errors();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfCells(), 0);
}

TEST(vtkGLTetrahedralizeSurface, DefaultsAndPrintSelf) {
  vtkNew<vtkGLTetrahedralizeSurface> filter;
  EXPECT_EQ(filter->GetTargetEdgeLength(), 0.0);
  EXPECT_EQ(filter->GetTargetTetCount(), 75000);
  EXPECT_EQ(filter->GetRadiusEdgeRatio(), 1.414);
  filter->SetTargetEdgeLength(2.5);
  filter->SetTargetTetCount(20000);
  filter->SetRadiusEdgeRatio(2.0);
  expectPrintMentions(filter,
                      {"TargetEdgeLength: 2.5", "TargetTetCount: 20000", "RadiusEdgeRatio: 2"});
}

TEST(vtkGLTetrahedralizeSurface, TargetTetCountDrivesTheAutomaticEdgeLength) {
  auto box = toPolyData(geolattice::boxSurface(Vec3(40, 40, 60), 100.0));
  vtkNew<vtkGLTetrahedralizeSurface> filter;
  filter->SetInputData(box);
  filter->SetTargetTetCount(5000);
  filter->Update();
  EXPECT_GE(filter->GetOutput()->GetNumberOfCells(), 4000);
  EXPECT_LE(filter->GetOutput()->GetNumberOfCells(), 6250);
}

TEST(vtkGLTetrahedralizeSurface, AbortLeavesAnEmptyOutputWithoutError) {
  auto box = toPolyData(geolattice::boxSurface(Vec3(40, 40, 60), 100.0));
  vtkNew<vtkGLTetrahedralizeSurface> filter;
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(filter);
  filter->SetInputData(box);
  filter->SetTargetEdgeLength(0.6);  // ~1.5M tets: seconds of TetGen
  vtkNew<vtkCallbackCommand> stop;   // what ParaView's stop button does
  stop->SetCallback([](vtkObject* caller, unsigned long, void*, void*) {
    static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
  });
  filter->AddObserver(vtkCommand::ProgressEvent, stop);
  filter->Update();
  EXPECT_FALSE(errors->HasError()) << errors->Errors();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfCells(), 0);
}

TEST(vtkGLTetrahedralizeSurface, ProgressAndAbortWhileTetGenRuns) {
  auto box = toPolyData(geolattice::boxSurface(Vec3(40, 40, 60), 100.0));
  vtkNew<vtkGLTetrahedralizeSurface> filter;
  filter->SetInputData(box);
  filter->SetTargetEdgeLength(4.0);
  // Input converted, TetGen polled (the same value), TetGen done, the tet quality loop.
  glExpectProgressReport(filter, 5);
  GLAbortRequest inTetGen;
  inTetGen.AfterEvents = 2;  // 0 (executive), 0.05 (input converted), then the first poll of TetGen
  glExpectCleanAbort(filter, inTetGen);
  glExpectCleanAbort(filter, glAbortAt(0.85));
}

TEST(vtkGLTetrahedralizeSurface, AutomaticEdgeLengthReportsEveryTetGenRun) {
  auto box = toPolyData(geolattice::boxSurface(Vec3(40, 40, 60), 100.0));
  vtkNew<vtkGLTetrahedralizeSurface> filter;
  filter->SetInputData(box);
  filter->SetTargetEdgeLength(0.0);
  filter->SetTargetTetCount(3000);
  glExpectProgressReport(filter, 5);
}
