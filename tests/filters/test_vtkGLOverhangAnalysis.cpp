// vtkGLOverhangAnalysis on in-code grids: the documented arrays, agreement with the core
// analysis, the threshold property, and bad input (missing arrays, non-tets, bad threshold).
#include "GLTestErrorObserver.h"
#include "GLTestProgress.h"

#include "mesh/AnalyticShapes.h"
#include "mesh/TetMeshTopology.h"
#include "overhang/OverhangAnalysis.h"
#include "vtkGLArrayNames.h"
#include "vtkGLGeodesicDistanceFields.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLOverhangAnalysis.h"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <string>

namespace arrays = geolattice::arrays;
namespace gl = geolattice;

namespace {

/// T / mushroom of 2 mm voxels (stem 10 x 10 x 20 mm, cap 30 x 30 x 10 mm on top): the tets of
/// boxTetMesh whose cell lies in the T, unused points removed. The cap's underside (800 mm^2)
/// faces straight down.
gl::TetMesh mushroom() {
  return gl::voxelTetMesh(gl::Vec3(30, 30, 30), 15, 15, 15, [](const gl::Vec3& c) {
    return c.z() > 20.0 || (c.x() > 10.0 && c.x() < 20.0 && c.y() > 10.0 && c.y() < 20.0);
  });
}

/// The GDF filter's output for the mushroom (base = its lowest vertices).
vtkSmartPointer<vtkUnstructuredGrid> fieldsOfMushroom() {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  gl::fromTetMesh(mushroom(), grid);
  vtkNew<vtkGLGeodesicDistanceFields> gdf;
  gdf->SetInputData(grid);
  gdf->Update();
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->DeepCopy(gdf->GetOutput());
  return out;
}

double field(vtkPolyData* p, const char* name) {
  vtkDataArray* a = p->GetFieldData()->GetArray(name);
  EXPECT_NE(a, nullptr) << name;
  return a ? a->GetTuple1(0) : std::nan("");
}

/// Runs the filter; returns its output and the recorded errors.
struct FilterRun {
  vtkSmartPointer<vtkPolyData> output;
  std::string errors;
};

FilterRun run(vtkUnstructuredGrid* input, double threshold = 135.0) {
  vtkNew<vtkGLOverhangAnalysis> filter;
  filter->SetInputData(input);
  filter->SetThresholdAngle(threshold);
  vtkNew<GLTestErrorObserver> observer;
  observer->Observe(filter);
  filter->Update();
  FilterRun r;
  r.output = filter->GetOutput();
  r.errors = observer->Errors();
  return r;
}

void expectEmptyWithError(const FilterRun& r, const std::string& part) {
  EXPECT_NE(r.errors.find(part), std::string::npos) << "errors: " << r.errors;
  EXPECT_EQ(r.output->GetNumberOfPoints(), 0);
  EXPECT_EQ(r.output->GetNumberOfCells(), 0);
  EXPECT_EQ(r.output->GetFieldData()->GetArray(arrays::OverhangPlanarFraction), nullptr);
}

}  // namespace

