#include "vtkGLPlaceOnPlatform.h"

#include "GLTestErrorObserver.h"
#include "GLTestProgress.h"
#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLMeshReader.h"
#include "mesh/AnalyticShapes.h"
#include "mesh/SurfaceCheck.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace {
const std::string kData = GEOLATTICE_TESTDATA;

vtkSmartPointer<vtkPointSet> readModel(const std::string& name) {
  vtkNew<vtkGLMeshReader> reader;
  reader->SetFileName((kData + "/" + name).c_str());
  reader->Update();
  return vtkPointSet::SafeDownCast(reader->GetOutputDataObject(0));
}

/// Bounds of all points.
std::array<double, 6> pointBounds(vtkPointSet* ds) {
  std::array<double, 6> b;
  ds->GetPoints()->GetBounds(b.data());
  return b;
}

double fieldValue(vtkPointSet* ds, const char* name, int i) {
  vtkDataArray* a = ds->GetFieldData()->GetArray(name);
  EXPECT_NE(a, nullptr) << name;
  return a ? a->GetComponent(i, 0) : std::numeric_limits<double>::quiet_NaN();
}

struct Placed {
  vtkSmartPointer<vtkPointSet> Output;
  vtkSmartPointer<GLTestErrorObserver> Errors;
};

Placed place(vtkPointSet* input, double scale, double fitSize, bool centerXY) {
  vtkNew<vtkGLPlaceOnPlatform> filter;
  Placed p;
  p.Errors = vtkSmartPointer<GLTestErrorObserver>::New();
  p.Errors->Observe(filter);
  filter->SetInputData(input);
  filter->SetScale(scale);
  filter->SetFitSize(fitSize);
  filter->SetCenterXY(centerXY);
  filter->Update();
  p.Output = vtkPointSet::SafeDownCast(filter->GetOutputDataObject(0));
  return p;
}
}  // namespace

TEST(PlaceOnPlatform, DefaultsCentreAndSitOnPlatform) {
  vtkNew<vtkGLPlaceOnPlatform> defaults;
  EXPECT_EQ(defaults->GetScale(), 1.0);
  EXPECT_EQ(defaults->GetFitSize(), 0.0);
  EXPECT_TRUE(defaults->GetCenterXY());

  vtkSmartPointer<vtkPointSet> bunny = readModel("bunny.obj");
  ASSERT_TRUE(bunny && bunny->GetNumberOfPoints() > 0);
  const auto in = pointBounds(bunny);
  ASSERT_GT(std::abs(in[4]), 1e-3) << "the test needs a model not already on z = 0";
  Placed p = place(bunny, 1.0, 0.0, true);
  EXPECT_FALSE(p.Errors->HasError()) << p.Errors->Errors();
  ASSERT_TRUE(vtkPolyData::SafeDownCast(p.Output));
  EXPECT_EQ(p.Output->GetNumberOfPoints(), bunny->GetNumberOfPoints());
  EXPECT_EQ(p.Output->GetNumberOfCells(), bunny->GetNumberOfCells());
  const auto out = pointBounds(p.Output);
  EXPECT_EQ(out[4], 0.0);  // exactly: the base sits on the platform
  EXPECT_NEAR(out[0] + out[1], 0.0, 1e-12);
  EXPECT_NEAR(out[2] + out[3], 0.0, 1e-12);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(out[2 * k + 1] - out[2 * k], in[2 * k + 1] - in[2 * k], 1e-12) << "axis " << k;
  }
  EXPECT_EQ(fieldValue(p.Output, geolattice::arrays::PlacementScale, 0), 1.0);
  EXPECT_EQ(p.Output->GetFieldData()
                ->GetArray(geolattice::arrays::PlacementTranslation)
                ->GetNumberOfTuples(),
            3);
  // Every point follows p_out = s p_in + t with the recorded s and t.
  const double s = fieldValue(p.Output, geolattice::arrays::PlacementScale, 0);
  double t[3];
  for (int k = 0; k < 3; ++k) {
    t[k] = fieldValue(p.Output, geolattice::arrays::PlacementTranslation, k);
  }
  EXPECT_NEAR(t[2], -in[4], 1e-12);
  for (vtkIdType i = 0; i < bunny->GetNumberOfPoints(); i += 97) {
    double a[3], b[3];
    bunny->GetPoint(i, a);
    p.Output->GetPoint(i, b);
    for (int k = 0; k < 3; ++k) {
      ASSERT_NEAR(b[k], s * a[k] + t[k], 1e-12) << "point " << i;
    }
  }
}

