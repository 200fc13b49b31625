// vtkGLPrintSequencer: the three outputs and their arrays on a hand-built two-tower lattice (DPT
// collides, A4 does not, as the collision verifier confirms), the end-to-end pipeline on the
// branching Y (reader -> ... -> lattice -> skeleton -> sequencer -> verifier), and bad input.
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
#include <vtkStringArray.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace arrays = geolattice::arrays;

namespace {

std::string strategyName(vtkDataObject* d) {
  auto* a =
      vtkStringArray::SafeDownCast(d->GetFieldData()->GetAbstractArray(arrays::SequenceStrategy));
  return a && a->GetNumberOfValues() == 1 ? a->GetValue(0) : "";
}

/// Sequencer + verifier on given inputs.
struct SequenceRun {
  vtkSmartPointer<vtkGLPrintSequencer> sequencer = vtkSmartPointer<vtkGLPrintSequencer>::New();
  vtkSmartPointer<vtkGLCollisionVerifier> verifier = vtkSmartPointer<vtkGLCollisionVerifier>::New();
  vtkNew<GLTestErrorObserver> errors;
  vtkNew<GLTestErrorObserver> verifierErrors;
  SequenceRun(vtkPolyData* lattice, vtkPolyData* skeleton, int strategy, double angle) {
    sequencer->SetInputData(0, lattice);
    sequencer->SetInputData(1, skeleton);
    sequencer->SetStrategy(strategy);
    sequencer->GetNozzle()->SetNozzleAngle(angle);
    errors->Observe(sequencer);
    verifier->SetInputConnection(sequencer->GetOutputPort(0));
    verifier->GetNozzle()->SetNozzleAngle(angle);
    verifierErrors->Observe(verifier);
  }
  vtkPolyData* output(int port) {
    sequencer->Update(port);
    return sequencer->GetOutput(port);
  }
  vtkPolyData* verify() {
    verifier->Update();
    return verifier->GetOutput();
  }
};

/// The PrintOrder of the skeleton points, checked to be a permutation of 0..N-1.
std::vector<int> checkedPrintOrder(vtkPolyData* skeleton) {
  vtkDataArray* order = skeleton->GetPointData()->GetArray(arrays::PrintOrder);
  EXPECT_NE(order, nullptr);
  if (!order) {
    return {};
  }
  const vtkIdType N = skeleton->GetNumberOfPoints();
  std::vector<int> position(N);
  std::vector<char> seen(N, 0);
  for (vtkIdType p = 0; p < N; ++p) {
    position[p] = static_cast<int>(order->GetTuple1(p));
    EXPECT_TRUE(position[p] >= 0 && position[p] < N && !seen[position[p]])
        << "PrintOrder is not a permutation";
    if (position[p] >= 0 && position[p] < N) {
      seen[position[p]] = 1;
    }
  }
  return position;
}

/// Criterion 1 on the skeleton output: every lower node before its upper node.
void expectLowerBeforeUpper(vtkPolyData* skeleton, const std::vector<int>& position) {
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < skeleton->GetNumberOfCells(); ++c) {
    skeleton->GetCellPoints(c, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), 2);
    EXPECT_LT(position[ids->GetId(0)], position[ids->GetId(1)]) << "skeleton edge " << c;
  }
}

void expectEmptyOutputs(SequenceRun& run, const std::string& text) {
  for (int port = 0; port < 3; ++port) {
    vtkPolyData* out = run.output(port);
    EXPECT_EQ(out->GetNumberOfPoints(), 0) << "port " << port;
    EXPECT_EQ(out->GetNumberOfCells(), 0) << "port " << port;
    EXPECT_EQ(out->GetFieldData()->GetArray(arrays::SequenceOrder), nullptr) << "port " << port;
  }
  EXPECT_TRUE(run.errors->HasError()) << text;
  EXPECT_NE(run.errors->Errors().find(text), std::string::npos) << run.errors->Errors();
}

}  // namespace