TEST(vtkGLOverhangAnalysis, BoundarySurfaceWithTheDocumentedArraysMatchesCore) {
  auto fields = fieldsOfMushroom();
  const FilterRun r = run(fields);
  ASSERT_TRUE(r.errors.empty()) << r.errors;
  vtkPolyData* out = r.output;

  // Core on the same data.
  const gl::TetMesh mesh = gl::toTetMesh(fields);
  const gl::TetMeshTopology topology(mesh);
  vtkDataArray* gradient = fields->GetCellData()->GetArray(arrays::GammaGradient);
  vtkDataArray* source = fields->GetPointData()->GetArray(arrays::HeatSource);
  std::vector<gl::Vec3> directions(mesh.tets.size());
  for (size_t t = 0; t < directions.size(); ++t) {
    gradient->GetTuple(static_cast<vtkIdType>(t), directions[t].data());
  }
  std::vector<std::uint8_t> base(mesh.points.size());
  for (size_t i = 0; i < base.size(); ++i) {
    base[i] = source->GetTuple1(static_cast<vtkIdType>(i)) != 0.0;
  }
  const gl::OverhangResult core = gl::analyzeOverhang(mesh, topology, directions, base);

  // Surface: one triangle per boundary face, only the points it uses.
  const auto& faces = topology.boundaryFaces();
  ASSERT_EQ(out->GetNumberOfCells(), static_cast<vtkIdType>(faces.size()));
  std::map<int, int> used;
  for (const auto& f : faces) {
    for (int v : f.vertices) {
      used[v] = 0;
    }
  }
  EXPECT_EQ(out->GetNumberOfPoints(), static_cast<vtkIdType>(used.size()));
  EXPECT_LT(out->GetNumberOfPoints(), fields->GetNumberOfPoints());

  vtkDataArray* planar = out->GetCellData()->GetArray(arrays::OverhangPlanar);
  vtkDataArray* curved = out->GetCellData()->GetArray(arrays::OverhangCurved);
  vtkDataArray* onBase = out->GetCellData()->GetArray(arrays::OnBase);
  vtkDataArray* faceGradient = out->GetCellData()->GetArray(arrays::GammaGradient);
  ASSERT_NE(planar, nullptr);
  ASSERT_NE(curved, nullptr);
  ASSERT_NE(onBase, nullptr);
  ASSERT_NE(faceGradient, nullptr);
  EXPECT_NE(vtkUnsignedCharArray::SafeDownCast(onBase), nullptr);
  vtkNew<vtkIdList> ids;
  for (vtkIdType f = 0; f < out->GetNumberOfCells(); ++f) {
    ASSERT_EQ(planar->GetTuple1(f), core.planarDeg[f]);
    ASSERT_EQ(curved->GetTuple1(f), core.curvedDeg[f]);
    ASSERT_EQ(onBase->GetTuple1(f), core.onBase[f]);
    // Same triangle, same orientation; the tet's cell data came along.
    out->GetCellPoints(f, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), 3);
    for (int k = 0; k < 3; ++k) {
      const double* p = out->GetPoint(ids->GetId(k));
      ASSERT_EQ(gl::Vec3(p[0], p[1], p[2]), mesh.points[faces[f].vertices[k]]);
    }
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(faceGradient->GetComponent(f, c), directions[faces[f].tet][c]);
    }
  }
  // Point arrays follow their points.
  for (const char* name : {arrays::Gamma, arrays::Alpha, arrays::Beta, arrays::HeatSource}) {
    ASSERT_NE(out->GetPointData()->GetArray(name), nullptr) << name;
  }
  vtkDataArray* gammaIn = fields->GetPointData()->GetArray(arrays::Gamma);
  vtkDataArray* gammaOut = out->GetPointData()->GetArray(arrays::Gamma);
  for (vtkIdType f = 0; f < out->GetNumberOfCells(); ++f) {
    out->GetCellPoints(f, ids);
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(gammaOut->GetTuple1(ids->GetId(k)), gammaIn->GetTuple1(faces[f].vertices[k]));
    }
  }

  // Field data: the core's totals, and the input's field data kept.
  EXPECT_EQ(field(out, arrays::OverhangPlanarFraction), core.planarFraction);
  EXPECT_EQ(field(out, arrays::OverhangCurvedFraction), core.curvedFraction);
  EXPECT_EQ(field(out, arrays::OverhangThresholdDeg), 135.0);
  EXPECT_EQ(field(out, arrays::OverhangBaseArea), core.baseArea);
  EXPECT_EQ(field(out, arrays::OverhangTotalArea), core.totalArea);
  EXPECT_NE(out->GetFieldData()->GetArray(arrays::GammaRange), nullptr);
  // The mushroom's known numbers: 800 mm^2 of cap underside out of 3700 mm^2 off the base.
  EXPECT_NEAR(core.planarFraction, 800.0 / 3700.0, 1e-12);
  EXPECT_NEAR(core.baseArea, 100.0, 1e-9);
  EXPECT_LT(core.curvedFraction, 0.25 * core.planarFraction);
}

