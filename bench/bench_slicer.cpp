// Curved layer slicing (core/slicer) on the bunny scaled to 100 mm and tetrahedralized by TetGen
// to ~66k tets (the paper's bunny size), 0.6 mm layers. Fields from the heat-method GDF.
// Run: build/bin/bench_slicer ; results in docs/performance.md.
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "io/MeshReader.h"
#include "slicer/CurvedLayerSlicer.h"
#include "slicer/LayerStatistics.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <benchmark/benchmark.h>

#include <string>

using namespace geolattice;

namespace {

struct Part {
  TetMesh mesh;
  GeodesicFields fields;
  std::vector<Vec3> normals;
};

const Part& bunny66k() {
  static const Part part = [] {
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
    Part out;
    out.mesh = tetrahedralizeSurface(s, options).mesh;
    out.fields = computeGeodesicDistanceFields(out.mesh, sourcesNearLowestZ(out.mesh, 1.0));
    out.normals = vertexGradientDirections(out.mesh, out.fields.gamma);
    return out;
  }();
  return part;
}

void BM_SliceAllLayers(benchmark::State& state) {
  const Part& part = bunny66k();
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
  const Part& part = bunny66k();
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
