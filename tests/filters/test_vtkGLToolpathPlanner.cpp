// vtkGLToolpathPlanner: the documented arrays and field data on hand-built towers of unit squares
// (exact lengths) and on the branching Y (reader -> ... -> sequencer -> planner -> verifier),
// the print replay over time (a prefix per requested time, planned once), and bad input.
#include "GLTestDefaults.h"
#include "GLTestErrorObserver.h"
#include "GLTestTowers.h"
#include "GLTestProgress.h"
#include "GLTestYPipeline.h"

#include "vtkGLArrayNames.h"
#include "vtkGLCollisionVerifier.h"
#include "vtkGLCurvedLayerSlicer.h"
#include "vtkGLGeodesicDistanceFields.h"
#include "vtkGLLatticeInfill.h"
#include "vtkGLMeshReader.h"
#include "vtkGLPlaceOnPlatform.h"
#include "vtkGLPrintSequencer.h"
#include "vtkGLSkeletonTree.h"
#include "vtkGLTetrahedralizeSurface.h"
#include "vtkGLToolpathPlanner.h"
#include "vtkGLPrintSummary.h"
#include "vtkGLToolpathReplay.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace arrays = geolattice::arrays;
namespace movekind = geolattice::movekind;

namespace {

/// Two towers 2 mm apart (GLTestTowers.h) whose lattice numbers its layers from 10 (not 0-based,
/// to see the lattice's LayerId pass through).
const TowerLayout kTowers{2, 2.0, 10};

/// Sequencer (A4) + planner on given inputs; the planner reads the sequencer's outputs 0 and 1.
struct PlannerRun {
  vtkNew<vtkGLPrintSequencer> sequencer;
  vtkNew<vtkGLToolpathPlanner> planner;
  vtkNew<GLTestErrorObserver> errors;
  PlannerRun(vtkPolyData* lattice, vtkPolyData* skeleton) {
    sequencer->SetInputData(0, lattice);
    sequencer->SetInputData(1, skeleton);
    sequencer->GetNozzle()->SetNozzleAngle(60.0);
    planner->SetInputConnection(0, sequencer->GetOutputPort(0));
    planner->SetInputConnection(1, sequencer->GetOutputPort(1));
    errors->Observe(sequencer);
    errors->Observe(planner);
  }
  vtkPolyData* output() {
    planner->Update();
    return planner->GetOutput();
  }
};

/// Every documented array and the consistency between the points, the cells and the field data.
void expectConsistentToolpath(vtkPolyData* path, vtkGLToolpathPlanner* planner) {
  const vtkIdType N = path->GetNumberOfPoints();
  ASSERT_GT(N, 2);
  vtkPointData* pd = path->GetPointData();
  for (const char* name : {arrays::NozzleAxis, arrays::Thickness, arrays::Width, arrays::Extrusion,
                           arrays::FeedRate, arrays::MoveKind, arrays::LayerId, arrays::SubgraphId,
                           arrays::PathIndex, arrays::PointIndex}) {
    ASSERT_NE(pd->GetArray(name), nullptr) << name;
    EXPECT_EQ(pd->GetArray(name)->GetNumberOfTuples(), N) << name;
  }
  EXPECT_EQ(pd->GetNormals(), nullptr);  // the nozzle axis does not light the lines
  for (const char* name :
       {arrays::MoveKind, arrays::PathIndex, arrays::LayerId, arrays::SubgraphId}) {
    ASSERT_NE(path->GetCellData()->GetArray(name), nullptr) << name;
  }
  for (const char* name : {arrays::ToolpathPrintLength,
                           arrays::ToolpathPerimeterLength,
                           arrays::ToolpathPerimeterLoops,
                           arrays::ToolpathPerimeterTeeth,
                           arrays::ToolpathAirLength,
                           arrays::ToolpathRetractions,
                           arrays::ToolpathTours,
                           arrays::ToolpathCrossings,
                           arrays::ToolpathSplitSubgraphs,
                           arrays::ToolpathContractedEdges,
                           arrays::ToolpathTrimmedEdges,
                           arrays::ToolpathTrimmedLength,
                           arrays::ToolpathFilament,
                           arrays::ToolpathVolume,
                           arrays::ToolpathThicknessDeviation,
                           arrays::ToolpathThicknessDeviationPerLayer,
                           arrays::ToolpathCappedVertices,
                           arrays::ToolpathUnsupportedVertices,
                           arrays::ToolpathRotationSteps,
                           arrays::ToolpathSeconds,
                           arrays::SkeletonEdges}) {
    ASSERT_NE(path->GetFieldData()->GetArray(name), nullptr) << name;
  }
  EXPECT_EQ(path->GetFieldData()->GetArray(arrays::ToolpathThicknessDeviation)->GetNumberOfTuples(),
            2);
  EXPECT_EQ(path->GetFieldData()
                ->GetArray(arrays::ToolpathThicknessDeviationPerLayer)
                ->GetNumberOfComponents(),
            3);

  vtkDataArray* kind = pd->GetArray(arrays::MoveKind);
  vtkDataArray* extrusion = pd->GetArray(arrays::Extrusion);
  vtkDataArray* thickness = pd->GetArray(arrays::Thickness);
  vtkDataArray* width = pd->GetArray(arrays::Width);
  vtkDataArray* feed = pd->GetArray(arrays::FeedRate);
  vtkDataArray* layer = pd->GetArray(arrays::LayerId);
  vtkDataArray* subgraph = pd->GetArray(arrays::SubgraphId);
  vtkDataArray* tour = pd->GetArray(arrays::PathIndex);
  EXPECT_EQ(kind->GetTuple1(0), movekind::Air);  // the start
  double print = 0, perimeter = 0, air = 0, filament = 0;
  std::set<int> tours;
  for (vtkIdType i = 0; i < N; ++i) {
    EXPECT_EQ(pd->GetArray(arrays::PointIndex)->GetTuple1(i), i);
    double n[3];
    pd->GetArray(arrays::NozzleAxis)->GetTuple(i, n);
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-9) << i;
    const int k = static_cast<int>(kind->GetTuple1(i));
    ASSERT_TRUE(k == movekind::Print || k == movekind::Perimeter || k == movekind::Air) << k;
    if (k == movekind::Air) {
      EXPECT_EQ(thickness->GetTuple1(i), 0.0);
      EXPECT_EQ(width->GetTuple1(i), 0.0);
      EXPECT_EQ(feed->GetTuple1(i), planner->GetAirFeedRate());
      EXPECT_EQ(layer->GetTuple1(i), -1.0);
      EXPECT_EQ(subgraph->GetTuple1(i), -1.0);
    } else {
      EXPECT_GT(thickness->GetTuple1(i), 0.0);
      if (k == movekind::Print ||
          width->GetTuple1(i) != 0) {  // a perimeter's way back does not extrude
        EXPECT_EQ(width->GetTuple1(i), planner->GetPathWidth());
      }
      EXPECT_EQ(feed->GetTuple1(i), planner->GetPrintFeedRate());
      EXPECT_GE(subgraph->GetTuple1(i), 0.0);
      tours.insert(static_cast<int>(tour->GetTuple1(i)));
    }
    if (i > 0) {
      double a[3], b[3];
      path->GetPoint(i - 1, a);
      path->GetPoint(i, b);
      const double len = std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
      const double dE = extrusion->GetTuple1(i) - extrusion->GetTuple1(i - 1);
      if (k == movekind::Air) {
        air += len;
      } else {
        (k == movekind::Print ? print : perimeter) += len;
        filament += dE;
        EXPECT_GE(dE, 0.0) << i;
      }
      EXPECT_GE(tour->GetTuple1(i), tour->GetTuple1(i - 1)) << i;
    }
  }
  EXPECT_NEAR(print, fieldValue(path, arrays::ToolpathPrintLength), 1e-6 * (1 + print));
  EXPECT_NEAR(perimeter, fieldValue(path, arrays::ToolpathPerimeterLength), 1e-6 * (1 + perimeter));
  EXPECT_NEAR(air, fieldValue(path, arrays::ToolpathAirLength), 1e-6 * (1 + air));
  EXPECT_NEAR(filament, fieldValue(path, arrays::ToolpathFilament), 1e-6 * (1 + filament));
  const double r = 0.5 * planner->GetFilamentDiameter();
  EXPECT_NEAR(fieldValue(path, arrays::ToolpathVolume), filament * M_PI * r * r,
              1e-6 * (1 + filament));
  EXPECT_EQ(static_cast<double>(tours.size()), fieldValue(path, arrays::ToolpathTours));
  EXPECT_EQ(fieldValue(path, arrays::ToolpathCrossings), 0.0);

