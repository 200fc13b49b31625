#pragma once
/// @file SurfaceTetrahedralizer.h
/// @brief Quality tetrahedral mesh of the solid enclosed by a closed triangle surface, with
/// TetGen 1.5 (constrained Delaunay + Delaunay refinement). The paper (Li et al., Sec. 3)
/// computes its geodesic distance fields on such a tet mesh of the input part.
///
/// Data flow: closed surface (mm) -> requireClosedManifold (+ orientOutward) -> TetGen
/// "pq<ratio>a<volume>Q" (boundary may be refined: no "Y") -> tets reoriented to positive
/// volume -> requireValidTetMesh -> TetMesh for the GDF stages.
#include "mesh/TetMesh.h"

#include <string>

namespace geolattice {

/// @brief Parameters of tetrahedralizeSurface().
struct TetrahedralizeOptions {
  /// Target edge length (mm). It sets TetGen's maximum tet volume to that of a regular tet with
  /// this edge, L^3 / (6 sqrt 2). 0 = automatic: chosen from the enclosed volume so that the
  /// mesh has about kAutoTargetTets tets. Must be >= 0 and finite.
  double targetEdgeLength = 0.0;
  /// Upper bound of the tets' circumradius / shortest-edge ratio (TetGen switch -q).
  /// Valid range [kMinRadiusEdgeRatio, kMaxRadiusEdgeRatio]; 1.414 = sqrt 2 (good quality).
  double radiusEdgeRatio = 1.414;
};

/// @brief Mesh plus what was done to get it.
struct TetrahedralizeResult {
  TetMesh mesh;                       ///< positively oriented, validated (requireValidTetMesh)
  double targetEdgeLength = 0.0;      ///< edge length used (mm): the option, or the automatic choice
  double maxTetVolume = 0.0;          ///< TetGen volume bound (mm^3)
  double meanEdgeLength = 0.0;        ///< mean length of the output's unique edges (mm)
  double enclosedVolume = 0.0;        ///< volume enclosed by the input surface (mm^3)
  double meshVolume = 0.0;            ///< sum of tet volumes (mm^3)
  int tetCount = 0;
  int flippedSurfaceTriangles = 0;    ///< input triangles reversed because the surface faced inward
  int flippedTets = 0;                ///< output tets reoriented from TetGen's convention
  double seconds = 0.0;               ///< wall time of the whole call
  std::string switches;               ///< TetGen switches used
};

/// Number of tets the automatic edge length aims at.
constexpr int kAutoTargetTets = 75000;
/// Accepted range of TetrahedralizeOptions::radiusEdgeRatio (see the .cpp for why).
constexpr double kMinRadiusEdgeRatio = 0.5;
constexpr double kMaxRadiusEdgeRatio = 10.0;
/// Estimated tet counts above this are refused before TetGen runs (memory / time guard).
constexpr double kMaxEstimatedTets = 2.0e7;

/// @brief Automatic target edge length (mm) for a solid of the given enclosed volume (mm^3):
/// the edge L whose calibrated tet count V / (kTetsPerBoundVolume * L^3 / (6 sqrt 2)) is
/// kAutoTargetTets. Throws on a non-positive volume.
double automaticEdgeLength(double enclosedVolume);

/// @brief Tetrahedralize the solid bounded by `surface` (closed, edge-manifold, consistently
/// oriented; an inward-oriented surface is flipped, see orientOutward()).
/// @throws GeoLatticeError for an invalid surface (see requireClosedManifold), invalid
/// options, an estimated tet count above kMaxEstimatedTets, or a TetGen failure (e.g.
/// "self-intersecting surface: TetGen found intersecting facets").
TetrahedralizeResult tetrahedralizeSurface(const TriangleSurface& surface,
                                           const TetrahedralizeOptions& options = {});

} // namespace geolattice
