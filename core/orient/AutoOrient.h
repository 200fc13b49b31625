#pragma once
/// @file AutoOrient.h
/// @brief Automatic orientation of a part on the build plate (the "free base selection" the
/// paper names as future work, Section 5): which side of the part faces down.
///
/// Data flow: placed surface (mm) -> one coarse tet mesh (TetGen, ~15k tets) and one set-up of the
/// geodesic fields (the FEM operators and the heat factorization do not change under rotation)
/// -> for every candidate down direction d: rotate d onto -z and place the part on the plate ->
/// the real stages on the coarse mesh: γ from the lowest vertices (heat method), the curved
/// layers, the lattice, the skeleton tree, the paper's A4 order and the independent collision
/// verifier with the configured nozzle and the build plate -> scores -> the best candidate by a
/// lexicographic objective.
///
/// Candidates: `sphereCandidates` directions of a Fibonacci sphere (uniform), the outward
/// normals of the largest convex-hull facets (a part lying on a facet of its hull sits flat), and
/// the part as placed ("keep", always candidate 0).
///
/// A pedestal (pedestal/Pedestal.h) widens the search: a direction whose part cannot stand on the
/// plate (a curved or pointed bottom: less than minBaseArea of contact), or whose nozzle meets the
/// plate at some station, is also tried standing pedestalHeight mm up on a column of its lowest
/// pedestalContactHeight mm (PedestalChoice::WhenItHelps, the default). Such a candidate is scored
/// on the same coarse mesh: γ grows from those lowest vertices (the column's top), the part is
/// lifted by the height over the plate, the column's own planar layers are not scored. Its base
/// area is the column's cross-section (pedestalFootprintArea: the footprint addPedestal builds).
///
/// Two passes. The coarse pass scores every candidate at layerInterval / latticeWidth; the best
/// refineCandidates of it and the part as placed are then scored again at the printing layer
/// interval, lattice width and order (refineLayerInterval, refineLatticeWidth, refineStrategy:
/// the coarse pass uses the paper's A4, the print by default the rollout) on the same mesh, where
/// sub-graphs and their mutual blocking are those the print will have (the coarse lattice can
/// rank two candidates the other way round). The choice is the best refined candidate.
///
/// Objective, lexicographic (earlier criteria decide; refined candidates rank before the others):
///   1. the base contact area is at least minBaseArea (the part sticks to the plate or its
///      pedestal's column is that wide);
///   2. fewest strict collision stations (material or plate inside the nozzle, the verifier on
///      the printing order of the evaluation lattice; for the part as placed on the plate, a
///      plate station whose nozzle the toolpath's tilt, at most maxTiltDeg towards +z, lifts
///      wholly off the plate is not counted); then, with a maxHeight, the part with its
///      pedestal no taller than that (the robot cell holds no taller part: tallestPart; a side
///      that collides less is still preferred, the robot gate's tries then go on);
///   3. fewest forced steps of the order (sub-graphs that block each other);
///   4. no pedestal (it costs material and a cut) over a pedestal;
///   5. the smallest curved-layer overhang fraction (surface that needs support, paper Fig. 8);
///   6. the fewest layers;
///   7. the part as placed, then the larger base area.
/// When no candidate has the base area, the search fails naming the best area found.
#include "gdf/HeatSources.h"
#include "lattice/LatticeInfill.h"
#include "mesh/TetMesh.h"
#include "nozzle/BuildPlate.h"
#include "nozzle/NozzleModel.h"
#include "sequence/PrintSequencer.h"
#include "slicer/CurvedLayerSlicer.h"
#include "toolpath/NozzleAxisClearance.h"

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