  // Cells: runs in printing order that share their end points and cover every move once; the cell
  // arrays are those of their moves; one air run per retraction.
  vtkNew<vtkIdList> ids;
  vtkIdType next = 0, airRuns = 0;
  for (vtkIdType c = 0; c < path->GetNumberOfCells(); ++c) {
    path->GetCellPoints(c, ids);
    ASSERT_GE(ids->GetNumberOfIds(), 2);
    EXPECT_EQ(ids->GetId(0), next) << "cell " << c;
    for (vtkIdType j = 1; j < ids->GetNumberOfIds(); ++j) {
      ASSERT_EQ(ids->GetId(j), ids->GetId(0) + j);
      for (const char* name :
           {arrays::MoveKind, arrays::PathIndex, arrays::LayerId, arrays::SubgraphId}) {
        EXPECT_EQ(path->GetCellData()->GetArray(name)->GetTuple1(c),
                  pd->GetArray(name)->GetTuple1(ids->GetId(j)))
            << name << " cell " << c;
      }
    }
    next = ids->GetId(ids->GetNumberOfIds() - 1);
    airRuns += path->GetCellData()->GetArray(arrays::MoveKind)->GetTuple1(c) == movekind::Air;
  }
  EXPECT_EQ(next, N - 1);
  EXPECT_EQ(static_cast<double>(airRuns), fieldValue(path, arrays::ToolpathRetractions));
}

}  // namespace

