// GL Pedestal on the bundled bunny (80 mm): Height 0 passes it through; Height 10 stands it on a
// column of its contact area 10 mm higher, closed, with the field data, and the next stage meshes
// it; the pipeline wiring runs it between the orientation and the mesh.
#include "vtkGLPedestal.h"

#include "GLPrintPipeline.h"
#include "GLTestArrays.h"
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
}  // namespace

TEST(vtkGLPedestal, RaisesTheBunnyOnAColumnOfItsFootprint) {
  GLPrintPipeline p;
  p.Reader->SetFileName((kData + "/bunny.obj").c_str());
  p.Placement->SetFitSize(80);
  ASSERT_TRUE(p.Pedestal->Update(0, nullptr));
  vtkPolyData* same = vtkPolyData::SafeDownCast(p.Pedestal->GetOutputDataObject(0));
  vtkPolyData* placed = vtkPolyData::SafeDownCast(p.Placement->GetOutputDataObject(0));
  EXPECT_EQ(same->GetNumberOfPoints(), placed->GetNumberOfPoints());
  EXPECT_EQ(fieldValue(same, geolattice::arrays::PedestalHeight), 0);
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
  EXPECT_EQ(fieldValue(raised, geolattice::arrays::PedestalHeight), 10);
  EXPECT_GT(fieldValue(raised, geolattice::arrays::PedestalFootprintArea), 10);
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

TEST(vtkGLPedestal, BuildsThePedestalTheOrientationSearchChose) {
  // GL Auto Orient's field data names the pedestal it scored the orientation on; with
  // UseOrientation (the default) that one is built, whatever Height says.
  GLPrintPipeline p;
  p.Reader->SetFileName((kData + "/bunny.obj").c_str());
  p.Placement->SetFitSize(80);
  ASSERT_TRUE(p.Placement->Update(0, nullptr));
  vtkNew<vtkPolyData> chosen;
  chosen->ShallowCopy(p.Placement->GetOutputDataObject(0));
  vtkNew<vtkFieldData> fd;
  geolattice::addFieldArray(fd, geolattice::arrays::OrientPedestalHeight, {7.0});
  geolattice::addFieldArray(fd, geolattice::arrays::OrientPedestalContactHeight, {1.0});
  chosen->SetFieldData(fd);
  vtkNew<vtkGLPedestal> f;
  f->SetInputData(chosen);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(f);
  EXPECT_EQ(f->HeightFor(chosen), 7.0);
  ASSERT_TRUE(f->Update(0, nullptr)) << errors->Errors();
  EXPECT_EQ(fieldValue(f->GetOutputDataObject(0), geolattice::arrays::PedestalHeight), 7);
  double bounds[6];
  vtkPolyData::SafeDownCast(f->GetOutputDataObject(0))->GetBounds(bounds);
  double placed[6];
  chosen->GetBounds(placed);
  EXPECT_NEAR(bounds[5], placed[5] + 7, 1e-9);
  // Its reach into the part is the search's 1 mm, not ContactHeight's 0.3 mm: a wider column
  // (on the bunny that band touched itself at a vertex: a pinch the footprint now leaves out).
  const double wide =
      fieldValue(f->GetOutputDataObject(0), geolattice::arrays::PedestalFootprintArea);
  f->SetUseOrientation(false);
  f->SetHeight(7);
  ASSERT_TRUE(f->Update(0, nullptr));
  EXPECT_LT(fieldValue(f->GetOutputDataObject(0), geolattice::arrays::PedestalFootprintArea), wide);
  // A height override (GLPrintPipeline::RaisePedestalByToolpath) replaces the search's height
  // and keeps its footprint.
  f->SetUseOrientation(true);
  f->SetHeightOverride(14);
  EXPECT_EQ(f->HeightFor(chosen), 14.0);
  ASSERT_TRUE(f->Update(0, nullptr)) << errors->Errors();
  EXPECT_EQ(fieldValue(f->GetOutputDataObject(0), geolattice::arrays::PedestalHeight), 14);
  EXPECT_EQ(fieldValue(f->GetOutputDataObject(0), geolattice::arrays::PedestalFootprintArea), wide);
  f->SetHeightOverride(-1);
  // The search chose none: nothing is built, with UseOrientation on.
  fd->GetArray(geolattice::arrays::OrientPedestalHeight)->SetTuple1(0, 0.0);
  chosen->Modified();
  f->SetUseOrientation(true);
  EXPECT_EQ(f->HeightFor(chosen), 0.0);
  ASSERT_TRUE(f->Update(0, nullptr));
  EXPECT_EQ(f->GetOutputDataObject(0)->GetNumberOfElements(vtkDataObject::POINT),
            chosen->GetNumberOfPoints());
}
