// vtkGLCollisionVerifier on hand-built towers: two vertical stacks of short horizontal segments
// 3 mm apart (NozzleAxis +z). Printing tower A completely before tower B collides at NA 60;
// alternating layer by layer does not. Cell and point time arrays, the output arrays, and bad input.
#include "GLTestArrays.h"
#include "GLTestDefaults.h"
#include "GLTestErrorObserver.h"
#include "GLTestProgress.h"

#include "vtkGLArrayNames.h"
#include "vtkGLCollisionVerifier.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>

namespace arrays = geolattice::arrays;
namespace role = geolattice::collisionrole;

namespace {

constexpr int kLayers = 10;

/// Towers A (x = 0) and B (x = 3): at z = 0, 1, .., kLayers - 1 a 1 mm segment along x (own
/// points, one line cell each), NozzleAxis +z. Cell array "PrintOrder" = time(tower, layer), point
/// array "PointTime" the same per point. Cells: A's layers, then B's.
vtkSmartPointer<vtkPolyData> towers(const std::function<int(int, int)>& time,
                                    double spacing = 3.0) {
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkDoubleArray> normals;
  normals->SetName(arrays::NozzleAxis);
  normals->SetNumberOfComponents(3);
  vtkNew<vtkIntArray> cellTime, pointTime;
  cellTime->SetName(arrays::PrintOrder);
  pointTime->SetName("PointTime");
  for (int tower = 0; tower < 2; ++tower) {
    for (int layer = 0; layer < kLayers; ++layer) {
      const double x = tower * spacing;
      const vtkIdType a = points->InsertNextPoint(x - 0.5, 0, layer);
      const vtkIdType b = points->InsertNextPoint(x + 0.5, 0, layer);
      const vtkIdType ids[2] = {a, b};
      lines->InsertNextCell(2, ids);
      cellTime->InsertNextValue(time(tower, layer));
      for (int k = 0; k < 2; ++k) {
        normals->InsertNextTuple3(0, 0, 1);
        pointTime->InsertNextValue(time(tower, layer));
      }
    }
  }
  pd->SetPoints(points);
  pd->SetLines(lines);
  pd->GetPointData()->AddArray(normals);
  pd->GetPointData()->AddArray(pointTime);
  pd->GetCellData()->AddArray(cellTime);
  return pd;
}

int towerByTower(int tower, int layer) {
  return tower * kLayers + layer;
}
int layerByLayer(int tower, int layer) {
  return 2 * layer + tower;
}

struct Verified {
  vtkSmartPointer<vtkPolyData> output;
  std::string errors;
};

Verified verify(vtkPolyData* input, double angle = 60.0,
                const std::function<void(vtkGLCollisionVerifier*)>& set = nullptr) {
  vtkNew<vtkGLCollisionVerifier> verifier;
  verifier->SetInputData(input);
  verifier->GetNozzle()->SetNozzleAngle(angle);
  if (set) {
    set(verifier);
  }
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(verifier);
  verifier->Update();
  return {verifier->GetOutput(), errors->Errors()};
}

void expectEmptyWithError(const Verified& v, const std::string& text) {
  EXPECT_NE(v.errors.find(text), std::string::npos) << "errors: " << v.errors;
  EXPECT_EQ(v.output->GetNumberOfPoints(), 0);
  EXPECT_EQ(v.output->GetNumberOfCells(), 0);
  EXPECT_EQ(v.output->GetFieldData()->GetArray(arrays::CollisionFree), nullptr);
}

}  // namespace

