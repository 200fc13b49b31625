#include "GLPrintPipeline.h"
#include "vtkGLProgress.h"

#include "vtkGLArrayNames.h"

#include "orient/AutoOrient.h"

#include <vtkAlgorithm.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <chrono>

#include <algorithm>

namespace {

/// Of the tries that ran, the one with the fewest colliding stations (the earlier on a tie), or
/// null when none ran.
template <class Try>
const Try* leastColliding(const std::vector<Try>& tries) {
  const Try* least = nullptr;
  for (const Try& t : tries) {
    if (t.ok && (!least || t.colliding < least->colliding)) {
      least = &t;
    }
  }
  return least;
}

}  // namespace

GLPrintPipeline::GLPrintPipeline(bool tetMeshInput) {
  this->Placement->SetInputConnection(this->Reader->GetOutputPort());
  this->Orientation->SetInputConnection(this->Placement->GetOutputPort());
  this->Pedestal->SetInputConnection(this->Orientation->GetOutputPort(0));
  this->Tetrahedralize->SetInputConnection(this->Pedestal->GetOutputPort());
  this->Slicer->SetInputConnection(this->GeodesicFields->GetOutputPort());
  this->OverhangAnalysis->SetInputConnection(this->GeodesicFields->GetOutputPort());
  this->LatticeInfill->SetInputConnection(this->Slicer->GetOutputPort(0));
  this->SkeletonTree->SetInputConnection(0, this->LatticeInfill->GetOutputPort());
  this->SkeletonTree->SetInputConnection(1, this->GeodesicFields->GetOutputPort());
  this->Sequencer->SetInputConnection(0, this->LatticeInfill->GetOutputPort());
  this->Sequencer->SetInputConnection(1, this->SkeletonTree->GetOutputPort());
  this->SequenceVerifier->SetInputConnection(this->Sequencer->GetOutputPort(0));
  this->SequenceVerifier->SetTimeArrayName(geolattice::arrays::PrintOrder);
  this->Planner->SetInputConnection(0, this->Sequencer->GetOutputPort(0));
  this->Planner->SetInputConnection(1, this->Sequencer->GetOutputPort(1));
  this->ToolpathVerifier->SetInputConnection(this->Planner->GetOutputPort());
  this->ToolpathVerifier->SetTimeArrayName(geolattice::arrays::PointIndex);
  this->PrintSummary->SetInputConnection(0, this->Planner->GetOutputPort());
  this->PrintSummary->SetInputConnection(1, this->ToolpathVerifier->GetOutputPort());
  this->ToolpathReplay->SetInputConnection(this->Planner->GetOutputPort());
  for (vtkGLNozzleAlgorithm* a :
       {static_cast<vtkGLNozzleAlgorithm*>(this->Orientation.Get()),
        static_cast<vtkGLNozzleAlgorithm*>(this->Sequencer.Get()),
        static_cast<vtkGLNozzleAlgorithm*>(this->SequenceVerifier.Get()),
        static_cast<vtkGLNozzleAlgorithm*>(this->Planner.Get()),
        static_cast<vtkGLNozzleAlgorithm*>(this->ToolpathVerifier.Get())}) {
    a->SetNozzle(this->Nozzle);
  }
  this->ScriptWriter->SetInputConnection(this->Planner->GetOutputPort());
  this->ScriptWriter->SetNozzle(this->Nozzle);  // its printhead file sets the arm's clearance
  this->GCodeWriter->SetInputConnection(this->Planner->GetOutputPort());
  this->WaypointWriter->SetInputConnection(this->Planner->GetOutputPort());
  this->TetMeshInput = !tetMeshInput;  // force the wiring below
  this->SetTetMeshInput(tetMeshInput);
}

void GLPrintPipeline::SetTetMeshInput(bool tetMeshInput) {
  if (tetMeshInput == this->TetMeshInput) {
    return;
  }
  this->TetMeshInput = tetMeshInput;
  vtkAlgorithm* tets = tetMeshInput ? static_cast<vtkAlgorithm*>(this->Placement.Get())
                                    : static_cast<vtkAlgorithm*>(this->Tetrahedralize.Get());
  this->GeodesicFields->SetInputConnection(tets->GetOutputPort());
}