TEST(vtkGLToolpathPlanner, TowersGiveTheDocumentedOutputs) {
  const int layers = 6;
  PlannerRun run(towerLattice(layers, kTowers), towerSkeleton(layers));
  vtkPolyData* path = run.output();
  ASSERT_FALSE(run.errors->HasError()) << run.errors->Errors();
  expectConsistentToolpath(path, run.planner);

  // Every square is an Eulerian loop: printed whole as one tour, 4 mm each.
  EXPECT_NEAR(fieldValue(path, arrays::ToolpathPrintLength), 4.0 * 2 * layers, 1e-9);
  EXPECT_EQ(fieldValue(path, arrays::ToolpathPerimeterLength), 0.0);
  EXPECT_EQ(fieldValue(path, arrays::ToolpathPerimeterLoops), 0.0);
  EXPECT_EQ(fieldValue(path, arrays::ToolpathTours), 2.0 * layers);
  EXPECT_EQ(fieldValue(path, arrays::ToolpathTrimmedEdges), 0.0);
  EXPECT_EQ(fieldValue(path, arrays::ToolpathSplitSubgraphs), 0.0);
  EXPECT_EQ(fieldValue(path, arrays::ToolpathRetractions), 2.0 * layers - 1);
  EXPECT_GT(fieldValue(path, arrays::ToolpathAirLength), 0.0);
  EXPECT_EQ(fieldValue(path, arrays::ToolpathRotationSteps), 0.0);  // the axis is +z everywhere
  // Layers 1 mm apart at z = 1, 2, ..: h = 1 everywhere, no deviation.
  EXPECT_NEAR(fieldValue(path, arrays::ToolpathThicknessDeviation, 0), 0.0, 1e-9);
  EXPECT_NEAR(fieldValue(path, arrays::ToolpathThicknessDeviation, 1), 0.0, 1e-9);
  EXPECT_EQ(path->GetFieldData()
                ->GetArray(arrays::ToolpathThicknessDeviationPerLayer)
                ->GetNumberOfTuples(),
            layers);
  // Eq. 14: E = μ w h L / (π r²) with h = 1.
  const double r = 0.875;
  EXPECT_NEAR(fieldValue(path, arrays::ToolpathFilament),
              0.95 * 0.6 * 1.0 * 8.0 * layers / (M_PI * r * r), 1e-9);
  // LayerId is the lattice's (10 + layer); the sub-graphs are printed in the sequencer's order.
  vtkPointData* pd = path->GetPointData();
  std::vector<int> firstSeen;
  for (vtkIdType i = 0; i < path->GetNumberOfPoints(); ++i) {
    const int s = static_cast<int>(pd->GetArray(arrays::SubgraphId)->GetTuple1(i));
    if (s >= 0) {
      EXPECT_EQ(pd->GetArray(arrays::LayerId)->GetTuple1(i), 10 + s / 2);
      double x[3];
      path->GetPoint(i, x);
      EXPECT_EQ(x[2], 1.0 + s / 2);
      if (firstSeen.empty() || firstSeen.back() != s) {
        firstSeen.push_back(s);
      }
    }
  }
  ASSERT_EQ(firstSeen.size(), 2u * layers);
  for (size_t k = 0; k < firstSeen.size(); ++k) {
    EXPECT_EQ(firstSeen[k],
              fieldValue(run.sequencer->GetOutput(0), arrays::SequenceOrder, static_cast<int>(k)));
  }
  // Cells: a print run per tour and an air run per retraction.
  EXPECT_EQ(path->GetNumberOfCells(), 2 * (2 * layers) - 1);

  // The filament diameter enters as the radius d / 2.
  run.planner->SetFilamentDiameter(3.5);
  path = run.output();
  ASSERT_FALSE(run.errors->HasError()) << run.errors->Errors();
  EXPECT_NEAR(fieldValue(path, arrays::ToolpathFilament),
              0.95 * 0.6 * 8.0 * layers / (M_PI * 1.75 * 1.75), 1e-9);
}

TEST(vtkGLToolpathPlanner, DefaultsAndPrintSelf) {
  vtkNew<vtkGLToolpathPlanner> f;
  EXPECT_EQ(f->GetPathWidth(), 0.6);
  EXPECT_EQ(f->GetFilamentDiameter(), 1.75);
  EXPECT_EQ(f->GetFlowCorrection(), 0.95);
  EXPECT_EQ(f->GetPrintFeedRate(), 10.0);
  EXPECT_EQ(f->GetAirFeedRate(), 50.0);
  EXPECT_EQ(f->GetThicknessCap(), 1.5);
  EXPECT_EQ(f->GetMaxTurnAngle(), 5.0);
  EXPECT_EQ(f->GetSafeMargin(), 5.0);
  EXPECT_EQ(f->GetLift(), 2.0);
  EXPECT_EQ(f->GetRetraction(), 1.0);
  EXPECT_EQ(f->GetSupportPerimeter(), 1);
  EXPECT_EQ(f->GetToothLength(), 0.0);
  EXPECT_EQ(f->GetMaxSegmentLength(), 1.0);
  expectCoreNozzleDefaults(f->GetNozzle());
  EXPECT_EQ(f->GetMaxAxisTilt(), 30.0);
  EXPECT_EQ(f->GetTiltBlendLength(), 5.0);
  expectPrintMentions(f, {"PathWidth: 0.6", "FilamentDiameter: 1.75", "SupportPerimeter: 1",
                          "MaxAxisTilt: 30", "TipFaceRadius: 0.5", "MaxSegmentLength: 1"});
}

