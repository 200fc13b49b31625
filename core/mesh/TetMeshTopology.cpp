#include "mesh/TetMeshTopology.h"

#include <algorithm>
#include <cstdint>

namespace geolattice {

namespace {
// Vertices of face k (opposite vertex k), ordered so the normal points away from vertex k
// for a positively oriented tet.
constexpr int kFaceVertices[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

struct FaceRecord {
  std::array<int, 3> key;  // sorted vertex ids
  int tet;
  int localFace;
  bool operator<(const FaceRecord& o) const { return key < o.key; }
};
}  // namespace

TetMeshTopology::TetMeshTopology(const TetMesh& mesh) {
  const size_t nt = mesh.tets.size();
  neighbors_.assign(nt, {-1, -1, -1, -1});
  std::vector<FaceRecord> faces;
  faces.reserve(4 * nt);
  for (size_t t = 0; t < nt; ++t) {
    for (int k = 0; k < 4; ++k) {
      std::array<int, 3> key = {mesh.tets[t][kFaceVertices[k][0]],
                                mesh.tets[t][kFaceVertices[k][1]],
                                mesh.tets[t][kFaceVertices[k][2]]};
      std::sort(key.begin(), key.end());
      faces.push_back({key, static_cast<int>(t), k});
    }
  }
  std::sort(faces.begin(), faces.end());
  for (size_t i = 0; i < faces.size();) {
    size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key) {
      ++j;
    }
    if (j - i == 1) {
      const FaceRecord& f = faces[i];
      const auto& tet = mesh.tets[f.tet];
      std::array<int, 3> v = {tet[kFaceVertices[f.localFace][0]],
                              tet[kFaceVertices[f.localFace][1]],
                              tet[kFaceVertices[f.localFace][2]]};
      // A negatively oriented tet flips its faces; keep boundary normals outward anyway.
      const double vol = signedTetVolume(mesh.points[tet[0]], mesh.points[tet[1]],
                                         mesh.points[tet[2]], mesh.points[tet[3]]);
      if (vol < 0) {
        std::swap(v[1], v[2]);
      }
      boundary_.push_back({f.tet, f.localFace, v});
    } else if (j - i == 2) {
      neighbors_[faces[i].tet][faces[i].localFace] = faces[i + 1].tet;
      neighbors_[faces[i + 1].tet][faces[i + 1].localFace] = faces[i].tet;
    } else {
      ++nonManifoldFaces_;
    }
    i = j;
  }
  // Deterministic order independent of the sort's tie-breaking: by tet, then face.
  std::sort(boundary_.begin(), boundary_.end(), [](const BoundaryFace& a, const BoundaryFace& b) {
    return a.tet != b.tet ? a.tet < b.tet : a.localFace < b.localFace;
  });
}

TriangleSurface boundarySurface(const TetMesh& mesh, const TetMeshTopology& topology) {
  TriangleSurface surface;
  surface.points = mesh.points;
  surface.triangles.reserve(topology.boundaryFaces().size());
  for (const BoundaryFace& f : topology.boundaryFaces()) {
    surface.triangles.push_back(f.vertices);
  }
  return surface;
}

}  // namespace geolattice
