#pragma once
/// @file TetMeshCheck.h
/// @brief Validity checks of a linear tet mesh before the GDF stages use it: indices in range,
/// finite points, positive orientation, no zero-volume tets, no face shared by more than two
/// tets, every vertex used by some tet.
///
/// Data flow: TetGen output / a read .vtu or .tet mesh -> checkTetMesh / requireValidTetMesh
/// (-> orientTetsPositively, an explicit repair) -> heat-method GDF solver.
#include "mesh/TetMesh.h"

namespace geolattice {

/// @brief Counts of tet mesh defects; each "first" member is -1 when the count is 0.
struct TetMeshCheckReport {
  int pointCount = 0;
  int tetCount = 0;
  int outOfRangeTets = 0;  ///< tets with a vertex index < 0 or >= pointCount
  int firstOutOfRangeTet = -1;
  int nonFinitePoints = 0;  ///< points with a NaN or infinite coordinate
  int firstNonFinitePoint = -1;
  int invertedTets = 0;  ///< negative signed volume, not flat
  int firstInvertedTet = -1;
  int zeroVolumeTets = 0;  ///< flat tets (isFlatTet in TetMesh.h; repeated vertices included)
  int firstZeroVolumeTet = -1;
  int nonManifoldFaces = 0;  ///< triangles shared by more than two tets
  int unusedPoints = 0;  ///< vertices referenced by no tet (they make the FEM Laplacian singular)
  int firstUnusedPoint = -1;
  double totalVolume = 0.0;  ///< sum of signed tet volumes (mm^3)

  /// True when every count above is zero and the mesh is non-empty.
  bool isValid() const;
};

/// @brief Count every defect listed in TetMeshCheckReport. Never throws; O(T) (faces matched
/// through TetMeshTopology).
TetMeshCheckReport checkTetMesh(const TetMesh& mesh);

/// @brief Throw GeoLatticeError naming the first problem, with its count and first offending
/// index, e.g. "tet mesh has 5 inverted tets (first: tet 17)". Order: empty mesh,
/// out-of-range indices, non-finite points, inverted tets, zero-volume tets, non-manifold
/// faces, unused vertices. @return the report of the accepted mesh.
TetMeshCheckReport requireValidTetMesh(const TetMesh& mesh);
/// The same on the report of checkTetMesh(mesh) already made (the mesh unchanged since).
const TetMeshCheckReport& requireValidTetMesh(const TetMeshCheckReport& report);

/// @brief Throw GeoLatticeError naming the first tet with a vertex index outside the points
/// (cheap, O(T): for stages that index arrays by vertex before any other check).
void requireTetVertexIndicesInRange(const TetMesh& mesh);

/// @brief Documented repair for a mesh written with the opposite orientation convention: if
/// EVERY tet has a negative signed volume, swap vertices 2 and 3 of every tet and return the
/// number of tets flipped. Otherwise the mesh is left unchanged and 0 is returned (a mix of
/// orientations is a tangled mesh, not a convention, and requireValidTetMesh reports it).
int orientTetsPositively(TetMesh& mesh);

/// @brief Documented repair of TetGen output: drops the flat tets (isFlatTet in TetMesh.h: their
/// corners in one plane, they hold no volume) and the points no other tet uses. Returns the
/// number of tets dropped.
size_t removeFlatTets(TetMesh& mesh);

}  // namespace geolattice
