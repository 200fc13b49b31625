// Printing sequences on the three-branch tree (paper Section 3.1, Table 3, Figs. 26-27): the part
// of testdata/three_branch_tree.obj scaled by 1.5 (81 mm tall, ~150 layers at 0.6 mm like the
// paper's 151), tetrahedralized by TetGen (~75k tets), heat-method GDF, lattice width 4 mm.
//  - `bench_sequence --table` prints the Table-3-style sweep (strategy x nozzle angle: retractions,
//    air-move length, collision-free by the independent verifier, seconds) as Markdown.
//  - Without --table: Google Benchmark timings of PCG (Algorithm 3) + A4 (Algorithm 4), of the
//    rollout order, and of the verifier, per nozzle angle; and of the verifier on long bars printed
//    layer by layer over the build plate.
#include "../tests/common/CoreStages.h"
#include "collision/CollisionVerifier.h"
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "io/MeshReader.h"
#include "lattice/LatticeInfill.h"
#include "nozzle/BuildPlate.h"
#include "nozzle/Printhead.h"
#include "sequence/PotentialCollisions.h"
#include "sequence/PrintMaterial.h"
#include "sequence/PrintSequencer.h"
#include "skeleton/SkeletonTree.h"
#include "slicer/CurvedLayerSlicer.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <string>

using namespace geolattice;

namespace {

struct TreePart {
  size_t tets = 0;
  int layers = 0;
  LatticeGraph lattice;
  SkeletonTree tree;
  MaterialSamples material;
  double skeletonSeconds = 0;
};

const TreePart& threeBranchPart() {
  static const TreePart part = [] {
    TreePart p;
    TriangleSurface s = readObj(std::string(GEOLATTICE_TESTDATA) + "/three_branch_tree.obj");
    for (Vec3& q : s.points) {
      q *= 1.5;
    }
    const TetMesh mesh = tetrahedralizeSurface(s, TetrahedralizeOptions{}).mesh;
    p.tets = mesh.tets.size();
    fixtures::CoreStageOptions o;
    o.until = fixtures::CoreStage::Lattice;
    fixtures::CoreStages stages = fixtures::runCoreStages(mesh, o);
    p.layers = static_cast<int>(stages.layers.layerValues.size());
    p.lattice = std::move(stages.lattice);
    const auto t0 = std::chrono::steady_clock::now();
    p.tree = buildSkeletonTree(stages.mesh, stages.fields.gamma, p.lattice);
    p.skeletonSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    p.material = sampleLatticeMaterial(p.lattice, 1.0);
    return p;
  }();
  return part;
}

double nozzleLength() {
  const char* e = std::getenv("GL_NOZZLE_LENGTH");
  return e ? std::atof(e) : std::numeric_limits<double>::infinity();
}

NozzleModel cone(double deg) {
  NozzleModel n;
  n.halfAngleDeg = deg;
  n.length = nozzleLength();
  return n;
}

/// Verifies the order; obstacles from a skeleton ancestor of the station's sub-graph (printed
/// first in every order) are reported as unavoidable.
CollisionReport verify(const TreePart& p, const PrintSequence& s, const NozzleModel& n) {
  std::vector<int> time(p.material.points.size());
  for (size_t i = 0; i < time.size(); ++i) {
    time[i] = s.printIndex[p.material.subgraph[i]];
  }
  static const SkeletonAncestry ancestry(p.tree);
  CollisionExemption exemption;
  exemption.group = p.material.subgraph;
  exemption.unavoidable = [&](int station, int obstacle) {
    return ancestry.isAncestor(obstacle, station);
  };
  return verifyNozzleClearance(p.material.points, p.material.normals, time, n, 20, &exemption);
}

void printTable() {
  const TreePart& p = threeBranchPart();
  std::printf(
      "Three-branch tree x1.5: %zu tets, %d layers, %zu sub-graphs, %zu material samples (1 mm), "
      "skeleton %zu edges (%d split, %d merge nodes) in %.3f s\n\n",
      p.tets, p.layers, p.tree.nodes.size(), p.material.points.size(), p.tree.edges.size(),
      p.tree.splitNodes, p.tree.mergeNodes, p.skeletonSeconds);
  std::printf(
      "| Strategy | NA | Retractions | Air-move length (mm) | Collision-free order (verifier) | "
      "Unavoidable stations | PCG pairs | Forced steps | Seconds |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (double na : {75.0, 60.0, 45.0, 30.0, 15.0, 1.0}) {
    const NozzleModel n = cone(na);
    const PotentialCollisions pcg = computePotentialCollisions(p.material, n);
    for (SequenceStrategy st : {SequenceStrategy::LayerPriority, SequenceStrategy::DepthPriority,
                                SequenceStrategy::Greedy, SequenceStrategy::Rollout}) {
      SequenceOptions o;
      o.strategy = st;
      const bool usesPcg = st == SequenceStrategy::Greedy || st == SequenceStrategy::Rollout;
      const PrintSequence s = sequencePrint(p.tree, p.material, usesPcg ? &pcg : nullptr, o);
      const CollisionReport r = verify(p, s, n);
      char pcgText[32] = "-";
      if (usesPcg) {
        std::snprintf(pcgText, sizeof pcgText, "%lld", pcg.pairs);
      }
      const long long orderStations = r.violatingStations - r.unavoidableStations;
      std::printf("| %s | %.0f° | %d | %.0f | %s | %lld | %s | %d | %.3f |\n",
                  sequenceStrategyName(st), na, s.retractions, s.airLength,
                  r.orderCollisionFree
                      ? "yes"
                      : ("**no** (" + std::to_string(orderStations) + " stations)").c_str(),
                  r.unavoidableStations, pcgText, s.forcedSteps,
                  s.seconds + (usesPcg ? pcg.seconds : 0.0));
    }
  }
}

void BM_PcgAndA4(benchmark::State& state) {
  const TreePart& p = threeBranchPart();
  const NozzleModel n = cone(static_cast<double>(state.range(0)));
  SequenceOptions o;
  o.strategy = SequenceStrategy::Greedy;
  PrintSequence s;
  long long pairs = 0;
  for (auto _ : state) {
    const PotentialCollisions pcg =
        computePotentialCollisions(p.material, n, static_cast<int>(state.range(1)));
    s = sequencePrint(p.tree, p.material, &pcg, o);
    pairs = pcg.pairs;
  }
  state.counters["subgraphs"] = static_cast<double>(p.tree.nodes.size());
  state.counters["pcg_pairs"] = static_cast<double>(pairs);
  state.counters["retractions"] = s.retractions;
}
BENCHMARK(BM_PcgAndA4)
    ->ArgNames({"NA", "threads"})
    ->Args({75, 1})
    ->Args({45, 1})
    ->Args({15, 1})
    ->Args({45, 2})
    ->Unit(benchmark::kMillisecond);

/// The potential collision graph alone (one thread): the 45° cone (0) or the example printhead
/// (1, testdata/printhead_slim.obj), whose time the issue wants within 2x of the cone's.
void BM_Pcg(benchmark::State& state) {
  const TreePart& p = threeBranchPart();
  NozzleModel n = cone(45);
  if (state.range(0) == 1) {
    n.printhead = std::make_shared<const Printhead>(
        readObj(std::string(GEOLATTICE_TESTDATA) + "/printhead_slim.obj"), "printhead_slim.obj");
  }
  PotentialCollisions pcg;
  for (auto _ : state) {
    pcg = computePotentialCollisions(p.material, n, 1);
  }
  state.counters["pcg_pairs"] = static_cast<double>(pcg.pairs);
  state.counters["leaf_tests"] = static_cast<double>(pcg.leafTests);
}
BENCHMARK(BM_Pcg)->ArgName("printhead")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_Rollout(benchmark::State& state) {
  const TreePart& p = threeBranchPart();
  const NozzleModel n = cone(static_cast<double>(state.range(0)));
  const PotentialCollisions pcg = computePotentialCollisions(p.material, n);
  SequenceOptions o;
  o.strategy = SequenceStrategy::Rollout;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sequencePrint(p.tree, p.material, &pcg, o).order.data());
  }
}
BENCHMARK(BM_Rollout)->ArgName("NA")->Arg(75)->Arg(45)->Unit(benchmark::kMillisecond);

