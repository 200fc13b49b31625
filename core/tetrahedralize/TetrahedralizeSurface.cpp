#include "tetrahedralize/TetrahedralizeSurface.h"

#include "mesh/OverlappingBodies.h"
#include "mesh/SurfaceSimplification.h"

#include "common/Error.h"
#include "common/Progress.h"
#include "mesh/SurfaceCheck.h"
#include "mesh/SurfaceRepair.h"
#include "mesh/TetMeshCheck.h"
#include "tetrahedralize/TetGenRunner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace geolattice {

namespace {

/// Share of the progress bar the surface simplification takes when it runs (it is most of the
/// time on a 1M-triangle surface: 27 s of 33 s).
constexpr double kSimplificationShare = 0.7;

// Mean tet volume over the bound "a" = L^3/(6 sqrt 2) with q1.414: ~0.5 on a 40x40x60 box,
// ~0.25 on the bunny at 100 mm (whose finely triangulated surface adds small tets). Measured at
// the first guess on the bundled parts near 75k tets (bunny, spot, knight, topopt, Y,
// three-branch): 0.17-0.24, median 0.21, so 0.21 is the first guess of the automatic edge
// length (0.4 overshot the count by about 2x, costing two or three more TetGen runs); 0.55
// (above every measured value) gives the smallest plausible count for the size guard.
constexpr double kGuessMeanTetVolumeOverBound = 0.21;
// Finer meshes hold a smaller share of the small tets the surface's own triangles force, so the
// ratio grows with the count: measured 0.26 (knight, 139k tets), 0.32 (spot, 475k), 0.35-0.39
// (bunny, 596k-897k), all at 100 mm, where 0.21 made the first run for a 1M-tet target give
// only 0.45-0.6 of it (and a second, larger run). Above kGuessCalibrationTets the first guess
// takes ratio = 0.21 * (N / 75k)^kGuessRatioExponent (0.22-0.34 fits those three parts; the low
// end is taken). At and below 75k (the default target) the guess is as before.
constexpr double kGuessCalibrationTets = 75000.0;
constexpr double kGuessRatioExponent = 0.22;
// log(count) / log(edge) near the target, for the first correction: -3 for a volume-filling
// mesh, measured -0.5 to -3.2 (median -1.6) on the parts above, flatter where the surface's own
// triangles drive the refinement. A first run with too many tets is refined by the surface
// (bunny -1.5, spot -0.9, topopt -1.8: kFirstSlopeOver); one with too few is not, and follows the
// volume law (ring -3.1, cube -2.9: kFirstSlopeUnder), so one correction reaches the target on
// every bundled part. Later corrections use the measured slope.
constexpr double kFirstSlopeOver = -1.6;
constexpr double kFirstSlopeUnder = -3.0;
// Where even the speculative run (kSpeculativeEdgeFactor) has too many tets, the surface drives
// the count and the slope is flatter still: measured between the first and the speculative run
// on the five such parts of 36 (spot -0.68, a generated arch -0.69, a cup -0.47, a helix -0.53,
// a trefoil knot -0.54). The first run, finer still, is then stopped unread: it would only have
// measured this slope (spot: 3 runs in 2.3 s before).
constexpr double kSecondSlopeOver = -0.6;
// TetGen runs on one edge length when its output is not a valid mesh (a flat sliver where
// boundary facets are nearly coplanar): the edge is changed by these factors and it runs again.
constexpr double kRetryEdgeFactors[] = {0.93, 1.07, 0.87, 1.15};
// A TetGen run's time limit: this much plus this much per expected tet (a 1M-tet mesh takes
// 9-11 s, so the limit is 5x its time; a 75k-tet one 1-3 s, limit 13 s).
constexpr double kTetGenBaseSeconds = 10.0;
constexpr double kTetGenSecondsPerTet = 40e-6;
// The unbounded run's (constrained Delaunay, "pAQ") limit: kTetGenBaseSeconds plus this much per
// surface triangle: it adds no point inside, so its time follows the surface (a 143,520-triangle
// thin ellipsoid: 3.6 s, 25 us per triangle; the limit is 5x that).
constexpr double kUnboundedSecondsPerTriangle = 125e-6;

constexpr double kLargestMeanTetVolumeOverBound = 0.55;
// Largest accepted relative difference between the winding-weighted tet volume and the
// enclosed (divergence-theorem) volume of the surface. Steiner points TetGen puts on finely
// curved facets move the volume by up to ~2e-5 relative (measured on generated parts of
// 12k triangles); overlapping parts or merged vertices change it by far more.
constexpr double kVolumeTolerance = 1e-3;
// The automatic search accepts a count within this factor of the target.
constexpr double kAutoTolerance = 1.25;
// The search stops above the target when a longer edge lowered the count with a slope
// (d log count / d log edge) flatter than this: -3 for a volume-filling mesh, -0.5 to -3.2 on
// the bundled parts (kFirstSlopeOver), -0.14 and 0 on a generated arch and a thin wall whose
// counts no edge length brings down.
constexpr double kSurfaceBoundSlope = -0.3;

double regularTetVolume(double edge) {
  return edge * edge * edge / (6.0 * std::sqrt(2.0));
}

std::string formatSwitchNumber(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.9g", value);
  return buffer;
}

double meanUniqueEdgeLength(const TetMesh& mesh) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(6 * mesh.tets.size());
  for (const auto& t : mesh.tets) {
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        edges.emplace_back(std::min(t[i], t[j]), std::max(t[i], t[j]));
      }
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  if (edges.empty()) {
    return 0.0;
  }
  double sum = 0.0;
  for (const auto& [a, b] : edges) {
    sum += (mesh.points[a] - mesh.points[b]).norm();
  }
  return sum / static_cast<double>(edges.size());
}

