// Curved layer slicing (core/slicer) on the bunny scaled to 100 mm and tetrahedralized by TetGen
// to ~66k tets (the paper's bunny size), 0.6 mm layers. Fields from the heat-method GDF.
// Run: build/bin/bench_slicer ; results in docs/performance.md.
#include "../tests/common/CoreStages.h"
#include "slicer/CurvedLayerSlicer.h"
#include "slicer/LayerStatistics.h"

#include <benchmark/benchmark.h>

#include <string>

using namespace geolattice;

namespace {

/// The bunny at 100 mm, ~66k tets, and its fields (base: 1 mm above the lowest z).
const fixtures::CoreStages& bunny66k() {
  static const fixtures::CoreStages part = fixtures::paperBunny(fixtures::CoreStage::Fields);
  return part;
}

void BM_SliceAllLayers(benchmark::State& state) {
  const fixtures::CoreStages& part = bunny66k();
  SlicerOptions options;  // 0.6 mm
  size_t triangles = 0, layers = 0;
  for (auto _ : state) {
    const std::vector<Vec3> normals = vertexGradientDirections(part.mesh, part.fields.gamma);
    const CurvedLayers result = sliceCurvedLayers(part.mesh, part.fields.gamma, part.fields.alpha,
                                                  part.fields.beta, normals, options);
    triangles = result.triangles.size();
    layers = result.layerValues.size();
    benchmark::DoNotOptimize(result.points.data());
  }
  state.counters["tets"] = static_cast<double>(part.mesh.tets.size());
  state.counters["layers"] = static_cast<double>(layers);
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_SliceAllLayers)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_LayerStatistics(benchmark::State& state) {
  const fixtures::CoreStages& part = bunny66k();
  const CurvedLayers layers = sliceCurvedLayers(part.mesh, part.fields.gamma, part.fields.alpha,
                                                part.fields.beta, part.normals, SlicerOptions{});
  for (auto _ : state) {
    benchmark::DoNotOptimize(computeLayerStatistics(layers).data());
  }
  state.counters["layers"] = static_cast<double>(layers.layerValues.size());
}
BENCHMARK(BM_LayerStatistics)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