TEST(vtkGLCollisionVerifier, TowerByTowerCollidesAndReportsTheViolations) {
  const Verified v = verify(towers(towerByTower));
  ASSERT_TRUE(v.errors.empty()) << v.errors;
  vtkPolyData* out = v.output;
  EXPECT_EQ(fieldValue(out, arrays::CollisionFree), 0.0);
  EXPECT_EQ(fieldValue(out, arrays::CollisionOrderFree),
            0.0);  // no skeleton: every violation counts
  EXPECT_EQ(fieldValue(out, arrays::CollisionUnavoidableStations), 0.0);
  EXPECT_EQ(out->GetFieldData()->GetArray(arrays::CollisionFree)->GetDataType(), VTK_INT);
  // 1 mm segments sampled every 1 mm: just their end points.
  EXPECT_EQ(fieldValue(out, arrays::CollisionStations), 4.0 * kLayers);
  EXPECT_GT(fieldValue(out, arrays::CollisionViolatingStations), 0.0);
  EXPECT_GE(fieldValue(out, arrays::CollisionSeconds), 0.0);
  EXPECT_EQ(fieldValue(out, arrays::NozzleAngleDeg), 60.0);
  const vtkIdType R = out->GetNumberOfCells();
  ASSERT_GT(R, 0);
  EXPECT_LE(R, 20);
  EXPECT_EQ(out->GetNumberOfPoints(), 2 * R);
  vtkPointData* pd = out->GetPointData();
  for (const char* name : {arrays::ViolationIndex, arrays::Role, arrays::Height, arrays::Radial,
                           arrays::Unavoidable}) {
    ASSERT_NE(pd->GetArray(name), nullptr) << name;
  }
  const double tanNA = std::tan(60.0 * M_PI / 180.0);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < R; ++c) {
    out->GetCellPoints(c, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), 2);
    const vtkIdType station = ids->GetId(0), obstacle = ids->GetId(1);
    EXPECT_EQ(pd->GetArray(arrays::Role)->GetTuple1(station), role::Station);
    EXPECT_EQ(pd->GetArray(arrays::Role)->GetTuple1(obstacle), role::Obstacle);
    EXPECT_EQ(pd->GetArray(arrays::ViolationIndex)->GetTuple1(station), c);
    EXPECT_EQ(pd->GetArray(arrays::ViolationIndex)->GetTuple1(obstacle), c);
    double s[3], o[3];
    out->GetPoint(station, s);
    out->GetPoint(obstacle, o);
    const double height = pd->GetArray(arrays::Height)->GetTuple1(station);
    const double radial = pd->GetArray(arrays::Radial)->GetTuple1(station);
    EXPECT_NEAR(height, o[2] - s[2], 1e-9);  // axis +z
    EXPECT_NEAR(radial, std::hypot(o[0] - s[0], o[1] - s[1]), 1e-9);
    EXPECT_GT(height, 0.0);
    EXPECT_LT(radial, height * tanNA);
    EXPECT_GT(s[0], 1.0);  // the station is on tower B, the obstacle on tower A
    EXPECT_LT(o[0], 1.0);
  }
  // A narrower nozzle clears the towers: 3 ± 0.5 mm away, 9 mm high at most.
  const Verified narrow = verify(towers(towerByTower), 10.0);
  ASSERT_TRUE(narrow.errors.empty()) << narrow.errors;
  EXPECT_EQ(fieldValue(narrow.output, arrays::CollisionFree), 1.0);
  // MaxReported limits the output, not the counts.
  const Verified few =
      verify(towers(towerByTower), 60.0, [](vtkGLCollisionVerifier* f) { f->SetMaxReported(3); });
  EXPECT_EQ(few.output->GetNumberOfCells(), 3);
  EXPECT_EQ(fieldValue(few.output, arrays::CollisionViolatingStations),
            fieldValue(out, arrays::CollisionViolatingStations));
}

TEST(vtkGLCollisionVerifier, LayerByLayerIsCollisionFree) {
  const Verified v = verify(towers(layerByLayer));
  ASSERT_TRUE(v.errors.empty()) << v.errors;
  EXPECT_EQ(fieldValue(v.output, arrays::CollisionFree), 1.0);
  EXPECT_EQ(fieldValue(v.output, arrays::CollisionViolatingStations), 0.0);
  EXPECT_EQ(fieldValue(v.output, arrays::CollisionStations), 4.0 * kLayers);
  EXPECT_EQ(v.output->GetNumberOfPoints(), 0);
  EXPECT_EQ(v.output->GetNumberOfCells(), 0);
}

