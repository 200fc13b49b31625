#pragma once
/// @file SurfaceRepair.h
/// @brief The documented repairs a surface as read gets before it is one closed solid, each done
/// only where its defect is there, so a valid surface passes through unchanged:
///  0. open seams no wider than rounding (a binary STL's float32 corners that differ in their
///     last bits on either side of an edge) are closed by welding their vertices (weldOpenSeams);
///  1. a triangle written twice (the same vertices, the same way round) loses its copies;
///  2. triangles traversed against their neighbours (an exporter that flipped some faces) are
///     turned to agree with them (CGAL's orient_polygon_soup; whole bodies still point either
///     way: orientOutward in mesh/SurfaceCheck.h turns them outward);
///  3. bodies welded where they touch along a face become their union (mergeTouchingBodies,
///     mesh/OverlappingBodies.h);
///  4. degenerate triangles (SurfaceCheck's: area <= 1e-12 diagonal^2), the slivers marching
///     cubes and a union's cuts leave, are removed by collapsing a needle's shortest edge or
///     flipping a cap's longest one (removeDegenerateTriangles);
///  5. a body written inside out beside bodies written outward (a mirrored body of an assembly)
///     is turned outward, with the shells inside it (orientInvertedBodies).
/// Holes, self-intersections and non-manifold edges of another origin are not repaired: the
/// caller's check (requireClosedManifold) names them.
///
/// Used before meshing (TetrahedralizeSurface), before the orientation search (GL Auto Orient)
/// and before a pedestal is added (Pedestal), so each sees the same solid.
/// Cost: one checkSurface (O(F log F)) and one labelling of the shells (O(F): 0.5 s on 1M
/// triangles) when nothing is wrong; each repair O(F) (the union: OverlappingBodies.h).
#include "mesh/TetMesh.h"

#include <array>
#include <string>
#include <vector>

namespace geolattice {

/// What repairSurface did (0: that defect was not there).
struct SurfaceRepairCounts {
  int weldedVertices = 0;       ///< vertices welded onto another across a seam (weldOpenSeams)
  int duplicateTriangles = 0;   ///< copies dropped
  int reorientedTriangles = 0;  ///< triangles turned to agree with their neighbours
  int mergedBodies = 0;         ///< bodies merged into another (mergeTouchingBodies' count)
  int degenerateTriangles = 0;  ///< degenerate triangles mended (removeDegenerateTriangles)
  int invertedBodies = 0;       ///< bodies turned outward (orientInvertedBodies)
  bool any() const {
    return weldedVertices + duplicateTriangles + reorientedTriangles + mergedBodies +
               degenerateTriangles + invertedBodies >
           0;
  }
};

/// One sentence per repair done, for a warning (GL Tetrahedralize Surface) or a note (the CLI,
/// which adds where report.json mesh.<reportKey> has the count), in the order of the repairs.
struct RepairNote {
  std::string text;
  std::string reportKey;
};
std::vector<RepairNote> describeRepairs(const SurfaceRepairCounts& counts);

/// The repairs 0-5 above, in that order; the surface is changed only by the repairs done.
SurfaceRepairCounts repairSurface(TriangleSurface& surface);

/// Repair 0: where the surface has open edges, welds each of their vertices with those within
/// 1e-6 of the bounding-box diagonal (10 float32 steps of a coordinate as large as the part;
/// 0.05 µm on a 50 mm part), drops the triangles that collapse and the points no longer used.
/// Kept only when it leaves fewer open edges and no more non-manifold ones; otherwise the
/// surface is left as it is (a real hole is named by the caller's check). Returns the vertices
/// welded onto another. O(F log F) (the checks) + a hash grid of the open edges' vertices.
int weldOpenSeams(TriangleSurface& surface);

/// Repair 1: drops every triangle on the same three vertices, the same way round, as an earlier
/// one (its edges are used by more than two triangles); the first is kept. Pairs the opposite
/// way round are walls between bodies, not copies (mergeTouchingBodies). Points are not
/// renumbered. Returns how many were dropped. Hand-written: vtkRemoveDuplicatePolys treats both
/// directions alike and would keep one triangle of such a wall. O(F).
int dropDuplicateTriangles(TriangleSurface& surface);

/// Repair 2: turns triangles so that every edge between two of them is traversed once each way,
/// with CGAL::Polygon_mesh_processing::orient_polygon_soup. Only where that needs no new points
/// (a surface whose edges are manifold and whose bodies are orientable); otherwise the surface
/// is left as it is. Returns the triangles turned.
int orientConsistently(TriangleSurface& surface);

/// Repair 4: removes the degenerate triangles of a closed, oriented 2-manifold surface with
/// CGAL::Polygon_mesh_processing::experimental::remove_almost_degenerate_faces restricted to
/// them (a needle: its shortest edge collapsed; a cap, an angle near 180 degrees: its longest
/// edge flipped); the neighbours move by at most the collapsed edge's length. A surface CGAL
/// cannot take (not a 2-manifold, a triangle with a repeated vertex) is left as it is. Points
/// are renumbered. Up to three passes while each leaves fewer (a collapse can line a neighbour
/// up into a new sliver). Returns how many degenerate triangles fewer the surface has (a
/// collapse also removes the neighbour across the edge; the caller's check says whether any is
/// left).
/// O(F log F) (the checks) + O(D log D).
int removeDegenerateTriangles(TriangleSurface& surface);

/// Repair 5: a closed, consistently oriented surface whose shells (edge-connected pieces) do
/// not all face the same way: each shell inside no other one (a body) that faces inward, while
/// another body faces outward, is turned, with every shell inside it (its cavities and what
/// they hold). Such a body cancels the others' volume (two equal spheres, one inside out:
/// "encloses no volume") or makes TetGen's regions winding number -1. Shells inside others are
/// left as they are (an outward one there is an embedded body, solid; an inward one a cavity),
/// and a surface whose bodies all face inward is left to orientOutward (SurfaceCheck.h), which
/// turns it whole. Nesting by the winding number of one point of the shell (its largest
/// triangle's centroid) within the shells whose bounding box holds it. Returns the bodies
/// turned. O(F) for one shell; O(F + sum over nested pairs of their triangles) otherwise.
int orientInvertedBodies(TriangleSurface& surface);

/// The cyclic order of a triangle's vertices: true when, from its smallest vertex id, the next
/// id is the smaller of the other two. Two triangles on the same vertices run the same way
/// exactly when their parities are equal.
bool cyclicParity(const std::array<int, 3>& t);

}  // namespace geolattice