struct RegionSummary {
  int removedRegions = 0;      // regions with winding number 0 (cavities), dropped
  double windingVolume = 0.0;  // sum over all tets of winding number * volume (mm^3)
};

// TetGen meshes every bounded region enclosed by the facets, cavities of hollow parts
// included; switch "A" numbers the regions. Each region gets the winding number of the
// surface at one of its tet centroids (an integer: a centroid is never on the surface):
//   0: cavity, dropped with the vertices no remaining tet uses;
//   1: solid; >= 2: inside nested outward shells (e.g. an embedded interface surface), solid;
//   < 0: an inward shell outside every other shell: inconsistent input, rejected.
// The winding-weighted volume equals the divergence-theorem volume of the surface when the
// regions match the surface; the caller checks that.
RegionSummary classifyRegions(const TriangleSurface& surface, TetGenOutput& out) {
  RegionSummary summary;
  const bool numbered = out.regions.size() == out.mesh.tets.size();
  std::map<int, long> windingOf;  // region -> winding number
  std::vector<long> tetWinding(out.mesh.tets.size());
  for (size_t t = 0; t < out.mesh.tets.size(); ++t) {
    const int region = numbered ? out.regions[t] : 0;
    auto it = windingOf.find(region);
    if (it == windingOf.end()) {
      Vec3 centroid = Vec3::Zero();
      for (int v : out.mesh.tets[t]) {
        centroid += out.mesh.points[v] / 4.0;
      }
      it = windingOf.emplace(region, std::lround(windingNumber(surface, centroid))).first;
      if (it->second < 0) {
        throw GeoLatticeError(
            "inconsistently oriented shells: a region has winding number " +
            std::to_string(it->second) +
            " (an inward-oriented shell lies outside every other shell; flip that shell)");
      }
      summary.removedRegions += it->second == 0 ? 1 : 0;
    }
    tetWinding[t] = it->second;
    const auto& tet = out.mesh.tets[t];
    summary.windingVolume += static_cast<double>(it->second) *
                             signedTetVolume(out.mesh.points[tet[0]], out.mesh.points[tet[1]],
                                             out.mesh.points[tet[2]], out.mesh.points[tet[3]]);
  }
  if (summary.removedRegions > 0) {
    TetMesh kept;
    std::vector<int> newId(out.mesh.points.size(), -1);
    for (size_t t = 0; t < out.mesh.tets.size(); ++t) {
      if (tetWinding[t] == 0) {
        continue;
      }
      std::array<int, 4> tet;
      for (int k = 0; k < 4; ++k) {
        int& id = newId[out.mesh.tets[t][k]];
        if (id < 0) {
          id = static_cast<int>(kept.points.size());
          kept.points.push_back(out.mesh.points[out.mesh.tets[t][k]]);
        }
        tet[k] = id;
      }
      kept.tets.push_back(tet);
    }
    out.mesh = std::move(kept);
  }
  out.regions.clear();
  return summary;
}

}  // namespace

