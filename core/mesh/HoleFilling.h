#pragma once
/// @file HoleFilling.h
/// @brief Closes the holes of an open surface (a 3D scan seen from too few sides, an export that
/// lost faces), so it bounds a solid that can be meshed. Asked for explicitly (GL Place On
/// Platform's FillHoles, `geolattice run --fill-holes`): a hole's patch is a guess at the part,
/// and a surface meant to be open (a cup modelled as one sheet) is not a solid whatever fills it.
///
/// Each boundary cycle is filled by CGAL's triangulate_refine_and_fair_hole (a minimal-area
/// triangulation of the hole, refined to the density of its rim, then faired so the patch
/// continues the surface around it); where fairing fails, the refined patch without it. The
/// surface must otherwise be an oriented 2-manifold (CGAL's halfedge mesh holds it).
/// Cost: O(h^3) for a hole of h rim edges (the triangulation's dynamic programme; CGAL falls back
/// to a Delaunay-restricted one for large holes), plus a sparse solve per patch.
#include "mesh/TetMesh.h"

namespace geolattice {

struct HoleFillingResult {
  int holes = 0;           ///< boundary cycles closed
  int addedTriangles = 0;  ///< triangles of their patches
};

/// Fills every hole of `surface` (unchanged when it has none). Throws GeoLatticeError when the
/// surface is not an oriented 2-manifold apart from its holes, or when CGAL cannot close one.
HoleFillingResult fillHoles(TriangleSurface& surface);

}  // namespace geolattice