TEST(PlaceOnPlatform, FitSizeGivesLargestSideOnTetMesh) {
  vtkSmartPointer<vtkPointSet> ring = readModel("ring.tet");
  ASSERT_TRUE(vtkUnstructuredGrid::SafeDownCast(ring));
  const auto in = pointBounds(ring);
  const double largestIn = std::max({in[1] - in[0], in[3] - in[2], in[5] - in[4]});
  Placed p = place(ring, /*scale ignored*/ 7.0, 50.0, true);
  EXPECT_FALSE(p.Errors->HasError()) << p.Errors->Errors();
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(p.Output);
  ASSERT_NE(grid, nullptr);
  EXPECT_EQ(grid->GetNumberOfCells(), 40064);
  const auto out = pointBounds(grid);
  const double largestOut = std::max({out[1] - out[0], out[3] - out[2], out[5] - out[4]});
  EXPECT_NEAR(largestOut, 50.0, 1e-12);
  EXPECT_EQ(out[4], 0.0);
  EXPECT_DOUBLE_EQ(fieldValue(grid, geolattice::arrays::PlacementScale, 0), 50.0 / largestIn);
}

TEST(PlaceOnPlatform, ScaleWithoutCentringKeepsXY) {
  vtkSmartPointer<vtkPointSet> knight = readModel("decimated-knight.off");
  ASSERT_TRUE(knight);
  const auto in = pointBounds(knight);
  Placed p = place(knight, 10.0, 0.0, false);
  EXPECT_FALSE(p.Errors->HasError()) << p.Errors->Errors();
  const auto out = pointBounds(p.Output);
  EXPECT_NEAR(out[0], 10.0 * in[0], 1e-12);
  EXPECT_NEAR(out[3], 10.0 * in[3], 1e-12);
  EXPECT_NEAR(out[5], 10.0 * (in[5] - in[4]), 1e-12);
  EXPECT_EQ(out[4], 0.0);
  EXPECT_EQ(fieldValue(p.Output, geolattice::arrays::PlacementTranslation, 0), 0.0);
  EXPECT_EQ(fieldValue(p.Output, geolattice::arrays::PlacementTranslation, 1), 0.0);
}

TEST(PlaceOnPlatform, ArraysPassAndUnusedPointsCount) {
  // Two triangles plus one point no cell uses, lowest of all: it must land on z = 0 too.
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->InsertNextPoint(0.1, 0.2, 1.3);
  points->InsertNextPoint(1.1, 0.2, 1.3);
  points->InsertNextPoint(0.1, 1.2, 1.7);
  points->InsertNextPoint(5.0, 5.0, 0.7);  // unused
  poly->SetPoints(points);
  vtkNew<vtkCellArray> tris;
  const vtkIdType tri[3] = {0, 1, 2};
  tris->InsertNextCell(3, tri);
  poly->SetPolys(tris);
  vtkNew<vtkDoubleArray> tag;
  tag->SetName("Tag");
  for (int i = 0; i < 4; ++i) {
    tag->InsertNextValue(i * 2.0);
  }
  poly->GetPointData()->AddArray(tag);

  Placed p = place(poly, 2.0, 0.0, true);
  EXPECT_FALSE(p.Errors->HasError()) << p.Errors->Errors();
  ASSERT_EQ(p.Output->GetNumberOfPoints(), 4);
  EXPECT_EQ(p.Output->GetPoints()->GetDataType(), VTK_DOUBLE);
  double q[3];
  p.Output->GetPoint(3, q);
  EXPECT_EQ(q[2], 0.0);
  vtkDataArray* passed = p.Output->GetPointData()->GetArray("Tag");
  ASSERT_NE(passed, nullptr);
  EXPECT_EQ(passed->GetComponent(3, 0), 6.0);
}