double automaticEdgeLength(double enclosedVolume, int targetTets) {
  if (!(enclosedVolume > 0.0) || !std::isfinite(enclosedVolume)) {
    throw GeoLatticeError("automatic edge length needs a positive enclosed volume, got " +
                          std::to_string(enclosedVolume) + " mm^3");
  }
  if (targetTets <= 0) {
    throw GeoLatticeError("automatic edge length needs a positive tet count, got " +
                          std::to_string(targetTets));
  }
  // N = V / (k * L^3 / (6 sqrt 2))  =>  L = cbrt(6 sqrt 2 * V / (k * N)).
  const double k = kGuessMeanTetVolumeOverBound *
                   std::pow(std::max(1.0, targetTets / kGuessCalibrationTets), kGuessRatioExponent);
  return std::cbrt(6.0 * std::sqrt(2.0) * enclosedVolume / (k * targetTets));
}

void TetrahedralizeOptions::validate() const {
  if (!(this->targetEdgeLength >= 0.0) || !std::isfinite(this->targetEdgeLength)) {
    throw GeoLatticeError("target edge length must be >= 0 mm (0 = automatic), got " +
                          std::to_string(this->targetEdgeLength));
  }
  if (!(this->radiusEdgeRatio >= kMinRadiusEdgeRatio &&
        this->radiusEdgeRatio <= kMaxRadiusEdgeRatio)) {
    throw GeoLatticeError("radius-edge ratio must be in [" +
                          formatSwitchNumber(kMinRadiusEdgeRatio) + ", " +
                          formatSwitchNumber(kMaxRadiusEdgeRatio) + "], got " +
                          std::to_string(this->radiusEdgeRatio));
  }
  if (this->targetEdgeLength == 0.0 &&
      (this->autoTargetTets < kMinAutoTargetTets || this->autoTargetTets > kMaxAutoTargetTets)) {
    throw GeoLatticeError(
        "automatic target tet count must be in [" + std::to_string(kMinAutoTargetTets) + ", " +
        std::to_string(kMaxAutoTargetTets) + "], got " + std::to_string(this->autoTargetTets));
  }
  if (!(this->simplifyFinerThan >= 0) || !std::isfinite(this->simplifyFinerThan)) {
    throw GeoLatticeError("surface simplification threshold must be >= 0 (0 = never), got " +
                          std::to_string(this->simplifyFinerThan));
  }
  if (!(this->tetgenSecondsLimit >= 0) || !std::isfinite(this->tetgenSecondsLimit)) {
    throw GeoLatticeError("TetGen time limit must be >= 0 s (0 = automatic), got " +
                          std::to_string(this->tetgenSecondsLimit));
  }
}

std::string qualityBoundDroppedNote(int tetCount) {
  return "TetGen's quality refinement did not finish within its time limit (it does not end "
         "near a knife edge or a needle tip of the surface, e.g. a rim thinner than the "
         "nozzle's bead): the surface was meshed without the quality and volume bounds (" +
         std::to_string(tetCount) +
         " tets, not quality-shaped; the layers follow the part less smoothly). A part with such "
         "edges prints them thicker than modelled: round or thicken them for a better mesh";
}

