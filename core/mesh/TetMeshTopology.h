#pragma once
/// @file TetMeshTopology.h
/// @brief Face adjacency of a tet mesh: the neighbour across each tet face and the boundary
/// faces (oriented outward). O(T log T) by sorting face keys; no hashing of pointers.
#include "mesh/TetMesh.h"

#include <array>
#include <vector>

namespace geolattice {

/// @brief One boundary triangle: its tet, the local index of the opposite vertex, and the
/// three vertex ids ordered so that the normal (b-a)x(c-a) points out of the mesh.
struct BoundaryFace {
  int tet;
  int localFace;
  std::array<int, 3> vertices;
};

/// @class TetMeshTopology
/// @brief Tet-to-tet adjacency and boundary faces. Face k of a tet is opposite vertex k.
class TetMeshTopology {
public:
  explicit TetMeshTopology(const TetMesh& mesh);

  /// Neighbour tet across face k of tet t, or -1 on the boundary.
  int neighbor(int t, int k) const { return neighbors_[t][k]; }
  const std::vector<std::array<int, 4>>& neighbors() const { return neighbors_; }
  const std::vector<BoundaryFace>& boundaryFaces() const { return boundary_; }
  /// Faces shared by more than two tets (a non-manifold tet mesh); 0 for a valid mesh.
  int nonManifoldFaceCount() const { return nonManifoldFaces_; }

private:
  std::vector<std::array<int, 4>> neighbors_;
  std::vector<BoundaryFace> boundary_;
  int nonManifoldFaces_ = 0;
};

/// Outward boundary surface of a tet mesh (the tet mesh's own vertex ids are kept, unused
/// vertices included), e.g. for overhang analysis or base selection.
TriangleSurface boundarySurface(const TetMesh& mesh, const TetMeshTopology& topology);

}  // namespace geolattice
