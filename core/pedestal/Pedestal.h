#pragma once
/// @file Pedestal.h
/// @brief Raises a part on a pedestal of its own footprint (a printed column under the faces that
/// touch the plate), so that what bulges out right above the plate can be printed from below.
///
/// Why: curved layers grow from the base (γ = 0) and curl around its rim; where the part bulges
/// out just above the plate (a sphere on a small flat, a figure's belly) they face sideways or
/// down at a height of a millimetre or two, and no nozzle can reach them without entering the
/// plate (the collision verifier counts these as plate stations). Slicers answer with a raft; a
/// multi-axis print needs height instead: with the part standing `height` mm above the plate on a
/// column of its contact area, the nozzle has that much room under the overhang. The pedestal is
/// printed with the part (planar layers, a vertical nozzle inside the column) and cut off after.
///
/// Construction (no Boolean operation): the contact faces (placement/PlaceOnPlatform.h,
/// baseContactFaces: within contactHeight of the lowest point, facing down; without the faces at
/// a vertex the region's outline passes twice or turns sharper than kMinFootprintAngleDeg) are
/// moved down to the plane `height` below the lowest point (flat), and every boundary edge of
/// that region gets a vertical wall from its place on the part down to the moved copy, in rings
/// about as tall as the boundary edges are long. The result is closed, edge-manifold and outward
/// when the part is; then it is moved up so the pedestal's bottom is at z = 0 (x and y
/// unchanged). Each connected piece of the contact region (e.g. two feet) gets its own column.
#include "mesh/TetMesh.h"

namespace geolattice {

/// The footprint's outline has no corner sharper than this (degrees, seen from above): the faces
/// at a sharper one are left out of the footprint (a column with a thin vertical edge cannot be
/// meshed with TetGen's quality bound).
constexpr double kMinFootprintAngleDeg = 60.0;

struct PedestalOptions {
  double height = 0.0;         ///< how far the part is raised (mm, in [0, 500]); 0 = no pedestal
  double contactHeight = 0.3;  ///< the footprint: faces within this of the lowest point (mm, > 0)
  /// Throws GeoLatticeError naming the bad option.
  void validate() const;
};

struct PedestalResult {
  TriangleSurface surface;   ///< the part on its pedestal, the pedestal's bottom at z = 0
  double footprintArea = 0;  ///< mm² of the contact faces (the pedestal's cross-section)
  int footprintPieces = 0;   ///< boundary loops of the footprint (columns and their holes)
  int wallRings = 0;         ///< rings of wall triangles between the part and the bottom
};

/// The faces of `part` (turned by R) a pedestal stands on: baseContactFaces within contactHeight
/// of the lowest point, without the pinch and spike faces (see the file comment). `part` is
/// welded (repairSurface) as addPedestal welds it, or the faces along open seams count as outline.
std::vector<int> pedestalFootprintFaces(const TriangleSurface& part, const Eigen::Matrix3d& R,
                                        double contactHeight);

/// mm² of pedestalFootprintFaces: the cross-section of the column addPedestal builds under the
/// part turned by R. The orientation search scores a side on a pedestal by it.
double pedestalFootprintArea(const TriangleSurface& part, const Eigen::Matrix3d& R,
                             double contactHeight);

/// `part`: a closed, outward triangle surface standing on z = 0 (as placed or oriented). With
/// height 0 the part comes back unchanged. Throws GeoLatticeError for bad options, or a part that
/// touches the plate with no face (a tip or an edge: nothing to stand a column on).
PedestalResult addPedestal(const TriangleSurface& part, const PedestalOptions& options);

}  // namespace geolattice