TetrahedralizeResult tetrahedralizeSurface(const TriangleSurface& input,
                                           const TetrahedralizeOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  options.validate();
  const bool automatic = options.targetEdgeLength == 0.0;
  // Only the vertices of triangles go to TetGen: a stray point inside the solid would become a
  // mesh vertex.
  TriangleSurface surface = withoutUnusedPoints(input);
  TetrahedralizeResult result;
  SurfaceCheckReport report;
  try {
    report = requireClosedManifold(input);  // its errors name the input's point ids
  } catch (const GeoLatticeError&) {
    // A face written twice, faces flipped against their neighbours, bodies that touch along a
    // face (welded by the reader): mesh/SurfaceRepair.h. Any other defect is the input's own.
    result.repairs = repairSurface(surface);
    if (!result.repairs.any()) {
      throw;
    }
    report = requireClosedManifold(surface);
  }
  // TetGen ignores facet orientation, but the cavity test (winding number) needs an outward
  // surface: a body inside out beside outward ones (they pass the check when they outweigh it;
  // repairSurface above has turned it when the check failed), then a surface inward as a whole.
  if (!result.repairs.any()) {
    result.repairs.invertedBodies = orientInvertedBodies(surface);
    if (result.repairs.invertedBodies > 0) {
      report = requireClosedManifold(surface);
    }
  }
  result.flippedSurfaceTriangles = orientOutward(surface);
  // Closed bodies that cross each other (an assembly exported as it is) are one solid: their
  // union, which TetGen accepts (it refuses the crossing facets).
  if (const int merged = mergeOverlappingBodies(surface).merged; merged > 0) {
    result.repairs.mergedBodies += merged;
    // The union's cuts can leave slivers (two mirror-image spheres: 4 of area ~0).
    result.repairs.degenerateTriangles += removeDegenerateTriangles(surface);
  }
  const double inputVolume = result.repairs.mergedBodies > 0
                                 ? std::abs(requireClosedManifold(surface).signedVolume)
                                 : std::abs(report.signedVolume);
  result.enclosedVolume = inputVolume;

  const double firstEdge = automatic
                               ? automaticEdgeLength(result.enclosedVolume, options.autoTargetTets)
                               : options.targetEdgeLength;
  result.inputTriangles = surface.triangles.size();
  const TriangleSurface original = surface;  // if TetGen refuses the simplified one
  if (options.simplifyFinerThan > 0) {
    SimplificationOptions simplify;
    simplify.method = options.simplification;
    simplify.targetEdgeLength = firstEdge;
    simplify.finerThan = options.simplifyFinerThan;
    simplify.shouldAbort = options.shouldAbort;
    simplify.progress = [&](double f) {
      if (options.progress) {
        options.progress(kSimplificationShare * f);
      }
    };
    const SimplificationResult s = simplifySurface(surface, simplify);
    if (s.simplified) {
      surface = s.surface;
      result.simplified = true;
      result.simplificationEdgeLength =
          s.remeshEdgeLength > 0 ? s.remeshEdgeLength / simplify.remeshEdgeFactor : firstEdge;
      result.simplificationDistance = s.hausdorff;
      result.enclosedVolume = std::abs(requireClosedManifold(surface).signedVolume);
    }
    result.simplificationRefused = s.refused;
    result.simplificationSeconds = s.seconds;
  }
  result.meshedTriangles = surface.triangles.size();
  const double smallestCount =
      result.enclosedVolume / (kLargestMeanTetVolumeOverBound * regularTetVolume(firstEdge));
  if (!automatic && smallestCount > kMaxEstimatedTets) {
    throw GeoLatticeError("target edge length " + std::to_string(firstEdge) +
                          " mm is too small for a solid of " +
                          std::to_string(result.enclosedVolume) + " mm^3: at least about " +
                          std::to_string(static_cast<long long>(smallestCount)) + " tets (limit " +
                          std::to_string(static_cast<long long>(kMaxEstimatedTets)) + ")");
  }

  // p: mesh the surface, q: radius-edge bound, a: volume bound, A: number the regions
  // (cavities), Q: quiet. No "Y": boundary triangles may be split, so the boundary gets the
  // target resolution too.
  auto switchesFor = [&](double edge) {
    return "pq" + formatSwitchNumber(options.radiusEdgeRatio) + "a" +
           formatSwitchNumber(regularTetVolume(edge)) + "AQ";
  };
  const ProgressReporter progress(options.progress, options.shouldAbort, "tetrahedralization");
  int removedRegions = 0;  // of the last run
  int runs = 0;
  // TetGen's refinement can loop without end on some inputs (seen on a generated genus-3 block
  // simplified for one edge length): each run gets a time limit far above its expected time, of
  // its own CPU time (TetGenRunner.h: load on the machine does not change which runs finish),
  // and a run past it fails with TetGenTimeLimitExceeded.
  IntersectionTest intersectionTest = IntersectionTest::Run;
  // Runs started ahead (the first and the speculative run, kSpeculativeEdgeFactor), by edge
  // length: runOnce reads one when the search asks for its edge length; the others are killed.
  std::map<double, std::unique_ptr<TetGenRun>> startedRuns;
  // unbounded: TetGen's constrained Delaunay tetrahedralization of the surface alone ("pAQ"),
  // the last resort when the quality-bounded runs do not finish.
  auto runOnce = [&](double edge, bool unbounded = false) {
    const double limit =
        options.tetgenSecondsLimit > 0 ? options.tetgenSecondsLimit
        : unbounded
            ? kTetGenBaseSeconds +
                  kUnboundedSecondsPerTriangle * static_cast<double>(surface.triangles.size())
            : kTetGenBaseSeconds + kTetGenSecondsPerTet * result.enclosedVolume /
                                       (kGuessMeanTetVolumeOverBound * regularTetVolume(edge));
    const std::string switches = unbounded ? "pAQ" : switchesFor(edge);
    TetGenOutput out;
    try {
      const auto ahead = unbounded ? startedRuns.end() : startedRuns.find(edge);
      if (ahead != startedRuns.end()) {
        const std::unique_ptr<TetGenRun> run = std::move(ahead->second);
        startedRuns.erase(ahead);
        out = run->finish(options.shouldAbort, limit);
      } else {
        out = runTetGen(surface, switches, options.shouldAbort, intersectionTest, limit);
      }
    } catch (const GeoLatticeError& e) {
      if (!result.simplified || (options.shouldAbort && options.shouldAbort())) {
        throw;
      }
      startedRuns.clear();  // they mesh the surface refused here
      // TetGen failed on the simplified surface (e.g. nearly coincident vertices it made, or a
      // refinement that does not end: seen on a generated genus-3 block, where the input as it
      // is meshes in 3 s): mesh the input as it is, with a new time limit.
      result.simplificationRefused = dynamic_cast<const TetGenTimeLimitExceeded*>(&e)
                                         ? "TetGen did not finish on it within its time limit"
                                         : e.what();
      surface = original;
      result.simplified = false;
      result.simplificationEdgeLength = 0;
      result.enclosedVolume = inputVolume;
      result.meshedTriangles = surface.triangles.size();
      intersectionTest = IntersectionTest::Run;
      out = runTetGen(surface, switches, options.shouldAbort, intersectionTest, limit);
    }
    intersectionTest = IntersectionTest::Skip;  // this surface passed: not again at other edges
    if (out.mesh.tets.empty()) {
      throw GeoLatticeError("TetGen produced no tetrahedra (switches " + switches + ")");
    }
    const RegionSummary regions = classifyRegions(surface, out);
    removedRegions = regions.removedRegions;
    // TetGen keeps the boundary geometrically (Steiner points lie on the input facets), so the
    // volumes agree to rounding (measured: <= 1e-7 relative on the test models). A larger gap
    // means TetGen changed the geometry, e.g. merged nearly coincident vertices.
    const double gap =
        std::abs(regions.windingVolume - result.enclosedVolume) / result.enclosedVolume;
    if (gap > kVolumeTolerance) {
      throw GeoLatticeError(
          "the tet mesh volume (" + std::to_string(regions.windingVolume) +
          " mm^3, counted with the winding number) differs from the volume enclosed by the "
          "surface (" +
          std::to_string(result.enclosedVolume) + " mm^3) by " + formatSwitchNumber(100.0 * gap) +
          " %: the surface has overlapping parts or nearly coincident vertices");
    }
    ++runs;
    const double tetgen = automatic ? 0.9 * runs / kMaxAutoAttempts : 0.9;
    progress.report(result.simplified ? kSimplificationShare + (1 - kSimplificationShare) * tetgen
                                      : tetgen);
    return std::move(out.mesh);
  };
  // TetGen's output must be a valid mesh. Flat slivers (zero volume: all four corners in one
  // plane, where boundary facets are nearly coplanar) are dropped, a documented repair that
  // changes no volume; inverted or overlapping tets make the same target run again with the
  // edge length changed by kRetryEdgeFactors. A run past its time limit is not retried at other
  // edges (its refinement does not end near a knife edge or a needle tip of the surface,
  // whatever the edge: a 2 mm thin ellipsoid timed out at all five): the surface is meshed
  // without the quality and volume bounds instead (qualityBoundDropped), which takes seconds.
  TetMeshCheckReport lastCheck;        // of the mesh TetGen last returned
  auto checked = [&](TetMesh& mesh) {  // true: valid after its flat slivers are dropped
    orientTetsPositively(mesh);
    result.removedFlatTets += removeFlatTets(mesh);
    lastCheck = checkTetMesh(mesh);
    return lastCheck.invertedTets == 0 && lastCheck.nonManifoldFaces == 0 && lastCheck.tetCount > 0;
  };
  auto invalid = [&](const std::string& what) {
    return "TetGen's mesh " + what + " has " + std::to_string(lastCheck.invertedTets) +
           " inverted tets and " + std::to_string(lastCheck.nonManifoldFaces) +
           " overlapping faces";
  };
  auto run = [&](double edge) {
    std::string failure;
    std::vector<double> factors = {1.0};
    factors.insert(factors.end(), std::begin(kRetryEdgeFactors), std::end(kRetryEdgeFactors));
    for (double factor : factors) {
      if (factor != 1.0) {
        ++result.tetgenRetries;
      }
      TetMesh mesh;
      try {
        mesh = runOnce(edge * factor);
      } catch (const TetGenTimeLimitExceeded&) {
        ++result.tetgenRetries;
        try {
          mesh = runOnce(edge, /*unbounded=*/true);
        } catch (const TetGenTimeLimitExceeded&) {
          throw GeoLatticeError("TetGen did not finish within its time limit at edge length " +
                                formatSwitchNumber(edge * factor) +
                                " mm, nor without its quality bound; give another edge length "
                                "(--edge-length) or repair the surface");
        }
        if (!checked(mesh)) {
          throw GeoLatticeError("TetGen did not finish within its time limit at edge length " +
                                formatSwitchNumber(edge * factor) + " mm, and " +
                                invalid("without its quality bound") +
                                "; give another edge length (--edge-length) or repair the surface");
        }
        result.qualityBoundDropped = true;
        return mesh;
      }
      if (checked(mesh)) {
        return mesh;
      }
      failure = invalid("at edge length " + formatSwitchNumber(edge * factor) + " mm");
    }
    throw GeoLatticeError(failure +
                          ", and at 7 % and 15 % shorter and longer edges; give "
                          "another edge length (--edge-length) or repair the surface");
  };

  const double target = options.autoTargetTets;
  auto miss = [&](size_t count) {
    return std::abs(std::log(static_cast<double>(count) / target));
  };
  // The speculative run (kSpeculativeEdgeFactor): meshed beside the first run and read first
  // (after the surface's intersection test, whose verdict comes first). Within the tolerance it
  // is the result and the first run is killed unread (the first guess gives too many tets on
  // surface-driven parts, whose first runs are the slow ones); otherwise the first run is read
  // and the search goes on as if the speculative run were read after it, as its second run.
  struct ReadRun {
    double edge = 0.0;
    TetMesh mesh;
    TetMeshCheckReport check;
    int removedRegions = 0;
  };
  std::optional<ReadRun> speculative;
  auto takeSpeculative = [&] {  // its mesh, as if run() had just returned it
    TetMesh mesh = std::move(speculative->mesh);
    lastCheck = speculative->check;
    removedRegions = speculative->removedRegions;
    speculative.reset();
    return mesh;
  };
  TetMesh best;
  double startEdge = firstEdge;  // of the run the search starts from
  bool speculativeOvershot = false;
  if (automatic && options.autoTargetTets <= kSpeculativeMaxTargetTets) {
    const double speculativeEdge = firstEdge * kSpeculativeEdgeFactor;
    // The intersection test beside the speculative run, the first run once the test is done:
    // three children on two cores slowed the run that is usually read (topopt's test takes
    // 0.65 s), and the first run is read only when the speculative one has too few tets.
    startedRuns[speculativeEdge] =
        std::make_unique<TetGenRun>(surface, switchesFor(speculativeEdge));
    result.speculativeRun = true;
    testForIntersectingFacets(surface, options.shouldAbort);
    intersectionTest = IntersectionTest::Skip;
    startedRuns[firstEdge] = std::make_unique<TetGenRun>(surface, switchesFor(firstEdge));
    try {
      speculative = ReadRun{speculativeEdge, run(speculativeEdge), lastCheck, removedRegions};
    } catch (const GeoLatticeError&) {
      if (options.shouldAbort && options.shouldAbort()) {
        throw;
      }
      // The first run decides (its own error, if any, is the one reported).
    }
    // Meshed without the bounds, the surface alone sets the count: no edge changes it.
    if (speculative && (result.qualityBoundDropped ||
                        miss(speculative->mesh.tets.size()) <= std::log(kAutoTolerance) ||
                        speculative->mesh.tets.size() > target)) {
      // Within the tolerance, or too many tets even here (kSecondSlopeOver): the first run is
      // not needed, stop it now, it holds a core.
      speculativeOvershot = speculative->mesh.tets.size() > target;
      startedRuns.clear();
      best = takeSpeculative();
      startEdge = speculativeEdge;
    }
  }
  if (best.tets.empty()) {
    best = run(firstEdge);
  }
  TetMeshCheckReport bestCheck = lastCheck;
  double bestEdge = startEdge;
  result.removedCavityRegions = removedRegions;
  result.attempts = 1;
  if (automatic && !result.qualityBoundDropped) {
    // Secant search on log(count) = slope * log(edge) + c. A volume-filling mesh has slope -3;
    // surface-driven refinement flattens it (and makes it jumpy near the surface's own edge
    // length), so the measured slope is used from run 2 on, and a proposal outside the
    // bracket (largest edge known to give too many tets, smallest known to give too few) is
    // replaced by the bracket's geometric mean.
    double edge = startEdge, count = static_cast<double>(best.tets.size());
    double slope = count <= target       ? kFirstSlopeUnder
                   : speculativeOvershot ? kSecondSlopeOver
                                         : kFirstSlopeOver;
    double tooFine = 0.0,
           tooCoarse = 0.0;  // largest edge with count > target, smallest with count < target
    auto updateBracket = [&](double e, double n) {
      if (n > target) {
        tooFine = std::max(tooFine, e);
      } else if (tooCoarse == 0.0 || e < tooCoarse) {
        tooCoarse = e;
      }
    };
    updateBracket(edge, count);
    if (!(miss(best.tets.size()) > std::log(kAutoTolerance) && count > target)) {
      speculative.reset();  // a first run with too few tets: the longer edge is no correction
    }
    while (miss(best.tets.size()) > std::log(kAutoTolerance) &&
           result.attempts < kMaxAutoAttempts) {
      double next = edge * std::exp(std::log(count / target) / -slope);
      if (speculative) {  // too many tets in the first run: its longer edge is ready
        next = speculative->edge;
      }
      next = std::max(edge / 4.0, std::min(next, std::min(edge * 4.0, report.bboxDiagonal)));
      if (tooFine > 0.0 && tooCoarse > tooFine && !(next > tooFine && next < tooCoarse)) {
        next = std::sqrt(tooFine * tooCoarse);
      }
      if (speculative && next != speculative->edge) {
        speculative.reset();
      }
      if (!(std::abs(next - edge) > 1e-9 * edge)) {
        break;  // no further change possible (the bound is the bounding-box diagonal)
      }
      TetMesh mesh = speculative ? takeSpeculative() : run(next);
      ++result.attempts;
      if (result.qualityBoundDropped) {  // this edge's refinement did not end: keep the best
        result.qualityBoundDropped = false;
        break;
      }
      const double nextCount = static_cast<double>(mesh.tets.size());
      const double measuredSlope = std::log(nextCount / count) / std::log(next / edge);
      // A count that hardly falls although the edge grew is set by the surface (its own
      // triangles, or thin walls that the quality bound refines), not by the volume bound, and
      // longer edges will not bring it down: a generated arch gave 125,871 / 112,641 / 112,641
      // tets at 2.9 / 6.5 / 14.6 mm, a 2 mm curved wall 74,693 at 2.4 and 3.4 mm.
      const bool surfaceBound =
          count > target && next > 1.1 * edge && measuredSlope > kSurfaceBoundSlope;
      // Keep the slope negative and not too flat, so the next step stays bounded.
      slope = std::clamp(measuredSlope, -4.0, -0.5);
      edge = next;
      count = nextCount;
      updateBracket(edge, count);
      if (miss(mesh.tets.size()) < miss(best.tets.size())) {
        best = std::move(mesh);
        bestCheck = lastCheck;
        bestEdge = edge;
        result.removedCavityRegions = removedRegions;
      }
      if (surfaceBound) {
        result.surfaceBoundCount = true;
        break;
      }
    }
  }

  if (result.simplified) {
    result.simplifiedSurface = std::move(surface);
  }
  result.targetEdgeLength = bestEdge;
  result.maxTetVolume = regularTetVolume(bestEdge);
  result.switches = result.qualityBoundDropped ? "pAQ" : switchesFor(bestEdge);
  result.mesh = std::move(best);
  // TetGen 1.5 writes positively oriented tets (measured); flip only if a build ever wrote
  // them all the other way, and let the validation below reject anything else.
  result.flippedTets = orientTetsPositively(result.mesh);
  const TetMeshCheckReport check =
      result.flippedTets == 0 ? requireValidTetMesh(bestCheck) : requireValidTetMesh(result.mesh);

  result.tetCount = check.tetCount;
  result.meshVolume = check.totalVolume;
  result.meanEdgeLength = meanUniqueEdgeLength(result.mesh);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.report(1.0);
  return result;
}

}  // namespace geolattice