TEST(vtkGLPrintSequencer, TwoTowersGiveTheDocumentedOutputs) {
  const int layers = 8;
  auto lattice = towerLattice(layers);
  auto skeleton = towerSkeleton(layers);
  SequenceRun run(lattice, skeleton, vtkGLPrintSequencer::A4, 60.0);
  vtkPolyData* sequenced = run.output(0);
  ASSERT_FALSE(run.errors->HasError()) << run.errors->Errors();
  const int K = 2 * layers;

  // Output 0: the lattice with PrintOrder; the input is not modified.
  EXPECT_EQ(sequenced->GetNumberOfCells(), lattice->GetNumberOfCells());
  EXPECT_EQ(sequenced->GetNumberOfPoints(), lattice->GetNumberOfPoints());
  EXPECT_EQ(lattice->GetCellData()->GetArray(arrays::PrintOrder), nullptr);
  EXPECT_EQ(lattice->GetFieldData()->GetArray(arrays::SequenceOrder), nullptr);
  vtkDataArray* cellOrder = sequenced->GetCellData()->GetArray(arrays::PrintOrder);
  vtkDataArray* pointOrder = sequenced->GetPointData()->GetArray(arrays::PrintOrder);
  ASSERT_NE(cellOrder, nullptr);
  ASSERT_NE(pointOrder, nullptr);
  std::vector<int> position(K, -1);
  for (int k = 0; k < K; ++k) {
    position[static_cast<int>(fieldValue(sequenced, arrays::SequenceOrder, k))] = k;
  }
  vtkDataArray* cellSubgraph = lattice->GetCellData()->GetArray(arrays::SubgraphId);
  vtkDataArray* pointSubgraph = lattice->GetPointData()->GetArray(arrays::SubgraphId);
  for (vtkIdType c = 0; c < sequenced->GetNumberOfCells(); ++c) {
    EXPECT_EQ(cellOrder->GetTuple1(c), position[static_cast<int>(cellSubgraph->GetTuple1(c))]);
  }
  for (vtkIdType v = 0; v < sequenced->GetNumberOfPoints(); ++v) {
    EXPECT_EQ(pointOrder->GetTuple1(v), position[static_cast<int>(pointSubgraph->GetTuple1(v))]);
  }

  // Output 1: the skeleton with PrintOrder, a permutation that respects Criterion 1.
  vtkPolyData* sequencedSkeleton = run.output(1);
  EXPECT_EQ(sequencedSkeleton->GetNumberOfPoints(), K);
  const std::vector<int> order = checkedPrintOrder(sequencedSkeleton);
  EXPECT_EQ(order, position);
  expectLowerBeforeUpper(sequencedSkeleton, order);

  // Output 2: the order polyline.
  vtkPolyData* polyline = run.output(2);
  EXPECT_EQ(polyline->GetNumberOfPoints(), K);
  EXPECT_EQ(polyline->GetNumberOfCells(), K - 1);
  vtkDataArray* retraction = polyline->GetCellData()->GetArray(arrays::Retraction);
  ASSERT_NE(retraction, nullptr);
  ASSERT_NE(polyline->GetPointData()->GetArray(arrays::SubgraphId), nullptr);
  ASSERT_NE(polyline->GetPointData()->GetArray(arrays::PrintOrder), nullptr);
  double retractions = 0;
  for (vtkIdType c = 0; c < polyline->GetNumberOfCells(); ++c) {
    retractions += retraction->GetTuple1(c);
    EXPECT_EQ(polyline->GetCellData()->GetArray(arrays::PrintOrder)->GetTuple1(c), c);
  }
  EXPECT_EQ(retractions, fieldValue(polyline, arrays::SequenceRetractions));
  for (vtkIdType k = 0; k < K; ++k) {
    EXPECT_EQ(polyline->GetPointData()->GetArray(arrays::SubgraphId)->GetTuple1(k),
              fieldValue(polyline, arrays::SequenceOrder, k));
    double p[3];
    polyline->GetPoint(k, p);
    for (int j = 0; j < 3; ++j) {
      EXPECT_EQ(p[j], fieldValue(polyline, arrays::SequenceStart, 3 * k + j));
    }
    EXPECT_EQ(p[2], 1.0 + static_cast<int>(fieldValue(polyline, arrays::SequenceOrder, k)) /
                              2);  // on its layer
  }

  // Field data on all three outputs.
  for (int port = 0; port < 3; ++port) {
    vtkPolyData* out = run.output(port);
    EXPECT_EQ(strategyName(out), "a4") << port;
    for (const char* name :
         {arrays::SequenceRetractions, arrays::SequenceAirLength, arrays::SequenceForcedSteps,
          arrays::SequenceSeconds, arrays::SequencePcgPairs, arrays::SequencePcgSeconds,
          arrays::SequenceUnavoidablePairs, arrays::NozzleAngleDeg}) {
      ASSERT_NE(out->GetFieldData()->GetArray(name), nullptr) << name << " on port " << port;
    }
    EXPECT_EQ(out->GetFieldData()->GetArray(arrays::SequenceOrder)->GetNumberOfTuples(), K);
    EXPECT_EQ(out->GetFieldData()->GetArray(arrays::SequenceStart)->GetNumberOfComponents(), 3);
    EXPECT_EQ(out->GetFieldData()->GetArray(arrays::SequenceEnd)->GetNumberOfTuples(), K);
    EXPECT_EQ(out->GetFieldData()->GetArray(arrays::SkeletonEdges)->GetNumberOfTuples(), K - 2);
  }
  EXPECT_EQ(fieldValue(sequenced, arrays::NozzleAngleDeg), 60.0);
  EXPECT_GT(fieldValue(sequenced, arrays::SequencePcgPairs), 0.0);
  EXPECT_EQ(fieldValue(sequenced, arrays::SequenceForcedSteps), 0.0);
  EXPECT_GT(fieldValue(sequenced, arrays::SequenceAirLength), 0.0);

  // The A4 order is collision-free for the verifier.
  vtkPolyData* report = run.verify();
  ASSERT_FALSE(run.verifierErrors->HasError()) << run.verifierErrors->Errors();
  EXPECT_EQ(fieldValue(report, arrays::CollisionFree), 1.0);
  EXPECT_EQ(fieldValue(report, arrays::CollisionOrderFree), 1.0);
  EXPECT_EQ(report->GetNumberOfPoints(), 0);
  EXPECT_EQ(fieldValue(report, arrays::CollisionStations),
            4.0 * K);  // the squares' corners (1 mm edges)
}