void GLPrintPipeline::SetPedestalRequest(double mm) {
  if (mm < 0) {
    this->Orientation->SetPedestal(vtkGLAutoOrient::PEDESTAL_WHEN_IT_HELPS);
    this->Orientation->SetPedestalHeight(geolattice::OrientOptions{}.pedestalHeight);
    this->Pedestal->SetHeight(0);
  } else if (mm == 0) {
    this->Orientation->SetPedestal(vtkGLAutoOrient::PEDESTAL_NEVER);
    this->Pedestal->SetHeight(0);
  } else {
    this->Orientation->SetPedestal(vtkGLAutoOrient::PEDESTAL_ALWAYS);
    this->Orientation->SetPedestalHeight(mm);
    this->Pedestal->SetHeight(mm);
  }
}

double GLPrintPipeline::GetPedestalRequest() {
  const bool automatic =
      this->Orientation->GetPedestal() == vtkGLAutoOrient::PEDESTAL_WHEN_IT_HELPS;
  return automatic && this->Pedestal->GetHeight() == 0 ? -1.0 : this->Pedestal->GetHeight();
}

void GLPrintPipeline::MatchOrientationToPrint() {
  if (this->Orientation->GetOrient() != vtkGLAutoOrient::AUTO) {
    return;  // Keep passes the part on: a print setting must not re-run it
  }
  this->Orientation->SetRefineLayerInterval(this->Slicer->GetLayerInterval());
  this->Orientation->SetRefineLatticeWidth(
      std::min(this->LatticeInfill->GetAlphaWidth(), this->LatticeInfill->GetBetaWidth()));
  this->Orientation->SetRefineStrategy(this->Sequencer->GetStrategy());
  this->Orientation->SetBaseFlatBand(this->GeodesicFields->GetBaseFlatBand());
  this->Orientation->SetMaxAxisTilt(this->Planner->GetMaxAxisTilt());
  if (this->RobotGate) {  // sides too tall for the robot cell rank last
    this->Orientation->SetMaxHeight(this->ScriptWriter->TallestPart());
  }
  // ChooseOrientationByToolpath runs refined candidates only: refine as many as it may try.
  this->Orientation->SetRefineCandidates(
      std::max(geolattice::OrientOptions{}.refineCandidates, this->OrientationTries));
}

