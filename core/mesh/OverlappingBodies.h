#pragma once
/// @file OverlappingBodies.h
/// @brief Merges the bodies of a surface whose shells cross each other into one solid, before
/// it is tetrahedralized.
///
/// CAD exports of assemblies and quick models often hold closed bodies that overlap (a boss sunk
/// into a plate, a handle pushed into a mug): each is a valid closed manifold, together they are a
/// self-intersecting surface that TetGen refuses, while the part meant is their union (what
/// desktop slicers print). A body is a connected component (triangles sharing vertices). Two
/// bodies whose surfaces intersect are replaced by their union (CGAL Polygon Mesh Processing
/// corefinement, exact predicates); nested shells that do not touch (a cavity, a body inside
/// another) are left as they are.
///
/// Cost: the components in O(F); CGAL's surface intersection test (AABB trees, O(F log F)) only
/// for pairs whose bounding boxes overlap, and the union only for pairs that cross. A surface of
/// one body is returned unchanged after the component pass.
#include "mesh/TetMesh.h"

namespace geolattice {

struct OverlappingBodiesResult {
  int bodies = 0;  ///< bodies (connected components) of the input
  int merged = 0;  ///< of those, bodies merged into another (the output has bodies - merged)
};

/// Merges every pair of bodies of `surface` whose surfaces intersect (repeatedly, so a chain of
/// three overlapping bodies becomes one); the surface is replaced only when something merged.
/// Every body must be closed and consistently oriented (requireClosedManifold holds for the whole
/// surface). Throws GeoLatticeError when a crossing body is oriented inward (a cavity's shell
/// that crosses another body: no union is meant) or crosses itself, or CGAL cannot build a
/// closed union.
OverlappingBodiesResult mergeOverlappingBodies(TriangleSurface& surface);

/// Bodies that touch along a face, welded into one surface by the reader's exact point merging
/// (an STL of a multi-body CAD part has no shared vertices; merged, the touching bodies' edges are
/// used by more than two triangles), replaced by their union. Faces triangulated alike on both
/// sides (bodies split from one solid) are pairs of triangles on the same vertices in opposite
/// directions: the pairs are dropped. Otherwise triangles are grouped into bodies
/// across the edges two triangles share in opposite directions; when there are non-manifold
/// edges and every group is a closed body, each gets its own vertices, the surface is oriented
/// outward and mergeOverlappingBodies unions them. The surface is replaced only when that gives a
/// closed manifold (bodies that touch along an edge or at a point have no manifold union: the
/// input stays as it is, and its non-manifold edges are reported by the caller's check).
/// Returns the bodies merged (0: unchanged; for dropped walls, their connected patches); the
/// new surface has only the triangles' vertices. Cost: one checkSurface (O(F log F)) when nothing is
/// non-manifold. mesh/SurfaceRepair.h runs it after the repairs that must come first.
int mergeTouchingBodies(TriangleSurface& surface);

}  // namespace geolattice