TEST(PlaceOnPlatform, SinglePointIsRefusedAsUnprintable) {
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(3, 4, 5);
  poly->SetPoints(points);
  Placed p = place(poly, 1.0, 0.0, true);
  EXPECT_NE(p.Errors->Errors().find("0 mm across"), std::string::npos) << p.Errors->Errors();
  EXPECT_EQ(p.Output->GetNumberOfPoints(), 0);
}

TEST(PlaceOnPlatform, UnitMistakesAreNamed) {
  // A 0.05 model-unit part (metres): refused with the likely fix.
  vtkSmartPointer<vtkPointSet> cube = readModel("cube.obj");
  Placed metres = place(cube, 0.05, 0.0, true);
  EXPECT_NE(metres.Errors->Errors().find("is the file in metres? use Scale 1000"),
            std::string::npos)
      << metres.Errors->Errors();
  Placed huge = place(cube, 1e12, 0.0, true);
  EXPECT_NE(huge.Errors->Errors().find("a printable part is 1 mm to 2000 mm"), std::string::npos)
      << huge.Errors->Errors();
  Placed fitted = place(cube, 0.05, 80.0, true);  // FitSize repairs it
  EXPECT_FALSE(fitted.Errors->HasError()) << fitted.Errors->Errors();
}

// ---------------------------------------------------------------- bad parameters

TEST(PlaceOnPlatform, BadParametersGiveErrorAndEmptyOutput) {
  vtkSmartPointer<vtkPointSet> cube = readModel("cube.obj");
  ASSERT_TRUE(cube && cube->GetNumberOfPoints() == 8);
  struct BadCase {
    double Scale;
    double FitSize;
    const char* Message;
  };
  const BadCase cases[] = {{0.0, 0.0, "Scale must be > 0"},
                           {-2.0, 0.0, "Scale must be > 0"},
                           {std::nan(""), 0.0, "Scale must be > 0"},
                           {1.0, -1.0, "FitSize must be >= 0"},
                           {-1.0, 10.0, "Scale must be > 0"}};
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.Message);
    Placed p = place(cube, c.Scale, c.FitSize, true);
    EXPECT_EQ(p.Errors->GetErrorCount(), 1);
    EXPECT_NE(p.Errors->Errors().find(c.Message), std::string::npos) << p.Errors->Errors();
    ASSERT_NE(p.Output, nullptr);
    EXPECT_EQ(p.Output->GetNumberOfPoints(), 0);
    EXPECT_EQ(p.Output->GetNumberOfCells(), 0);
  }
}

TEST(PlaceOnPlatform, EmptyInput) {
  vtkNew<vtkUnstructuredGrid> empty;
  Placed p = place(empty, 1.0, 0.0, true);
  EXPECT_NE(p.Errors->Errors().find("empty input"), std::string::npos) << p.Errors->Errors();
  ASSERT_TRUE(vtkUnstructuredGrid::SafeDownCast(p.Output));
  EXPECT_EQ(p.Output->GetNumberOfPoints(), 0);
}

TEST(PlaceOnPlatform, FitSizeOfDegenerateModel) {
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(1, 1, 1);
  points->InsertNextPoint(1, 1, 1);
  poly->SetPoints(points);
  Placed p = place(poly, 1.0, 10.0, true);
  EXPECT_NE(p.Errors->Errors().find("bounding box is a single point"), std::string::npos)
      << p.Errors->Errors();
  EXPECT_EQ(p.Output->GetNumberOfPoints(), 0);
}

TEST(PlaceOnPlatform, ProgressAndAbort) {
  vtkNew<vtkGLMeshReader> reader;
  reader->SetFileName((kData + "/bunny.obj").c_str());
  reader->Update();
  vtkNew<vtkGLPlaceOnPlatform> place;
  place->SetInputConnection(reader->GetOutputPort());
  glExpectProgressReport(place, 10);
  glExpectCleanAbort(place, glAbortAt(0.5));
}

