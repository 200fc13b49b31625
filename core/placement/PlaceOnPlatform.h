#pragma once
/// @file PlaceOnPlatform.h
/// @brief Placing a model on the build platform: a uniform scale (given, or fitted so the largest
/// bounding-box side has a given size), x/y centred on the platform origin (optional) and the
/// lowest point moved to z = 0, the platform. Models come in arbitrary units; GeoLattice works in
/// millimetres, so the placed part must be of a printable size: its largest side in
/// [kMinPartSizeMm, kMaxPartSizeMm] (a part in metres or inches is caught here, before minutes
/// of meshing, with the likely fix in the message).
///
/// Data flow: model file (GL Mesh Reader) -> placement -> tet mesh (GL Tetrahedralize Surface).
#include "mesh/TetMesh.h"

#include <string>
#include <vector>

namespace geolattice {

constexpr double kMinPartSizeMm = 1.0;     ///< smaller parts are refused (a 0.6 mm bead)
constexpr double kMaxPartSizeMm = 2000.0;  ///< larger parts are refused (2 m: beyond any cell)

struct PlacementOptions {
  double scale = 1.0;    ///< uniform scale factor (> 0), used when fitSize is 0
  double fitSize = 0.0;  ///< largest bounding-box side after scaling (mm); 0 = use scale
  bool centerXY = true;  ///< bounding box centred on x = y = 0
  /// A surface's holes closed before it is placed (mesh/HoleFilling.h); off: an open surface is
  /// refused by the stages that need a solid, naming the holes.
  bool fillHoles = false;
  /// A surface's closed inner cavities filled before it is placed (mesh/ShellNesting.h: the
  /// cavities' shells removed, the part printed solid there); off: they stay hollow.
  bool fillCavities = false;
  /// A surface replaced by its alpha wrap at this resolution (mm of the placed part; 0 = off)
  /// before it is placed (mesh/SurfaceWrap.h): closed and free of crossing facets whatever the
  /// input's defects, an approximation of the part (offset by wrap / 30 outward, features and
  /// gaps narrower than wrap closed, sealed voids filled).
  double wrap = 0.0;
  /// Checks the options; throws GeoLatticeError naming the bad one (Scale, FitSize, Wrap).
  void validate() const;
};

/// x' = scale · x + translation.
struct Placement {
  double scale = 1.0;
  Vec3 translation = Vec3::Zero();
  Vec3 size = Vec3::Zero();  ///< bounding-box size after placement (mm)
};

/// The placement of a model whose points span [lo, hi] (bounding box of all points). Throws
/// GeoLatticeError for bad options, a non-finite box, a box that is a single point with FitSize,
/// or a placed part outside the printable size range (naming the likely unit mistake and the fix:
/// "use Scale 1000 or FitSize MM").
Placement placeOnPlatform(const Vec3& lo, const Vec3& hi, const PlacementOptions& options);

/// The faces of `surface` (rotated by R) that touch the plate: all three corners within
/// contactHeight of the lowest point and the outward normal within 30° of -z (a first layer is
/// squeezed onto the plate over them). Outward: the triangles' own normals, or their opposites
/// when the surface encloses a negative volume (every triangle turned inward). Used by the
/// orientation search (base area) and the pedestal (its footprint). Indices ascending.
std::vector<int> baseContactFaces(const TriangleSurface& surface, const Eigen::Matrix3d& R,
                                  double contactHeight);

}  // namespace geolattice
