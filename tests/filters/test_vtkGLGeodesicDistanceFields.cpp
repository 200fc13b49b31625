// vtkGLGeodesicDistanceFields on in-code grids: arrays, source modes, and bad input.
#include "GLTestErrorObserver.h"
#include "GLTestProgress.h"

#include "mesh/AnalyticShapes.h"
#include "vtkGLArrayNames.h"
#include "vtkGLGeodesicDistanceFields.h"
#include "vtkGLMeshConversion.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

namespace arrays = geolattice::arrays;

namespace {

vtkSmartPointer<vtkUnstructuredGrid> boxGrid(double sx, double sy, double sz, int nx, int ny,
                                             int nz) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  geolattice::fromTetMesh(geolattice::boxTetMesh(geolattice::Vec3(sx, sy, sz), nx, ny, nz), grid);
  return grid;
}

vtkDataArray* pointArray(vtkUnstructuredGrid* g, const char* name) {
  return g->GetPointData()->GetArray(name);
}

}  // namespace

TEST(vtkGLGeodesicDistanceFields, AddsTheDocumentedArrays) {
  auto grid = boxGrid(8, 8, 12, 4, 4, 6);
  vtkNew<vtkGLGeodesicDistanceFields> filter;
  filter->SetInputData(grid);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(filter);
  filter->Update();
  ASSERT_FALSE(errors->HasError()) << errors->Errors();
  vtkUnstructuredGrid* out = filter->GetOutput();
  ASSERT_EQ(out->GetNumberOfCells(), grid->GetNumberOfCells());
  for (const char* name : {arrays::Gamma, arrays::Alpha, arrays::Beta, arrays::HeatSource}) {
    ASSERT_NE(pointArray(out, name), nullptr) << name;
    EXPECT_EQ(pointArray(out, name)->GetNumberOfTuples(), grid->GetNumberOfPoints()) << name;
  }
  for (const char* name : {arrays::GammaGradient, arrays::AlphaDirection, arrays::BetaDirection}) {
    vtkDataArray* a = out->GetCellData()->GetArray(name);
    ASSERT_NE(a, nullptr) << name;
    ASSERT_EQ(a->GetNumberOfComponents(), 3);
    for (vtkIdType c = 0; c < a->GetNumberOfTuples(); ++c) {
      const double* v = a->GetTuple3(c);
      ASSERT_NEAR(v[0] * v[0] + v[1] * v[1] + v[2] * v[2], 1.0, 1e-9);
    }
  }
  double range[2];
  pointArray(out, arrays::Gamma)->GetRange(range);
  EXPECT_EQ(range[0], 0.0);
  EXPECT_NEAR(range[1], 12.0, 0.6);
  vtkFieldData* fd = out->GetFieldData();
  for (const char* name :
       {arrays::GammaRange, arrays::AlphaRange, arrays::BetaRange, arrays::GdfTimings,
        arrays::OrthogonalityDeg, arrays::ReferenceFallbackTets, arrays::SourceCount}) {
    ASSERT_NE(fd->GetArray(name), nullptr) << name;
  }
  EXPECT_DOUBLE_EQ(fd->GetArray(arrays::GammaRange)->GetComponent(1, 0), 0.0 + range[1]);
  EXPECT_EQ(fd->GetArray(arrays::SourceCount)->GetTuple1(0), 25.0);
  EXPECT_EQ(fd->GetArray(arrays::GdfTimings)->GetNumberOfTuples(), 4);
}

TEST(vtkGLGeodesicDistanceFields, MaskAndDownwardFaceSources) {
  auto grid = boxGrid(6, 6, 10, 3, 3, 5);
  // Mask: the top face is the base, so γ is the distance from the top.
  vtkNew<vtkDoubleArray> mask;
  mask->SetName("TopMask");
  mask->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    mask->SetValue(i, grid->GetPoint(i)[2] > 10 - 1e-9 ? 1.0 : 0.0);
  }
  grid->GetPointData()->AddArray(mask);
  vtkNew<vtkGLGeodesicDistanceFields> filter;
  filter->SetInputData(grid);
  filter->SetSourceMode(vtkGLGeodesicDistanceFields::MASK_ARRAY);
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "TopMask");
  filter->Update();
  vtkUnstructuredGrid* out = filter->GetOutput();
  ASSERT_NE(pointArray(out, arrays::Gamma), nullptr);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    if (mask->GetValue(i) != 0) {
      EXPECT_EQ(pointArray(out, arrays::Gamma)->GetTuple1(i), 0.0);
    }
  }
  double bottomGamma = 0;
  int bottomCount = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    if (out->GetPoint(i)[2] < 1e-9) {
      bottomGamma += pointArray(out, arrays::Gamma)->GetTuple1(i);
      ++bottomCount;
    }
  }
  EXPECT_NEAR(bottomGamma / bottomCount, 10.0, 0.5);

  filter->SetSourceMode(vtkGLGeodesicDistanceFields::DOWNWARD_FACES);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetFieldData()->GetArray(arrays::SourceCount)->GetTuple1(0), 16.0);
}