// GL Toolpath Replay, on the planner's output (the tower fixtures above).
TEST(vtkGLToolpathReplay, DefaultsAndPrintSelf) {
  vtkNew<vtkGLToolpathReplay> f;
  EXPECT_EQ(f->GetStepBy(), vtkGLToolpathReplay::Points);
  EXPECT_EQ(f->GetNumberOfTimeSteps(), 200);
  EXPECT_EQ(f->GetKeepUnprintedPoints(), 1);
  expectPrintMentions(f,
                      {"StepBy: 0 (Points)", "NumberOfTimeSteps: 200", "KeepUnprintedPoints: 1"});
}

TEST(vtkGLToolpathReplay, TimeStepsReplayThePrint) {
  const int layers = 5;
  PlannerRun run(towerLattice(layers, kTowers), towerSkeleton(layers));
  // The planner has no time: Apply in ParaView shows the whole toolpath.
  run.planner->UpdateInformation();
  EXPECT_FALSE(
      run.planner->GetOutputInformation(0)->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  vtkNew<vtkPolyData> full;
  full->DeepCopy(run.output());
  ASSERT_FALSE(run.errors->HasError()) << run.errors->Errors();
  const vtkIdType N = full->GetNumberOfPoints();
  ASSERT_GT(N, 10);

  vtkNew<vtkGLToolpathReplay> replay;
  replay->SetInputConnection(run.planner->GetOutputPort());
  run.errors->Observe(replay);
  replay->UpdateInformation();
  vtkInformation* info = replay->GetOutputInformation(0);
  ASSERT_TRUE(info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  ASSERT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 200);
  const double* steps = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  EXPECT_EQ(steps[0], 0.0);
  EXPECT_EQ(steps[199], 1.0);
  const double* range = info->Get(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  EXPECT_EQ(range[0], 0.0);
  EXPECT_EQ(range[1], 1.0);
  vtkDataArray* seconds =
      run.planner->GetOutput()->GetFieldData()->GetArray(arrays::ToolpathSeconds);

  for (bool keep : {true, false}) {
    replay->SetKeepUnprintedPoints(keep);
    vtkIdType previousCells = 0;
    for (double p : {0.0, 0.25, 0.5, 0.999, 1.0}) {
      replay->UpdateTimeStep(p);
      vtkPolyData* part = replay->GetOutput();
      ASSERT_FALSE(run.errors->HasError()) << run.errors->Errors();
      const vtkIdType n = std::llround(p * (N - 1)) + 1;
      // Kept points: all of them (the colour range of every point array is the whole print's);
      // else the printed ones.
      ASSERT_EQ(part->GetNumberOfPoints(), keep ? N : (part->GetNumberOfCells() ? n : 0)) << p;
      EXPECT_EQ(part->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), p);
      EXPECT_GE(part->GetNumberOfCells(), previousCells);
      previousCells = part->GetNumberOfCells();
      if (keep) {
        EXPECT_EQ(part->GetPointData()->GetArray(arrays::PointIndex)->GetRange()[1], N - 1.0);
      }
      for (vtkIdType i = 0; i < part->GetNumberOfPoints(); ++i) {
        double a[3], b[3];
        part->GetPoint(i, a);
        full->GetPoint(i, b);
        ASSERT_EQ(a[0], b[0]);
        ASSERT_EQ(a[2], b[2]);
        for (const char* name : {arrays::Extrusion, arrays::MoveKind, arrays::PointIndex}) {
          ASSERT_EQ(part->GetPointData()->GetArray(name)->GetTuple1(i),
                    full->GetPointData()->GetArray(name)->GetTuple1(i));
        }
      }
      EXPECT_NE(part->GetPointData()->GetArray(arrays::NozzleAxis), nullptr);
      vtkNew<vtkIdList> ids, fullIds;
      for (vtkIdType c = 0; c < part->GetNumberOfCells(); ++c) {
        part->GetCellPoints(c, ids);
        full->GetCellPoints(c, fullIds);
        EXPECT_EQ(ids->GetId(0), fullIds->GetId(0));
        EXPECT_LE(ids->GetId(ids->GetNumberOfIds() - 1), n - 1);
        EXPECT_EQ(part->GetCellData()->GetArray(arrays::MoveKind)->GetTuple1(c),
                  full->GetCellData()->GetArray(arrays::MoveKind)->GetTuple1(c));
      }
      const double lastPoint = fieldValue(part, arrays::ReplayLastPoint);
      if (part->GetNumberOfCells() > 0) {
        part->GetCellPoints(part->GetNumberOfCells() - 1, ids);
        EXPECT_EQ(ids->GetId(ids->GetNumberOfIds() - 1), n - 1)
            << "the last cell ends at the last point";
        EXPECT_EQ(lastPoint, n - 1.0);
      } else {
        EXPECT_EQ(lastPoint, -1.0);
      }
      // The field data describe the whole path, from the same planning.
      EXPECT_EQ(part->GetFieldData()->GetArray(arrays::ToolpathSeconds), seconds)
          << "planned again at " << p;
    }
    EXPECT_EQ(previousCells, full->GetNumberOfCells());
  }

  // Step by layer: one step per LayerId (10 + layer), the print cells of the layers up to it.
  replay->SetStepBy(vtkGLToolpathReplay::Layers);
  replay->SetKeepUnprintedPoints(false);  // ignored: layers keep every point
  replay->UpdateInformation();
  ASSERT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), layers);
  EXPECT_EQ(info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS())[0], 10.0);
  replay->UpdateTimeStep(11.0);
  vtkPolyData* twoLayers = replay->GetOutput();
  ASSERT_FALSE(run.errors->HasError()) << run.errors->Errors();
  EXPECT_EQ(twoLayers->GetNumberOfPoints(), N);
  vtkIdType expected = 0;
  vtkDataArray* fullLayer = full->GetCellData()->GetArray(arrays::LayerId);
  for (vtkIdType c = 0; c < full->GetNumberOfCells(); ++c) {
    expected += fullLayer->GetTuple1(c) >= 0 && fullLayer->GetTuple1(c) <= 11 ? 1 : 0;
  }
  EXPECT_GT(expected, 0);
  EXPECT_EQ(twoLayers->GetNumberOfCells(), expected);
  vtkDataArray* shownLayer = twoLayers->GetCellData()->GetArray(arrays::LayerId);
  EXPECT_EQ(shownLayer->GetRange()[0], 10.0);
  EXPECT_EQ(shownLayer->GetRange()[1], 11.0);

  // A planner parameter change plans again, and the replay follows.
  run.planner->SetPathWidth(0.5);
  replay->SetStepBy(vtkGLToolpathReplay::Points);
  replay->UpdateTimeStep(1.0);
  ASSERT_FALSE(run.errors->HasError()) << run.errors->Errors();
  EXPECT_EQ(replay->GetOutput()->GetNumberOfCells(), full->GetNumberOfCells());
  EXPECT_NE(replay->GetOutput()->GetFieldData()->GetArray(arrays::ToolpathSeconds), seconds);
}

