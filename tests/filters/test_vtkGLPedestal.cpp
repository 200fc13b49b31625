// GL Pedestal on the bundled bunny (80 mm): Height 0 passes it through; Height 10 stands it on a
// column of its contact area 10 mm higher, closed, with the field data, and the next stage meshes
// it; the pipeline wiring runs it between the orientation and the mesh.
#include "vtkGLPedestal.h"

#include "GLPrintPipeline.h"
#include "GLTestErrorObserver.h"
#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"

#include "mesh/SurfaceCheck.h"

#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <string>

namespace {
const std::string kData = GEOLATTICE_TESTDATA;

double field(vtkDataObject* d, const char* name) {
  vtkDataArray* a = d->GetFieldData()->GetArray(name);
  EXPECT_NE(a, nullptr) << name;
  return a ? a->GetComponent(0, 0) : -1;
}
}  // namespace

TEST(vtkGLPedestal, RaisesTheBunnyOnAColumnOfItsFootprint) {
  GLPrintPipeline p;
  p.Reader->SetFileName((kData + "/bunny.obj").c_str());
  p.Placement->SetFitSize(80);
  ASSERT_TRUE(p.Pedestal->Update(0, nullptr));
  vtkPolyData* same = vtkPolyData::SafeDownCast(p.Pedestal->GetOutputDataObject(0));
  vtkPolyData* placed = vtkPolyData::SafeDownCast(p.Placement->GetOutputDataObject(0));
  EXPECT_EQ(same->GetNumberOfPoints(), placed->GetNumberOfPoints());
  EXPECT_EQ(field(same, geolattice::arrays::PedestalHeight), 0);
  double before[6];
  same->GetPoints()->GetBounds(before);

  p.Pedestal->SetHeight(10);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(p.Pedestal);
  ASSERT_TRUE(p.Pedestal->Update(0, nullptr));
  EXPECT_FALSE(errors->HasError());
  vtkPolyData* raised = vtkPolyData::SafeDownCast(p.Pedestal->GetOutputDataObject(0));
  double after[6];
  raised->GetPoints()->GetBounds(after);
  EXPECT_NEAR(after[4], 0, 1e-9);
  EXPECT_NEAR(after[5], before[5] + 10, 1e-9);
  EXPECT_NEAR(after[0], before[0], 1e-9);  // the part bulges beyond its footprint
  EXPECT_EQ(field(raised, geolattice::arrays::PedestalHeight), 10);
  EXPECT_GT(field(raised, geolattice::arrays::PedestalFootprintArea), 10);
  const geolattice::SurfaceCheckReport check =
      geolattice::checkSurface(geolattice::toTriangleSurface(raised));
  EXPECT_TRUE(check.isClosedManifold());
  EXPECT_GT(check.signedVolume, 0);
  // The tetrahedralizer meshes the raised part.
  p.Tetrahedralize->SetTargetEdgeLength(4);
  ASSERT_TRUE(p.Tetrahedralize->Update(0, nullptr));
  EXPECT_GT(p.Tetrahedralize->GetOutputDataObject(0)->GetNumberOfElements(vtkDataObject::CELL), 0);
}

TEST(vtkGLPedestal, BadHeightIsReportedBeforeAnyData) {
  vtkNew<vtkGLPedestal> f;
  f->SetHeight(-3);
  vtkNew<vtkPolyData> empty;
  f->SetInputData(empty);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(f);
  EXPECT_FALSE(f->Update(0, nullptr));
  EXPECT_NE(errors->Errors().find("[0, 500]"), std::string::npos) << errors->Errors();
}