TEST(PlaceOnPlatform, FillHolesClosesAnOpenSurfaceBeforePlacingIt) {
  vtkNew<vtkGLPlaceOnPlatform> defaults;
  EXPECT_FALSE(defaults->GetFillHoles());
  // The bunny with the triangles around two of its vertices cut away: two holes in a curved
  // surface, one of them at the bottom (its patch may reach below the rim: placed afterwards).
  vtkSmartPointer<vtkPointSet> bunny = readModel("bunny.obj");
  geolattice::TriangleSurface s = geolattice::toTriangleSurface(vtkPolyData::SafeDownCast(bunny));
  int lowest = 0, highest = 0;
  for (int i = 0; i < static_cast<int>(s.points.size()); ++i) {
    lowest = s.points[i].z() < s.points[lowest].z() ? i : lowest;
    highest = s.points[i].z() > s.points[highest].z() ? i : highest;
  }
  std::vector<std::array<int, 3>> kept;
  for (const auto& t : s.triangles) {
    const bool cut =
        std::count(t.begin(), t.end(), lowest) + std::count(t.begin(), t.end(), highest);
    if (!cut) {
      kept.push_back(t);
    }
  }
  ASSERT_LT(kept.size(), s.triangles.size());
  s.triangles = kept;
  vtkNew<vtkPolyData> open;
  geolattice::fromTriangleSurface(s, open);
  ASSERT_GT(geolattice::checkSurface(s).boundaryEdges, 0);

  Placed asIs = place(open, 1.0, 0.0, true);  // off: passed on as it is
  EXPECT_EQ(asIs.Output->GetNumberOfCells(), open->GetNumberOfCells());
  EXPECT_FALSE(asIs.Output->GetFieldData()->GetArray(geolattice::arrays::FilledHoles));

  vtkNew<vtkGLPlaceOnPlatform> filter;
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(filter);
  filter->SetInputData(open);
  filter->SetFillHoles(true);
  filter->Update();
  EXPECT_FALSE(errors->HasError()) << errors->Errors();
  vtkPolyData* closed = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
  ASSERT_TRUE(closed);
  EXPECT_GT(closed->GetNumberOfCells(), open->GetNumberOfCells());
  EXPECT_TRUE(geolattice::checkSurface(geolattice::toTriangleSurface(closed)).isClosedManifold());
  EXPECT_EQ(fieldValue(closed, geolattice::arrays::FilledHoles, 0), 2.0);
  EXPECT_EQ(fieldValue(closed, geolattice::arrays::FilledHoleTriangles, 0),
            static_cast<double>(closed->GetNumberOfCells() - open->GetNumberOfCells()));
  EXPECT_EQ(pointBounds(closed)[4], 0.0);  // the patches placed with the part
}

TEST(PlaceOnPlatform, FillCavitiesPrintsAHollowBallSolid) {
  vtkNew<vtkGLPlaceOnPlatform> defaults;
  EXPECT_FALSE(defaults->GetFillCavities());
  // A ball with a sealed void (the void's faces inward), as a hollow part is exported.
  geolattice::TriangleSurface hollow = geolattice::sphereSurface(geolattice::Vec3::Zero(), 20, 3);
  const geolattice::TriangleSurface voidShell =
      geolattice::sphereSurface(geolattice::Vec3::Zero(), 12, 3);
  const int offset = static_cast<int>(hollow.points.size());
  hollow.points.insert(hollow.points.end(), voidShell.points.begin(), voidShell.points.end());
  for (const auto& t : voidShell.triangles) {
    hollow.triangles.push_back({t[0] + offset, t[2] + offset, t[1] + offset});
  }
  vtkNew<vtkPolyData> input;
  geolattice::fromTriangleSurface(hollow, input);

  Placed asIs = place(input, 1.0, 0.0, true);  // off: passed on as it is
  EXPECT_EQ(asIs.Output->GetNumberOfCells(), input->GetNumberOfCells());
  EXPECT_FALSE(asIs.Output->GetFieldData()->GetArray(geolattice::arrays::FilledCavities));

  vtkNew<vtkGLPlaceOnPlatform> filter;
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(filter);
  filter->SetInputData(input);
  filter->SetFillCavities(true);
  filter->Update();
  EXPECT_FALSE(errors->HasError()) << errors->Errors();
  vtkPolyData* solid = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
  ASSERT_TRUE(solid);
  EXPECT_EQ(solid->GetNumberOfCells(),
            static_cast<vtkIdType>(hollow.triangles.size() - voidShell.triangles.size()));
  EXPECT_EQ(solid->GetNumberOfPoints(), static_cast<vtkIdType>(offset));
  EXPECT_EQ(fieldValue(solid, geolattice::arrays::FilledCavities, 0), 1.0);
  const auto check = geolattice::checkSurface(geolattice::toTriangleSurface(solid));
  EXPECT_TRUE(check.isClosedManifold());
  EXPECT_GT(check.signedVolume, 0.97 * 4.0 / 3.0 * M_PI * 20 * 20 * 20);  // solid: no void
  EXPECT_EQ(pointBounds(solid)[4], 0.0);
}

