#include "mesh/SurfaceRepair.h"

#include "common/UnionFind.h"
#include "mesh/OverlappingBodies.h"
#include "mesh/SurfaceCheck.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <unordered_set>
#include <vector>

namespace geolattice {

bool cyclicParity(const std::array<int, 3>& t) {
  const int first = static_cast<int>(std::min_element(t.begin(), t.end()) - t.begin());
  return t[(first + 1) % 3] < t[(first + 2) % 3];
}

int dropDuplicateTriangles(TriangleSurface& surface) {
  // A triangle's key: its sorted vertices, the last one complemented when it runs the other way.
  struct KeyHash {
    size_t operator()(const std::array<int, 3>& k) const {
      const std::hash<int> h;
      return (h(k[0]) * 0x9E3779B97F4A7C15ULL) ^ (h(k[1]) * 0xC2B2AE3D27D4EB4FULL) ^ h(k[2]);
    }
  };
  std::unordered_set<std::array<int, 3>, KeyHash> seen;
  seen.reserve(surface.triangles.size());
  std::vector<std::array<int, 3>> kept;
  kept.reserve(surface.triangles.size());
  for (const std::array<int, 3>& t : surface.triangles) {
    std::array<int, 3> key = t;
    std::sort(key.begin(), key.end());
    if (!cyclicParity(t)) {
      key[2] = ~key[2];
    }
    if (seen.insert(key).second) {
      kept.push_back(t);
    }
  }
  const int dropped = static_cast<int>(surface.triangles.size() - kept.size());
  if (dropped > 0) {
    surface.triangles = std::move(kept);
  }
  return dropped;
}

int orientConsistently(TriangleSurface& surface) {
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<Point> points;
  points.reserve(surface.points.size());
  for (const Vec3& p : surface.points) {
    points.emplace_back(p.x(), p.y(), p.z());
  }
  std::vector<std::array<std::size_t, 3>> polygons;
  polygons.reserve(surface.triangles.size());
  for (const auto& t : surface.triangles) {
    polygons.push_back({static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
                        static_cast<std::size_t>(t[2])});
  }
  // false: points had to be duplicated (non-manifold or non-orientable): not this repair's case.
  if (!CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons) ||
      points.size() != surface.points.size() || polygons.size() != surface.triangles.size()) {
    return 0;
  }
  // CGAL keeps each body's first triangle as it is and turns the rest to agree with it: where
  // that turned most of a body, its first triangle was one of the flipped ones, and the body is
  // turned back as a whole (the way most of its triangles ran, e.g. inward for a cavity).
  const int n = static_cast<int>(surface.triangles.size());
  UnionFind sets(static_cast<int>(surface.points.size()));
  for (const auto& t : surface.triangles) {
    sets.unite(t[0], t[1]);
    sets.unite(t[0], t[2]);
  }
  std::vector<char> changed(static_cast<size_t>(n));
  std::vector<int> bodyTriangles(surface.points.size(), 0), bodyChanged(surface.points.size(), 0);
  for (int i = 0; i < n; ++i) {
    const std::array<int, 3> t = {static_cast<int>(polygons[i][0]),
                                  static_cast<int>(polygons[i][1]),
                                  static_cast<int>(polygons[i][2])};
    changed[i] = cyclicParity(t) != cyclicParity(surface.triangles[i]);
    const int body = sets.find(t[0]);
    ++bodyTriangles[body];
    bodyChanged[body] += changed[i];
  }
  int turned = 0;
  for (int i = 0; i < n; ++i) {
    const int body = sets.find(surface.triangles[i][0]);
    const bool back = 2 * bodyChanged[body] > bodyTriangles[body];
    if (changed[i] != back) {  // turned by CGAL and kept, or not turned and turned with its body
      std::swap(surface.triangles[i][1], surface.triangles[i][2]);
      ++turned;
    }
  }
  return turned;
}

SurfaceRepairCounts repairSurface(TriangleSurface& surface) {
  SurfaceRepairCounts counts;
  SurfaceCheckReport check = checkSurface(surface);
  if (check.nonManifoldEdges == 0 && check.inconsistentEdges == 0) {
    return counts;  // holes and the rest are not repaired here
  }
  counts.duplicateTriangles = dropDuplicateTriangles(surface);
  if (counts.duplicateTriangles > 0) {
    check = checkSurface(surface);
  }
  if (check.inconsistentEdges > 0 && check.nonManifoldEdges == 0) {
    counts.reorientedTriangles = orientConsistently(surface);
  }
  if (check.nonManifoldEdges > 0) {
    counts.mergedBodies = mergeTouchingBodies(surface);
  }
  return counts;
}

}  // namespace geolattice
