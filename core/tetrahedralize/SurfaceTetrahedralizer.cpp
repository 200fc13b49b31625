#include "tetrahedralize/SurfaceTetrahedralizer.h"

#include "common/Error.h"
#include "mesh/SurfaceCheck.h"
#include "mesh/TetMeshCheck.h"

#include <tetgen.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <new>
#include <string>
#include <utility>
#include <vector>

namespace geolattice {

namespace {

// Calibration of the automatic edge length: TetGen's mean tet volume relative to the bound
// "a" = L^3/(6 sqrt 2) (measured with q1.414 on a box and on the Stanford bunny at ~100 mm).
constexpr double kMeanTetVolumeOverBound = 0.30;

double regularTetVolume(double edge) { return edge * edge * edge / (6.0 * std::sqrt(2.0)); }

// Messages of TetGen's terminatetetgen() codes (tetgen.h, TETLIBRARY build throws the code).
std::string tetgenErrorMessage(int code) {
  switch (code) {
  case 1:
    return "TetGen ran out of memory (try a larger target edge length)";
  case 2:
    return "TetGen internal error (code 2); the surface may have nearly coincident or degenerate features";
  case 3:
    return "self-intersecting surface: TetGen found intersecting facets";
  case 4:
    return "TetGen found a very small input feature (code 4): nearly coincident vertices or "
           "extremely thin triangles on the surface";
  case 5:
    return "TetGen found two very close, nearly overlapping input facets (code 5)";
  case 10:
    return "TetGen rejected the input (code 10: input error)";
  default:
    return "TetGen failed with error code " + std::to_string(code);
  }
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

} // namespace

double automaticEdgeLength(double enclosedVolume) {
  if (!(enclosedVolume > 0.0) || !std::isfinite(enclosedVolume)) {
    throw GeoLatticeError("automatic edge length needs a positive enclosed volume, got " +
                          std::to_string(enclosedVolume) + " mm^3");
  }
  // N = V / (k * L^3 / (6 sqrt 2))  =>  L = cbrt(6 sqrt 2 * V / (k * N)).
  return std::cbrt(6.0 * std::sqrt(2.0) * enclosedVolume / (kMeanTetVolumeOverBound * kAutoTargetTets));
}

TetrahedralizeResult tetrahedralizeSurface(const TriangleSurface& input, const TetrahedralizeOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (!(options.targetEdgeLength >= 0.0) || !std::isfinite(options.targetEdgeLength)) {
    throw GeoLatticeError("target edge length must be >= 0 mm (0 = automatic), got " +
                          std::to_string(options.targetEdgeLength));
  }
  // TetGen's Delaunay refinement is proven to terminate for a ratio bound >= 2 and in practice
  // works down to about 1.1; a regular tet has ratio sqrt(6)/4 = 0.61, so bounds near or
  // below 1 make TetGen refine (nearly) forever. Above 10 the bound no longer shapes the mesh.
  if (!(options.radiusEdgeRatio >= kMinRadiusEdgeRatio && options.radiusEdgeRatio <= kMaxRadiusEdgeRatio)) {
    throw GeoLatticeError("radius-edge ratio must be in [" + formatSwitchNumber(kMinRadiusEdgeRatio) + ", " +
                          formatSwitchNumber(kMaxRadiusEdgeRatio) + "], got " +
                          std::to_string(options.radiusEdgeRatio));
  }

  TriangleSurface surface = input;
  requireClosedManifold(surface);
  TetrahedralizeResult result;
  // TetGen ignores facet orientation, but keep the documented contract (outward surface) so
  // that the enclosed volume below is positive.
  result.flippedSurfaceTriangles = orientOutward(surface);
  result.enclosedVolume = checkSurface(surface).signedVolume;

  result.targetEdgeLength =
      options.targetEdgeLength > 0.0 ? options.targetEdgeLength : automaticEdgeLength(result.enclosedVolume);
  result.maxTetVolume = regularTetVolume(result.targetEdgeLength);
  const double estimatedTets = result.enclosedVolume / (kMeanTetVolumeOverBound * result.maxTetVolume);
  if (estimatedTets > kMaxEstimatedTets) {
    throw GeoLatticeError("target edge length " + std::to_string(result.targetEdgeLength) +
                          " mm is too small for a solid of " + std::to_string(result.enclosedVolume) +
                          " mm^3: about " + std::to_string(static_cast<long long>(estimatedTets)) +
                          " tets (limit " + std::to_string(static_cast<long long>(kMaxEstimatedTets)) + ")");
  }

  tetgenio in;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(surface.points.size());
  in.pointlist = new REAL[3 * surface.points.size()];
  for (size_t i = 0; i < surface.points.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      in.pointlist[3 * i + a] = surface.points[i][a];
    }
  }
  in.numberoffacets = static_cast<int>(surface.triangles.size());
  in.facetlist = new tetgenio::facet[surface.triangles.size()];
  for (size_t f = 0; f < surface.triangles.size(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k) {
      facet.polygonlist[0].vertexlist[k] = surface.triangles[f][k];
    }
  }

  // p: mesh the PLC, q: radius-edge bound, a: volume bound, Q: quiet. No "Y": boundary
  // triangles may be split so the boundary gets the target resolution too.
  result.switches = "pq" + formatSwitchNumber(options.radiusEdgeRatio) + "a" +
                    formatSwitchNumber(result.maxTetVolume) + "Q";
  std::vector<char> switches(result.switches.begin(), result.switches.end());
  switches.push_back('\0'); // tetrahedralize() needs a writable char*
  tetgenio out;
  try {
    tetrahedralize(switches.data(), &in, &out);
  } catch (int code) {
    throw GeoLatticeError(tetgenErrorMessage(code));
  } catch (const std::bad_alloc&) {
    throw GeoLatticeError(tetgenErrorMessage(1));
  }
  if (out.numberoftetrahedra <= 0 || out.numberofcorners != 4) {
    throw GeoLatticeError("TetGen produced no tetrahedra (" + std::to_string(out.numberoftetrahedra) +
                          " tets, " + std::to_string(out.numberofcorners) + " corners)");
  }

  TetMesh& mesh = result.mesh;
  mesh.points.resize(out.numberofpoints);
  for (int i = 0; i < out.numberofpoints; ++i) {
    mesh.points[i] = Vec3(out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2]);
  }
  mesh.tets.resize(out.numberoftetrahedra);
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    for (int k = 0; k < 4; ++k) {
      mesh.tets[t][k] = out.tetrahedronlist[4 * t + k] - out.firstnumber;
    }
  }
  // TetGen writes every tet with the fourth vertex below the plane of the first three, i.e.
  // negative signed volume in our convention: flip all of them (checked, not assumed).
  result.flippedTets = orientTetsPositively(mesh);
  const TetMeshCheckReport check = requireValidTetMesh(mesh);

  result.tetCount = check.tetCount;
  result.meshVolume = check.totalVolume;
  result.meanEdgeLength = meanUniqueEdgeLength(mesh);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace geolattice