std::vector<GLPrintPipeline::OrientationTry> GLPrintPipeline::ChooseOrientationByToolpath(
    int tries, const std::function<void(const OrientationTry&)>& starting) {
  std::vector<OrientationTry> done;
  if (this->Orientation->GetOrient() != vtkGLAutoOrient::AUTO || tries < 2 || this->TetMeshInput) {
    return done;
  }
  auto field = [](vtkDataObject* d, const char* name) {
    vtkDataArray* a = d ? d->GetFieldData()->GetArray(name) : nullptr;
    return a && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0) : -1.0;
  };
  // The ranks to try: the best ones, then the part as placed (on the plate) if it can stand:
  // the user's placement is never beaten by a candidate that prints worse.
  this->Orientation->Update();  // the search (cached); a failure shows in the first try
  vtkPolyData* candidates = vtkPolyData::SafeDownCast(this->Orientation->GetOutputDataObject(1));
  auto array = [candidates](const char* name) {
    return candidates ? candidates->GetPointData()->GetAbstractArray(name) : nullptr;
  };
  auto number = [&](const char* name, vtkIdType i) {
    vtkDataArray* a = vtkDataArray::SafeDownCast(array(name));
    return a ? a->GetTuple1(i) : 0.0;
  };
  auto usable = [&](int rank, bool asPlaced) {
    auto* source = vtkStringArray::SafeDownCast(array(geolattice::arrays::OrientSource));
    for (vtkIdType i = 0; candidates && i < candidates->GetNumberOfPoints(); ++i) {
      if (number(geolattice::arrays::OrientRank, i) == rank &&
          number(geolattice::arrays::Feasible, i) > 0 &&
          number(geolattice::arrays::Refined, i) > 0 &&
          (!asPlaced || (source && source->GetValue(i) == "keep" &&
                         number(geolattice::arrays::Pedestal, i) == 0))) {
        return true;
      }
    }
    return false;
  };
  // `tries` candidates besides the placement: where the placement ranks among them it does not
  // take one's place (its plate stations the tilt clears are not counted, so it may rank first).
  std::vector<int> ranks;
  const vtkIdType count =
      candidates && candidates->GetNumberOfPoints() > 0 ? candidates->GetNumberOfPoints() : tries;
  bool placementIn = false;
  for (int rank = 0, others = 0; rank < count && (others < tries || !placementIn); ++rank) {
    const bool placement = candidates && usable(rank, true);
    if (placement || others < tries) {
      ranks.push_back(rank);
    }
    placementIn = placementIn || placement;
    others += !placement;
  }
  // The current candidate first: its outputs are the pipeline's (the search's best, or the one
  // PreferTheBaseToAPedestal put first).
  const int current = this->Orientation->GetCandidateRank();
  ranks.erase(std::remove(ranks.begin(), ranks.end(), current), ranks.end());
  ranks.insert(ranks.begin(), current);
  std::string after;  // why the try before was not printed
  for (int rank : ranks) {
    if (geolattice::stopRequest().load() || (rank != current && !usable(rank, false))) {
      continue;
    }
    this->Orientation->SetCandidateRank(rank);
    OrientationTry t;
    t.rank = rank;
    t.after = after;
    if (rank != current && starting) {
      starting(t);
    }
    const ToolpathVerdict verdict = this->UpdateToolpathVerdict();
    t.ok = verdict.ok;
    t.colliding = verdict.colliding;
    t.stations = verdict.stations;
    t.seconds = verdict.seconds;
    t.pedestal =
        field(this->Orientation->GetOutputDataObject(0), geolattice::arrays::OrientPedestalHeight);
    const bool printable = t.ok && t.colliding == 0 && this->RobotFollows(t);
    done.push_back(t);
    if (printable) {
      break;
    }
    after = t.ok && t.colliding == 0 ? "robot" : "collides";
  }
  // The least colliding; of those, one the robot follows; else the earliest.
  const OrientationTry* best = nullptr;
  for (const OrientationTry& t : done) {
    if (t.ok && (!best || t.colliding < best->colliding ||
                 (t.colliding == best->colliding && best->robot == 0 && t.robot == 1))) {
      best = &t;
    }
  }
  this->Orientation->SetCandidateRank(best ? best->rank : 0);
  return done;
}

vtkPointData* GLPrintPipeline::OrientationCandidates() {
  if (this->Orientation->GetOrient() != vtkGLAutoOrient::AUTO || this->TetMeshInput ||
      !this->Orientation->GetExecutive()->Update()) {
    return nullptr;
  }
  vtkPolyData* candidates = vtkPolyData::SafeDownCast(this->Orientation->GetOutputDataObject(1));
  return candidates ? candidates->GetPointData() : nullptr;
}

