// vtkGLCurvedLayerSlicer on in-code grids: arrays, layer count, selected layer, bad input.
#include "GLTestErrorObserver.h"
#include "GLTestProgress.h"

#include "mesh/AnalyticShapes.h"
#include "vtkGLArrayNames.h"
#include "vtkGLCurvedLayerSlicer.h"
#include "vtkGLGeodesicDistanceFields.h"
#include "vtkGLMeshConversion.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <cmath>

namespace arrays = geolattice::arrays;

namespace {

vtkSmartPointer<vtkUnstructuredGrid> fieldsOfBox() {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  geolattice::fromTetMesh(geolattice::boxTetMesh(geolattice::Vec3(10, 10, 15), 5, 5, 8), grid);
  vtkNew<vtkGLGeodesicDistanceFields> gdf;
  gdf->SetInputData(grid);
  gdf->Update();
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->ShallowCopy(gdf->GetOutput());
  return out;
}

}  // namespace

TEST(vtkGLCurvedLayerSlicer, LayersCarryTheDocumentedArrays) {
  auto fields = fieldsOfBox();
  double gammaRange[2];
  fields->GetPointData()->GetArray(arrays::Gamma)->GetRange(gammaRange);
  vtkNew<vtkGLCurvedLayerSlicer> slicer;
  slicer->SetInputData(fields);
  slicer->SetLayerInterval(0.6);
  slicer->SetFirstLayerOffset(0.6);
  slicer->SetSelectedLayer(3);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(slicer);
  slicer->Update();
  ASSERT_FALSE(errors->HasError()) << errors->Errors();
  vtkPolyData* all = slicer->GetOutput(0);
  const int expected = static_cast<int>(std::floor((gammaRange[1] - 0.6) / 0.6)) + 1;
  vtkDataArray* values = all->GetFieldData()->GetArray(arrays::LayerValues);
  ASSERT_NE(values, nullptr);
  EXPECT_EQ(values->GetNumberOfTuples(), expected);
  ASSERT_GT(all->GetNumberOfCells(), 0);
  for (const char* name :
       {arrays::Gamma, arrays::Alpha, arrays::Beta, arrays::SourceEdge, arrays::EdgeParameter}) {
    EXPECT_NE(all->GetPointData()->GetArray(name), nullptr) << name;
  }
  ASSERT_NE(all->GetPointData()->GetNormals(), nullptr);
  EXPECT_STREQ(all->GetPointData()->GetNormals()->GetName(), arrays::Normals);
  vtkDataArray* layerId = all->GetCellData()->GetArray(arrays::LayerId);
  ASSERT_NE(layerId, nullptr);
  double idRange[2];
  layerId->GetRange(idRange);
  EXPECT_EQ(idRange[0], 0);
  EXPECT_EQ(idRange[1], expected - 1);
  for (const char* name : {arrays::LayerArea, arrays::LayerComponents, arrays::LayerSpacingMin,
                           arrays::LayerSpacingMean, arrays::LayerSpacingMax}) {
    ASSERT_NE(all->GetFieldData()->GetArray(name), nullptr) << name;
    EXPECT_EQ(all->GetFieldData()->GetArray(name)->GetNumberOfTuples(), expected) << name;
  }
  // The box's layers are one piece each, of area ~100 mm², spaced ~0.6 mm apart.
  EXPECT_EQ(all->GetFieldData()->GetArray(arrays::LayerComponents)->GetTuple1(2), 1.0);
  EXPECT_NEAR(all->GetFieldData()->GetArray(arrays::LayerArea)->GetTuple1(2), 100.0, 2.0);
  EXPECT_NEAR(all->GetFieldData()->GetArray(arrays::LayerSpacingMean)->GetTuple1(2), 0.6, 0.05);
  EXPECT_TRUE(
      std::isnan(all->GetFieldData()->GetArray(arrays::LayerSpacingMean)->GetTuple1(expected - 1)));

  // Port 1: only layer 3, every point at γ = φ_3.
  vtkPolyData* one = slicer->GetOutput(1);
  ASSERT_GT(one->GetNumberOfCells(), 0);
  double oneRange[2];
  one->GetCellData()->GetArray(arrays::LayerId)->GetRange(oneRange);
  EXPECT_EQ(oneRange[0], 3);
  EXPECT_EQ(oneRange[1], 3);
  double g[2];
  one->GetPointData()->GetArray(arrays::Gamma)->GetRange(g);
  EXPECT_DOUBLE_EQ(g[0], 0.6 + 3 * 0.6);
  EXPECT_DOUBLE_EQ(g[1], 0.6 + 3 * 0.6);

  slicer->SetSelectedLayer(10000);
  slicer->Update();
  EXPECT_EQ(slicer->GetOutput(1)->GetNumberOfCells(), 0);
  EXPECT_FALSE(errors->HasError());
}

