#pragma once
/// @file SurfaceSimplification.h
/// @brief Coarsening a closed triangle surface to the edge length the tet mesh needs, before
/// TetGen: TetGen keeps every input triangle, so a 1M-triangle scan or CAD export gives millions of
/// tets (and minutes of meshing) although the heat method and the layers need ~75k. CGAL's
/// edge-collapse simplification (Garland-Heckbert quadric cost and placement, each new vertex
/// within `tolerance` of the input surface, no collapse that flips a face normal by more than
/// 90°) reduces it to about the target edge length, keeping it closed and edge-manifold; the
/// result is refused (the input returned unchanged) if it self-intersects.
///
/// Or, with SimplificationMethod::IsotropicRemeshing, CGAL's isotropic remeshing to
/// remeshEdgeFactor x the target edge length (edge splits, collapses, flips and tangential
/// relaxation, vertices projected back onto the input; edges sharper than sharpAngleDeg kept as
/// constraints): well-shaped triangles of about that length whatever the input's triangulation.
/// It runs where the edge collapse would (an input finer than finerThan x the target) and also
/// on a coarse input full of slivers (CAD needles). A remeshed surface farther than the
/// tolerance from the input (a sharp tip cut off) is remeshed again with the input kept as it is
/// within one remeshed edge of the far vertices (at most twice, when those are few); one still
/// too far, or self-intersecting, is refused and the surface is remeshed for shorter edges (by
/// factors of sqrt 2 down to a third), within the same tolerance (rounded features narrower than the edge all
/// over: a gear's teeth, a cone's rounded tip); when those are refused too, the edge collapse
/// runs instead (for a finer input) or the input stays. A collapse that leaves a surface full of needles (it keeps the
/// distance by sliding vertices along a cone's or a cylinder's straight lines) is refused too,
/// unless the input had them already. Why: TetGen keeps every input triangle
/// and refines around small and thin ones; a well-shaped surface at the tets' size meshes in a
/// fraction of the time and near the asked count (a generated genus-3 block, 17k triangles, 75k
/// target: 15.0 s after the collapse was refused, 0.78 s remeshed; the 1M-triangle torus: 33 s ->
/// 16 s, its surface 29 -> 14 s).
#include "mesh/TetMesh.h"

#include <functional>

namespace geolattice {

enum class SimplificationMethod {
  EdgeCollapse,       ///< Garland-Heckbert edge collapse, when the input is finer
  IsotropicRemeshing  ///< remeshing where it helps, the edge collapse where it is refused
};

struct SimplificationOptions {
  SimplificationMethod method = SimplificationMethod::IsotropicRemeshing;
  double sharpAngleDeg = 60;  ///< remeshing: edges whose faces meet sharper than this are kept
  /// Remeshing: the surface's edge length over targetEdgeLength. TetGen's boundary triangles come
  /// out a little shorter than its interior edges: 0.7 gives the asked tet count within 20 % on
  /// a genus-3 block at 15k and 75k tets.
  double remeshEdgeFactor = 0.7;
  double targetEdgeLength = 0;  ///< mm (> 0): the mean edge length aimed at
  /// Largest distance of a new vertex from the input surface (mm); 0 = a quarter of the target
  /// edge length.
  double tolerance = 0;
  /// Simplify only when the input's mean edge length is below this fraction of the target.
  double finerThan = 0.5;
  /// Polled every 4096 collapses; true stops with GeoLatticeError "surface simplification
  /// aborted". Optional.
  std::function<bool()> shouldAbort;
  /// Called with the fraction of the collapses done (the count is known from the target).
  /// Optional.
  std::function<void(double)> progress;
};

struct SimplificationResult {
  TriangleSurface surface;
  bool simplified = false;  ///< false: the input was coarse enough (or the result was refused)
  size_t inputTriangles = 0, outputTriangles = 0;
  double inputMeanEdge = 0, outputMeanEdge = 0;  ///< mm
  /// Largest distance from an input vertex to the output surface (mm): a sampled one-sided
  /// Hausdorff distance.
  double hausdorff = 0;
  double seconds = 0;
  /// Why the surface remeshed for the target edge (or else the collapse) was refused: empty when
  /// it was used or not tried. Also set when a shorter remeshing edge was then used.
  std::string refused;
  double remeshEdgeLength = 0;  ///< edge of the remeshed output (mm; 0: not remeshed)
};

/// Mean edge length of a triangle surface (mm).
double meanEdgeLength(const TriangleSurface& surface);

/// Simplifies `surface` (closed, edge-manifold, consistently oriented) when it is much finer than
/// the target. Throws GeoLatticeError for a bad target edge length.
SimplificationResult simplifySurface(const TriangleSurface& surface,
                                     const SimplificationOptions& options);

}  // namespace geolattice
