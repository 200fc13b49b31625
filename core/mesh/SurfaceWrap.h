#pragma once
/// @file SurfaceWrap.h
/// @brief Replaces a surface that cannot be meshed as it is (facets crossing each other,
/// non-manifold edges, small holes, overlapping shells: what a careless export gives) by a
/// closed, 2-manifold, non-self-intersecting wrap of it. Asked for explicitly (GL Place On
/// Platform's Wrap, `geolattice run --wrap MM`): the wrap is an approximation of the part.
///
/// CGAL's 3D alpha wrapping (CGAL::alpha_wrap_3, CGAL 5.5): the surface is shrink-wrapped from
/// outside by a Delaunay refinement that cannot pass gaps narrower than alpha and stays at an
/// offset of alpha / 30 (CGAL's default) outside the input. So the result is watertight and free
/// of self-intersections whatever the input's defects, grows by the offset everywhere, loses
/// features and closes channels narrower than alpha, and fills sealed inner voids (a wrap from
/// outside never sees them). A hole wider than alpha lets the wrap inside: an open sheet (a scan
/// seen from too few sides) becomes a thin shell around it, 2 alpha / 30 thick, not the solid
/// meant (the full-resolution bunny scan at 2 mm: 49k triangles in 15 s, and TetGen then meets
/// knife edges); its holes are closed first (HoleFilling.h). alpha is the resolution: 1 mm keeps
/// what the 0.6 mm beads and the 4 mm lattice of the default print resolve.
///
/// Cost: CGAL's wrap is about linear in the output's size, which grows as the area / alpha²
/// (about 7,000 output triangles a second here: a 34 x 34 x 40 mm twisted star 15k triangles in
/// 2.4 s at 1 mm, 63k in 10 s at 0.5 mm; the bunny at 80 mm 128k in 14 s and topopt 315k in 44 s
/// at 0.5 mm); refused up front (common/WorkLimit.h) when that estimate is above the limit.
#include "mesh/TetMesh.h"

namespace geolattice {

/// The way out named by the errors of surfaces that cannot be meshed as they are. The CLI turns
/// the property's name into its flag (apps/CliOptions.h withFlagNames): "--wrap 1 mm in ...".
inline constexpr const char* kWrapHint = "; or wrap it: Wrap 1 mm in GL Place On Platform";

struct SurfaceWrapResult {
  int inputTriangles = 0;
  int triangles = 0;  ///< of the wrap
  double offset = 0;  ///< alpha / 30, in the surface's units
  double seconds = 0;
};

/// Replaces `surface` (any triangle soup with at least one non-degenerate triangle) by its alpha
/// wrap. alpha in the surface's units (> 0). maxTriangles bounds the wrap's estimated size
/// (common/WorkLimit.h). mmPerUnit (> 0): millimetres of the printed part per surface unit (the
/// placement's scale), for the messages, which speak in the user's --wrap mm. Throws
/// GeoLatticeError for alpha <= 0, an empty surface, a wrap estimated above the limit or an
/// empty wrap.
SurfaceWrapResult wrapSurface(TriangleSurface& surface, double alpha, double maxTriangles,
                              double mmPerUnit = 1.0);

}  // namespace geolattice
