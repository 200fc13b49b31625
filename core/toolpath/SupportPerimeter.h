#pragma once
/// @file SupportPerimeter.h
/// @brief The support perimeter of a trimmed sub-graph (paper Section 3.2, Fig. 14c-d): a
/// closed curve at distance w inside each boundary loop, jagged where the trimming deleted
/// boundary edges, so the next layer's boundary is still supported there.
///
/// Per boundary loop b_0 … b_{m-1} (the sub-graph's boundary edges, kept or trimmed) the offset
/// points are p_i = b_i + w·d_i with d_i the unit in-layer direction n_i × t_i (t_i the loop
/// tangent), turned towards the interior. The interior side is decided by the isolines that end
/// on the loop (their first edge leaves the boundary inwards), by majority; a loop without any
/// isoline end is not trimmed and gets no perimeter. Where the region is narrower than 2w
/// along d_i (its far side, another boundary edge of the sub-graph, is crossed in the tangent
/// plane within 2w: a sliver where the layer meets the surface almost tangentially), p_i lies
/// halfway across instead, so it stays inside the part. Along kept boundary edges the perimeter
/// follows p_i; along a trimmed edge it zig-zags between the offset curve and the boundary with
/// tooth length l (one tooth = out and back over l of arc length), reaching out to support the
/// missing boundary. The perimeter meets the isoline ends near the boundary; these contacts are
/// by design (the paper's Fig. 14d) and are not self-crossings of the Euler tours.
#include "lattice/LatticeInfill.h"

#include <vector>

namespace geolattice {

struct PerimeterLoop {
  int subgraph = 0;
  std::vector<Vec3> points;     ///< closed: points.front() == points.back()
  std::vector<Vec3> normals;    ///< unit nozzle axes (from the boundary vertices)
  std::vector<int> nearVertex;  ///< per point: the boundary lattice vertex it belongs to
  /// Lattice vertex on the loop where the perimeter is joined to the tour (points.front() is
  /// its offset point); it lies on a kept edge.
  int anchorVertex = -1;
};

struct PerimeterResult {
  std::vector<PerimeterLoop> loops;
  int loopsWithoutIsolines = 0;  ///< skipped (never trimmed)
  int teeth = 0;
};

/// offset w > 0 (mm), toothLength l > 0 (mm). kept: per lattice edge, from trimToEulerian.
/// Throws GeoLatticeError for bad parameters or mismatched sizes. O(E) (the far sides are
/// looked up in a hash grid of the boundary edges with cells of 2w).
PerimeterResult supportPerimeters(const LatticeGraph& g, const std::vector<char>& kept,
                                  double offset, double toothLength);

}  // namespace geolattice