TEST(vtkGLCurvedLayerSlicer, BadInputGivesAnErrorAndEmptyOutputs) {
  auto fields = fieldsOfBox();
  struct Case {
    const char* what;
    std::function<void(vtkUnstructuredGrid*, vtkGLCurvedLayerSlicer*)> setUp;
    const char* expected;
  };
  const std::vector<Case> cases = {
      {"no Gamma",
       [](vtkUnstructuredGrid* g, vtkGLCurvedLayerSlicer*) {
         g->GetPointData()->RemoveArray(arrays::Gamma);
       },
       "no point array 'Gamma'"},
      {"no Beta",
       [](vtkUnstructuredGrid* g, vtkGLCurvedLayerSlicer*) {
         g->GetPointData()->RemoveArray(arrays::Beta);
       },
       "no point array 'Beta'"},
      {"zero interval",
       [](vtkUnstructuredGrid*, vtkGLCurvedLayerSlicer* s) { s->SetLayerInterval(0); }, "interval"},
      {"negative interval",
       [](vtkUnstructuredGrid*, vtkGLCurvedLayerSlicer* s) { s->SetLayerInterval(-0.5); },
       "interval"},
      {"interval above the part",
       [](vtkUnstructuredGrid*, vtkGLCurvedLayerSlicer* s) {
         s->SetLayerInterval(100);
         s->SetFirstLayerOffset(100);
       },
       "no layer"},
      {"hexahedron",
       [](vtkUnstructuredGrid* g, vtkGLCurvedLayerSlicer*) {
         const vtkIdType ids[8] = {0, 1, 2, 3, 4, 5, 6, 7};
         g->InsertNextCell(VTK_HEXAHEDRON, 8, ids);
       },
       "not a linear tetrahedron"},
  };
  for (const Case& c : cases) {
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->DeepCopy(fields);
    vtkNew<vtkGLCurvedLayerSlicer> slicer;
    c.setUp(grid, slicer);
    slicer->SetInputData(grid);
    vtkNew<GLTestErrorObserver> errors;
    errors->Observe(slicer);
    slicer->Update();
    EXPECT_TRUE(errors->HasError()) << c.what;
    EXPECT_NE(errors->Errors().find(c.expected), std::string::npos)
        << c.what << ": " << errors->Errors();
    EXPECT_EQ(slicer->GetOutput(0)->GetNumberOfCells(), 0) << c.what;
    EXPECT_EQ(slicer->GetOutput(1)->GetNumberOfCells(), 0) << c.what;
  }
}

TEST(vtkGLCurvedLayerSlicer, ProgressAndAbort) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  geolattice::fromTetMesh(geolattice::boxTetMesh(geolattice::Vec3(20, 20, 30), 10, 10, 15), grid);
  vtkNew<vtkGLGeodesicDistanceFields> gdf;
  gdf->SetInputData(grid);
  gdf->Update();
  vtkNew<vtkGLCurvedLayerSlicer> slicer;
  slicer->SetInputConnection(gdf->GetOutputPort());
  slicer->SetLayerInterval(0.5);
  // The tet loop of the core reports about 64 times.
  glExpectProgressReport(slicer, 20);
  glExpectCleanAbort(slicer, glAbortAt(0.3));
  glExpectCleanAbort(slicer, glAbortAt(0.65));
}