int GLPrintPipeline::PreferTheBaseToAPedestal() {
  vtkPointData* pd = this->OrientationCandidates();
  auto array = [pd](const char* name) {
    return pd ? vtkDataArray::SafeDownCast(pd->GetAbstractArray(name)) : nullptr;
  };
  namespace arrays = geolattice::arrays;
  vtkDataArray *rank = array(arrays::OrientRank), *up = array(arrays::OrientUp),
               *pedestal = array(arrays::Pedestal), *feasible = array(arrays::Feasible),
               *refined = array(arrays::Refined), *colliding = array(arrays::CollidingStations),
               *stations = array(arrays::CollisionStations);
  if (!rank || !up || !pedestal || !feasible || !refined || !colliding || !stations) {
    return -1;
  }
  const vtkIdType n = rank->GetNumberOfTuples();
  vtkIdType best = -1;
  for (vtkIdType i = 0; i < n && best < 0; ++i) {
    best = rank->GetTuple1(i) == 0 ? i : -1;
  }
  if (best < 0 || !(pedestal->GetTuple1(best) > 0)) {
    return -1;
  }
  for (vtkIdType i = 0; i < n; ++i) {
    double a[3], b[3];
    up->GetTuple(i, a);
    up->GetTuple(best, b);
    const bool sameDirection = a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
    if (i != best && sameDirection && pedestal->GetTuple1(i) == 0 && feasible->GetTuple1(i) > 0 &&
        refined->GetTuple1(i) > 0 && colliding->GetTuple1(i) <= 0.01 * stations->GetTuple1(i)) {
      const int r = static_cast<int>(rank->GetTuple1(i));
      this->Orientation->SetCandidateRank(r);
      return r;
    }
  }
  return -1;
}

int GLPrintPipeline::PreferThePlacementToATallerPrint() {
  vtkPointData* pd = this->OrientationTries < 2 ? nullptr : this->OrientationCandidates();
  auto array = [pd](const char* name) {
    return pd ? vtkDataArray::SafeDownCast(pd->GetAbstractArray(name)) : nullptr;
  };
  namespace arrays = geolattice::arrays;
  vtkDataArray *rank = array(arrays::OrientRank), *pedestal = array(arrays::Pedestal),
               *feasible = array(arrays::Feasible), *refined = array(arrays::Refined),
               *colliding = array(arrays::CollidingStations), *plate = array(arrays::PlateStations),
               *layers = array(arrays::LayerCount);
  auto* source =
      pd ? vtkStringArray::SafeDownCast(pd->GetAbstractArray(arrays::OrientSource)) : nullptr;
  if (!rank || !pedestal || !feasible || !refined || !colliding || !plate || !layers || !source) {
    return -1;
  }
  const vtkIdType n = rank->GetNumberOfTuples();
  vtkIdType best = -1, placement = -1;
  for (vtkIdType i = 0; i < n; ++i) {
    if (rank->GetTuple1(i) == 0) {
      best = i;
    }
    if (source->GetValue(i) == "keep" && pedestal->GetTuple1(i) == 0) {
      placement = i;
    }
  }
  if (best < 0 || placement < 0 || best == placement || !(feasible->GetTuple1(placement) > 0) ||
      !(refined->GetTuple1(placement) > 0)) {
    return -1;
  }
  // The coarse search's count against the placement is often one the print does not have:
  // material (three touching rings 850 of 18,042 stations with 78 forced steps, a bottle 422 of
  // 28,535) or, on a part thinner than its elements, the plate (a 120 x 120 x 2 mm plate 1,118
  // of 54,402); each 0 in the full run. It is checked by running the placement when the best
  // is a much longer print: twice the layers, or a pedestal (material, time, a cut) where the
  // placement collided mostly with material. (Plate stations are what a pedestal is for: the
  // bunny's placement collides with the plate in the search and in the print.)
  const double collisions = colliding->GetTuple1(placement);
  const bool twiceTheLayers = 2 * layers->GetTuple1(placement) <= layers->GetTuple1(best);
  const bool pedestalForMaterial =
      pedestal->GetTuple1(best) > 0 && plate->GetTuple1(placement) <= 0.5 * collisions;
  if (!(collisions > 0) || !(twiceTheLayers || pedestalForMaterial)) {
    return -1;
  }
  const int r = static_cast<int>(rank->GetTuple1(placement));
  this->Orientation->SetCandidateRank(r);
  return r;
}