TEST(vtkGLGeodesicDistanceFields, BadInputGivesAnErrorAndAnEmptyOutput) {
  struct Case {
    const char* what;
    std::function<void(vtkUnstructuredGrid*, vtkGLGeodesicDistanceFields*)> setUp;
    const char* expected;
  };
  const std::vector<Case> cases = {
      {"empty grid", [](vtkUnstructuredGrid* g, vtkGLGeodesicDistanceFields*) { g->Initialize(); },
       "empty mesh"},
      {"hexahedron",
       [](vtkUnstructuredGrid* g, vtkGLGeodesicDistanceFields*) {
         const vtkIdType ids[8] = {0, 1, 2, 3, 4, 5, 6, 7};
         g->InsertNextCell(VTK_HEXAHEDRON, 8, ids);
       },
       "not a linear tetrahedron"},
      {"inverted tet",
       [](vtkUnstructuredGrid* g, vtkGLGeodesicDistanceFields*) {
         vtkIdType npts;
         const vtkIdType* pts;
         g->GetCellPoints(3, npts, pts);
         const vtkIdType swapped[4] = {pts[1], pts[0], pts[2], pts[3]};
         g->GetCells()->ReplaceCellAtId(3, 4, swapped);
       },
       "inverted tet 3"},
      {"zero time factor",
       [](vtkUnstructuredGrid*, vtkGLGeodesicDistanceFields* f) { f->SetTimeFactor(0); },
       "time factor"},
      {"zero reference",
       [](vtkUnstructuredGrid*, vtkGLGeodesicDistanceFields* f) { f->SetReferenceVector(0, 0, 0); },
       "reference vector"},
      {"missing mask array",
       [](vtkUnstructuredGrid*, vtkGLGeodesicDistanceFields* f) {
         f->SetSourceMode(vtkGLGeodesicDistanceFields::MASK_ARRAY);
         f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "NoSuchArray");
       },
       "array is missing"},
      {"all-zero mask",
       [](vtkUnstructuredGrid* g, vtkGLGeodesicDistanceFields* f) {
         vtkNew<vtkDoubleArray> mask;
         mask->SetName("Zero");
         mask->SetNumberOfTuples(g->GetNumberOfPoints());
         mask->FillValue(0);
         g->GetPointData()->AddArray(mask);
         f->SetSourceMode(vtkGLGeodesicDistanceFields::MASK_ARRAY);
         f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Zero");
       },
       "empty source set"},
      {"negative base tolerance",
       [](vtkUnstructuredGrid*, vtkGLGeodesicDistanceFields* f) { f->SetBaseTolerance(-1); },
       "base tolerance"},
  };
  for (const Case& c : cases) {
    auto grid = boxGrid(2, 2, 2, 2, 2, 2);
    vtkNew<vtkGLGeodesicDistanceFields> filter;
    c.setUp(grid, filter);
    filter->SetInputData(grid);
    vtkNew<GLTestErrorObserver> errors;
    errors->Observe(filter);
    filter->Update();
    EXPECT_TRUE(errors->HasError()) << c.what;
    EXPECT_NE(errors->Errors().find(c.expected), std::string::npos)
        << c.what << ": " << errors->Errors();
    EXPECT_EQ(filter->GetOutput()->GetNumberOfCells(), 0) << c.what;
    EXPECT_EQ(filter->GetOutput()->GetPointData()->GetArray(arrays::Gamma), nullptr) << c.what;
  }
}

TEST(vtkGLGeodesicDistanceFields, ProgressAndAbortInTheSetUpAndInTheSolve) {
  auto grid = boxGrid(20, 20, 30, 10, 10, 15);
  vtkNew<vtkGLGeodesicDistanceFields> reference;
  reference->SetInputData(grid);
  // Fresh filter: conversion, the set-up (assembly, two factorizations), the solve steps.
  glExpectProgressReport(reference, 8);
  vtkDataArray* gamma = pointArray(reference->GetOutput(), arrays::Gamma);
  ASSERT_NE(gamma, nullptr);

  vtkNew<vtkGLGeodesicDistanceFields> filter;
  filter->SetInputData(grid);
  glExpectCleanAbort(filter, glAbortAt(0.3));  // after the heat factorization
  // The recovery run rebuilt the solver and keeps it: this abort comes inside solve().
  glExpectCleanAbort(filter, glAbortAt(0.7));
  // After both aborts the fields are those of an undisturbed run.
  vtkDataArray* again = pointArray(filter->GetOutput(), arrays::Gamma);
  ASSERT_NE(again, nullptr);
  ASSERT_EQ(again->GetNumberOfTuples(), gamma->GetNumberOfTuples());
  for (vtkIdType i = 0; i < gamma->GetNumberOfTuples(); ++i) {
    ASSERT_EQ(again->GetTuple1(i), gamma->GetTuple1(i)) << i;
  }
}

TEST(vtkGLGeodesicDistanceFields, AReleasedSolverIsFactoredAgainWithTheSameFields) {
  auto grid = boxGrid(8, 8, 12, 4, 4, 6);
  vtkNew<vtkGLGeodesicDistanceFields> filter;
  filter->SetInputData(grid);
  filter->Update();
  vtkNew<vtkDoubleArray> before;
  before->DeepCopy(pointArray(filter->GetOutput(), arrays::Gamma));
  filter->ReleaseSolver();
  filter->Modified();  // the same set-up, updated after the release: factored again
  filter->Update();
  vtkDataArray* after = pointArray(filter->GetOutput(), arrays::Gamma);
  ASSERT_EQ(after->GetNumberOfTuples(), before->GetNumberOfTuples());
  for (vtkIdType i = 0; i < after->GetNumberOfTuples(); ++i) {
    ASSERT_NEAR(after->GetTuple1(i), before->GetTuple1(i), 1e-12) << i;
  }
  filter->ReleaseSolver();
  filter->ReleaseSolver();  // twice: nothing to drop
}