namespace geolattice {

/// Whether the search may stand a candidate on a pedestal.
enum class PedestalChoice {
  Never,        ///< every candidate stands on the plate
  WhenItHelps,  ///< also on a pedestal where the part cannot stand or the plate is in the way
  Always        ///< every candidate on a pedestal (the user asked for one)
};

struct OrientOptions {
  int sphereCandidates = 100;  ///< Fibonacci sphere directions (>= 0)
  int hullCandidates = 24;     ///< normals of the largest convex-hull facets (>= 0)
  double minBaseArea = 10.0;   ///< mm² of contact with the plate a candidate needs (>= 0)
  /// mm (>= 0; 0 = no limit): sides on which the part with its pedestal stands taller than this
  /// rank after the sides that fit and collide as little (objective 2), e.g. the robot cell's
  /// tallest part (robot/RobotPathSolver.h tallestPart: a taller one's top layers need the arm
  /// below the floor).
  double maxHeight = 0.0;
  double contactHeight = 0.3;  ///< faces within this height of the lowest point touch (mm): half
                               ///< a first layer, squeezed onto the plate
  int evaluationTets = 15000;  ///< tets of the coarse evaluation mesh
  double layerInterval = 1.5;  ///< layer spacing of the evaluation (mm, > 0; coarser than printing)
  double latticeWidth = 8.0;   ///< lattice width of the evaluation (mm, > 0)
  double sampleSpacing = 2.0;  ///< material samples of the evaluation's collision check (mm)
  /// The base: vertices this close to the lowest point (mm).
  double baseTolerance = BaseOptions{}.tolerance;
  /// The base's near-flat bottom too: downward faces this close to the lowest point (mm, >= 0;
  /// sourcesNearLowestZ with a flat band), as the print's fields take it.
  double baseFlatBand = BaseOptions{}.flatBand;
  double overhangThresholdDeg = 135.0;
  PedestalChoice pedestal = PedestalChoice::WhenItHelps;
  double pedestalHeight = 10.0;  ///< height of a pedestal under a candidate (mm, > 0)
  /// A pedestal's column reaches this far up into the part (mm, > 0): its cross-section, the base
  /// area of a candidate on a pedestal, is the downward faces this close to the lowest point. The
  /// part's lowest pedestalContactHeight mm are printed as the column's top and cut off with it.
  double pedestalContactHeight = 1.0;
  int refineCandidates = 4;  ///< best coarse candidates scored again (>= 0; 0 = coarse only)
  double refineLayerInterval = SlicerOptions{}.interval;    ///< layers of the refinement (mm, > 0)
  double refineLatticeWidth = LatticeOptions{}.alphaWidth;  ///< its lattice width (mm, > 0)
  SequenceStrategy refineStrategy = SequenceOptions{}.strategy;  ///< its printing order
  /// The toolpath's largest axis tilt off the layer normal (deg, in [0, 60]): a plate station
  /// of the part as placed whose nozzle a tilt this large towards +z lifts off the plate is not
  /// counted (objective 2).
  double maxTiltDeg = AxisClearanceOptions{}.maxTiltDeg;
  NozzleModel nozzle;  ///< the configured nozzle
  BuildPlate plate;    ///< the build plate (an obstacle when enabled)
  int threads = 0;     ///< candidates evaluated in parallel; 0 = hardware concurrency
  std::function<void(double)> progress;  ///< fraction done (calling thread). Optional.
  std::function<bool()> shouldAbort;     ///< true stops with "orientation search aborted".
  /// Throws GeoLatticeError naming a bad option.
  void validate() const;
};

/// One candidate orientation and its scores.
struct OrientCandidate {
  std::string source;          ///< "keep", "hull" or "sphere"
  Vec3 down = -Vec3::UnitZ();  ///< the part's direction (as placed) that faces the plate
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< as placed -> printed (down -> -z)
  double pedestal = 0;    ///< mm of pedestal under the part (0: it stands on the plate)
  double baseArea = 0;    ///< mm² touching the plate (with a pedestal: the column's cross-section)
  bool feasible = false;  ///< baseArea >= minBaseArea (and evaluated)
  bool evaluated = false;           ///< the stages ran (skipped below the base area)
  long long collidingStations = 0;  ///< strict verifier, printing order of the coarse lattice
  long long plateStations = 0;      ///< of those, where the nozzle meets the plate
  /// The placement's plate stations the toolpath's tilt lifts off the plate (not counted above)
  long long tiltClearedPlateStations = 0;
  long long stations = 0;  ///< stations checked
  int forcedSteps = 0;
  double overhangFraction = 0;  ///< curved-layer overhang area fraction
  int layers = 0;
  double height = 0;  ///< part height in this orientation (mm, the surface's, with the pedestal)
  bool fitsHeight = true;  ///< height <= OrientOptions::maxHeight (or no limit)
  double seconds = 0;
  bool refined = false;  ///< scored again at the printing resolution (the scores above are those)
  long long coarseCollidingStations = 0;  ///< collidingStations of the coarse pass
  std::string error;  ///< a stage that failed on this candidate (then it is not feasible)
  int rank = -1;      ///< 0 = best
};

struct OrientResult {
  std::vector<OrientCandidate> candidates;  ///< candidate 0 is "keep" on the plate
  int best = 0;                             ///< index of the chosen candidate
  int evaluationTets = 0;                   ///< tets of the coarse mesh
  /// Factor on the evaluations' layer intervals, lattice widths and sample spacing (1 up to
  /// kFullResolutionVolume; see evaluationScale).
  double evaluationScale = 1;
  int refined = 0;  ///< candidates scored at the printing resolution
  double seconds = 0;
};

/// Volume (mm³) up to which the candidates are scored at the given resolutions (the coarse
/// pass's and the print's): a little above the largest bundled part (topopt, 182,000 mm³; the
/// bunny at 80 mm is 102,000 mm³), whose search takes 9-20 s on 2 cores.
constexpr double kFullResolutionVolume = 200000;

/// The factor by which a part of `volume` mm³ is scored coarser: 1 up to kFullResolutionVolume,
/// then sqrt(volume / kFullResolutionVolume). Why: an evaluation's layers times lattice lines
/// grow as volume / (layer interval x lattice width), so both (and the material samples'
/// spacing) scaled by this factor keep a large part's evaluation no larger than one of
/// kFullResolutionVolume (the bunny at 300 mm: 3.0M
/// stations and 38 s per refined candidate, a 251 s search, at the print's resolution; 5.4 s
/// scaled, the same side chosen). The
/// geometry the 45° cone sees is the same at every scale: a part scaled up and scored at a
/// resolution scaled alike is scored as the smaller one.
double evaluationScale(double volume);

/// Outward normals of the convex hull's facets of `surface`, coplanar ones (within 2°) merged,
/// the `count` of largest area first: on such a facet the part sits flat on the plate. The
/// result depends only on the hull's facets, not on their order in CGAL's hull (nor on the
/// order of the surface's points).
std::vector<Vec3> hullFacetNormals(const TriangleSurface& surface, int count);

/// Rotation that turns `down` onto -z by the smallest angle.
Eigen::Matrix3d rotationTakingDownToMinusZ(const Vec3& down);

/// Area of the faces of `surface` (rotated by R) within contactHeight of its lowest point and
/// facing down (outward normal within 30° of -z): the contact with the plate (mm²).
double baseContactArea(const TriangleSurface& surface, const Eigen::Matrix3d& R,
                       double contactHeight);

/// The search (see the file comment). `surface` is the placed, closed part in mm. Throws
/// GeoLatticeError for bad options, a surface TetGen cannot mesh, or no candidate with the
/// minimum base area (naming the largest area found and its direction).
OrientResult searchOrientation(const TriangleSurface& surface, const OrientOptions& options);

/// `surface` rotated by R and moved so its lowest point is at z = 0 with the x/y centre of its
/// bounding box where the original one was.
TriangleSurface orientSurface(const TriangleSurface& surface, const Eigen::Matrix3d& R);

}  // namespace geolattice