TEST(vtkGLPrintSequencer, DepthPriorityCollidesWhereA4DoesNot) {
  const int layers = 8;
  auto lattice = towerLattice(layers);
  auto skeleton = towerSkeleton(layers);
  std::printf("[sequencer filter] two towers, %d layers, NA 60:\n", layers);
  for (int strategy : {vtkGLPrintSequencer::LPT, vtkGLPrintSequencer::DPT, vtkGLPrintSequencer::A4,
                       vtkGLPrintSequencer::BEST}) {
    SequenceRun run(lattice, skeleton, strategy, 60.0);
    vtkPolyData* report = run.verify();
    ASSERT_FALSE(run.errors->HasError()) << run.errors->Errors();
    ASSERT_FALSE(run.verifierErrors->HasError()) << run.verifierErrors->Errors();
    vtkPolyData* out = run.output(1);
    expectLowerBeforeUpper(out, checkedPrintOrder(out));
    const double free = fieldValue(report, arrays::CollisionFree);
    std::printf(
        "  %-4s retractions %g, air %.1f mm, PCG pairs %g, collision-free %g (%g violating "
        "stations)\n",
        strategyName(out).c_str(), fieldValue(out, arrays::SequenceRetractions),
        fieldValue(out, arrays::SequenceAirLength), fieldValue(out, arrays::SequencePcgPairs), free,
        fieldValue(report, arrays::CollisionViolatingStations));
    if (strategy == vtkGLPrintSequencer::DPT) {
      EXPECT_EQ(strategyName(out), "dpt");
      EXPECT_EQ(fieldValue(out, arrays::SequencePcgPairs), 0.0);  // not computed
      EXPECT_EQ(free, 0.0);
      EXPECT_GT(report->GetNumberOfPoints(), 0);
      EXPECT_EQ(fieldValue(out, arrays::SequenceRetractions), 1.0);  // one tower, then the other
    } else {
      EXPECT_EQ(free, 1.0) << strategyName(out);
      EXPECT_EQ(fieldValue(out, arrays::SequenceForcedSteps), 0.0);
    }
    if (strategy == vtkGLPrintSequencer::LPT) {
      EXPECT_EQ(strategyName(out), "lpt");
      EXPECT_GE(fieldValue(out, arrays::SequenceRetractions),
                layers);  // at least once per layer, to the other tower
    }
  }
}