TEST(vtkGLToolpathReplay, AnEmptyInputIsReported) {
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkGLToolpathReplay> replay;
  replay->SetInputData(empty);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(replay);
  EXPECT_EQ(replay->GetExecutive()->Update(), 0);
  EXPECT_NE(errors->Errors().find("no toolpath to replay"), std::string::npos) << errors->Errors();
}

// GL Print Summary, on the planner's tower toolpath and its verifier.
TEST(vtkGLPrintSummary, TheTableAgreesWithThePlannerAndTheVerifier) {
  const int layers = 5;
  PlannerRun run(towerLattice(layers, kTowers), towerSkeleton(layers));
  vtkPolyData* path = run.output();
  ASSERT_FALSE(run.errors->HasError()) << run.errors->Errors();
  vtkNew<vtkGLCollisionVerifier> verifier;
  verifier->SetInputConnection(run.planner->GetOutputPort());
  verifier->SetTimeArrayName(arrays::PointIndex);
  verifier->GetNozzle()->SetNozzleAngle(60.0);
  vtkNew<vtkGLPrintSummary> summary;
  summary->SetInputConnection(0, run.planner->GetOutputPort());
  summary->SetInputConnection(1, verifier->GetOutputPort());
  run.errors->Observe(summary);
  summary->Update();
  ASSERT_FALSE(run.errors->HasError()) << run.errors->Errors();
  vtkTable* table = summary->GetOutput();
  auto* key = vtkStringArray::SafeDownCast(table->GetColumnByName("Key"));
  vtkDataArray* value = vtkDataArray::SafeDownCast(table->GetColumnByName("Value"));
  ASSERT_NE(key, nullptr);
  ASSERT_NE(value, nullptr);
  ASSERT_NE(table->GetColumnByName("Quantity"), nullptr);
  ASSERT_NE(table->GetColumnByName("Unit"), nullptr);
  auto row = [&](const std::string& k) {
    for (vtkIdType r = 0; r < table->GetNumberOfRows(); ++r) {
      if (key->GetValue(r) == k) {
        return value->GetTuple1(r);
      }
    }
    ADD_FAILURE() << "no row " << k;
    return std::nan("");
  };
  EXPECT_EQ(row("layers"), layers);
  EXPECT_EQ(row("points"), path->GetNumberOfPoints());
  EXPECT_EQ(row("tours"), fieldValue(path, arrays::ToolpathTours));
  EXPECT_EQ(row("retractions"), fieldValue(path, arrays::ToolpathRetractions));
  EXPECT_NEAR(row("print_length_mm"),
              fieldValue(path, arrays::ToolpathPrintLength) +
                  fieldValue(path, arrays::ToolpathPerimeterLength),
              1e-6 * row("print_length_mm"));
  EXPECT_NEAR(row("air_length_mm"), fieldValue(path, arrays::ToolpathAirLength),
              1e-6 * row("air_length_mm"));
  // Print moves at 10 mm/s, air moves at 50 mm/s (the planner's defaults).
  EXPECT_NEAR(row("print_time_min"),
              (row("print_length_mm") / 10.0 + row("air_length_mm") / 50.0) / 60.0, 1e-9);
  EXPECT_NEAR(row("filament_m"), fieldValue(path, arrays::ToolpathFilament) / 1000.0, 1e-12);
  EXPECT_NEAR(row("filament_g"),
              fieldValue(path, arrays::ToolpathFilament) * M_PI * 0.875 * 0.875 * 1e-3 * 1.24,
              1e-9);
  vtkPolyData* verdict = verifier->GetOutput();
  EXPECT_EQ(row("collision_free"), fieldValue(verdict, arrays::CollisionFree));
  EXPECT_EQ(row("stations"), fieldValue(verdict, arrays::CollisionStations));
  EXPECT_EQ(row("colliding_stations"), fieldValue(verdict, arrays::CollisionViolatingStations));
  auto* text =
      vtkStringArray::SafeDownCast(table->GetFieldData()->GetAbstractArray(arrays::SummaryVerdict));
  ASSERT_NE(text, nullptr);
  EXPECT_NE(text->GetValue(0).find(row("collision_free") ? "collision-free" : "COLLIDES"),
            std::string::npos)
      << text->GetValue(0);

  // Without the verifier: the planner's own check.
  vtkNew<vtkGLPrintSummary> alone;
  alone->SetInputConnection(run.planner->GetOutputPort());
  alone->Update();
  EXPECT_EQ(alone->GetOutput()->GetNumberOfRows(), table->GetNumberOfRows());
  EXPECT_NE(
      std::string(alone->GetOutput()->GetValueByName(11, "Quantity").ToString()).find("planner"),
      std::string::npos);
}

