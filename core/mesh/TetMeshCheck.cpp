#include "mesh/TetMeshCheck.h"

#include "common/Error.h"
#include "mesh/TetMeshTopology.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace geolattice {

namespace {

bool tetInRange(const std::array<int, 4>& tet, int pointCount) {
  for (int v : tet) {
    if (v < 0 || v >= pointCount) {
      return false;
    }
  }
  return true;
}

std::string first(const char* what, int index) {
  return " (first: " + std::string(what) + " " + std::to_string(index) + ")";
}

}  // namespace

bool TetMeshCheckReport::isValid() const {
  return pointCount > 0 && tetCount > 0 && outOfRangeTets == 0 && nonFinitePoints == 0 &&
         invertedTets == 0 && zeroVolumeTets == 0 && nonManifoldFaces == 0 && unusedPoints == 0;
}

TetMeshCheckReport checkTetMesh(const TetMesh& mesh) {
  TetMeshCheckReport r;
  r.pointCount = static_cast<int>(mesh.points.size());
  r.tetCount = static_cast<int>(mesh.tets.size());

  const FinitePointScan scan = scanPoints(mesh.points);
  r.nonFinitePoints = scan.nonFinite;
  r.firstNonFinitePoint = scan.firstNonFinite;

  std::vector<char> used(mesh.points.size(), 0);
  bool allInRange = true;
  for (int t = 0; t < r.tetCount; ++t) {
    const auto& tet = mesh.tets[t];
    if (!tetInRange(tet, r.pointCount)) {
      allInRange = false;
      if (r.outOfRangeTets++ == 0) {
        r.firstOutOfRangeTet = t;
      }
      continue;
    }
    for (int v : tet) {
      used[v] = 1;
    }
    const Vec3 &a = mesh.points[tet[0]], &b = mesh.points[tet[1]], &c = mesh.points[tet[2]],
               &d = mesh.points[tet[3]];
    const double vol = signedTetVolume(a, b, c, d);
    if (std::isfinite(vol)) {
      r.totalVolume += vol;
    }
    if (isFlatTet(a, b, c, d, vol)) {
      if (r.zeroVolumeTets++ == 0) {
        r.firstZeroVolumeTet = t;
      }
    } else if (vol < 0.0) {
      if (r.invertedTets++ == 0) {
        r.firstInvertedTet = t;
      }
    }
  }
  for (int i = 0; i < r.pointCount; ++i) {
    if (!used[i] && r.unusedPoints++ == 0) {
      r.firstUnusedPoint = i;
    }
  }
  if (allInRange && r.tetCount > 0) {
    r.nonManifoldFaces = TetMeshTopology(mesh).nonManifoldFaceCount();
  }
  return r;
}

void requireTetVertexIndicesInRange(const TetMesh& mesh) {
  const int n = static_cast<int>(mesh.points.size());
  for (size_t t = 0; t < mesh.tets.size(); ++t) {
    for (int v : mesh.tets[t]) {
      if (v < 0 || v >= n) {
        throw GeoLatticeError("tet " + std::to_string(t) + " has vertex index " +
                              std::to_string(v) + ", outside the mesh's " + std::to_string(n) +
                              " vertices");
      }
    }
  }
}

TetMeshCheckReport requireValidTetMesh(const TetMesh& mesh) {
  return requireValidTetMesh(checkTetMesh(mesh));
}

const TetMeshCheckReport& requireValidTetMesh(const TetMeshCheckReport& r) {
  if (r.tetCount == 0 || r.pointCount == 0) {
    throw GeoLatticeError("empty tet mesh: " + std::to_string(r.pointCount) + " points, " +
                          std::to_string(r.tetCount) + " tets");
  }
  if (r.outOfRangeTets > 0) {
    throw GeoLatticeError("tet mesh has " + std::to_string(r.outOfRangeTets) +
                          " tets with a vertex index outside 0.." +
                          std::to_string(r.pointCount - 1) + first("tet", r.firstOutOfRangeTet));
  }
  if (r.nonFinitePoints > 0) {
    throw GeoLatticeError("tet mesh has " + std::to_string(r.nonFinitePoints) +
                          " points with NaN or infinite coordinates" +
                          first("point", r.firstNonFinitePoint));
  }
  if (r.invertedTets > 0) {
    throw GeoLatticeError(
        "tet mesh has " + std::to_string(r.invertedTets) + " inverted tets" +
        first("tet", r.firstInvertedTet) +
        (r.invertedTets == r.tetCount
             ? "; all tets are negatively oriented, orientTetsPositively() can flip them"
             : ""));
  }
  if (r.zeroVolumeTets > 0) {
    throw GeoLatticeError("tet mesh has " + std::to_string(r.zeroVolumeTets) + " zero-volume tets" +
                          first("tet", r.firstZeroVolumeTet));
  }
  if (r.nonManifoldFaces > 0) {
    throw GeoLatticeError("tet mesh has " + std::to_string(r.nonManifoldFaces) +
                          " faces shared by more than two tets (overlapping tets)");
  }
  if (r.unusedPoints > 0) {
    throw GeoLatticeError("tet mesh has " + std::to_string(r.unusedPoints) +
                          " vertices used by no tet" + first("vertex", r.firstUnusedPoint));
  }
  return r;
}

int orientTetsPositively(TetMesh& mesh) {
  const int n = static_cast<int>(mesh.points.size());
  if (mesh.tets.empty()) {
    return 0;
  }
  for (const auto& tet : mesh.tets) {
    if (!tetInRange(tet, n) || !(signedTetVolume(mesh.points[tet[0]], mesh.points[tet[1]],
                                                 mesh.points[tet[2]], mesh.points[tet[3]]) < 0.0)) {
      return 0;
    }
  }
  for (auto& tet : mesh.tets) {
    std::swap(tet[2], tet[3]);
  }
  return static_cast<int>(mesh.tets.size());
}

size_t removeFlatTets(TetMesh& mesh) {
  const size_t before = mesh.tets.size();
  mesh.tets.erase(std::remove_if(mesh.tets.begin(), mesh.tets.end(),
                                 [&](const std::array<int, 4>& t) {
                                   const Vec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]],
                                              &c = mesh.points[t[2]], &d = mesh.points[t[3]];
                                   return isFlatTet(a, b, c, d, signedTetVolume(a, b, c, d));
                                 }),
                  mesh.tets.end());
  const size_t removed = before - mesh.tets.size();
  if (removed > 0) {  // a point only flat tets used goes too
    std::vector<int> id(mesh.points.size(), -1);
    for (const auto& t : mesh.tets) {
      for (int v : t) {
        id[v] = 0;
      }
    }
    std::vector<Vec3> kept;
    for (size_t v = 0; v < id.size(); ++v) {
      if (id[v] == 0) {
        id[v] = static_cast<int>(kept.size());
        kept.push_back(mesh.points[v]);
      }
    }
    for (auto& t : mesh.tets) {
      for (int& v : t) {
        v = id[v];
      }
    }
    mesh.points = std::move(kept);
  }
  return removed;
}

}  // namespace geolattice