TEST(vtkGLPrintSequencer, AStrategyOverrideOrdersAsThatStrategyWouldAndIsNamed) {
  // GLPrintPipeline::ChooseOrderByToolpath puts another order in place of Best's this way.
  const int layers = 8;
  auto lattice = towerLattice(layers);
  auto skeleton = towerSkeleton(layers);
  SequenceRun dpt(lattice, skeleton, vtkGLPrintSequencer::DPT, 60.0);
  const std::vector<int> dptOrder = checkedPrintOrder(dpt.output(1));
  SequenceRun best(lattice, skeleton, vtkGLPrintSequencer::BEST, 60.0);
  const std::vector<int> bestOrder = checkedPrintOrder(best.output(1));
  ASSERT_NE(bestOrder, dptOrder);  // DPT collides here, Best does not
  best.sequencer->SetStrategyOverride(vtkGLPrintSequencer::DPT);
  vtkPolyData* out = best.output(1);
  EXPECT_EQ(checkedPrintOrder(out), dptOrder);
  EXPECT_EQ(strategyName(out), "dpt");
  EXPECT_EQ(best.sequencer->GetStrategy(), vtkGLPrintSequencer::BEST);  // the setting is kept
  best.sequencer->SetStrategyOverride(-1);
  EXPECT_EQ(checkedPrintOrder(best.output(1)), bestOrder);
  EXPECT_FALSE(best.errors->HasError()) << best.errors->Errors();
}

TEST(vtkGLPrintSequencer, CollisionsWithAnAncestorAreUnavoidable) {
  // One tower of two layers; the upper square is moved 4 mm to -x and its nozzle axis turned to
  // +x, so the lower square (its skeleton parent, printed first in every order) is in its nozzle.
  auto lattice = towerLattice(2, {1});
  vtkDataArray* normals = lattice->GetPointData()->GetArray(arrays::NozzleAxis);
  for (vtkIdType v = 4; v < 8; ++v) {
    double p[3];
    lattice->GetPoint(v, p);
    p[0] -= 4.0;
    lattice->GetPoints()->SetPoint(v, p);
    normals->SetTuple3(v, 1, 0, 0);
  }
  SequenceRun run(lattice, towerSkeleton(2, {1}), vtkGLPrintSequencer::A4, 45.0);
  vtkPolyData* report = run.verify();
  ASSERT_FALSE(run.errors->HasError()) << run.errors->Errors();
  ASSERT_FALSE(run.verifierErrors->HasError()) << run.verifierErrors->Errors();
  vtkPolyData* out = run.output(0);
  EXPECT_EQ(fieldValue(out, arrays::SequencePcgPairs), 1.0);
  EXPECT_EQ(fieldValue(out, arrays::SequenceUnavoidablePairs), 1.0);
  EXPECT_EQ(fieldValue(out, arrays::SequenceForcedSteps), 0.0);
  vtkDataArray* edges = out->GetFieldData()->GetArray(arrays::SkeletonEdges);
  ASSERT_NE(edges, nullptr);
  ASSERT_EQ(edges->GetNumberOfTuples(), 1);
  EXPECT_EQ(edges->GetComponent(0, 0), 0.0);
  EXPECT_EQ(edges->GetComponent(0, 1), 1.0);
  // The verifier reports the collision but knows no order avoids it.
  EXPECT_EQ(fieldValue(report, arrays::CollisionFree), 0.0);
  EXPECT_EQ(fieldValue(report, arrays::CollisionOrderFree), 1.0);
  EXPECT_GT(fieldValue(report, arrays::CollisionViolatingStations), 0.0);
  EXPECT_EQ(fieldValue(report, arrays::CollisionUnavoidableStations),
            fieldValue(report, arrays::CollisionViolatingStations));
  vtkDataArray* unavoidable = report->GetPointData()->GetArray(arrays::Unavoidable);
  ASSERT_NE(unavoidable, nullptr);
  ASSERT_GT(report->GetNumberOfPoints(), 0);
  EXPECT_EQ(unavoidable->GetRange()[0], 1.0);
  // Without the skeleton edges every violation counts against the order.
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(out);
  copy->GetFieldData()->RemoveArray(arrays::SkeletonEdges);
  vtkNew<vtkGLCollisionVerifier> plain;
  plain->SetInputData(copy);
  plain->Update();
  EXPECT_EQ(fieldValue(plain->GetOutput(), arrays::CollisionOrderFree), 0.0);
  EXPECT_EQ(fieldValue(plain->GetOutput(), arrays::CollisionUnavoidableStations), 0.0);
  EXPECT_EQ(plain->GetOutput()->GetPointData()->GetArray(arrays::Unavoidable)->GetRange()[1], 0.0);
}

