// Lattice infill graphs (core/lattice, paper Section 2.2, Algorithm 1) of all curved layers of
// the bunny scaled to 100 mm, tetrahedralized by TetGen to ~66k tets (the paper's bunny size),
// 0.6 mm layers, fields from the heat-method GDF. Arguments: lattice width (mm), threads.
// Run: build/bin/bench_lattice
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "io/MeshReader.h"
#include "lattice/LatticeInfill.h"
#include "slicer/CurvedLayerSlicer.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <benchmark/benchmark.h>

#include <string>

using namespace geolattice;

namespace {

const CurvedLayers& bunnyLayers() {
  static const CurvedLayers layers = [] {
    TriangleSurface s = readObj(std::string(GEOLATTICE_TESTDATA) + "/bunny.obj");
    Eigen::AlignedBox3d box;
    for (const Vec3& p : s.points) {
      box.extend(p);
    }
    const double scale = 100.0 / box.sizes().maxCoeff();
    for (Vec3& p : s.points) {
      p = (p - box.min()) * scale;
    }
    TetrahedralizeOptions options;
    options.autoTargetTets = 66000;
    const TetMesh mesh = tetrahedralizeSurface(s, options).mesh;
    const GeodesicFields fields =
        computeGeodesicDistanceFields(mesh, sourcesNearLowestZ(mesh, 1.0));
    return sliceCurvedLayers(mesh, fields.gamma, fields.alpha, fields.beta,
                             vertexGradientDirections(mesh, fields.gamma), SlicerOptions{});
  }();
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
