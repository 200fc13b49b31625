#pragma once
/// @file TetrahedralizeSurface.h
/// @brief Quality tetrahedral mesh of the solid enclosed by a closed triangle surface, with
/// TetGen 1.5 (constrained Delaunay + Delaunay refinement). The paper (Li et al., Sec. 3)
/// computes its geodesic distance fields on such a tet mesh of the input part.
///
/// Data flow: closed surface (mm) -> requireClosedManifold (+ orientOutward) -> TetGen in a
/// child process (TetGenRunner: intersection test "pdQ", then "pq<ratio>a<volume>AQ"; the
/// boundary may be refined: no "Y"; "pAQ" when no such run finishes in time) -> regions
/// outside the solid (cavities of hollow parts, winding number 0) removed -> tets reoriented
/// to positive volume -> requireValidTetMesh -> TetMesh for the GDF stages.
#include "mesh/SurfaceRepair.h"
#include "mesh/SurfaceSimplification.h"
#include "mesh/TetMesh.h"

#include <functional>
#include <string>

namespace geolattice {

/// @brief Parameters of tetrahedralizeSurface().
struct TetrahedralizeOptions {
  /// Target edge length (mm). It sets TetGen's maximum tet volume to that of a regular tet with
  /// this edge, L^3 / (6 sqrt 2). Must be >= 0 and finite. 0 = automatic: TetGen runs with the
  /// edge length automaticEdgeLength(enclosed volume, autoTargetTets); if the tet count misses
  /// autoTargetTets by more than a factor 1.25, the edge length is corrected from the measured
  /// counts (secant on log count vs log length) and TetGen runs again, at most
  /// kMaxAutoAttempts times in all; the run closest to the target is returned. A run at
  /// kSpeculativeEdgeFactor x the first edge is meshed beside the first run and read first:
  /// within the tolerance it is the result, above it the search goes on from it (the first run
  /// is stopped), below it it is the first correction of a first run above the tolerance
  /// (autoTargetTets <= kSpeculativeMaxTargetTets). (The count is
  /// not a function of the volume alone: the refinement near a finely triangulated surface adds
  /// tets that no volume bound removes, e.g. ~46k tets for the 3674-triangle bunny.)
  double targetEdgeLength = 0.0;
  /// Tet count the automatic edge length aims at; used only when targetEdgeLength == 0.
  /// Range [kMinAutoTargetTets, kMaxAutoTargetTets].
  int autoTargetTets = 75000;
  /// Upper bound of the tets' circumradius / shortest-edge ratio (TetGen switch -q).
  /// Range [kMinRadiusEdgeRatio, kMaxRadiusEdgeRatio]; 1.414 = sqrt 2 (good quality).
  double radiusEdgeRatio = 1.414;
  /// A surface whose mean edge is shorter than this fraction of the (first) target edge length
  /// is first simplified to about the target edge (mesh/SurfaceSimplification.h): TetGen keeps
  /// every input triangle, so a fine scan would give far more tets than asked for. 0 = never.
  double simplifyFinerThan = 0.5;
  /// How the surface is prepared (mesh/SurfaceSimplification.h): isotropic remeshing to the
  /// first target edge where it is finer than simplifyFinerThan x that edge or full of slivers,
  /// checked against a quarter of the edge, else the edge collapse (the default), or the edge
  /// collapse alone. simplifyFinerThan 0 turns both off.
  SimplificationMethod simplification = SimplificationMethod::IsotropicRemeshing;
  /// Time limit of one TetGen run (s of the TetGen process's own CPU time, so that load on the
  /// machine does not change which runs finish: TetGenRunner.h); 0 = automatic: 10 s plus 40 us
  /// per expected tet (5x the time such a mesh takes; the unbounded run 125 us per surface
  /// triangle). A bounded run
  /// past it does not finish: TetGen's refinement does not end near a knife edge or a needle
  /// tip of the surface (a 2 mm thin ellipsoid: no -q or -a run finished within 40 s), and the
  /// surface is then meshed without the bounds (TetrahedralizeResult::qualityBoundDropped).
  /// Must be >= 0 and finite.
  double tetgenSecondsLimit = 0.0;
  /// Polled about every 50 ms while TetGen runs, and after each run; returning true stops it
  /// and throws "tetrahedralization aborted" (filters pass their AbortExecute flag). Optional.
  std::function<bool()> shouldAbort;
  /// Called on the calling thread with the fraction done: during the surface simplification
  /// (when it runs, the first 70 %), after each TetGen run (runs / kMaxAutoAttempts of 0.9 for
  /// the automatic edge length, 0.9 for a given one, of the rest) and 1 at the end. Optional.
  std::function<void(double)> progress;
  /// Throws GeoLatticeError naming the first parameter out of its range (cheap: no data).
  void validate() const;
};

/// @brief Mesh plus what was done to get it.
struct TetrahedralizeResult {
  TetMesh mesh;                   ///< positively oriented, validated (requireValidTetMesh)
  double targetEdgeLength = 0.0;  ///< edge length used (mm): the option, or the automatic choice
  double maxTetVolume = 0.0;      ///< TetGen volume bound (mm^3)
  double meanEdgeLength = 0.0;    ///< mean length of the output's unique edges (mm)
  double enclosedVolume = 0.0;    ///< divergence-theorem volume of the outward surface (mm^3);
                                  ///< nested outward shells count twice inside the inner one
  double meshVolume = 0.0;        ///< sum of tet volumes (mm^3)
  int tetCount = 0;
  int flippedSurfaceTriangles = 0;  ///< input triangles reversed because the surface faced inward
  /// The surface repairs done before meshing (mesh/SurfaceRepair.h); mergedBodies also counts
  /// bodies that cross another (mesh/OverlappingBodies.h), degenerateTriangles the union's slivers.
  SurfaceRepairCounts repairs;
  int flippedTets = 0;  ///< output tets reoriented (0 in practice: TetGen 1.5 writes positive tets)
  int removedCavityRegions =
      0;                  ///< regions TetGen filled with winding number 0 (cavities), removed
  int attempts = 0;       ///< TetGen runs (1 unless the edge length was automatic)
  int tetgenRetries = 0;  ///< extra runs: TetGen's output was invalid or it ran too long
  /// A speculative run at a longer edge was started beside the first automatic one (counted in
  /// attempts when it is the result, or the correction of a first run with too many tets).
  bool speculativeRun = false;
  /// The automatic search stopped above the target: a much longer edge left the count nearly
  /// unchanged, so the count is set by the surface (fine triangles or thin walls).
  bool surfaceBoundCount = false;
  size_t removedFlatTets = 0;  ///< zero-volume slivers dropped from TetGen's output
  /// No quality-bounded TetGen run finished within its time limit: the mesh is TetGen's
  /// constrained Delaunay tetrahedralization of the surface (switches "pAQ": no radius-edge or
  /// volume bound, no point added inside), its flat slivers removed; the count is then set by
  /// the surface (surfaceBoundCount) and the tets are not quality-shaped.
  bool qualityBoundDropped = false;
  double seconds = 0.0;        ///< wall time of the whole call
  bool simplified = false;     ///< the surface was simplified before TetGen
  size_t inputTriangles = 0;   ///< triangles of the input surface
  size_t meshedTriangles = 0;  ///< triangles given to TetGen
  /// Edge the meshed surface was prepared for (mm): the first target edge, or a shorter one
  /// (down to a third) when the remeshing for it was refused; 0 when TetGen got the input as it is.
  double simplificationEdgeLength = 0;
  double simplificationDistance = 0;  ///< largest input-vertex distance to them (mm)
  double simplificationSeconds = 0;
  /// The simplified surface TetGen meshed (about the mesh's size); empty when TetGen got the
  /// input as it is. A caller meshing again for a longer edge simplifies this one, not the input.
  TriangleSurface simplifiedSurface;
  /// Why the surface remeshed for the target edge was refused (mesh/SurfaceSimplification.h;
  /// then a shorter edge or the collapse was tried), or why TetGen failed on the prepared
  /// surface and meshed the input instead. Empty: nothing was refused.
  std::string simplificationRefused;
  std::string switches;  ///< TetGen switches used
};

/// Range of TetrahedralizeOptions::autoTargetTets.
constexpr int kMinAutoTargetTets = 1000;
constexpr int kMaxAutoTargetTets = 5000000;
/// Most TetGen runs of the automatic edge length search.
constexpr int kMaxAutoAttempts = 4;
/// The automatic search meshes a second, longer edge length (this times the first guess) beside
/// its first run (started when the surface's intersection test is done) and reads it first: within the tolerance it is the result
/// and the first run is killed unread; with too many tets the first run (finer still) is killed
/// too and the search corrects from the speculative run; with too few the first run is read, and
/// the speculative run is the search's second run when the first gave too many tets. The first guess gives too many
/// on parts whose surface triangles drive the refinement: 1.1-2.1x the target on 10 of 15
/// measured parts (bunny 80 mm 1.50x, spot 80 mm 1.61x, topopt 1.81x), too few only on the cube,
/// the ring and a mug, whose first runs are the cheap ones. At 1.45x bunny, topopt and a
/// generated wrench land within the 1.25x tolerance of 75k (1.35x left topopt at 105k, 1.4x at
/// 91k, the count jumps there); spot's count stays near 93k over 4.5-5.3 mm and takes a second
/// run (7.14 mm, 81k tets). On knight, Y and three-branch (first runs within the tolerance) it gives 46k, 33k and
/// 51k tets: below the tolerance, so the first run is read and used, as without it.
constexpr double kSpeculativeEdgeFactor = 1.45;
/// Above this target the speculative run is not started: two large TetGen runs at once would
/// double TetGen's memory (the first guess above 75k is calibrated separately).
constexpr int kSpeculativeMaxTargetTets = 250000;
/// Range of TetrahedralizeOptions::radiusEdgeRatio. TetGen itself accepts any number, but its
/// refinement is only proven to terminate for bounds >= 2; measured on the bunny at 100 mm
/// (edge 6 mm): q2 -> 47k tets, q1.414 -> 78k, q1.2 -> 170k, q1.1 -> 467k tets in 3.3 s,
/// q1.05 / q1.0 / q0.9 did not finish within 30 s. Above 10 the bound shapes nothing.
constexpr double kMinRadiusEdgeRatio = 1.1;
constexpr double kMaxRadiusEdgeRatio = 10.0;
/// Requests whose smallest plausible tet count exceeds this are refused before TetGen runs
/// (memory / time guard; ~1 GB of TetGen memory per 5M tets).
constexpr double kMaxEstimatedTets = 2.0e7;

/// @brief First guess of the automatic target edge length (mm) for a solid of the given
/// enclosed volume (mm^3): the edge L for which targetTets tets of mean volume
/// k * L^3 / (6 sqrt 2) fill the volume, k = 0.21 * max(1, targetTets / 75000)^0.22 (calibrated
/// with q1.414 on the bundled parts: ~0.5 on a box, 0.17-0.24 near 75k tets, 0.26-0.39 at
/// 139k-897k; see TetrahedralizeSurface.cpp). Throws on a non-positive volume or target.
double automaticEdgeLength(double enclosedVolume, int targetTets = 75000);

/// @brief Tetrahedralize the solid bounded by `surface` (closed, edge-manifold, consistently
/// oriented; an inward-oriented surface is flipped, see orientOutward()). Several shells are
/// allowed: disjoint parts are all meshed; an inner shell oriented inward is a cavity and stays
/// empty; an inner shell oriented outward is an interface: both sides are meshed and the shell
/// is a surface of the tet mesh (e.g. to make a heat-source region). Each region TetGen makes
/// is classified by the winding number of the surface (0 = cavity).
/// @throws GeoLatticeError for an invalid surface (see requireClosedManifold), invalid
/// options, an estimated tet count above kMaxEstimatedTets, a TetGen failure (e.g.
/// "self-intersecting surface: TetGen found 12 intersecting facets"), an inward shell outside
/// every other shell (winding number -1), or a mesh whose winding-weighted volume differs
/// from the enclosed volume by more than 1e-5 relative (TetGen changed the geometry, e.g.
/// merged nearly coincident vertices).
TetrahedralizeResult tetrahedralizeSurface(const TriangleSurface& surface,
                                           const TetrahedralizeOptions& options = {});

/// @brief What a mesh with TetrahedralizeResult::qualityBoundDropped is, for the user (the
/// filter's warning, the CLI's note).
std::string qualityBoundDroppedNote(int tetCount);

}  // namespace geolattice