TEST(vtkGLPrintSequencer, DefaultsAndPrintSelf) {
  vtkNew<vtkGLPrintSequencer> s;
  EXPECT_EQ(s->GetNumberOfInputPorts(), 2);
  EXPECT_EQ(s->GetNumberOfOutputPorts(), 3);
  EXPECT_EQ(s->GetStrategy(), vtkGLPrintSequencer::BEST);
  expectCoreNozzleDefaults(s->GetNozzle());
  EXPECT_EQ(s->GetSampleSpacing(), 1.0);
  EXPECT_EQ(s->GetRolloutCandidates(), 6);
  EXPECT_EQ(s->GetRetractionCost(), 20.0);
  EXPECT_EQ(s->GetNumberOfThreads(), 0);
  s->SetStrategy(7);
  EXPECT_EQ(s->GetStrategy(), vtkGLPrintSequencer::BEST);
  expectPrintMentions(s,
                      {"Strategy: 3", "NozzleAngle: 45", "SampleSpacing: 1", "RetractionCost: 20"});
}

TEST(vtkGLPrintSequencer, BadInputIsReported) {
  const int layers = 4;
  {
    SequenceRun run(towerLattice(layers), towerSkeleton(layers), vtkGLPrintSequencer::LPT, 0.0);
    expectEmptyOutputs(run, "nozzle angle must be in (0, 90) degrees");
  }
  {
    SequenceRun run(towerLattice(layers), towerSkeleton(layers), vtkGLPrintSequencer::A4, 90.0);
    expectEmptyOutputs(run, "nozzle angle must be in (0, 90) degrees");
  }
  {
    SequenceRun run(towerLattice(layers), towerSkeleton(layers), vtkGLPrintSequencer::A4, 45.0);
    run.sequencer->GetNozzle()->SetNozzleLength(-1);
    expectEmptyOutputs(run, "nozzle length must be > 0 mm");
  }
  {
    SequenceRun run(towerLattice(layers), towerSkeleton(layers), vtkGLPrintSequencer::A4, 45.0);
    run.sequencer->SetSampleSpacing(0);
    expectEmptyOutputs(run, "sample spacing must be > 0 mm");
  }
  {
    SequenceRun run(towerLattice(layers), towerSkeleton(layers), vtkGLPrintSequencer::BEST, 45.0);
    run.sequencer->SetRolloutCandidates(0);
    expectEmptyOutputs(run, "rollout candidates must be >= 1");
  }
  {
    vtkNew<vtkPolyData> empty;
    SequenceRun run(empty, towerSkeleton(layers), vtkGLPrintSequencer::A4, 45.0);
    expectEmptyOutputs(run, "empty lattice");
  }
  {
    vtkNew<vtkPolyData> empty;
    SequenceRun run(towerLattice(layers), empty, vtkGLPrintSequencer::A4, 45.0);
    expectEmptyOutputs(run, "empty skeleton");
  }
  {
    SequenceRun run(towerLattice(layers), towerSkeleton(layers - 1), vtkGLPrintSequencer::A4, 45.0);
    expectEmptyOutputs(run, "the skeleton has 6 nodes but the lattice has 8 sub-graphs");
  }
  {
    SequenceRun run(towerLattice(layers), towerSkeleton(layers, {}, {{0, 5}}),
                    vtkGLPrintSequencer::LPT, 45.0);
    expectEmptyOutputs(run, "cyclic or missing adjacency");  // node 0 (layer 0) - node 5 (layer 2)
  }
  {
    SequenceRun run(towerLattice(layers), towerSkeleton(layers, {}, {{0, 1}}),
                    vtkGLPrintSequencer::LPT, 45.0);
    expectEmptyOutputs(run, "cyclic or missing adjacency");  // an edge within layer 0
  }
  {
    auto lattice = towerLattice(layers);
    lattice->GetCellData()->RemoveArray(arrays::SubgraphId);
    SequenceRun run(lattice, towerSkeleton(layers), vtkGLPrintSequencer::A4, 45.0);
    expectEmptyOutputs(run, "lattice has no SubgraphId cell array");
  }
  {
    auto lattice = towerLattice(layers);
    lattice->GetCellData()->RemoveArray(arrays::LayerId);
    SequenceRun run(lattice, towerSkeleton(layers), vtkGLPrintSequencer::A4, 45.0);
    expectEmptyOutputs(run, "lattice has no LayerId cell array");
  }
  {
    auto lattice = towerLattice(layers);
    lattice->GetPointData()->RemoveArray(arrays::NozzleAxis);
    SequenceRun run(lattice, towerSkeleton(layers), vtkGLPrintSequencer::A4, 45.0);
    expectEmptyOutputs(run, "lattice has no NozzleAxis point array");
  }
  {
    // A lattice written before the nozzle axis was renamed (point array Normals) still reads.
    auto lattice = towerLattice(layers);
    lattice->GetPointData()->GetArray(arrays::NozzleAxis)->SetName(arrays::Normals);
    SequenceRun run(lattice, towerSkeleton(layers), vtkGLPrintSequencer::A4, 45.0);
    EXPECT_GT(run.output(0)->GetNumberOfCells(), 0);
    EXPECT_FALSE(run.errors->HasError());
  }
  {
    auto lattice = towerLattice(layers);
    lattice->GetPointData()->RemoveArray(arrays::Gamma);
    SequenceRun run(lattice, towerSkeleton(layers), vtkGLPrintSequencer::A4, 45.0);
    expectEmptyOutputs(run, "lattice has no Gamma point array");
  }
  {
    auto skeleton = towerSkeleton(layers);
    skeleton->GetPointData()->RemoveArray(arrays::LayerId);
    SequenceRun run(towerLattice(layers), skeleton, vtkGLPrintSequencer::A4, 45.0);
    expectEmptyOutputs(run, "skeleton has no LayerId point array");
  }
  {
    // Sub-graph ids with a gap: the last two sub-graphs renumbered 7 -> 9, 6 -> 8.
    auto lattice = towerLattice(layers);
    for (vtkDataArray* a : {lattice->GetCellData()->GetArray(arrays::SubgraphId),
                            lattice->GetPointData()->GetArray(arrays::SubgraphId)}) {
      for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) {
        if (a->GetTuple1(i) >= 6) {
          a->SetTuple1(i, a->GetTuple1(i) + 2);
        }
      }
    }
    SequenceRun run(lattice, towerSkeleton(layers), vtkGLPrintSequencer::A4, 45.0);
    expectEmptyOutputs(run,
                       "sub-graph ids must be 0..K-1 without gaps: no line cell has SubgraphId 6");
  }
  {
    // A skeleton whose nodes are on other layers than the lattice's sub-graphs.
    auto skeleton = towerSkeleton(layers);
    vtkDataArray* nodeId = skeleton->GetPointData()->GetArray(arrays::NodeId);
    for (vtkIdType p = 0; p < nodeId->GetNumberOfTuples(); ++p) {
      nodeId->SetTuple1(p, nodeId->GetNumberOfTuples() - 1 - p);
    }
    SequenceRun run(towerLattice(layers), skeleton, vtkGLPrintSequencer::A4, 45.0);
    expectEmptyOutputs(
        run, "skeleton node 0 is on lattice layer 3 but sub-graph 0 of the lattice is on layer 0");
  }
  {
    // A recovered error: the next update with good input has outputs and no new error.
    SequenceRun run(towerLattice(layers), towerSkeleton(layers), vtkGLPrintSequencer::A4, 90.0);
    run.output(0);
    EXPECT_TRUE(run.errors->HasError());
    run.errors->Clear();
    run.sequencer->GetNozzle()->SetNozzleAngle(45.0);
    EXPECT_EQ(run.output(0)->GetNumberOfCells(),
              vtkPolyData::SafeDownCast(run.sequencer->GetInput(0))->GetNumberOfCells());
    EXPECT_FALSE(run.errors->HasError()) << run.errors->Errors();
  }
}