TEST(vtkGLToolpathPlanner, BadInputIsReported) {
  const int layers = 3;
  auto expectError = [](PlannerRun& run, const std::string& text) {
    vtkPolyData* out = run.output();
    EXPECT_EQ(out->GetNumberOfPoints(), 0) << text;
    EXPECT_EQ(out->GetNumberOfCells(), 0) << text;
    EXPECT_EQ(out->GetFieldData()->GetArray(arrays::ToolpathTours), nullptr) << text;
    EXPECT_TRUE(run.errors->HasError()) << text;
    EXPECT_NE(run.errors->Errors().find(text), std::string::npos) << run.errors->Errors();
  };
  {
    PlannerRun run(towerLattice(layers, kTowers), towerSkeleton(layers));
    run.planner->SetPathWidth(0);
    expectError(run, "path width must be > 0");
  }
  {
    PlannerRun run(towerLattice(layers, kTowers), towerSkeleton(layers));
    run.planner->SetFlowCorrection(1.5);
    expectError(run, "flow correction mu must be in (0, 1]");
  }
  {
    PlannerRun run(towerLattice(layers, kTowers), towerSkeleton(layers));
    run.planner->SetFilamentDiameter(0);
    expectError(run, "filament diameter must be > 0");
  }
  {
    PlannerRun run(towerLattice(layers, kTowers), towerSkeleton(layers));
    run.planner->SetMaxTurnAngle(-1);
    expectError(run, "maximum turn angle must be > 0");
  }
  {
    PlannerRun run(towerLattice(layers, kTowers), towerSkeleton(layers));
    run.planner->SetRetraction(-1);
    expectError(run, "retraction must be >= 0");
  }
  {
    PlannerRun run(towerLattice(layers, kTowers), towerSkeleton(layers));
    run.planner->SetToothLength(-1);
    expectError(run, "tooth length must be >= 0");
  }
  {
    auto lattice = towerLattice(layers, kTowers);
    lattice->GetCellData()->RemoveArray(arrays::EdgeKind);
    PlannerRun run(lattice, towerSkeleton(layers));
    expectError(run, "the lattice has no EdgeKind cell array");
  }
  {
    auto lattice = towerLattice(layers, kTowers);
    lattice->GetCellData()->GetArray(arrays::EdgeKind)->SetTuple1(5, 7);
    PlannerRun run(lattice, towerSkeleton(layers));
    expectError(run, "lattice line cell 5 has EdgeKind 7");
  }
  {
    // The lattice itself instead of the sequencer's output: no SequenceOrder.
    PlannerRun run(towerLattice(layers, kTowers), towerSkeleton(layers));
    run.planner->SetInputData(0, towerLattice(layers, kTowers));
    expectError(run,
                "no field array SequenceOrder (the printing order): run GL Print Sequencer first");
  }
  {
    // An order that is not a permutation of the sub-graphs.
    auto lattice = towerLattice(layers, kTowers);
    vtkNew<vtkDoubleArray> order;
    order->SetName(arrays::SequenceOrder);
    for (int k = 0; k < 2 * layers; ++k) {
      order->InsertNextValue(0);
    }
    lattice->GetFieldData()->AddArray(order);
    PlannerRun run(lattice, towerSkeleton(layers));
    run.planner->SetInputData(0, lattice);
    run.planner->SetInputData(1, towerSkeleton(layers));
    expectError(run, "the print order must list every sub-graph exactly once");
  }
  {
    PlannerRun run(towerLattice(layers, kTowers), towerSkeleton(layers));
    vtkNew<vtkPolyData> empty;
    run.planner->SetInputData(1, empty);
    expectError(run, "empty skeleton");
  }
  {
    // The skeleton of another lattice.
    PlannerRun run(towerLattice(layers, kTowers), towerSkeleton(layers));
    run.planner->SetInputData(1, towerSkeleton(layers + 1));
    expectError(run, "the skeleton has 8 nodes but the lattice has 6 sub-graphs");
  }
  {
    PlannerRun run(towerLattice(layers, kTowers), towerSkeleton(layers));
    vtkNew<vtkPolyData> empty;
    run.planner->SetInputData(0, empty);
    expectError(run, "empty lattice");
  }
  {
    // No skeleton connected at all: the pipeline refuses to run the filter.
    vtkNew<vtkGLToolpathPlanner> planner;
    vtkNew<GLTestErrorObserver> errors;
    errors->Observe(planner);
    errors->Observe(planner->GetExecutive());
    planner->SetInputData(0, towerLattice(layers, kTowers));
    planner->Update();
    EXPECT_EQ(planner->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_TRUE(errors->HasError());
  }
  {
    // A recovered error: the next update with good parameters has a toolpath and no new error.
    PlannerRun run(towerLattice(layers, kTowers), towerSkeleton(layers));
    run.planner->SetPathWidth(0);
    run.output();
    EXPECT_TRUE(run.errors->HasError());
    run.errors->Clear();
    run.planner->SetPathWidth(0.6);
    EXPECT_GT(run.output()->GetNumberOfPoints(), 0);
    EXPECT_FALSE(run.errors->HasError()) << run.errors->Errors();
  }
}

// ---------------------------------------------------------------------------------------------
// End to end on the branching Y: reader -> place -> tets -> GDF -> slicer -> lattice -> skeleton
// -> sequencer -> toolpath -> verifier. Built once for the suite (coarse, like the sequencer test).

class BranchingYToolpath : public GLTestYSuite<BranchingYToolpath> {
public:
  static vtkAlgorithm* Stage(GLTestYPipeline& y) { return y.planner; }
};

TEST_F(BranchingYToolpath, ToolpathIsConsistent) {
  ASSERT_FALSE(p->errors->HasError()) << p->errors->Errors();
  vtkPolyData* path = p->planner->GetOutput();
  expectConsistentToolpath(path, p->planner);
  // The axis stays within MaxAxisTilt of ∇γ and nothing is left colliding.
  vtkDataArray* tilt = path->GetPointData()->GetArray(arrays::AxisTilt);
  ASSERT_NE(tilt, nullptr);
  EXPECT_LE(tilt->GetRange()[1], p->planner->GetMaxAxisTilt() + 1e-9);
  EXPECT_EQ(path->GetFieldData()->GetArray(arrays::ToolpathUnclearedStations)->GetTuple1(0), 0.0);
  EXPECT_EQ(path->GetFieldData()->GetArray(arrays::ToolpathMaxAxisTilt)->GetTuple1(0),
            tilt->GetRange()[1]);
  vtkPolyData* lattice = p->lattice->GetOutput();
  // Every sub-graph printed, on its own layer: the lattice's LayerId of the sub-graph.
  std::map<int, int> layerOf;
  std::set<int> layerIds;
  for (vtkIdType c = 0; c < lattice->GetNumberOfCells(); ++c) {
    const int layer =
        static_cast<int>(lattice->GetCellData()->GetArray(arrays::LayerId)->GetTuple1(c));
    layerOf[static_cast<int>(lattice->GetCellData()->GetArray(arrays::SubgraphId)->GetTuple1(c))] =
        layer;
    layerIds.insert(layer);
  }
  std::set<int> printed;
  for (vtkIdType i = 0; i < path->GetNumberOfPoints(); ++i) {
    const int s =
        static_cast<int>(path->GetPointData()->GetArray(arrays::SubgraphId)->GetTuple1(i));
    if (s >= 0) {
      printed.insert(s);
      ASSERT_EQ(path->GetPointData()->GetArray(arrays::LayerId)->GetTuple1(i), layerOf.at(s)) << i;
    }
  }
  EXPECT_EQ(static_cast<double>(printed.size()), fieldValue(lattice, arrays::LatticeSubgraphs));
  EXPECT_EQ(path->GetFieldData()
                ->GetArray(arrays::ToolpathThicknessDeviationPerLayer)
                ->GetNumberOfTuples(),
            static_cast<vtkIdType>(layerIds.size()));
  EXPECT_GE(fieldValue(path, arrays::ToolpathTours), fieldValue(lattice, arrays::LatticeSubgraphs));
  // The lattice printed is the lattice minus what the trimming left out (contracted edges have
  // no length).
  double latticeLength = 0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < lattice->GetNumberOfCells(); ++c) {
    lattice->GetCellPoints(c, ids);
    for (vtkIdType j = 0; j + 1 < ids->GetNumberOfIds(); ++j) {
      double a[3], b[3];
      lattice->GetPoint(ids->GetId(j), a);
      lattice->GetPoint(ids->GetId(j + 1), b);
      latticeLength += std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
    }
  }
  EXPECT_NEAR(fieldValue(path, arrays::ToolpathPrintLength) +
                  fieldValue(path, arrays::ToolpathTrimmedLength),
              latticeLength, 1e-6 * latticeLength);
  // Trimmed boundaries get a support perimeter.
  if (fieldValue(path, arrays::ToolpathTrimmedEdges) > 0) {
    EXPECT_GT(fieldValue(path, arrays::ToolpathPerimeterLoops), 0.0);
    EXPECT_GT(fieldValue(path, arrays::ToolpathPerimeterLength), 0.0);
  }
  std::printf(
      "[toolpath filter] Y: %lld points, %lld cells, print %.1f mm, perimeter %.1f mm (%g loops), "
      "air %.1f mm, "
      "%g retractions, %g tours, %g split, %g trimmed edges (%.1f mm), %g rotation steps, filament "
      "%.1f mm, "
      "thickness deviation %.3f .. %.3f, %.3f s\n",
      static_cast<long long>(path->GetNumberOfPoints()),
      static_cast<long long>(path->GetNumberOfCells()),
      fieldValue(path, arrays::ToolpathPrintLength),
      fieldValue(path, arrays::ToolpathPerimeterLength),
      fieldValue(path, arrays::ToolpathPerimeterLoops), fieldValue(path, arrays::ToolpathAirLength),
      fieldValue(path, arrays::ToolpathRetractions), fieldValue(path, arrays::ToolpathTours),
      fieldValue(path, arrays::ToolpathSplitSubgraphs),
      fieldValue(path, arrays::ToolpathTrimmedEdges),
      fieldValue(path, arrays::ToolpathTrimmedLength),
      fieldValue(path, arrays::ToolpathRotationSteps), fieldValue(path, arrays::ToolpathFilament),
      fieldValue(path, arrays::ToolpathThicknessDeviation, 0),
      fieldValue(path, arrays::ToolpathThicknessDeviation, 1),
      fieldValue(path, arrays::ToolpathSeconds));
}

