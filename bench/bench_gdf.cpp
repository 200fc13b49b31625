// Benchmark of the geodesic-distance-field stage (paper Section 2.1, Eqs. 1-5): set-up
// (FEM assembly + factorizations) and solve (heat step, three Poisson solves) of γ, α, β on the
// Stanford bunny scaled to 100 mm, tetrahedralized by TetGen at ~13k, ~66k, ~100k and ~1M tets,
// with CHOLMOD (supernodal) and Eigen's SimplicialLDLT. Results: docs/performance.md.
//
// Data flow: testdata/bunny.obj -> scale (largest extent 100 mm) -> tetrahedralizeSurface
// (cached as .tet under GEOLATTICE_BENCH_CACHE) -> sourcesNearLowestZ (base) ->
// GeodesicDistanceFields(mesh) + solve(sources), timed per iteration (manual time).
//
// Counters per run: tets, vertices, sources, the assembly / factorization / solve split of
// GeodesicFields::timings (s, mean over iterations), peak_MiB: peak resident memory of the GDF
// computation above the resident size just before it (mesh already loaded; from
// /proc/self/status VmHWM after resetting it through /proc/self/clear_refs, or the process's
// ru_maxrss where that is not permitted), and the orthogonality of the solved fields (median and
// 95th percentile of |90° - angle(∇α, ∇γ)| and of (∇β, ∇γ), degrees).
//
// Extra command-line use (before the Google Benchmark flags):
//   bench_gdf --tet-count=<edge mm>   tetrahedralizes the bunny at that target edge length and
//                                     prints the tet and vertex counts (to pick the sizes).
#include "common/Error.h"
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "io/MeshReader.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <benchmark/benchmark.h>
#include <malloc.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <sys/stat.h>

using namespace geolattice;

namespace {

/// Base selection: vertices within this height (mm) of the lowest point of the 100 mm bunny.
constexpr double kSourceToleranceMm = 0.5;
/// The bunny is scaled so that its largest bounding-box extent is this long (mm).
constexpr double kModelSizeMm = 100.0;

/// One mesh size: label, TetGen target edge length (mm) and radius-edge ratio bound, found by
/// trying (`--tet-count`) to give about that many tets on the 100 mm bunny. The 3674-triangle
/// surface alone needs ~45k tets at the default ratio 1.414 whatever the edge length, so the
/// smallest size relaxes the quality bound to 10 (13.5k tets, the fewest TetGen makes from it).
struct MeshSize {
  const char* label;
  double edgeLengthMm;
  double radiusEdgeRatio;
};
constexpr MeshSize kSizes[] = {
    {"13k", 40.0, 10.0},   // 13508 tets, 5017 vertices
    {"66k", 7.5, 1.414},   // 65842 tets, 15456 vertices
    {"100k", 5.0, 1.414},  // 102232 tets, 23008 vertices
    {"1M", 1.62, 1.414},   // 989619 tets, 182606 vertices
};

/// Minimal Wavefront OBJ reader: `v x y z` and `f a b c ...` lines (indices 1-based or negative,
/// `a/t/n` forms accepted, polygons fan-triangulated); everything else is ignored.
TriangleSurface readObj(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    throw GeoLatticeError(path + ": cannot open");
  }
  TriangleSurface s;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v") {
      Vec3 p;
      if (!(ls >> p.x() >> p.y() >> p.z())) {
        throw GeoLatticeError(path + ":" + std::to_string(lineNo) + ": malformed vertex line");
      }
      s.points.push_back(p);
    } else if (tag == "f") {
      std::vector<int> face;
      std::string token;
      while (ls >> token) {
        const long i = std::strtol(token.c_str(), nullptr, 10);
        const long n = static_cast<long>(s.points.size());
        const long index = i > 0 ? i - 1 : n + i;
        if (i == 0 || index < 0 || index >= n) {
          throw GeoLatticeError(path + ":" + std::to_string(lineNo) + ": face index '" + token +
                                "' out of range");
        }
        face.push_back(static_cast<int>(index));
      }
      if (face.size() < 3) {
        throw GeoLatticeError(path + ":" + std::to_string(lineNo) +
                              ": face with fewer than 3 vertices");
      }
      for (size_t k = 1; k + 1 < face.size(); ++k) {
        s.triangles.push_back({face[0], face[k], face[k + 1]});
      }
    }
  }
  if (s.points.empty() || s.triangles.empty()) {
    throw GeoLatticeError(path + ": no vertices or faces");
  }
  return s;
}