TEST(vtkGLCollisionVerifier, PointTimeArrayAndInteriorSamples) {
  // The same verdicts with the per-point times.
  for (auto time : {towerByTower, layerByLayer}) {
    auto input = towers(time);
    input->GetCellData()->RemoveArray(arrays::PrintOrder);
    const Verified v =
        verify(input, 60.0, [](vtkGLCollisionVerifier* f) { f->SetTimeArrayName("PointTime"); });
    ASSERT_TRUE(v.errors.empty()) << v.errors;
    EXPECT_EQ(fieldValue(v.output, arrays::CollisionStations), 4.0 * kLayers);
    EXPECT_EQ(fieldValue(v.output, arrays::CollisionFree), time == layerByLayer ? 1.0 : 0.0);
  }
  // Spacing 0.3 mm: ceil(1 / 0.3) - 1 = 3 interior samples per segment.
  const Verified fine = verify(towers(layerByLayer), 60.0,
                               [](vtkGLCollisionVerifier* f) { f->SetSampleSpacing(0.3); });
  ASSERT_TRUE(fine.errors.empty()) << fine.errors;
  EXPECT_EQ(fieldValue(fine.output, arrays::CollisionStations), (4.0 + 6.0) * kLayers);
  EXPECT_EQ(fieldValue(fine.output, arrays::CollisionFree), 1.0);
  // A cell array of that name takes precedence over a point array.
  auto both = towers(layerByLayer);
  vtkNew<vtkIntArray> cellTime;
  cellTime->DeepCopy(both->GetCellData()->GetArray(arrays::PrintOrder));
  cellTime->SetName("PointTime");
  for (vtkIdType c = 0; c < cellTime->GetNumberOfTuples(); ++c) {
    cellTime->SetValue(c, towerByTower(c / kLayers, c % kLayers));
  }
  both->GetCellData()->AddArray(cellTime);
  const Verified cell =
      verify(both, 60.0, [](vtkGLCollisionVerifier* f) { f->SetTimeArrayName("PointTime"); });
  EXPECT_EQ(fieldValue(cell.output, arrays::CollisionFree), 0.0);
}

TEST(vtkGLCollisionVerifier, TheStationsOutputColoursTheToolpathByItsVerdict) {
  // Per-point times (a toolpath): output 1 is the input with Collision per point, 1 where earlier
  // material is in the nozzle, as many as the violating stations; a plate under a nozzle tilted
  // into it marks 2. Line-cell times: the samples as vertices.
  auto input = towers(towerByTower);
  vtkNew<vtkGLCollisionVerifier> f;
  f->SetInputData(input);
  f->SetTimeArrayName("PointTime");
  f->GetNozzle()->SetNozzleAngle(60);
  f->Update();
  auto* stations = vtkPolyData::SafeDownCast(f->GetOutputDataObject(1));
  ASSERT_NE(stations, nullptr);
  EXPECT_EQ(stations->GetNumberOfPoints(), input->GetNumberOfPoints());
  EXPECT_EQ(stations->GetNumberOfLines(), input->GetNumberOfLines());
  vtkDataArray* kind = stations->GetPointData()->GetArray(arrays::Collision);
  ASSERT_NE(kind, nullptr);
  int material = 0, plate = 0;
  for (vtkIdType p = 0; p < kind->GetNumberOfTuples(); ++p) {
    material += kind->GetTuple1(p) == geolattice::collisionkind::Material;
    plate += kind->GetTuple1(p) == geolattice::collisionkind::Plate;
  }
  EXPECT_GT(material, 0);
  EXPECT_EQ(material + plate, fieldValue(f->GetOutput(), arrays::CollisionViolatingStations));
  // Every axis tilted 80 degrees from +z: the cone reaches the plate under the towers.
  vtkDataArray* axes = input->GetPointData()->GetArray(arrays::NozzleAxis);
  for (vtkIdType p = 0; p < axes->GetNumberOfTuples(); ++p) {
    axes->SetTuple3(p, std::sin(80 * M_PI / 180), 0, std::cos(80 * M_PI / 180));
  }
  axes->Modified();
  f->Update();
  kind = vtkPolyData::SafeDownCast(f->GetOutputDataObject(1))
             ->GetPointData()
             ->GetArray(arrays::Collision);
  plate = 0;
  for (vtkIdType p = 0; p < kind->GetNumberOfTuples(); ++p) {
    plate += kind->GetTuple1(p) == geolattice::collisionkind::Plate;
  }
  EXPECT_GT(plate, 0);
  EXPECT_EQ(plate, fieldValue(f->GetOutput(), arrays::CollisionPlateStations));
  // Cell times: the sampled stations.
  f->SetTimeArrayName(arrays::PrintOrder);
  f->Update();
  stations = vtkPolyData::SafeDownCast(f->GetOutputDataObject(1));
  EXPECT_EQ(stations->GetNumberOfPoints(), fieldValue(f->GetOutput(), arrays::CollisionStations));
  EXPECT_EQ(stations->GetNumberOfVerts(), stations->GetNumberOfPoints());
  EXPECT_NE(stations->GetPointData()->GetArray(arrays::Collision), nullptr);
}