void BM_Verifier(benchmark::State& state) {
  const TreePart& p = threeBranchPart();
  const NozzleModel n = cone(static_cast<double>(state.range(0)));
  SequenceOptions o;
  o.strategy = SequenceStrategy::LayerPriority;
  const PrintSequence s = sequencePrint(p.tree, p.material, nullptr, o);
  for (auto _ : state) {
    benchmark::DoNotOptimize(verify(p, s, n).violatingStations);
  }
  state.counters["stations"] = static_cast<double>(p.material.points.size());
}
BENCHMARK(BM_Verifier)->ArgName("NA")->Arg(75)->Arg(45)->Unit(benchmark::kMillisecond);

/// A long bar printed layer by layer over the build plate, as the generated 240 mm bar of
/// docs/performance.md: `length` x 16 mm, 60 layers 0.6 mm apart, a point per mm, one sub-graph
/// per layer whose ancestors are the layers below. Every nozzle axis leans 50° along the bar, so
/// each 45° cone reaches the plate and holds thousands of points of the layers below: exempt
/// material the verifier must look past for anything an order could have kept out.
void BM_VerifierLongBarOverThePlate(benchmark::State& state) {
  const int length = static_cast<int>(state.range(0));
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<int> time;
  const double tilt = 50 * M_PI / 180;
  for (int layer = 0; layer < 60; ++layer) {
    for (int x = 0; x <= length; ++x) {
      for (int y = 0; y <= 16; ++y) {
        points.emplace_back(x, y, 0.3 + 0.6 * layer);
        normals.emplace_back(std::sin(tilt), 0, std::cos(tilt));
        time.push_back(layer);
      }
    }
  }
  CollisionExemption exemption;
  exemption.group = time;
  exemption.unavoidable = [](int station, int obstacle) {
    return obstacle < station;
  };
  const BuildPlate plate;
  long long plateStations = 0;
  for (auto _ : state) {
    plateStations =
        verifyNozzleClearance(points, normals, time, cone(45), 20, &exemption, nullptr, &plate)
            .plateStations;
  }
  state.counters["stations"] = static_cast<double>(points.size());
  state.counters["plate_stations"] = static_cast<double>(plateStations);
}
BENCHMARK(BM_VerifierLongBarOverThePlate)
    ->ArgName("mm")
    ->Arg(240)
    ->Arg(720)
    ->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--table") == 0) {
      printTable();
      return 0;
    }
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
