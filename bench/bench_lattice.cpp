// Lattice infill graphs (core/lattice, paper Section 2.2, Algorithm 1) of all curved layers of
// the bunny scaled to 100 mm, tetrahedralized by TetGen to ~66k tets (the paper's bunny size),
// 0.6 mm layers, fields from the heat-method GDF. Arguments: lattice width (mm), threads.
// Run: build/bin/bench_lattice
#include "../tests/common/CoreStages.h"
#include "lattice/LatticeInfill.h"

#include <benchmark/benchmark.h>

#include <string>

using namespace geolattice;

namespace {

const CurvedLayers& bunnyLayers() {
  static const CurvedLayers layers = fixtures::paperBunny(fixtures::CoreStage::Layers).layers;
  return layers;
}

void BM_LatticeAllLayers(benchmark::State& state) {
  const CurvedLayers& layers = bunnyLayers();
  LatticeOptions options;
  options.alphaWidth = options.betaWidth = static_cast<double>(state.range(0));
  options.threads = static_cast<int>(state.range(1));
  LatticeGraph g;
  for (auto _ : state) {
    g = buildLatticeGraph(layers, options);
    benchmark::DoNotOptimize(g.points.data());
  }
  state.counters["layers"] = static_cast<double>(layers.layerValues.size());
  state.counters["triangles"] = static_cast<double>(layers.triangles.size());
  state.counters["vertices"] = static_cast<double>(g.points.size());
  state.counters["edges"] = static_cast<double>(g.edges.size());
  state.counters["crossings"] = g.stats.crossings;
  state.counters["subgraphs"] = static_cast<double>(g.subgraphs.size());
  state.counters["irregular"] = g.stats.irregularVertices;
}
BENCHMARK(BM_LatticeAllLayers)
    ->ArgNames({"width_mm", "threads"})
    ->Args({6, 1})
    ->Args({6, 2})
    ->Args({2, 2})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