// ---------------------------------------------------------------------------------------------
// End to end on the branching Y: reader -> place -> tets -> GDF -> slicer -> lattice -> skeleton
// -> sequencer -> verifier. Built once for the suite.

class BranchingYPipeline : public GLTestYSuite<BranchingYPipeline> {
public:
  static vtkAlgorithm* Stage(GLTestYPipeline& y) { return y.skeleton; }

protected:
  /// A sequencer (and verifier on its lattice output) on the Y with the given settings.
  struct Run {
    vtkNew<vtkGLPrintSequencer> sequencer;
    vtkNew<vtkGLCollisionVerifier> verifier;
    vtkNew<GLTestErrorObserver> errors;
  };
  static std::unique_ptr<Run> sequence(int strategy, double angle) {
    auto r = std::make_unique<Run>();
    r->sequencer->SetInputConnection(0, p->lattice->GetOutputPort());
    r->sequencer->SetInputConnection(1, p->skeleton->GetOutputPort());
    r->sequencer->SetStrategy(strategy);
    r->sequencer->GetNozzle()->SetNozzleAngle(angle);
    r->verifier->SetInputConnection(r->sequencer->GetOutputPort(0));
    r->verifier->GetNozzle()->SetNozzleAngle(angle);
    r->errors->Observe(r->sequencer);
    r->errors->Observe(r->verifier);
    r->verifier->Update();
    r->sequencer->Update(1);
    r->sequencer->Update(2);
    return r;
  }
};

