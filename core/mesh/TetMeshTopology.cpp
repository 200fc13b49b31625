#include "mesh/TetMeshTopology.h"

#include "common/Error.h"

#include <algorithm>
#include <cstdint>

namespace geolattice {

namespace {
// Vertices of face k (opposite vertex k), ordered so the normal points away from vertex k
// for a positively oriented tet.
constexpr int kFaceVertices[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

/// A face in the bucket of its smallest vertex: the two larger vertex ids and 4 tet + k.
struct BucketFace {
  int mid, high;
  int tetFace;
  bool operator<(const BucketFace& o) const { return mid != o.mid ? mid < o.mid : high < o.high; }
};
}  // namespace

// Faces are matched by their sorted vertex triples: a counting sort by the smallest vertex, then
// a sort of each (small) bucket, so O(n) for the ~4n faces instead of one O(n log n) sort (1M
// tets: most of the mesh stage's own time). Equal triples in a bucket are adjacent.
TetMeshTopology::TetMeshTopology(const TetMesh& mesh) {
  const size_t nt = mesh.tets.size();
  neighbors_.assign(nt, {-1, -1, -1, -1});
  int maxVertex = -1;
  for (const auto& tet : mesh.tets) {
    if (std::min({tet[0], tet[1], tet[2], tet[3]}) < 0) {
      throw GeoLatticeError("tet mesh topology: a tet has a negative vertex index");
    }
    maxVertex = std::max({maxVertex, tet[0], tet[1], tet[2], tet[3]});
  }
  auto sortedFace = [&](size_t t, int k) {
    std::array<int, 3> key = {mesh.tets[t][kFaceVertices[k][0]], mesh.tets[t][kFaceVertices[k][1]],
                              mesh.tets[t][kFaceVertices[k][2]]};
    std::sort(key.begin(), key.end());
    return key;
  };
  std::vector<size_t> bucketStart(static_cast<size_t>(maxVertex) + 2, 0);
  for (size_t t = 0; t < nt; ++t) {
    for (int k = 0; k < 4; ++k) {
      ++bucketStart[static_cast<size_t>(sortedFace(t, k)[0]) + 1];
    }
  }
  for (size_t v = 1; v < bucketStart.size(); ++v) {
    bucketStart[v] += bucketStart[v - 1];
  }
  std::vector<BucketFace> faces(4 * nt);
  {
    std::vector<size_t> fill(bucketStart.begin(), bucketStart.end() - 1);
    for (size_t t = 0; t < nt; ++t) {
      for (int k = 0; k < 4; ++k) {
        const std::array<int, 3> key = sortedFace(t, k);
        faces[fill[static_cast<size_t>(key[0])]++] = {key[1], key[2], static_cast<int>(4 * t) + k};
      }
    }
  }
  for (size_t v = 0; v + 1 < bucketStart.size(); ++v) {
    const auto first = faces.begin() + static_cast<std::ptrdiff_t>(bucketStart[v]);
    const auto last = faces.begin() + static_cast<std::ptrdiff_t>(bucketStart[v + 1]);
    std::sort(first, last);
    for (auto i = first; i != last;) {
      auto j = i + 1;
      while (j != last && j->mid == i->mid && j->high == i->high) {
        ++j;
      }
      const int tet = i->tetFace / 4, localFace = i->tetFace % 4;
      if (j - i == 1) {
        const auto& tv = mesh.tets[tet];
        std::array<int, 3> vtx = {tv[kFaceVertices[localFace][0]], tv[kFaceVertices[localFace][1]],
                                  tv[kFaceVertices[localFace][2]]};
        // A negatively oriented tet flips its faces; keep boundary normals outward anyway.
        const double vol = signedTetVolume(mesh.points[tv[0]], mesh.points[tv[1]],
                                           mesh.points[tv[2]], mesh.points[tv[3]]);
        if (vol < 0) {
          std::swap(vtx[1], vtx[2]);
        }
        boundary_.push_back({tet, localFace, vtx});
      } else if (j - i == 2) {
        const int other = (i + 1)->tetFace / 4, otherFace = (i + 1)->tetFace % 4;
        neighbors_[tet][localFace] = other;
        neighbors_[other][otherFace] = tet;
      } else {
        ++nonManifoldFaces_;
      }
      i = j;
    }
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