TEST(vtkGLCollisionVerifier, PointMoveKindAirIsNoMaterial) {
  // A toolpath-like input: per-point times, tower A printed first. With tower A's points marked as
  // air moves (MoveKind 2) nothing is printed before tower B: no collision; every point is still a
  // station. Print (0) and perimeter (1) points are material.
  auto input = towers(towerByTower);
  input->GetCellData()->RemoveArray(arrays::PrintOrder);
  vtkNew<vtkIntArray> kind;
  kind->SetName(arrays::MoveKind);
  for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p) {
    kind->InsertNextValue(p < 2 * kLayers ? geolattice::movekind::Air
                                          : geolattice::movekind::Print);
  }
  input->GetPointData()->AddArray(kind);
  auto pointTime = [](vtkGLCollisionVerifier* f) {
    f->SetTimeArrayName("PointTime");
  };
  Verified v = verify(input, 60.0, pointTime);
  ASSERT_TRUE(v.errors.empty()) << v.errors;
  EXPECT_EQ(fieldValue(v.output, arrays::CollisionStations), 4.0 * kLayers);
  EXPECT_EQ(fieldValue(v.output, arrays::CollisionFree), 1.0);
  for (int k : {geolattice::movekind::Print, geolattice::movekind::Perimeter}) {
    for (vtkIdType p = 0; p < 2 * kLayers; ++p) {
      kind->SetValue(p, k);
    }
    kind->Modified();
    v = verify(input, 60.0, pointTime);
    ASSERT_TRUE(v.errors.empty()) << v.errors;
    EXPECT_EQ(fieldValue(v.output, arrays::CollisionFree), 0.0) << "MoveKind " << k;
  }
}

TEST(vtkGLCollisionVerifier, SkeletonEdgesMakeAncestorObstaclesUnavoidable) {
  // Each segment is a sub-graph (id = cell index: A's layers 0..9, B's 10..19). With the two
  // towers as separate chains, A is no ancestor of B: the tower-by-tower order is at fault.
  auto input = towers(towerByTower);
  vtkNew<vtkIntArray> subgraph;
  subgraph->SetName(arrays::SubgraphId);
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c) {
    subgraph->InsertNextValue(static_cast<int>(c));
  }
  input->GetCellData()->AddArray(subgraph);
  vtkNew<vtkDoubleArray> edges;
  edges->SetName(arrays::SkeletonEdges);
  edges->SetNumberOfComponents(2);
  for (int tower = 0; tower < 2; ++tower) {
    for (int layer = 0; layer + 1 < kLayers; ++layer) {
      edges->InsertNextTuple2(tower * kLayers + layer, tower * kLayers + layer + 1);
    }
  }
  input->GetFieldData()->AddArray(edges);
  Verified v = verify(input);
  ASSERT_TRUE(v.errors.empty()) << v.errors;
  EXPECT_EQ(fieldValue(v.output, arrays::CollisionFree), 0.0);
  EXPECT_EQ(fieldValue(v.output, arrays::CollisionOrderFree), 0.0);
  EXPECT_EQ(fieldValue(v.output, arrays::CollisionUnavoidableStations), 0.0);
  // One chain A0 .. A9 B0 .. B9: all of A is below B, so no order avoids the collisions.
  edges->InsertNextTuple2(kLayers - 1, kLayers);
  v = verify(input);
  ASSERT_TRUE(v.errors.empty()) << v.errors;
  EXPECT_EQ(fieldValue(v.output, arrays::CollisionFree), 0.0);
  EXPECT_EQ(fieldValue(v.output, arrays::CollisionOrderFree), 1.0);
  EXPECT_GT(fieldValue(v.output, arrays::CollisionUnavoidableStations), 0.0);
  EXPECT_EQ(fieldValue(v.output, arrays::CollisionUnavoidableStations),
            fieldValue(v.output, arrays::CollisionViolatingStations));
  EXPECT_EQ(v.output->GetPointData()->GetArray(arrays::Unavoidable)->GetRange()[0], 1.0);
  // Bad skeleton edges: a cycle, the wrong number of components.
  edges->InsertNextTuple2(kLayers, kLayers - 1);
  expectEmptyWithError(verify(input), "'SkeletonEdges' has a cycle");
  vtkNew<vtkDoubleArray> flat;
  flat->SetName(arrays::SkeletonEdges);
  flat->InsertNextValue(0);
  input->GetFieldData()->AddArray(flat);
  expectEmptyWithError(verify(input), "must have 2 components");
}

