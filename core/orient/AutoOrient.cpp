#include "orient/AutoOrient.h"

#include "collision/CollisionVerifier.h"
#include "common/Error.h"
#include "common/ParallelFor.h"
#include "common/Progress.h"
#include "common/Rotation.h"
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "lattice/LatticeInfill.h"
#include "mesh/TetMeshTopology.h"
#include "placement/PlaceOnPlatform.h"
#include "overhang/OverhangAnalysis.h"
#include "pedestal/Pedestal.h"
#include "sequence/PotentialCollisions.h"
#include "sequence/PrintMaterial.h"
#include "sequence/PrintSequencer.h"
#include "skeleton/SkeletonTree.h"
#include "slicer/CurvedLayerSlicer.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <memory>
#include <sstream>

namespace geolattice {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kDeg = M_PI / 180.0;
// A coarse evaluation mesh above this many times its target is meshed again at a longer edge.
constexpr size_t kCoarseOvershoot = 4;

double seconds(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// `count` unit directions spread evenly over the sphere (Fibonacci lattice).
std::vector<Vec3> fibonacciSphere(int count) {
  std::vector<Vec3> out;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    out.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return out;
}

/// The resolution and set-up one evaluation runs at.
struct Evaluation {
  double layerInterval, latticeWidth;
  SequenceStrategy strategy;
  double sampleSpacing;  ///< material samples of the collision check (mm)
};

/// Does the nozzle's bounding cone (nozzle/NozzleBound.h), its tip at height z and its axis
/// `tilt` (rad) off +z, lie wholly above the plate's top face (z = 0)?
bool boundingConeAbovePlate(const NozzleModel& nozzle, double z, double tilt) {
  return tilt + nozzle.boundingHalfAngleRad() <= M_PI / 2 &&
         z - nozzle.boundingApexOffset() * std::cos(tilt) >= 0;
}

/// The stations the verifier has to search: those of a sub-graph with a blocker printed before
/// it, and those whose nozzle may reach the plate. The others are clear: the potential-collision
/// graph holds j in pcg[i] exactly when some station of i has material of j inside its nozzle (the
/// same nozzle volume, searched to the samples), and a station whose bounding cone (nozzle/
/// NozzleBound.h) lies wholly above the plate's top face cannot meet the plate. Most stations of
/// a candidate are of neither kind, and searching each took a third of the search's time.
std::vector<char> stationsThatMayCollide(const MaterialSamples& material,
                                         const PotentialCollisions& pcg,
                                         const PrintSequence& sequence, const OrientOptions& o) {
  const size_t subgraphs = pcg.pcg.size();
  std::vector<char> blocked(subgraphs, 0);
  for (size_t i = 0; i < subgraphs; ++i) {
    for (int j : pcg.pcg[i]) {
      blocked[i] |= sequence.printIndex[j] < sequence.printIndex[i];
    }
  }
  std::vector<char> checked(material.points.size(), 0);
  for (size_t s = 0; s < checked.size(); ++s) {
    const double tilt = std::acos(std::clamp(material.normals[s].normalized().z(), -1.0, 1.0));
    checked[s] =
        blocked[material.subgraph[s]] ||
        (o.plate.enabled && !boundingConeAbovePlate(o.nozzle, material.points[s].z(), tilt));
  }
  return checked;
}

/// The scores of one candidate, with the real stages on the coarse mesh (see the file comment).
/// `gdf` is this worker's set-up of the fields on the coarse mesh as placed.
void evaluate(OrientCandidate& c, GeodesicDistanceFields& gdf, const OrientOptions& o,
              const Evaluation& at) {
  const bool debug = std::getenv("GEOLATTICE_ORIENT_DEBUG") != nullptr;
  auto tick = Clock::now();
  auto lap = [&](const char* what) {
    if (debug) {
      std::fprintf(stderr, "  %s %.3f s\n", what, seconds(tick));
    }
    tick = Clock::now();
  };
  const TetMesh& placed = gdf.mesh();
  TetMesh mesh = placed;
  double zmin = std::numeric_limits<double>::infinity();
  for (Vec3& p : mesh.points) {
    p = c.rotation * p;
    zmin = std::min(zmin, p.z());
  }
  for (Vec3& p : mesh.points) {
    p.z() -= zmin;
  }
  if (c.height - c.pedestal < o.refineLayerInterval) {
    // Not even the print's first layer (a thin plate lying flat): this side cannot be printed,
    // however well it would score with nothing to collide. The surface's height, not the coarse
    // mesh's (its remeshing can thicken a sub-millimetre plate) nor γ (the coarse heat method
    // overstates a sub-millimetre distance).
    std::ostringstream m;
    m << "no layer: the part is " << c.height - c.pedestal << " mm tall on this side, less than "
      << "the print's layer interval (" << o.refineLayerInterval << " mm)";
    throw GeoLatticeError(m.str());
  }
  // On a pedestal the layers grow from the column's top, the part's lowest vertices up to the
  // column's reach into it.
  const std::vector<int> sources =
      c.pedestal > 0 ? sourcesNearLowestZ(mesh, o.pedestalContactHeight)
                     : sourcesNearLowestZ(mesh, o.baseTolerance, gdf.topology(), o.baseFlatBand,
                                          BaseOptions{}.maxFaceAngleDeg);
  // γ, α, β do not change under rotation, but the reference vector r of Eq. 3 is fixed in the
  // printing frame: in the placed frame it is Rᵀ r.
  gdf.setReference(c.rotation.transpose() * Vec3::UnitX());
  GeodesicFields fields = gdf.solve(sources);
  lap("gdf");
  for (Vec3& d : fields.gammaDirection) {
    d = c.rotation * d;
  }

  // Curved layers, lattice, skeleton.
  SlicerOptions slicer;
  slicer.interval = at.layerInterval;
  slicer.firstLayerOffset = at.layerInterval;
  if (fields.gamma.maxCoeff() < slicer.firstLayerOffset) {
    c.layers = 0;
    return;  // thinner than one evaluation layer: nothing to collide
  }
  const std::vector<Vec3> normals = vertexGradientDirections(mesh, fields.gamma);
  const CurvedLayers layers =
      sliceCurvedLayers(mesh, fields.gamma, fields.alpha, fields.beta, normals, slicer);
  c.layers = static_cast<int>(layers.layerValues.size());
  lap("slice");
  std::vector<std::uint8_t> base(mesh.points.size(), 0);
  for (int s : sources) {
    base[s] = 1;
  }
  OverhangOptions overhang;
  overhang.thresholdDeg = o.overhangThresholdDeg;
  c.overhangFraction =
      analyzeOverhang(mesh, gdf.topology(), fields.gammaDirection, base, overhang).curvedFraction;
  LatticeOptions lattice;
  lattice.alphaWidth = lattice.betaWidth = at.latticeWidth;
  lattice.threads = 1;
  const LatticeGraph graph = buildLatticeGraph(layers, lattice);
  lap("overhang+lattice");
  if (graph.subgraphs.empty()) {
    return;
  }
  SkeletonTreeOptions skeleton;
  skeleton.topology = &gdf.topology();  // the candidates share the mesh: its adjacency too
  const SkeletonTree tree = buildSkeletonTree(mesh, fields.gamma, graph, skeleton);
  lap("skeleton");

  // The paper's A4 order and the independent verifier on it, with the nozzle and the plate.
  MaterialSamples material = sampleLatticeMaterial(graph, at.sampleSpacing);
  const PotentialCollisions pcg = computePotentialCollisions(material, o.nozzle, 1);
  lap("pcg");
  SequenceOptions order;
  order.strategy = at.strategy;
  const PrintSequence sequence = sequencePrint(tree, material, &pcg, order);
  c.forcedSteps = sequence.forcedSteps;
  lap("sequence");
  std::vector<int> time(material.points.size());
  for (size_t s = 0; s < time.size(); ++s) {
    time[s] = sequence.printIndex[material.subgraph[s]];
  }
  for (Vec3& p : material.points) {
    p.z() += c.pedestal;  // the plate is that much further down
  }
  const std::vector<char> checked = stationsThatMayCollide(material, pcg, sequence, o);
  const CollisionReport report =
      verifyNozzleClearance(material.points, material.normals, time, o.nozzle, 0, nullptr, nullptr,
                            o.plate.enabled ? &o.plate : nullptr, &checked);
  lap("verify");
  if (debug) {
    std::fprintf(stderr,
                 "candidate %s%s: %zu samples (%td searched), %zu subgraphs, %d layers, %lld "
                 "colliding\n",
                 c.source.c_str(), c.pedestal > 0 ? " (pedestal)" : "", material.points.size(),
                 std::count(checked.begin(), checked.end(), 1), graph.subgraphs.size(), c.layers,
                 report.violatingStations);
  }
  // The part as placed on the plate: the toolpath tilts the axis up to maxTiltDeg off the layer
  // normal where it collides (toolpath/NozzleAxisClearance.h), and towards +z that lifts the
  // nozzle off the plate. Its plate stations whose nozzle, so tilted, lies wholly above the
  // plate's top face are not counted (sufficient: the bounding cone points nowhere down), so a
  // placement the toolpath prints is not put on a pedestal or turned over for them (a generated
  // spire, mushroom, branches and ring: 32, 15, 6, 4 stations). Only the placement: it is always
  // among the toolpath's tries (GLPrintPipeline::ChooseOrientationByToolpath), so when the tilt
  // meets material instead, the next candidates still print. For every candidate alike, a
  // generated arch standing on its crown chose a placement on the plate whose tilts met its own
  // base (248 stations) over a pedestal that prints.
  long long liftedOffPlate = 0;
  if (c.source == "keep" && c.pedestal == 0) {
    const double maxTilt = o.maxTiltDeg * kDeg;
    for (int k : report.plateStationIds) {
      const Vec3 n = material.normals[k].normalized();
      const double tilted = std::max(0.0, std::acos(std::clamp(n.z(), -1.0, 1.0)) - maxTilt);
      liftedOffPlate += boundingConeAbovePlate(o.nozzle, material.points[k].z(), tilted);
    }
  }
  c.tiltClearedPlateStations = liftedOffPlate;
  c.collidingStations = report.violatingStations - liftedOffPlate;
  c.plateStations = report.plateStations - liftedOffPlate;
  c.stations = report.stations;
}

/// Lexicographic "a is better than b" (see the file comment).
bool better(const OrientCandidate& a, const OrientCandidate& b) {
  if (a.feasible != b.feasible) {
    return a.feasible;
  }
  if (a.refined != b.refined) {
    return a.refined;  // scores of the two passes are not comparable; refined ones are the print's
  }
  if (a.collidingStations != b.collidingStations) {
    return a.collidingStations < b.collidingStations;
  }
  if (a.fitsHeight != b.fitsHeight) {
    return a.fitsHeight;
  }
  if (a.forcedSteps != b.forcedSteps) {
    return a.forcedSteps < b.forcedSteps;
  }
  if ((a.pedestal > 0) != (b.pedestal > 0)) {
    return a.pedestal == 0;
  }
  // Overhang fractions within 0.1 % and layer counts within 2 % are ties.
  if (std::abs(a.overhangFraction - b.overhangFraction) > 1e-3) {
    return a.overhangFraction < b.overhangFraction;
  }
  if (std::abs(a.layers - b.layers) > 0.02 * std::max(a.layers, b.layers)) {
    return a.layers < b.layers;
  }
  if ((a.source == "keep") != (b.source == "keep")) {
    return a.source == "keep";
  }
  return a.baseArea > b.baseArea;
}

}  // namespace

void OrientOptions::validate() const {
  std::ostringstream m;
  if (sphereCandidates < 0 || hullCandidates < 0 || sphereCandidates + hullCandidates > 100000) {
    m << "orientation: the candidate counts must be >= 0 (got " << sphereCandidates << " sphere, "
      << hullCandidates << " hull)";
  } else if (!(minBaseArea >= 0) || !std::isfinite(minBaseArea)) {
    m << "orientation: the minimum base area must be >= 0 mm^2 (got " << minBaseArea << ")";
  } else if (!(maxHeight >= 0) || !std::isfinite(maxHeight)) {
    m << "orientation: the maximum height must be >= 0 mm, 0 for none (got " << maxHeight << ")";
  } else if (!(contactHeight > 0) || !(layerInterval > 0) || !(latticeWidth > 0) ||
             !(sampleSpacing > 0) || !(baseTolerance >= 0) || !(baseFlatBand >= 0)) {
    m << "orientation: contact height, layer interval, lattice width and sample spacing must be "
         "> 0 mm and the base tolerance and flat band >= 0 mm";
  } else if (evaluationTets < 100) {
    m << "orientation: the evaluation mesh needs at least 100 tets (got " << evaluationTets << ")";
  } else if (pedestal != PedestalChoice::Never &&
             (!(pedestalHeight > 0 && pedestalHeight <= 500) ||
              !(pedestalContactHeight > 0 && pedestalContactHeight <= 50))) {
    m << "orientation: a pedestal's height must be in (0, 500] mm and its reach into the part in "
         "(0, 50] mm (got "
      << pedestalHeight << " and " << pedestalContactHeight << ")";
  } else if (refineCandidates < 0 || refineCandidates > 1000 || !(refineLayerInterval > 0) ||
             !(refineLatticeWidth > 0) || !std::isfinite(refineLayerInterval) ||
             !std::isfinite(refineLatticeWidth)) {
    m << "orientation: the refinement needs 0-1000 candidates and a layer interval and lattice "
         "width > 0 mm (got "
      << refineCandidates << ", " << refineLayerInterval << ", " << refineLatticeWidth << ")";
  } else if (!(maxTiltDeg >= 0 && maxTiltDeg <= 60)) {
    m << "orientation: the largest axis tilt must be in [0, 60] degrees (got " << maxTiltDeg << ")";
  } else {
    nozzle.validate();
    if (plate.enabled) {
      plate.validate();
    }
    return;
  }
  throw GeoLatticeError(m.str());
}

std::vector<Vec3> hullFacetNormals(const TriangleSurface& surface, int count) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  std::vector<K::Point_3> points;
  points.reserve(surface.points.size());
  for (const Vec3& p : surface.points) {
    points.emplace_back(p.x(), p.y(), p.z());
  }
  Mesh hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  // The facets in an order of their own (by corners), not the hull's: the grouping below is
  // greedy, and the hull's face order follows where the allocator put its nodes (measured: the
  // same part gave another merged normal with malloc on huge pages).
  struct Facet {
    std::array<Vec3, 3> corners;  ///< rotated so the lexicographically smallest comes first
    Vec3 cross;
  };
  auto less = [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::vector<Facet> facets;
  for (auto f : hull.faces()) {
    Facet facet;
    int k = 0;
    for (auto vertex : CGAL::vertices_around_face(hull.halfedge(f), hull)) {
      const K::Point_3& p = hull.point(vertex);
      facet.corners[k++] = Vec3(p.x(), p.y(), p.z());
    }
    auto& c = facet.corners;
    std::rotate(c.begin(), std::min_element(c.begin(), c.end(), less), c.end());
    facet.cross = (c[1] - c[0]).cross(c[2] - c[0]);
    facets.push_back(facet);
  }
  std::sort(facets.begin(), facets.end(), [&](const Facet& a, const Facet& b) {
    return std::lexicographical_compare(a.corners.begin(), a.corners.end(), b.corners.begin(),
                                        b.corners.end(), less);
  });
  std::vector<std::pair<double, Vec3>> groups;  // (area, area-weighted normal)
  for (const Facet& facet : facets) {
    const double area = 0.5 * facet.cross.norm();
    if (!(area > 0)) {
      continue;
    }
    const Vec3 n = facet.cross.normalized();
    bool merged = false;
    for (auto& g : groups) {
      if (g.second.normalized().dot(n) > std::cos(2 * kDeg)) {
        g.first += area;
        g.second += area * n;
        merged = true;
        break;
      }
    }
    if (!merged) {
      groups.emplace_back(area, area * n);
    }
  }
  std::sort(groups.begin(), groups.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<Vec3> normals;
  for (size_t i = 0; i < groups.size() && static_cast<int>(normals.size()) < count; ++i) {
    normals.push_back(groups[i].second.normalized());
  }
  return normals;
}

double evaluationScale(double volume) {
  return volume > kFullResolutionVolume ? std::sqrt(volume / kFullResolutionVolume) : 1.0;
}

Eigen::Matrix3d rotationTakingDownToMinusZ(const Vec3& down) {
  return rotationBetween(down, -Vec3::UnitZ());
}

double baseContactArea(const TriangleSurface& surface, const Eigen::Matrix3d& R,
                       double contactHeight) {
  double area = 0;
  for (int f : baseContactFaces(surface, R, contactHeight)) {
    const auto& t = surface.triangles[f];
    area += 0.5 * (surface.points[t[1]] - surface.points[t[0]])
                      .cross(surface.points[t[2]] - surface.points[t[0]])
                      .norm();
  }
  return area;
}

TriangleSurface orientSurface(const TriangleSurface& surface, const Eigen::Matrix3d& R) {
  TriangleSurface out = surface;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  Vec3 rlo = lo, rhi = hi;
  for (size_t i = 0; i < surface.points.size(); ++i) {
    lo = lo.cwiseMin(surface.points[i]);
    hi = hi.cwiseMax(surface.points[i]);
    out.points[i] = R * surface.points[i];
    rlo = rlo.cwiseMin(out.points[i]);
    rhi = rhi.cwiseMax(out.points[i]);
  }
  const Vec3 shift(0.5 * (lo.x() + hi.x() - rlo.x() - rhi.x()),
                   0.5 * (lo.y() + hi.y() - rlo.y() - rhi.y()), -rlo.z());
  for (Vec3& p : out.points) {
    p += shift;
  }
  return out;
}

OrientResult searchOrientation(const TriangleSurface& surface, const OrientOptions& o) {
  const auto t0 = Clock::now();
  o.validate();
  if (surface.points.empty() || surface.triangles.empty()) {
    throw GeoLatticeError("orientation: the surface is empty");
  }
  const ProgressReporter progress(o.progress, o.shouldAbort, "orientation search");

  // Candidates: as placed, the hull facets, the sphere; near-duplicates (within 2°) dropped.
  OrientResult result;
  auto add = [&](const Vec3& down, const char* source) {
    for (const OrientCandidate& c : result.candidates) {
      if (c.down.dot(down) > std::cos(2 * kDeg)) {
        return;
      }
    }
    OrientCandidate c;
    c.source = source;
    c.down = down.normalized();
    c.rotation = rotationTakingDownToMinusZ(c.down);
    result.candidates.push_back(c);
  };
  add(-Vec3::UnitZ(), "keep");
  if (o.hullCandidates > 0) {
    for (const Vec3& n : hullFacetNormals(surface, o.hullCandidates)) {
      add(n, "hull");
    }
  }
  for (const Vec3& d : fibonacciSphere(o.sphereCandidates)) {
    add(d, "sphere");
  }
  // On the plate (on a pedestal when one is asked for every candidate) and, where it may help,
  // on a pedestal too: at once where the part cannot stand, after the first pass where the plate
  // is in the nozzle's way.
  const size_t directions = result.candidates.size();
  auto setBase = [&](OrientCandidate& c, double pedestal) {
    c.pedestal = pedestal;
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -lowest;
    for (const Vec3& p : surface.points) {
      const double z = c.rotation.row(2).dot(p);
      lowest = std::min(lowest, z);
      highest = std::max(highest, z);
    }
    c.height = highest - lowest + pedestal;
    c.fitsHeight = !(o.maxHeight > 0) || c.height <= o.maxHeight;
    // On a pedestal: the column's cross-section as addPedestal will build it (its footprint
    // leaves out the faces at pinches and sharp corners: a genus-3 block's side measured
    // 10.4 mm² of faces near its lowest point, the column built on them 4.2 mm²).
    c.baseArea = pedestal > 0 ? pedestalFootprintArea(surface, c.rotation, o.pedestalContactHeight)
                              : baseContactArea(surface, c.rotation, o.contactHeight);
  };
  auto addPedestal = [&](size_t i) {
    OrientCandidate c = result.candidates[i];
    setBase(c, o.pedestalHeight);
    result.candidates.push_back(c);
  };
  for (size_t i = 0; i < directions; ++i) {
    setBase(result.candidates[i], o.pedestal == PedestalChoice::Always ? o.pedestalHeight : 0.0);
    if (o.pedestal == PedestalChoice::WhenItHelps &&
        result.candidates[i].baseArea < o.minBaseArea) {
      addPedestal(i);
    }
  }
  progress.report(0.02);

  // One coarse mesh for all candidates (rotation changes no tet).
  TetrahedralizeOptions tetOptions;
  tetOptions.autoTargetTets = o.evaluationTets;
  // A coarse mesh from well-shaped triangles of its own size (remeshed, as every mesh by
  // default): after an edge collapse TetGen made 202k tets in 12 s of a genus-3 block, 18k in
  // 0.2 s after remeshing. Nothing finer than the coarse mesh needs is kept.
  tetOptions.simplifyFinerThan = 1.0;
  TetrahedralizeResult tets = tetrahedralizeSurface(surface, tetOptions);
  // A thin wall or fine teeth make the count follow the surface's triangles (a generated 2 mm
  // curved wall: 573,778 tets for 15k; a 2.5 mm bowl 146k, a gear 122k), and every evaluation
  // costs in proportion: mesh again, while that helps, with the simplified surface made coarser
  // by the square root of the overshoot (a surface-bound count goes as 1/edge^2; 1.5x to 3x).
  // The surface simplified for the first mesh is the input of the next one: simplifying the
  // part's own surface again took 10-44 s each on 250k-550k triangles, this one 0.3-0.6 s.
  // (Not when the surface was meshed without TetGen's bounds: no edge length changes that mesh.)
  // The mesh in hand is kept when the longer edge fails (a 20-tooth gear at 33 mm: TetGen past
  // its time limit) or leaves too few tets to score anything (a 1M-triangle blob: 93 tets).
  TriangleSurface simplified;  // the surface the mesh in hand was made from, when simplified
  for (int again = 0; again < 2 && !tets.qualityBoundDropped &&
                      tets.mesh.tets.size() > kCoarseOvershoot * o.evaluationTets;
       ++again) {
    if (tets.simplified) {
      simplified = std::move(tets.simplifiedSurface);
    }
    const double overshoot =
        static_cast<double>(tets.mesh.tets.size()) / static_cast<double>(o.evaluationTets);
    TetrahedralizeOptions longer = tetOptions;
    longer.targetEdgeLength =
        tets.simplified ? std::clamp(std::sqrt(overshoot), 1.5, 3.0) * tets.simplificationEdgeLength
                        : 2.0 * tets.targetEdgeLength;
    TetrahedralizeResult coarser;
    try {
      coarser = tetrahedralizeSurface(simplified.triangles.empty() ? surface : simplified, longer);
    } catch (const GeoLatticeError&) {
      break;
    }
    if (coarser.mesh.tets.size() >= tets.mesh.tets.size() ||
        coarser.mesh.tets.size() * kCoarseOvershoot < static_cast<size_t>(o.evaluationTets)) {
      break;
    }
    tets = std::move(coarser);
  }
  result.evaluationTets = static_cast<int>(tets.mesh.tets.size());
  progress.report(0.1);

  // Each worker its own set-up of the fields (the heat and Laplacian factorizations) and its
  // own solves, side by side: the BLAS on one thread each until the search ends.
  const SingleThreadedBlas oneBlasThreadPerWorker;
  const int workers = workerCount(o.threads, result.candidates.size());
  std::vector<std::unique_ptr<GeodesicDistanceFields>> gdf(workers);
  parallelFor(static_cast<size_t>(workers), workers, [&](size_t w, int) {
    GeodesicFieldOptions fields;
    fields.dirichletGamma = false;  // a source set per candidate: no factorization each
    fields.factorTogether = false;  // the workers already take the cores
    gdf[w] = std::make_unique<GeodesicDistanceFields>(tets.mesh, fields);
  });
  progress.report(0.15);

  // Scores the candidates `ids` at `at` on the workers, reporting over [lo, hi].
  auto score = [&](const std::vector<size_t>& ids, const Evaluation& at, double lo, double hi) {
    const ProgressReporter part = progress.part(lo, hi);
    parallelFor(
        ids.size(), workers,
        [&](size_t k, int w) {
          OrientCandidate& c = result.candidates[ids[k]];
          const auto start = Clock::now();
          try {
            evaluate(c, *gdf[w], o, at);
            c.evaluated = true;
            c.feasible = c.baseArea >= o.minBaseArea;
          } catch (const GeoLatticeError& e) {
            c.error = e.what();
            c.evaluated = c.feasible = false;
          }
          c.seconds += seconds(start);
        },
        [&](size_t done) { part.report(static_cast<double>(done) / ids.size()); });
  };
  // A large part is scored at a resolution its size scales (see evaluationScale): the same
  // layers and lattice per candidate, relative to the part, as a part of kFullResolutionVolume.
  result.evaluationScale = evaluationScale(tets.meshVolume);
  const double f = result.evaluationScale;
  const Evaluation coarse{f * o.layerInterval, f * o.latticeWidth, SequenceStrategy::Greedy,
                          f * o.sampleSpacing};
  // Candidates that cannot stick to the plate are not worth the stages; "keep" is always scored.
  auto worthScoring = [&](size_t begin, size_t end) {
    std::vector<size_t> ids;
    for (size_t i = begin; i < end; ++i) {
      if (i == 0 || result.candidates[i].baseArea >= o.minBaseArea) {
        ids.push_back(i);
      }
    }
    return ids;
  };
  const bool refine = o.refineCandidates > 0;
  score(worthScoring(0, result.candidates.size()), coarse, 0.15, refine ? 0.6 : 0.85);
  if (o.pedestal == PedestalChoice::WhenItHelps) {
    const size_t before = result.candidates.size();
    for (size_t i = 0; i < directions; ++i) {
      // The placement too where only the tilt clears the plate: on a pedestal it needs none.
      const OrientCandidate& c = result.candidates[i];
      if (c.feasible && c.plateStations + c.tiltClearedPlateStations > 0) {
        addPedestal(i);
      }
    }
    score(worthScoring(before, result.candidates.size()), coarse, refine ? 0.6 : 0.85,
          refine ? 0.7 : 1.0);
  }

  // The refinement: the best of the coarse pass and the part as placed at the printing
  // resolution.
  if (refine) {
    std::vector<size_t> ranked;
    for (size_t i = 0; i < result.candidates.size(); ++i) {
      if (result.candidates[i].feasible) {
        ranked.push_back(i);
      }
    }
    std::stable_sort(ranked.begin(), ranked.end(), [&](size_t a, size_t b) {
      return better(result.candidates[a], result.candidates[b]);
    });
    ranked.resize(std::min<size_t>(ranked.size(), static_cast<size_t>(o.refineCandidates)));
    // The part as placed too, so that before and after compare at the same resolution.
    if (std::find(ranked.begin(), ranked.end(), size_t{0}) == ranked.end() &&
        result.candidates[0].evaluated) {
      ranked.push_back(0);
    }
    for (size_t i : ranked) {
      result.candidates[i].coarseCollidingStations = result.candidates[i].collidingStations;
    }
    score(ranked,
          Evaluation{f * o.refineLayerInterval, f * o.refineLatticeWidth, o.refineStrategy,
                     f * o.sampleSpacing},
          0.7, 1.0);
    for (size_t i : ranked) {
      result.candidates[i].refined = result.candidates[i].evaluated;
    }
    result.refined = static_cast<int>(ranked.size());
  }
  for (OrientCandidate& c : result.candidates) {
    if (!c.refined) {
      c.coarseCollidingStations = c.collidingStations;
    }
  }

  // Rank.
  const size_t n = result.candidates.size();
  std::vector<int> order(n);
  for (size_t i = 0; i < n; ++i) {
    order[i] = static_cast<int>(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return better(result.candidates[a], result.candidates[b]);
  });
  for (size_t r = 0; r < n; ++r) {
    result.candidates[order[r]].rank = static_cast<int>(r);
  }
  result.best = order[0];
  result.seconds = seconds(t0);
  if (!result.candidates[result.best].feasible) {
    const auto widest = std::max_element(
        result.candidates.begin(), result.candidates.end(),
        [](const OrientCandidate& a, const OrientCandidate& b) { return a.baseArea < b.baseArea; });
    std::ostringstream m;
    if (widest->baseArea >= o.minBaseArea && !widest->error.empty()) {
      // Enough contact exists: a stage failed on the candidates that have it (e.g. a body that
      // touches no base in any orientation). Its message is the reason, not the area.
      m << "orientation: every orientation with a base contact area of at least " << o.minBaseArea
        << " mm^2 failed a stage; with the part's side (" << widest->down.x() << ", "
        << widest->down.y() << ", " << widest->down.z() << ") down (" << widest->baseArea
        << " mm^2): " << widest->error;
      throw GeoLatticeError(m.str());
    }
    m << "orientation: no orientation has a base contact area of " << o.minBaseArea
      << " mm^2 (the largest is " << widest->baseArea << " mm^2, with the part's side ("
      << widest->down.x() << ", " << widest->down.y() << ", " << widest->down.z() << ") down"
      << (widest->pedestal > 0 ? ", on a pedestal reaching " +
                                     std::to_string(o.pedestalContactHeight) + " mm into it"
                               : std::string())
      << "); lower MinBaseArea or give the part a flat side";
    throw GeoLatticeError(m.str());
  }
  return result;
}

}  // namespace geolattice