GLPrintPipeline::ToolpathVerdict GLPrintPipeline::UpdateToolpathVerdict() {
  ToolpathVerdict v;
  const auto start = std::chrono::steady_clock::now();
  v.ok = this->ToolpathVerifier->GetExecutive()->Update() != 0;
  v.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  vtkDataObject* out = this->ToolpathVerifier->GetOutputDataObject(0);
  auto count = [out](const char* name) {
    vtkDataArray* a = out ? out->GetFieldData()->GetArray(name) : nullptr;
    return a && a->GetNumberOfTuples() > 0 ? static_cast<long long>(a->GetTuple1(0)) : -1LL;
  };
  v.colliding = count(geolattice::arrays::CollisionViolatingStations);
  v.plate = count(geolattice::arrays::CollisionPlateStations);
  v.stations = count(geolattice::arrays::CollisionStations);
  v.ok = v.ok && v.colliding >= 0;
  return v;
}

std::vector<GLPrintPipeline::OrderTry> GLPrintPipeline::ChooseOrderByToolpath(
    const std::function<void(const OrderTry&)>& starting) {
  std::vector<OrderTry> done;
  if (this->Orientation->GetOrient() != vtkGLAutoOrient::AUTO || this->TetMeshInput ||
      this->Sequencer->GetStrategy() != vtkGLPrintSequencer::BEST) {
    return done;
  }
  for (int strategy :
       {vtkGLPrintSequencer::BEST, vtkGLPrintSequencer::LPT, vtkGLPrintSequencer::DPT}) {
    if (geolattice::stopRequest().load()) {
      break;
    }
    const bool best = strategy == vtkGLPrintSequencer::BEST;
    this->Sequencer->SetStrategyOverride(best ? -1 : strategy);
    OrderTry t;
    t.strategy = strategy;
    if (!best && starting) {
      starting(t);
    }
    const ToolpathVerdict verdict = this->UpdateToolpathVerdict();  // Best's: from the cache
    t.ok = verdict.ok;
    t.colliding = verdict.colliding;
    t.stations = verdict.stations;
    t.seconds = verdict.seconds;
    done.push_back(t);
    // Done when it is collision-free, or (Best's) when it collides only with the build plate,
    // which is there from the start whatever the order.
    if (t.ok && (t.colliding == 0 || (best && verdict.plate == t.colliding))) {
      break;
    }
  }
  const OrderTry* chosen = leastColliding(done);
  this->Sequencer->SetStrategyOverride(
      chosen && chosen->strategy != vtkGLPrintSequencer::BEST ? chosen->strategy : -1);
  return done;
}

std::vector<GLPrintPipeline::PedestalTry> GLPrintPipeline::RaisePedestalByToolpath(
    const std::function<void(const PedestalTry&)>& starting) {
  std::vector<PedestalTry> done;
  if (this->Orientation->GetOrient() != vtkGLAutoOrient::AUTO || this->TetMeshInput ||
      this->Orientation->GetPedestal() != vtkGLAutoOrient::PEDESTAL_WHEN_IT_HELPS) {
    return done;
  }
  this->Pedestal->SetHeightOverride(-1);
  ToolpathVerdict verdict = this->UpdateToolpathVerdict();  // the search's pedestal: cached
  const double chosen = this->Pedestal->HeightFor(this->Orientation->GetOutputDataObject(0));
  if (!verdict.ok || verdict.plate <= 0 || !(chosen > 0)) {
    return done;
  }
  for (double factor : {1.0, 2.0, 3.0}) {
    if (geolattice::stopRequest().load()) {
      break;
    }
    PedestalTry t;
    t.height = factor * chosen;
    if (factor > 1) {
      if (starting) {
        starting(t);
      }
      this->Pedestal->SetHeightOverride(t.height);
      verdict = this->UpdateToolpathVerdict();
    }
    t.ok = verdict.ok;
    t.colliding = verdict.colliding;
    t.plate = verdict.plate;
    t.stations = verdict.stations;
    t.seconds = verdict.seconds;
    done.push_back(t);
    if (t.ok && t.plate == 0) {  // a taller one cannot do better
      break;
    }
  }
  const PedestalTry* best = leastColliding(done);
  this->Pedestal->SetHeightOverride(best && best->height != chosen ? best->height : -1.0);
  return done;
}