TriangleSurface scaledBunny() {
  TriangleSurface s = readObj(std::string(GEOLATTICE_TESTDATA) + "/bunny.obj");
  Eigen::AlignedBox3d box;
  for (const Vec3& p : s.points) {
    box.extend(p);
  }
  const double scale = kModelSizeMm / box.sizes().maxCoeff();
  for (Vec3& p : s.points) {
    p = (p - box.min()) * scale;
  }
  return s;
}

std::string cacheDir() {
  const char* env = std::getenv("GEOLATTICE_BENCH_CACHE");
  return env && *env ? env : GEOLATTICE_BENCH_CACHE;
}

/// The bunny at the given size, from the .tet cache or TetGen (then cached).
const TetMesh& bunnyMesh(const MeshSize& size) {
  static std::map<std::string, TetMesh> meshes;
  auto it = meshes.find(size.label);
  if (it != meshes.end()) {
    return it->second;
  }
  const std::string dir = cacheDir();
  ::mkdir(dir.c_str(), 0755);
  char name[64];
  std::snprintf(name, sizeof name, "/bunny100mm_L%.4f_q%.3f.tet", size.edgeLengthMm,
                size.radiusEdgeRatio);
  const std::string path = dir + name;
  TetMesh mesh;
  if (std::ifstream(path).good()) {
    mesh = readTetFile(path);
  } else {
    TetrahedralizeOptions options;
    options.targetEdgeLength = size.edgeLengthMm;
    options.radiusEdgeRatio = size.radiusEdgeRatio;
    mesh = tetrahedralizeSurface(scaledBunny(), options).mesh;
    writeTetFile(path, mesh);
  }
  return meshes.emplace(size.label, std::move(mesh)).first->second;
}

long statusKb(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const size_t n = std::strlen(key);
  while (std::getline(in, line)) {
    if (line.compare(0, n, key) == 0 && line.size() > n && line[n] == ':') {
      return std::strtol(line.c_str() + n + 1, nullptr, 10);
    }
  }
  return -1;
}

/// Resets VmHWM to the current resident size (Linux >= 4.0); false if not permitted.
bool resetPeakRss() {
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return out.good();
}

long maxRssKb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