TEST(vtkGLOverhangAnalysis, ThresholdAngleProperty) {
  vtkNew<vtkGLOverhangAnalysis> filter;
  EXPECT_EQ(filter->GetThresholdAngle(), 135.0);
  std::ostringstream print;
  filter->Print(print);
  EXPECT_NE(print.str().find("ThresholdAngle: 135 deg"), std::string::npos) << print.str();

  auto fields = fieldsOfMushroom();
  const FilterRun strict = run(fields, 180.0);  // nothing exceeds 180°
  ASSERT_TRUE(strict.errors.empty()) << strict.errors;
  EXPECT_EQ(field(strict.output, arrays::OverhangPlanarFraction), 0.0);
  EXPECT_EQ(field(strict.output, arrays::OverhangThresholdDeg), 180.0);
  const FilterRun loose = run(fields, 179.0);
  EXPECT_NEAR(field(loose.output, arrays::OverhangPlanarFraction), 800.0 / 3700.0, 1e-12);
}

TEST(vtkGLOverhangAnalysis, BadThresholdGivesAnErrorAndEmptyOutput) {
  auto fields = fieldsOfMushroom();
  for (double bad : {90.0, 45.0, 180.5, std::nan("")}) {
    SCOPED_TRACE(bad);
    expectEmptyWithError(run(fields, bad), "threshold angle must be in (90, 180] degrees");
  }
}

TEST(vtkGLOverhangAnalysis, MissingOrMalformedArraysAreNamed) {
  auto fields = fieldsOfMushroom();
  {
    auto g = vtkSmartPointer<vtkUnstructuredGrid>::New();
    g->DeepCopy(fields);
    g->GetCellData()->RemoveArray(arrays::GammaGradient);
    expectEmptyWithError(run(g), "missing cell array 'GammaGradient'");
  }
  {
    auto g = vtkSmartPointer<vtkUnstructuredGrid>::New();
    g->DeepCopy(fields);
    g->GetPointData()->RemoveArray(arrays::HeatSource);
    expectEmptyWithError(run(g), "missing point array 'HeatSource'");
  }
  {
    auto g = vtkSmartPointer<vtkUnstructuredGrid>::New();
    g->DeepCopy(fields);
    vtkNew<vtkDoubleArray> scalar;
    scalar->SetName(arrays::GammaGradient);
    scalar->SetNumberOfTuples(g->GetNumberOfCells());
    scalar->FillValue(1.0);
    g->GetCellData()->AddArray(scalar);  // replaces the 3-component array
    expectEmptyWithError(run(g), "cell array 'GammaGradient' has 1 components, expected 3");
  }
  {
    // A zero nozzle direction on a boundary tet.
    auto g = vtkSmartPointer<vtkUnstructuredGrid>::New();
    g->DeepCopy(fields);
    vtkDataArray* a = g->GetCellData()->GetArray(arrays::GammaGradient);
    for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t) {
      a->SetComponent(t, 0, 0.0);
      a->SetComponent(t, 1, 0.0);
      a->SetComponent(t, 2, 0.0);
    }
    expectEmptyWithError(run(g), "expected a unit vector");
  }
  // An empty input.
  vtkNew<vtkUnstructuredGrid> empty;
  expectEmptyWithError(run(empty), "the input has no cells");
}

TEST(vtkGLOverhangAnalysis, NonTetCellsAreAnError) {
  // A hexahedron with the arrays the filter asks for: the arrays are fine, the cell is not.
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 8; ++i) {
    points->InsertNextPoint(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  const vtkIdType hex[8] = {0, 1, 3, 2, 4, 5, 7, 6};
  grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  vtkNew<vtkDoubleArray> gradient;
  gradient->SetName(arrays::GammaGradient);
  gradient->SetNumberOfComponents(3);
  gradient->InsertNextTuple3(0, 0, 1);
  grid->GetCellData()->AddArray(gradient);
  vtkNew<vtkUnsignedCharArray> source;
  source->SetName(arrays::HeatSource);
  source->SetNumberOfTuples(8);
  source->FillValue(0);
  grid->GetPointData()->AddArray(source);
  expectEmptyWithError(run(grid), "cell 0 is not a linear tetrahedron");
}

TEST(vtkGLOverhangAnalysis, ProgressAndAbort) {
  auto fields = fieldsOfMushroom();
  vtkNew<vtkGLOverhangAnalysis> filter;
  filter->SetInputData(fields);
  glExpectProgressReport(filter, 4);
  glExpectCleanAbort(filter, glAbortAt(0.5));
  glExpectCleanAbort(filter, glAbortAt(0.8));
}