bool GLPrintPipeline::RobotFollows(OrientationTry& t) {
  if (!this->RobotGate) {
    return true;
  }
  const auto start = std::chrono::steady_clock::now();
  const bool follows = this->ScriptWriter->SolveRobotPath() != 0;
  t.robotSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  t.robot = follows ? 1 : 0;
  t.unreachable = static_cast<long long>(this->ScriptWriter->GetUnreachableCount());
  t.largeSteps = static_cast<long long>(this->ScriptWriter->GetLargeJointSteps());
  return follows;
}

GLPrintPipeline::SetUpTries GLPrintPipeline::FindAPrintableSetUp(
    const std::function<void(SetUpStep)>& runStages, const SetUpListener& listener) {
  SetUpTries tries;
  auto collides = [this] {
    const ToolpathVerdict v = this->UpdateToolpathVerdict();  // the current outputs: cached
    return v.ok && v.colliding > 0;
  };
  if (!collides()) {
    // A collision-free set-up is printed as it is unless other orientations may be tried and
    // the robot cannot follow it (its solution is kept for the program).
    const bool mayTryOthers = this->RobotGate &&
                              this->Orientation->GetOrient() == vtkGLAutoOrient::AUTO &&
                              !this->TetMeshInput && this->UpdateToolpathVerdict().ok;
    OrientationTry current;
    if (!mayTryOthers || this->RobotFollows(current)) {
      return tries;
    }
  }
  tries.orientations =
      this->ChooseOrientationByToolpath(this->OrientationTries, listener.orientation);
  if (tries.orientations.size() > 1) {
    runStages(SetUpStep::Orientation);
  }
  if (!collides()) {
    return tries;  // the pedestal and the order below are for collisions
  }
  // Then taller pedestals, where the plate is in the nozzle's way.
  tries.pedestals = this->RaisePedestalByToolpath(listener.pedestal);
  if (tries.pedestals.size() > 1) {
    runStages(SetUpStep::Pedestal);
  }
  if (!collides()) {
    return tries;
  }
  // Then other print orders (Strategy Best only).
  tries.orders = this->ChooseOrderByToolpath(listener.order);
  if (tries.orders.size() > 1) {
    runStages(SetUpStep::Order);
  }
  return tries;
}

vtkAlgorithm* GLPrintPipeline::Filter(Stage stage) {
  switch (stage) {
    case Read:
      return this->Reader;
    case Place:
      return this->Placement;
    case Orient:
      return this->Orientation;
    case Raise:
      return this->Pedestal;
    case Mesh:
      return this->Tetrahedralize;
    case Fields:
      return this->GeodesicFields;
    case Layers:
      return this->Slicer;
    case Overhang:
      return this->OverhangAnalysis;
    case Lattice:
      return this->LatticeInfill;
    case Skeleton:
      return this->SkeletonTree;
    case Sequence:
      return this->Sequencer;
    case SequenceVerify:
      return this->SequenceVerifier;
    case Toolpath:
      return this->Planner;
    case ToolpathVerify:
      return this->ToolpathVerifier;
    case Summary:
      return this->PrintSummary;
    case Replay:
      return this->ToolpathReplay;
    case NumberOfStages:
      break;
  }
  return nullptr;
}

const char* GLPrintPipeline::StageName(Stage stage) {
  static const char* const names[NumberOfStages] = {
      "read",     "place",           "orient",  "pedestal", "mesh",     "fields",
      "layers",   "overhang",        "lattice", "skeleton", "sequence", "sequence-verify",
      "toolpath", "toolpath-verify", "summary", "replay"};
  return stage >= 0 && stage < NumberOfStages ? names[stage] : "";
}

void GLPrintPipeline::RequestStop() {
  geolattice::stopRequest().store(true);
}

void GLPrintPipeline::ClearStopRequest() {
  geolattice::stopRequest().store(false);
}