TEST_F(BranchingYToolpath, SequencedSkeletonGivesTheSamePath) {
  ASSERT_FALSE(p->errors->HasError()) << p->errors->Errors();
  vtkNew<vtkGLToolpathPlanner> planner;
  planner->SetInputConnection(0, p->sequencer->GetOutputPort(0));
  planner->SetInputConnection(1, p->sequencer->GetOutputPort(1));
  p->errors->Observe(planner);
  planner->Update();
  ASSERT_FALSE(p->errors->HasError()) << p->errors->Errors();
  EXPECT_EQ(planner->GetOutput()->GetNumberOfPoints(),
            p->planner->GetOutput()->GetNumberOfPoints());
  EXPECT_EQ(fieldValue(planner->GetOutput(), arrays::ToolpathAirLength),
            fieldValue(p->planner->GetOutput(), arrays::ToolpathAirLength));
}

TEST_F(BranchingYToolpath, VerifierUsesOnlyPrintedPointsAsMaterial) {
  ASSERT_FALSE(p->errors->HasError()) << p->errors->Errors();
  vtkPolyData* path = p->planner->GetOutput();
  auto verify = [](vtkPolyData* input) {
    vtkNew<vtkGLCollisionVerifier> verifier;
    verifier->SetInputData(input);
    verifier->SetTimeArrayName(arrays::PointIndex);
    verifier->GetNozzle()->SetNozzleAngle(45.0);
    vtkNew<GLTestErrorObserver> errors;
    errors->Observe(verifier);
    verifier->Update();
    EXPECT_FALSE(errors->HasError()) << errors->Errors();
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->ShallowCopy(verifier->GetOutput());
    return out;
  };
  vtkSmartPointer<vtkPolyData> masked = verify(path);
  EXPECT_EQ(fieldValue(masked, arrays::CollisionStations),
            static_cast<double>(path->GetNumberOfPoints()));
  // The same points with every air point as material: at least as many violations.
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(path);
  copy->GetPointData()->RemoveArray(arrays::MoveKind);
  vtkSmartPointer<vtkPolyData> unmasked = verify(copy);
  EXPECT_GE(fieldValue(unmasked, arrays::CollisionViolatingStations),
            fieldValue(masked, arrays::CollisionViolatingStations));
  std::printf(
      "[toolpath filter] Y, NA 45, verifier on the toolpath: %g stations, %g violating (%g "
      "unavoidable), "
      "collision-free %g; air points as material: %g violating\n",
      fieldValue(masked, arrays::CollisionStations),
      fieldValue(masked, arrays::CollisionViolatingStations),
      fieldValue(masked, arrays::CollisionUnavoidableStations),
      fieldValue(masked, arrays::CollisionFree),
      fieldValue(unmasked, arrays::CollisionViolatingStations));
}

TEST_F(BranchingYToolpath, ProgressAndAbortBeforeAndAfterThePlanning) {
  ASSERT_FALSE(p->errors->HasError()) << p->errors->Errors();
  // A new planner for each check: a planner that has planned keeps the path (the replay of
  // another time only cuts it, with nothing to report or abort).
  auto planner = [this] {
    auto f = vtkSmartPointer<vtkGLToolpathPlanner>::New();
    f->SetInputConnection(0, p->sequencer->GetOutputPort(0));
    f->SetInputConnection(1, p->sequencer->GetOutputPort(1));
    return f;
  };
  // Inputs converted, the planning (one core call), the output built.
  glExpectProgressReport(planner(), 3);
  glExpectCleanAbort(planner(), glAbortAt(0.1));
  glExpectCleanAbort(planner(), glAbortAt(0.8));  // nothing cached: the recovery run plans again
}
