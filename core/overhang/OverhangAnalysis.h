#pragma once
/// @file OverhangAnalysis.h
/// @brief Overhang angles of a part's boundary surface under planar (2.5-axis) slicing and
/// under curved-layer (multi-axis) slicing (paper Section 2.2, Fig. 7-8).
///
/// Data flow: tet mesh + TetMeshTopology::boundaryFaces (outward) + per-tet nozzle axis
/// (GeodesicFields::gammaDirection, the unit ∇γ) + per-vertex base flags (the heat sources)
/// -> per face: outward unit normal n, θ_planar = acos(+z · n), θ_curved = acos(d_tet · n),
/// area, on-base flag -> area fractions of the faces with θ > threshold.
///
/// θ is the angle between the nozzle orientation d and the outward normal n (Fig. 7): 0° on a
/// face looking along the nozzle (a "roof" seen from below is 180°), 90° on a wall parallel to
/// the nozzle. Faces with θ > threshold (135° in the paper) need support. Faces whose three
/// vertices are all base vertices rest on the platform: they need no support and are left out
/// of both fractions; their area is reported separately.
#include "mesh/TetMesh.h"

#include <cstdint>
#include <vector>

namespace geolattice {

class TetMeshTopology;

/// @brief Parameters of analyzeOverhang().
struct OverhangOptions {
  /// Overhang angle above which a face needs support (degrees), in (90, 180]. Default 135°.
  double thresholdDeg = 135.0;
  /// Throws GeoLatticeError naming the first parameter out of its range (cheap: no data).
  void validate() const;
};

/// @brief Per boundary face results (index f = the f-th TetMeshTopology::boundaryFaces entry)
/// and the totals.
struct OverhangResult {
  std::vector<double> planarDeg;  ///< #F θ for d = +z (degrees, [0, 180])
  std::vector<double> curvedDeg;  ///< #F θ for d = the nozzle direction of the face's tet (degrees)
  std::vector<std::uint8_t> onBase;  ///< #F 1 if all three vertices are base vertices
  std::vector<double> area;          ///< #F face area (mm^2)
  double thresholdDeg = 135.0;       ///< threshold used (degrees)
  double totalArea = 0.0;            ///< area of all boundary faces, base included (mm^2)
  double baseArea = 0.0;             ///< area of the on-base faces (mm^2)
  double planarOverhangArea = 0.0;   ///< off-base area with θ_planar > threshold (mm^2)
  double curvedOverhangArea = 0.0;   ///< off-base area with θ_curved > threshold (mm^2)
  /// planarOverhangArea / (totalArea - baseArea), in [0, 1].
  double planarFraction = 0.0;
  /// curvedOverhangArea / (totalArea - baseArea), in [0, 1].
  double curvedFraction = 0.0;
  double maxPlanarDeg = 0.0;  ///< largest θ_planar over the off-base faces (degrees)
  double maxCurvedDeg = 0.0;  ///< largest θ_curved over the off-base faces (degrees)
  int zeroAreaFaces = 0;      ///< faces with no defined normal: θ set to 90°, area 0
};

/// @brief Overhang angles of the boundary faces of `mesh`.
/// @param mesh      tet mesh (mm), positively oriented tets
/// @param topology  TetMeshTopology(mesh): its boundaryFaces() are the analysed faces (outward)
/// @param nozzleDirections #T unit vectors, the curved-layer nozzle axis per tet (e.g.
///                  GeodesicFields::gammaDirection); lengths within 1e-3 of 1 are accepted
///                  (float arrays) and renormalised
/// @param baseVertex #V flags, non-zero = base vertex (on the platform, e.g. the heat sources)
/// @throws GeoLatticeError on a threshold outside (90, 180], sizes that do not match the mesh,
///   a non-finite or non-unit direction (naming the first offending tet), a mesh without
///   boundary faces, or a boundary that lies entirely on the base.
OverhangResult analyzeOverhang(const TetMesh& mesh, const TetMeshTopology& topology,
                               const std::vector<Vec3>& nozzleDirections,
                               const std::vector<std::uint8_t>& baseVertex,
                               const OverhangOptions& options = {});

/// @brief Overhang angle θ = acos(d · n) in degrees of a face with outward normal n (any
/// length > 0) for a unit nozzle direction d; clamps rounding so that the result is in [0, 180].
double overhangAngleDeg(const Vec3& nozzle, const Vec3& normal);

}  // namespace geolattice
