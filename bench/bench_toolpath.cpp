// Toolpath planning (paper Section 3.2) on the bunny scaled to 100 mm, ~66k tets, 0.6 mm layers,
// lattice width 6 mm (the paper's bunny: Fleury 77 s + thickness 36 s). Timed separately:
// trimming + crossover-free Euler tours + layer thickness (the paper's steps), and the whole
// planner (with support perimeters, rotation steps, air moves, extrusion). Also the point tree
// of the axis clearance and the verifier (TimedPointTree) over 470k points along a helix, the
// stations of a topopt-sized toolpath, built once per clearance round. And the planner on
// topopt at 80 mm under a 30° nozzle with and without trying its colliding tours in other ways.
// Run: build/bin/bench_toolpath
#include "../tests/common/CoreStages.h"
#include "collision/TimedPointTree.h"
#include "lattice/LatticeInfill.h"
#include "sequence/PotentialCollisions.h"
#include "sequence/PrintMaterial.h"
#include "sequence/PrintSequencer.h"
#include "skeleton/SkeletonTree.h"
#include "toolpath/EulerTour.h"
#include "toolpath/EulerianTrimming.h"
#include "toolpath/LayerThickness.h"
#include "toolpath/ToolpathPlanner.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

using namespace geolattice;

namespace {

struct Bunny {
  LatticeGraph lattice;
  SkeletonTree tree;
  std::vector<int> order;
};

const Bunny& bunny() {
  static const Bunny b = [] {
    fixtures::CoreStages stages = fixtures::paperBunny(fixtures::CoreStage::Skeleton, 6.0);
    Bunny r;
    r.lattice = std::move(stages.lattice);
    r.tree = std::move(stages.tree);
    SequenceOptions so;
    so.strategy = SequenceStrategy::LayerPriority;
    r.order = sequencePrint(r.tree, sampleLatticeMaterial(r.lattice, 1.0), nullptr, so).order;
    return r;
  }();
  return b;
}

void BM_TrimToursThickness(benchmark::State& state) {
  const Bunny& b = bunny();
  EulerTours tours;
  for (auto _ : state) {
    LatticeGraph g = b.lattice;
    contractShortEdges(g, 1e-9);
    const TrimResult trim = trimToEulerian(g);
    tours = nonCrossingEulerTours(g, trim.kept);
    const LayerThicknessResult h = computeLayerThickness(g, b.tree, 1.5);
    benchmark::DoNotOptimize(h.thickness.data());
  }
  state.counters["edges"] = static_cast<double>(b.lattice.edges.size());
  state.counters["subgraphs"] = static_cast<double>(b.lattice.subgraphs.size());
  state.counters["tours"] = static_cast<double>(tours.edges.size());
}
BENCHMARK(BM_TrimToursThickness)->Unit(benchmark::kMillisecond);

/// Plans the part's toolpath once per iteration; returns the last one (its points counted).
Toolpath timePlanning(benchmark::State& state, const Bunny& part, const ToolpathOptions& options) {
  Toolpath p;
  for (auto _ : state) {
    p = planToolpath(part.lattice, part.tree, part.order, options);
    benchmark::DoNotOptimize(p.points.data());
  }
  state.counters["points"] = static_cast<double>(p.points.size());
  return p;
}

/// Argument 0: the paper's axes (no clearance, only its detection pass); 1: the axis clearance.
void BM_PlanToolpath(benchmark::State& state) {
  ToolpathOptions options;
  options.clearance.maxTiltDeg = state.range(0) ? 15.0 : 0.0;
  const Toolpath p = timePlanning(state, bunny(), options);
  state.counters["print_mm"] = p.printLength;
  state.counters["perimeter_mm"] = p.perimeterLength;
  state.counters["air_mm"] = p.airLength;
  state.counters["retractions"] = p.retractions;
  state.counters["split"] = p.splitSubgraphs;
  state.counters["crossings"] = p.crossings;
  double sum = 0;
  int n = 0;
  for (const auto& l : p.thicknessStats.perLayer) {
    sum += l.mean * l.vertices;
    n += l.vertices;
  }
  state.counters["dev_min"] = p.thicknessStats.deviationMin;
  state.counters["dev_mean"] = n ? sum / n : 0.0;
  state.counters["dev_max"] = p.thicknessStats.deviationMax;
  state.counters["capped"] = p.thicknessStats.cappedVertices;
  state.counters["colliding_along_normal"] = p.collidingStations;
  state.counters["tilted"] = p.tiltedStations;
  state.counters["uncleared"] = p.unclearedStations;
  state.counters["max_tilt_deg"] = p.maxAxisTiltDeg;
  state.counters["inserted"] = p.subdivisionPoints;
}
BENCHMARK(BM_PlanToolpath)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

/// topopt at 80 mm under a 30° nozzle (tet edge 2 mm, lattice 4 mm, the rollout order): 47
/// stations collide after the axis clearance, in few enough tours that they are planned again
/// in the other ways (toolpath/TourWays.h). Argument 0: tour ways off; 1: on (the default).
void BM_PlanToolpathTourWays(benchmark::State& state) {
  static const Bunny part = [] {
    fixtures::CoreStageOptions o;
    o.edgeLength = 2.0;
    o.latticeWidth = 4.0;
    fixtures::CoreStages stages =
        fixtures::runCoreStages(fixtures::scaledModel("topopt_new4_surf.obj", 80, true), o);
    Bunny r;
    r.lattice = std::move(stages.lattice);
    r.tree = std::move(stages.tree);
    const MaterialSamples m = sampleLatticeMaterial(r.lattice, 1.0);
    NozzleModel n;
    n.halfAngleDeg = 30;
    const PotentialCollisions pcg = computePotentialCollisions(m, n);
    SequenceOptions so;
    so.strategy = SequenceStrategy::Rollout;
    r.order = sequencePrint(r.tree, m, &pcg, so).order;
    return r;
  }();
  ToolpathOptions options;
  options.nozzle.halfAngleDeg = 30;
  options.retryTourWays = state.range(0) != 0;
  const Toolpath p = timePlanning(state, part, options);
  state.counters["uncleared"] = p.unclearedStations;
  state.counters["reordered_tours"] = p.reorderedTours;
}
BENCHMARK(BM_PlanToolpathTourWays)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_BuildTimedPointTree(benchmark::State& state) {
  const int n = 470000;
  std::vector<Vec3> points(n);
  std::vector<int> time(n);
  for (int i = 0; i < n; ++i) {  // 300 turns of a 40 mm helix, 0.3 mm apart along the path
    const double a = 2 * M_PI * 300.0 * i / n;
    points[i] = Vec3(40 * std::cos(a), 40 * std::sin(a), 120.0 * i / n);
    time[i] = i;
  }
  for (auto _ : state) {
    const TimedPointTree tree(points, time);
    benchmark::DoNotOptimize(tree.pointAt(0));
  }
  state.counters["points"] = n;
}
BENCHMARK(BM_BuildTimedPointTree)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