TEST_F(BranchingYPipeline, SkeletonSplitsAtTheFork) {
  ASSERT_FALSE(p->errors->HasError()) << p->errors->Errors();
  vtkPolyData* lattice = p->lattice->GetOutput();
  vtkPolyData* skeleton = p->skeleton->GetOutput();
  ASSERT_GT(skeleton->GetNumberOfPoints(), 0);
  EXPECT_EQ(skeleton->GetNumberOfPoints(), fieldValue(lattice, arrays::LatticeSubgraphs));
  EXPECT_GE(fieldValue(skeleton, arrays::SkeletonSplitNodes), 1.0);
  EXPECT_EQ(fieldValue(skeleton, arrays::SkeletonRoots), 1.0);
  EXPECT_EQ(fieldValue(skeleton, arrays::SkeletonFloatingNodes), 0.0);
  EXPECT_EQ(fieldValue(skeleton, arrays::SkeletonMergeNodes), 0.0);
  std::printf(
      "[sequencer filter] Y: %g layers, %lld sub-graphs, %lld skeleton edges, %g split node(s), "
      "skeleton %.3f s\n",
      static_cast<double>(
          skeleton->GetFieldData()->GetArray(arrays::LayerValues)->GetNumberOfTuples()),
      static_cast<long long>(skeleton->GetNumberOfPoints()),
      static_cast<long long>(skeleton->GetNumberOfCells()),
      fieldValue(skeleton, arrays::SkeletonSplitNodes),
      fieldValue(skeleton, arrays::SkeletonSeconds));
}

TEST_F(BranchingYPipeline, EveryStrategyGivesAPermutationInTreeOrder) {
  ASSERT_FALSE(p->errors->HasError()) << p->errors->Errors();
  const double K = fieldValue(p->lattice->GetOutput(), arrays::LatticeSubgraphs);
  for (int strategy : {vtkGLPrintSequencer::LPT, vtkGLPrintSequencer::DPT, vtkGLPrintSequencer::A4,
                       vtkGLPrintSequencer::BEST}) {
    auto r = sequence(strategy, 45.0);
    ASSERT_FALSE(r->errors->HasError()) << r->errors->Errors();
    vtkPolyData* skeleton = r->sequencer->GetOutput(1);
    ASSERT_EQ(skeleton->GetNumberOfPoints(), K);
    expectLowerBeforeUpper(skeleton, checkedPrintOrder(skeleton));
    vtkPolyData* report = r->verifier->GetOutput();
    vtkPolyData* out = r->sequencer->GetOutput(0);
    std::printf(
        "[sequencer filter] Y, NA 45, %-4s: retractions %g, air %.1f mm, forced %g, PCG pairs %g "
        "(%.3f s), "
        "order %.3f s; verifier: collision-free %g, %g stations, %g violating (%.3f s)\n",
        strategyName(out).c_str(), fieldValue(out, arrays::SequenceRetractions),
        fieldValue(out, arrays::SequenceAirLength), fieldValue(out, arrays::SequenceForcedSteps),
        fieldValue(out, arrays::SequencePcgPairs), fieldValue(out, arrays::SequencePcgSeconds),
        fieldValue(out, arrays::SequenceSeconds), fieldValue(report, arrays::CollisionFree),
        fieldValue(report, arrays::CollisionStations),
        fieldValue(report, arrays::CollisionViolatingStations),
        fieldValue(report, arrays::CollisionSeconds));
    if (strategy != vtkGLPrintSequencer::DPT) {
      EXPECT_EQ(fieldValue(report, arrays::CollisionFree), 1.0) << strategyName(out);
    }
    if (strategy == vtkGLPrintSequencer::A4 || strategy == vtkGLPrintSequencer::BEST) {
      EXPECT_EQ(fieldValue(out, arrays::SequenceForcedSteps), 0.0);
    }
  }
}

