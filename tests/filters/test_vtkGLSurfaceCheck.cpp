// GL Surface Check: the edges that keep a surface from being meshed, and the verdict (issue 20,
// "errors that help": the boundary edges of an open surface are an output a user can show).
#include "GLTestErrorObserver.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshReader.h"
#include "vtkGLSurfaceCheck.h"
#include "vtkGLTetrahedralizeSurface.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <gtest/gtest.h>

#include <string>

namespace arrays = geolattice::arrays;

namespace {
vtkSmartPointer<vtkPolyData> readCube() {
  vtkNew<vtkGLMeshReader> reader;
  reader->SetFileName((std::string(GEOLATTICE_TESTDATA) + "/cube.obj").c_str());
  reader->Update();
  auto cube = vtkSmartPointer<vtkPolyData>::New();
  cube->DeepCopy(reader->GetOutputDataObject(0));
  return cube;
}

double field(vtkPolyData* data, const char* name) {
  vtkDataArray* a = data->GetFieldData()->GetArray(name);
  return a ? a->GetTuple1(0) : -1.0;
}

std::string verdict(vtkPolyData* data) {
  auto* a =
      vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(arrays::SurfaceVerdict));
  return a ? a->GetValue(0) : "";
}
}  // namespace

TEST(vtkGLSurfaceCheck, AClosedSurfaceHasNoDefectEdges) {
  vtkNew<vtkGLSurfaceCheck> check;
  check->SetInputData(readCube());
  ASSERT_EQ(check->GetExecutive()->Update(), 1);
  vtkPolyData* out = check->GetOutput();
  EXPECT_EQ(out->GetNumberOfLines(), 0);
  EXPECT_EQ(field(out, arrays::SurfaceClosed), 1.0);
  EXPECT_EQ(field(out, arrays::BoundaryEdges), 0.0);
  EXPECT_GT(field(out, arrays::SignedVolume), 0.0);
  EXPECT_EQ(verdict(out), "closed manifold");
}

TEST(vtkGLSurfaceCheck, TheHoleOfAnOpenCubeIsShownAndNamedInTheMeshingError) {
  vtkSmartPointer<vtkPolyData> cube = readCube();
  // One triangle less: a hole bounded by its three edges.
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 1; c < cube->GetNumberOfPolys(); ++c) {
    cube->GetCellPoints(c, ids);
    polys->InsertNextCell(ids);
  }
  cube->SetPolys(polys);
  vtkNew<vtkGLSurfaceCheck> check;
  check->SetInputData(cube);
  ASSERT_EQ(check->GetExecutive()->Update(), 1);
  vtkPolyData* out = check->GetOutput();
  ASSERT_EQ(out->GetNumberOfLines(), 3);
  vtkDataArray* kind = out->GetCellData()->GetArray(arrays::DefectKind);
  ASSERT_NE(kind, nullptr);
  for (vtkIdType c = 0; c < 3; ++c) {
    EXPECT_EQ(kind->GetTuple1(c), 0.0);  // boundary
  }
  EXPECT_EQ(field(out, arrays::SurfaceClosed), 0.0);
  EXPECT_EQ(field(out, arrays::BoundaryEdges), 3.0);
  EXPECT_EQ(verdict(out).rfind("open surface: 3 boundary edges", 0), 0u) << verdict(out);

  // GL Tetrahedralize Surface refuses it and says where to see the edges.
  vtkNew<vtkGLTetrahedralizeSurface> tets;
  tets->SetInputData(cube);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(tets);
  EXPECT_EQ(tets->GetExecutive()->Update(), 0);
  EXPECT_NE(errors->Errors().find("open surface"), std::string::npos) << errors->Errors();
  EXPECT_NE(errors->Errors().find("GL Surface Check"), std::string::npos) << errors->Errors();
}
