// Meshing a large closed surface (issue 19, point 5): a torus of 1,000,000 triangles (80 mm
// across, a scan-like resolution of ~0.25 mm) through tetrahedralizeSurface with the automatic
// edge length (~75k tets). The surface is first simplified to the target edge length
// (core/mesh/SurfaceSimplification), then given to TetGen. Counters: the tets, the triangles
// TetGen got, the largest input-vertex distance to the simplified surface (mm) and the time of
// the simplification. Also the tet adjacency (TetMeshTopology: built by the mesh check, the GDF,
// the overhang and the skeleton stages) of a 1.04M-tet block with shuffled vertex ids, as a
// TetGen mesh numbers them. Run: build/bin/bench_mesh (results in docs/performance.md).
#include "mesh/AnalyticShapes.h"
#include "mesh/TetMeshTopology.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <exception>
#include <numeric>
#include <random>
#include <vector>

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

void BM_TetMeshTopologyMillionTets(benchmark::State& state) {
  TetMesh mesh = boxTetMesh(Vec3(100, 100, 100), 56, 56, 56 - 1);  // 1,034,880 tets
  std::vector<int> relabel(mesh.points.size());
  std::iota(relabel.begin(), relabel.end(), 0);
  std::shuffle(relabel.begin(), relabel.end(), std::mt19937(1));
  for (auto& tet : mesh.tets) {
    for (int& v : tet) {
      v = relabel[v];
    }
  }
  size_t boundary = 0;
  for (auto _ : state) {
    const TetMeshTopology topology(mesh);
    boundary = topology.boundaryFaces().size();
    benchmark::DoNotOptimize(boundary);
  }
  state.counters["tets"] = static_cast<double>(mesh.tets.size());
  state.counters["boundary_faces"] = static_cast<double>(boundary);
}
BENCHMARK(BM_TetMeshTopologyMillionTets)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
