#pragma once
/// @file BranchingShapes.h
/// @brief Branching test parts built in code: the Y model of the paper (Li et al., Figs. 6-8,
/// ~45 mm tall) and a tree with three branches (in the spirit of Fig. 26). Their leaning
/// branches have real overhangs under planar (2.5-axis) slicing that curved layers avoid.
///
/// Data flow: closed capsule meshes (a trunk with a flat bottom disk at z = 0 and a round top,
/// the joint sphere; branches starting just behind the joint centre, inside the joint sphere,
/// with round tips) -> per branch: CGAL Polygon Mesh Processing corefinement union (exact
/// predicates, intersection points rounded to double) -> self-intersection check -> isotropic
/// remeshing (the union leaves needle/cap triangles along the intersection curves; creases and
/// the bottom rim stay as constrained polylines) -> bottom vertices snapped to z = 0 ->
/// self-intersection and SurfaceCheck validity checks -> TriangleSurface (closed,
/// edge-manifold, outward) -> tetrahedralizeSurface -> GDF / overhang analysis. The round caps
/// keep the unions free of coincident or tangent faces.
/// Generated copies: testdata/y_shape.obj and testdata/three_branch_tree.obj (default
/// parameters; see testdata/README.md).
#include "mesh/TetMesh.h"

namespace geolattice {

/// @brief Dimensions of a branching part (mm and degrees). The trunk is a vertical cylinder
/// of radius trunkRadius from the platform z = 0 (flat bottom disk) up to the joint centre
/// (0, 0, trunkHeight), closed there by a hemisphere (the joint sphere). Each branch is a
/// cylinder of radius branchRadius from the joint centre (it reaches 0.25 * trunkRadius behind
/// it, inside the joint sphere) along a unit axis that leans
/// branchLeanDeg from +z towards its azimuth, of length branchLength (joint centre to the
/// centre of its hemispherical tip). Branch k has azimuth firstAzimuthDeg + k * 360 / #branches
/// (measured from +x towards +y).
struct BranchingShapeParameters {
  double trunkRadius = 6.0;   ///< > 0 (mm)
  double trunkHeight = 22.0;  ///< z of the joint centre, > trunkRadius (mm)
  double branchRadius =
      4.5;  ///< in (0, 0.9 * trunkRadius]: a branch starts inside the joint sphere (mm)
  double branchLength = 28.0;    ///< joint centre to tip centre, >= trunkRadius (mm)
  double branchLeanDeg = 50.0;   ///< angle between a branch axis and +z, [10, 80] (degrees)
  double firstAzimuthDeg = 0.0;  ///< azimuth of branch 0 (degrees, finite)
  int segments = 48;             ///< facets around every cylinder before remeshing, [8, 256]; the
      ///< axial ring spacing and the cap rings follow the same edge length
  double surfaceEdgeLength = 1.5;  ///< target edge length of the final isotropic remeshing, in
                                   ///< [branchRadius / 50, branchRadius] (mm)
};

/// Defaults of the Y model: the members' defaults (trunk r 6 mm to z = 22 mm, two branches of
/// r 4.5 mm and 28 mm leaning 50° towards ±x); 44.5 mm tall (the paper's Y: max γ 44.3 mm),
/// 52 mm wide, 12 mm deep.
BranchingShapeParameters yShapeDefaults();

/// Defaults of the three-branch tree: trunk r 7 mm to z = 30 mm, three branches of r 5 mm and
/// 30 mm leaning 50° at azimuths 90°, 210°, 330°; 54 mm tall, 50 x 44 mm wide.
BranchingShapeParameters threeBranchTreeDefaults();

/// @brief Y-shaped part: trunk + two branches (azimuths firstAzimuthDeg and +180°).
/// @return closed, edge-manifold, outward-oriented surface; the trunk's bottom is a flat disk
///   at z = 0 (vertices with z exactly 0) and every other vertex has z > 0.
/// @throws GeoLatticeError on parameters outside the documented ranges, or if the union fails
///   or leaves self-intersections (not observed for valid parameters).
TriangleSurface yShapeSurface(const BranchingShapeParameters& parameters = yShapeDefaults());

/// @brief Tree with three branches (azimuths firstAzimuthDeg + 0°, 120°, 240°). Same
/// guarantees and errors as yShapeSurface.
TriangleSurface threeBranchTreeSurface(
    const BranchingShapeParameters& parameters = threeBranchTreeDefaults());

}  // namespace geolattice
