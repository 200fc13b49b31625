#pragma once
/// @file SurfaceCheck.h
/// @brief Validity checks of a triangle surface before it is tetrahedralized: closedness
/// (watertight), edge-manifoldness, consistent orientation, degenerate triangles, index range
/// and the enclosed signed volume.
///
/// Data flow: input surface (reader / VTK polydata) -> checkSurface / requireClosedManifold ->
/// orientOutward (explicit repair of an inward-oriented surface) -> TetrahedralizeSurface.
#include "mesh/TetMesh.h"

#include <array>
#include <vector>

namespace geolattice {

/// @brief An edge that keeps a surface from being a closed manifold.
struct SurfaceDefectEdge {
  enum Kind { Boundary = 0, NonManifold = 1, Inconsistent = 2 };
  int lo = -1, hi = -1;  ///< its point ids, lower first
  Kind kind =
      Boundary;  ///< used by one triangle, by more than two, or traversed the same way twice
};

/// @brief Counts of surface defects. Edges are undirected vertex pairs of in-range triangles.
struct SurfaceCheckReport {
  int pointCount = 0;
  int triangleCount = 0;
  int outOfRangeTriangles = 0;  ///< triangles with a vertex index < 0 or >= pointCount
  int firstOutOfRangeTriangle = -1;
  int nonFinitePoints = 0;  ///< points with a NaN or infinite coordinate
  int firstNonFinitePoint = -1;
  int degenerateTriangles = 0;  ///< area <= 1e-12 * (bounding-box diagonal)^2, or a repeated vertex
  int firstDegenerateTriangle = -1;
  int boundaryEdges = 0;                           ///< edges used by exactly one triangle (holes)
  std::array<int, 2> firstBoundaryEdge{{-1, -1}};  ///< its two point ids (lower first)
  int nonManifoldEdges = 0;                        ///< edges used by more than two triangles
  std::array<int, 2> firstNonManifoldEdge{{-1, -1}};
  int inconsistentEdges = 0;  ///< edges whose two triangles traverse it in the same direction
  int unusedPoints = 0;       ///< points no triangle references (harmless, reported only)
  double signedVolume = 0.0;  ///< enclosed volume (mm^3) by the divergence theorem; < 0 if inward
  double bboxDiagonal = 0.0;  ///< bounding-box diagonal of the finite points (mm)
  /// Every boundary, non-manifold and inconsistently oriented edge, sorted by point ids (what
  /// GL Surface Check shows, so a user sees where to repair).
  std::vector<SurfaceDefectEdge> defectEdges;

  /// True when the surface is non-empty, closed, edge-manifold, consistently oriented, with
  /// in-range indices, finite points and no degenerate triangles (orientation not required).
  bool isClosedManifold() const;
};

/// @brief Count every defect listed in SurfaceCheckReport. Never throws; O(F log F).
SurfaceCheckReport checkSurface(const TriangleSurface& surface);

/// @brief Throw GeoLatticeError naming the first problem found, in this order: empty surface,
/// out-of-range indices, non-finite coordinates, open surface (boundary edges), non-manifold
/// edges, inconsistently oriented triangles, degenerate triangles, zero enclosed volume.
/// An inward-oriented but otherwise valid surface (negative volume) is accepted: the surface
/// is const here, so callers flip it with orientOutward() (TetrahedralizeSurface does).
/// @return the report of the accepted surface.
SurfaceCheckReport requireClosedManifold(const TriangleSurface& surface);

/// @brief Documented repair: if the enclosed signed volume is negative (a closed, consistently
/// oriented surface whose normals point inward), reverse every triangle. Returns the number of
/// triangles flipped (0 when already outward). Call after requireClosedManifold().
int orientOutward(TriangleSurface& surface);

/// @brief The surface with only the points its triangles use, renumbered in order of first use
/// (the triangles as they are, on the new numbers). O(F).
TriangleSurface withoutUnusedPoints(const TriangleSurface& surface);

/// @brief Generalized winding number at q of the surface's triangles (of `triangles` only, when
/// given): 1 inside a closed outward shell, 0 outside it, -1 inside an inward one; sums over
/// nested shells. Solid angles by Van Oosterom & Strackee (1983). O(triangles).
double windingNumber(const TriangleSurface& surface, const Vec3& q,
                     const std::vector<int>* triangles = nullptr);

}  // namespace geolattice