void benchGdf(benchmark::State& state, MeshSize size, CholeskyBackend backend) {
  const TetMesh& mesh = bunnyMesh(size);
  const std::vector<int> sources = sourcesNearLowestZ(mesh, kSourceToleranceMm);
  GeodesicFieldOptions options;
  options.backend = backend;

  GeodesicFieldTimings sum;
  GeodesicFields fields;
  double peakMiB = 0;
  for (auto _ : state) {
    fields = GeodesicFields{};
    TetMesh copy = mesh;  // the solver takes the mesh by value; copy outside the timed part
    malloc_trim(0);       // hand freed heap back, so the baseline below is what is really in use
    const long before = statusKb("VmRSS");
    const bool peakReset = resetPeakRss();
    const auto start = std::chrono::steady_clock::now();
    GeodesicDistanceFields gdf(std::move(copy), options);
    fields = gdf.solve(sources);
    state.SetIterationTime(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    const long peak = peakReset ? statusKb("VmHWM") : maxRssKb();
    peakMiB = std::max(peakMiB, static_cast<double>(peak - before) / 1024.0);
    sum.assembly += fields.timings.assembly;
    sum.factorization += fields.timings.factorization;
    sum.solve += fields.timings.solve;
  }
  using benchmark::Counter;
  state.counters["tets"] = static_cast<double>(mesh.tets.size());
  state.counters["verts"] = static_cast<double>(mesh.points.size());
  state.counters["sources"] = static_cast<double>(sources.size());
  state.counters["assembly_s"] = Counter(sum.assembly, Counter::kAvgIterations);
  state.counters["factor_s"] = Counter(sum.factorization, Counter::kAvgIterations);
  state.counters["solve_s"] = Counter(sum.solve, Counter::kAvgIterations);
  state.counters["peak_MiB"] = peakMiB;
  state.counters["ag_med_deg"] = fields.orthogonalityDeviationDeg[0];
  state.counters["ag_p95_deg"] = fields.orthogonalityDeviationDeg[1];
  state.counters["bg_med_deg"] = fields.orthogonalityDeviationDeg[2];
  state.counters["bg_p95_deg"] = fields.orthogonalityDeviationDeg[3];
}

/// The BLAS library CHOLMOD's supernodal factorization runs on (as mapped into this process;
/// Debian selects it with update-alternatives), e.g. .../openblas-pthread/libblas.so.3.
std::string loadedBlas() {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line)) {
    const size_t slash = line.find('/');
    if (slash != std::string::npos && line.find("blas", slash) != std::string::npos) {
      return line.substr(slash);
    }
  }
  return "none loaded";
}

int printTetCount(const char* arg) {
  char* end = nullptr;
  const double edge = std::strtod(arg, &end);
  TetrahedralizeOptions options;
  if (end != arg && *end == ',') {
    options.radiusEdgeRatio = std::strtod(end + 1, &end);
  }
  if (end == arg || *end != '\0' || !(edge > 0)) {
    std::cerr
        << "--tet-count needs a positive edge length in mm, optionally ',<radius-edge ratio>'\n";
    return 2;
  }
  options.targetEdgeLength = edge;
  const TetrahedralizeResult r = tetrahedralizeSurface(scaledBunny(), options);
  std::cout << "edge " << edge << " mm, ratio " << options.radiusEdgeRatio << ": " << r.tetCount
            << " tets, " << r.mesh.points.size() << " vertices, mean edge " << r.meanEdgeLength
            << " mm, " << sourcesNearLowestZ(r.mesh, kSourceToleranceMm).size()
            << " sources, TetGen " << r.seconds << " s\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--tet-count=", 12) == 0) {
      try {
        return printTetCount(argv[i] + 12);
      } catch (const GeoLatticeError& e) {
        std::cerr << e.what() << "\n";
        return 1;
      }
    }
  }
  for (const MeshSize& size : kSizes) {
    for (CholeskyBackend backend : {CholeskyBackend::Cholmod, CholeskyBackend::EigenLDLT}) {
      // Eigen's simplicial LDL^T needs minutes at ~1M tets (see docs/performance.md).
      if (backend == CholeskyBackend::EigenLDLT && std::strcmp(size.label, "1M") == 0) {
        continue;
      }
      const std::string name = std::string("GDF/bunny_") + size.label +
                               (backend == CholeskyBackend::Cholmod ? "/cholmod" : "/eigen_ldlt");
      benchmark::RegisterBenchmark(name.c_str(), benchGdf, size, backend)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond)
          ->MinTime(2.0);
    }
  }
  benchmark::AddCustomContext("blas", loadedBlas());
  const char* blasThreads = std::getenv("OPENBLAS_NUM_THREADS");
  benchmark::AddCustomContext("OPENBLAS_NUM_THREADS", blasThreads ? blasThreads : "unset");
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
    return 1;
  }
  try {
    benchmark::RunSpecifiedBenchmarks();
  } catch (const GeoLatticeError& e) {
    std::cerr << "bench_gdf: " << e.what() << "\n";
    return 1;
  }
  benchmark::Shutdown();
  return 0;
}