TEST_F(BranchingYPipeline, VerifierSamplesTheLatticeLikeTheGenericLineSampling) {
  ASSERT_FALSE(p->errors->HasError()) << p->errors->Errors();
  auto r = sequence(vtkGLPrintSequencer::DPT, 70.0);
  ASSERT_FALSE(r->errors->HasError()) << r->errors->Errors();
  // The same lines without SubgraphId are sampled by the verifier's own code: same stations,
  // same verdict.
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(r->sequencer->GetOutput(0));
  copy->GetCellData()->RemoveArray(arrays::SubgraphId);
  vtkNew<vtkGLCollisionVerifier> generic;
  generic->SetInputData(copy);
  generic->GetNozzle()->SetNozzleAngle(70.0);
  r->errors->Observe(generic);
  generic->Update();
  ASSERT_FALSE(r->errors->HasError()) << r->errors->Errors();
  vtkPolyData* a = r->verifier->GetOutput();
  vtkPolyData* b = generic->GetOutput();
  EXPECT_GT(fieldValue(a, arrays::CollisionStations),
            static_cast<double>(copy->GetNumberOfPoints()));
  EXPECT_EQ(fieldValue(a, arrays::CollisionStations), fieldValue(b, arrays::CollisionStations));
  EXPECT_EQ(fieldValue(a, arrays::CollisionViolatingStations),
            fieldValue(b, arrays::CollisionViolatingStations));
  EXPECT_EQ(fieldValue(a, arrays::CollisionFree), fieldValue(b, arrays::CollisionFree));
  std::printf("[sequencer filter] Y, DPT at NA 70: collision-free %g, %g of %g stations violate\n",
              fieldValue(a, arrays::CollisionFree),
              fieldValue(a, arrays::CollisionViolatingStations),
              fieldValue(a, arrays::CollisionStations));
}

TEST_F(BranchingYPipeline, SequencerProgressAndAbort) {
  ASSERT_FALSE(p->errors->HasError()) << p->errors->Errors();
  for (int strategy :
       {vtkGLPrintSequencer::LPT, vtkGLPrintSequencer::A4, vtkGLPrintSequencer::BEST}) {
    SCOPED_TRACE(strategy);
    vtkNew<vtkGLPrintSequencer> sequencer;
    sequencer->SetInputConnection(0, p->lattice->GetOutputPort());
    sequencer->SetInputConnection(1, p->skeleton->GetOutputPort());
    sequencer->SetStrategy(strategy);
    sequencer->SetNumberOfThreads(2);
    // Material, the potential collisions per sub-graph (A4, best), the order step by step.
    glExpectProgressReport(sequencer, 20);
    glExpectCleanAbort(sequencer,
                       glAbortAt(0.3));  // A4, best: in the potential collisions; LPT: in the order
    glExpectCleanAbort(sequencer, glAbortAt(0.8));  // in the order
  }
}

TEST_F(BranchingYPipeline, VerifierProgressAndAbort) {
  ASSERT_FALSE(p->errors->HasError()) << p->errors->Errors();
  vtkNew<vtkGLPrintSequencer> sequencer;
  sequencer->SetInputConnection(0, p->lattice->GetOutputPort());
  sequencer->SetInputConnection(1, p->skeleton->GetOutputPort());
  sequencer->Update();
  vtkNew<vtkGLCollisionVerifier> verifier;
  verifier->SetInputConnection(sequencer->GetOutputPort(0));
  // Inputs checked, stations sampled, the check (one core call), the output.
  glExpectProgressReport(verifier, 3);
  glExpectCleanAbort(verifier, glAbortAt(0.2));
  glExpectCleanAbort(verifier, glAbortAt(0.9));
}
