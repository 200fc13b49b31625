// Meshing a large closed surface (issue 19, point 5): a torus of 1,000,000 triangles (80 mm
// across, a scan-like resolution of ~0.25 mm) through tetrahedralizeSurface with the automatic
// edge length (~75k tets). The surface is first simplified to the target edge length
// (core/mesh/SurfaceSimplification), then given to TetGen. Counters: the tets, the triangles
// TetGen got, the largest input-vertex distance to the simplified surface (mm) and the time of
// the simplification. Run: build/bin/bench_mesh (results in docs/performance.md).
#include "mesh/AnalyticShapes.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <benchmark/benchmark.h>

#include <exception>

using namespace geolattice;

namespace {

void BM_MeshMillionTriangleTorus(benchmark::State& state) {
  const TriangleSurface torus = torusSurface(Vec3(0, 0, 40), 28, 12, 1000, 500);
  TetrahedralizeResult r;
  for (auto _ : state) {
    try {
      r = tetrahedralizeSurface(torus, TetrahedralizeOptions());
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      return;
    }
    benchmark::DoNotOptimize(r.tetCount);
  }
  state.counters["input_triangles"] = static_cast<double>(r.inputTriangles);
  state.counters["meshed_triangles"] = static_cast<double>(r.meshedTriangles);
  state.counters["tets"] = r.tetCount;
  state.counters["distance_mm"] = r.simplificationDistance;
  state.counters["simplify_s"] = r.simplificationSeconds;
  state.counters["tetgen_runs"] = r.attempts;
}
BENCHMARK(BM_MeshMillionTriangleTorus)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