TEST(PlaceOnPlatform, WrapReplacesACrossingSurfaceByAClosedOneInPlacedMillimetres) {
  vtkNew<vtkGLPlaceOnPlatform> defaults;
  EXPECT_EQ(defaults->GetWrap(), 0.0);
  // Two unit boxes overlapping by half, their points not shared (facets cross), in metres-like
  // units: FitSize 30 scales by 20, so Wrap 1 mm is 0.05 input units and the wrap's offset
  // 1/30 mm of the placed part.
  geolattice::TriangleSurface soup = geolattice::boxSurface(geolattice::Vec3(1, 1, 1), 0.25);
  const geolattice::TriangleSurface second =
      geolattice::boxSurface(geolattice::Vec3(1, 1, 1), 0.25);
  const int offset = static_cast<int>(soup.points.size());
  for (const geolattice::Vec3& p : second.points) {
    soup.points.push_back(p + geolattice::Vec3(0.5, 0, 0));
  }
  for (const auto& t : second.triangles) {
    soup.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  vtkNew<vtkPolyData> input;
  geolattice::fromTriangleSurface(soup, input);

  vtkNew<vtkGLPlaceOnPlatform> filter;
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(filter);
  filter->SetInputData(input);
  filter->SetFitSize(30);
  filter->SetWrap(1.0);
  filter->Update();
  EXPECT_FALSE(errors->HasError()) << errors->Errors();
  vtkPolyData* wrapped = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
  ASSERT_TRUE(wrapped);
  const double triangles = fieldValue(wrapped, geolattice::arrays::WrapTriangles, 0);
  EXPECT_EQ(triangles, static_cast<double>(wrapped->GetNumberOfCells()));
  const auto check = geolattice::checkSurface(geolattice::toTriangleSurface(wrapped));
  EXPECT_TRUE(check.isClosedManifold());
  // The union, 30 x 20 x 20 mm placed, within the offset and the rounding of its edges.
  EXPECT_GT(check.signedVolume, 0.99 * 30 * 20 * 20);
  EXPECT_LT(check.signedVolume, 30.1 * 20.1 * 20.1);
  const auto b = pointBounds(wrapped);
  EXPECT_NEAR(b[1] - b[0], 30.0, 1e-9);  // FitSize holds for the wrap
  EXPECT_EQ(b[4], 0.0);
  // Facets about 1 mm across (1 mm of the placed part; 1 input unit would be 20 mm and give a
  // few dozen): more than facets 2 mm across (0.43 x 2² mm² each) would need for 3,200 mm².
  EXPECT_GT(triangles, 3200 / (0.43 * 2 * 2));

  vtkNew<vtkGLPlaceOnPlatform> bad;
  vtkNew<GLTestErrorObserver> badErrors;
  badErrors->Observe(bad);
  bad->SetInputData(input);
  bad->SetWrap(-1);
  EXPECT_FALSE(bad->Update(0, nullptr));
  EXPECT_NE(badErrors->Errors().find("Wrap must be >= 0"), std::string::npos)
      << badErrors->Errors();
}
