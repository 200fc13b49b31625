// The orientation search (core/orient/AutoOrient.h) on the bundled models at their usual print
// sizes: ~100 sphere candidates + the convex-hull facets + as placed, each evaluated with the
// real stages on a ~15k-tet mesh (nozzle 45°, the build plate an obstacle).
//  - `bench_orient --table [MODEL.obj SIZE_MM ...]` prints, per model, the time and the scores of
//    the part as placed and of the chosen orientation (docs/performance.md).
//  - Without --table: Google Benchmark timing of the search on the bunny at 80 mm.
#include "io/MeshReader.h"
#include "orient/AutoOrient.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace geolattice;

namespace {

TriangleSurface load(const std::string& file, double size) {
  const std::string path =
      file.find('/') == std::string::npos ? std::string(GEOLATTICE_TESTDATA) + "/" + file : file;
  TriangleSurface s =
      path.size() > 4 && path.substr(path.size() - 4) == ".off" ? readOff(path) : readObj(path);
  Vec3 lo = s.points[0], hi = s.points[0];
  for (const Vec3& p : s.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double scale = size > 0 ? size / (hi - lo).maxCoeff() : 1.0;
  for (Vec3& p : s.points) {
    p = scale * (p - Vec3(0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()), lo.z()));
  }
  return s;
}

void printRow(const char* name, const OrientResult& r) {
  const OrientCandidate& keep = r.candidates[0];
  const OrientCandidate& best = r.candidates[r.best];
  int evaluated = 0;
  for (const OrientCandidate& c : r.candidates) {
    evaluated += c.evaluated;
  }
  std::printf(
      "| %s | %zu (%d evaluated) | %d | %.1f | %lld (%lld plate) / %lld, %d forced, "
      "%.1f mm² | %s (%.2f, %.2f, %.2f) | %lld (%lld plate) / %lld, %d forced, %.1f mm², "
      "overhang %.3f |\n",
      name, r.candidates.size(), evaluated, r.evaluationTets, r.seconds, keep.collidingStations,
      keep.plateStations, keep.stations, keep.forcedSteps, keep.baseArea, best.source.c_str(),
      best.down.x(), best.down.y(), best.down.z(), best.collidingStations, best.plateStations,
      best.stations, best.forcedSteps, best.baseArea, best.overhangFraction);
  if (std::getenv("GEOLATTICE_ORIENT_ALL")) {
    for (const OrientCandidate& c : r.candidates) {
      if (c.evaluated) {
        std::printf(
            "  rank %3d %-6s down (%5.2f %5.2f %5.2f) base %6.1f colliding %6lld plate %6lld "
            "forced %3d overhang %.3f layers %d  %.2f s %s\n",
            c.rank, c.source.c_str(), c.down.x(), c.down.y(), c.down.z(), c.baseArea,
            c.collidingStations, c.plateStations, c.forcedSteps, c.overhangFraction, c.layers,
            c.seconds, c.error.c_str());
      }
    }
  }
  std::fflush(stdout);
}

void BM_OrientBunny(benchmark::State& state) {
  const TriangleSurface s = load("bunny.obj", 80);
  for (auto _ : state) {
    benchmark::DoNotOptimize(searchOrientation(s, OrientOptions{}).best);
  }
}
BENCHMARK(BM_OrientBunny)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && !std::strcmp(argv[1], "--table")) {
    std::vector<std::pair<std::string, double>> models;
    for (int i = 2; i + 1 < argc; i += 2) {
      models.emplace_back(argv[i], std::atof(argv[i + 1]));
    }
    if (models.empty()) {
      models = {{"bunny.obj", 80},
                {"spot.obj", 80},
                {"decimated-knight.off", 60},
                {"topopt_new4_surf.obj", 0},
                {"y_shape.obj", 0},
                {"three_branch_tree.obj", 81},
                {"cube.obj", 30},
                {"ring_surf.obj", 0}};
    }
    std::printf(
        "| model | candidates | eval tets | seconds | as placed: colliding / stations, "
        "forced, base | chosen (down) | chosen: colliding / stations, forced, base |\n"
        "|---|---|---|---|---|---|---|\n");
    for (const auto& [file, size] : models) {
      try {
        OrientOptions o;
        if (const char* a = std::getenv("GEOLATTICE_ORIENT_MIN_BASE")) {
          o.minBaseArea = std::atof(a);
        }
        if (const char* n = std::getenv("GEOLATTICE_ORIENT_CANDIDATES")) {
          o.sphereCandidates = std::atoi(n);
          o.hullCandidates = std::min(o.hullCandidates, o.sphereCandidates);
        }
        printRow(file.c_str(), searchOrientation(load(file, size), o));
      } catch (const std::exception& e) {
        std::printf("| %s | error: %s |\n", file.c_str(), e.what());
      }
    }
    return 0;
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