TEST(vtkGLCollisionVerifier, DefaultsAndPrintSelf) {
  vtkNew<vtkGLCollisionVerifier> f;
  EXPECT_STREQ(f->GetTimeArrayName(), arrays::PrintOrder);
  expectCoreNozzleDefaults(f->GetNozzle());
  EXPECT_EQ(f->GetSampleSpacing(), 1.0);
  EXPECT_EQ(f->GetMaxReported(), 20);
  expectPrintMentions(f, {"TimeArrayName: PrintOrder", "NozzleAngle: 45", "MaxReported: 20"});
}

TEST(vtkGLCollisionVerifier, BadInputIsReported) {
  expectEmptyWithError(verify(towers(towerByTower), 0.0),
                       "nozzle angle must be in (0, 90) degrees");
  expectEmptyWithError(verify(towers(towerByTower), 90.0),
                       "nozzle angle must be in (0, 90) degrees");
  expectEmptyWithError(
      verify(towers(towerByTower), 60.0,
             [](vtkGLCollisionVerifier* f) { f->GetNozzle()->SetHolderRadius(-1); }),
      "holder radius must be finite and >= 0 mm");
  expectEmptyWithError(
      verify(towers(towerByTower), 60.0, [](vtkGLCollisionVerifier* f) { f->SetSampleSpacing(0); }),
      "sample spacing must be > 0 mm");
  vtkNew<vtkPolyData> empty;
  expectEmptyWithError(verify(empty), "empty input");
  auto noNormals = towers(towerByTower);
  noNormals->GetPointData()->RemoveArray(arrays::NozzleAxis);
  expectEmptyWithError(verify(noNormals), "input has no NozzleAxis point array");
  expectEmptyWithError(verify(towers(towerByTower), 60.0,
                              [](vtkGLCollisionVerifier* f) { f->SetTimeArrayName("NoSuchTime"); }),
                       "input has no cell or point array 'NoSuchTime'");
  auto noTime = towers(towerByTower);
  noTime->GetCellData()->RemoveArray(arrays::PrintOrder);
  expectEmptyWithError(verify(noTime), "input has no cell or point array 'PrintOrder'");
  auto fractional = towers(towerByTower);
  vtkNew<vtkDoubleArray> t;
  t->SetName(arrays::PrintOrder);
  t->SetNumberOfTuples(fractional->GetNumberOfCells());
  t->Fill(0.5);
  fractional->GetCellData()->AddArray(t);
  expectEmptyWithError(verify(fractional), "print times must be integers");
  auto zeroNormal = towers(towerByTower);
  zeroNormal->GetPointData()->GetArray(arrays::NozzleAxis)->SetTuple3(0, 0, 0, 0);
  expectEmptyWithError(verify(zeroNormal), "normal");
}

TEST(vtkGLCollisionVerifier, ProgressAndAbort) {
  auto input = towers(towerByTower);
  vtkNew<vtkGLCollisionVerifier> verifier;
  verifier->SetInputData(input);
  verifier->GetNozzle()->SetNozzleAngle(60.0);
  glExpectProgressReport(verifier, 3);
  glExpectCleanAbort(verifier, glAbortAt(0.2));
  glExpectCleanAbort(verifier, glAbortAt(0.9));
}
