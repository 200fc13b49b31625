#include "mesh/ShellNesting.h"

#include "common/UnionFind.h"
#include "mesh/SurfaceCheck.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace geolattice {

ShellNesting nestShells(const TriangleSurface& surface) {
  ShellNesting r;
  const int n = static_cast<int>(surface.triangles.size());
  // Shells: triangles joined across their edges.
  UnionFind joined(n);
  std::unordered_map<std::uint64_t, int> firstAcross;
  firstAcross.reserve(3 * static_cast<size_t>(n) / 2);
  for (int f = 0; f < n; ++f) {
    const auto& t = surface.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::uint64_t>(std::min(t[k], t[(k + 1) % 3]));
      const auto b = static_cast<std::uint64_t>(std::max(t[k], t[(k + 1) % 3]));
      const auto [it, fresh] = firstAcross.emplace((a << 32) | b, f);
      if (!fresh) {
        joined.unite(f, it->second);
      }
    }
  }
  r.shells = joined.labels(r.shellOf);
  r.triangles.assign(r.shells, {});
  r.volume6.assign(r.shells, 0.0);
  r.box.assign(r.shells, Eigen::AlignedBox3d());
  r.inside.assign(r.shells, {});
  std::vector<double> largest(r.shells, -1.0);
  std::vector<Vec3> probe(r.shells, Vec3::Zero());
  for (int f = 0; f < n; ++f) {
    const int s = r.shellOf[f];
    const auto& t = surface.triangles[f];
    const Vec3 &p0 = surface.points[t[0]], &p1 = surface.points[t[1]], &p2 = surface.points[t[2]];
    r.triangles[s].push_back(f);
    r.volume6[s] += p0.dot(p1.cross(p2));
    const double area2 = (p1 - p0).cross(p2 - p0).norm();
    if (area2 > largest[s]) {
      largest[s] = area2;
      probe[s] = (p0 + p1 + p2) / 3.0;
    }
    r.box[s].extend(p0);
    r.box[s].extend(p1);
    r.box[s].extend(p2);
  }
  if (r.shells < 2) {
    return r;
  }
  for (int s = 0; s < r.shells; ++s) {
    for (int o = 0; o < r.shells; ++o) {
      if (o != s && r.box[o].contains(r.box[s]) &&
          std::abs(windingNumber(surface, probe[s], &r.triangles[o])) > 0.5) {
        r.inside[s].push_back(o);
      }
    }
  }
  return r;
}

CavityFilling fillCavities(TriangleSurface& surface) {
  CavityFilling result;
  const ShellNesting nesting = nestShells(surface);
  std::vector<char> removed(nesting.shells, 0);
  for (int s = 0; s < nesting.shells; ++s) {
    if (nesting.isCavity(s)) {
      removed[s] = 1;
      ++result.cavities;
      continue;
    }
    for (int o : nesting.inside[s]) {
      if (nesting.isCavity(o)) {
        removed[s] = 1;
        ++result.enclosedBodies;
        break;
      }
    }
  }
  if (result.cavities == 0) {
    return result;
  }
  std::vector<std::array<int, 3>> kept;
  kept.reserve(surface.triangles.size());
  for (size_t f = 0; f < surface.triangles.size(); ++f) {
    if (removed[nesting.shellOf[f]]) {
      ++result.removedTriangles;
    } else {
      kept.push_back(surface.triangles[f]);
    }
  }
  // The points no kept triangle uses go too (ids renumbered in their order).
  std::vector<int> newId(surface.points.size(), -1);
  for (const auto& t : kept) {
    for (int v : t) {
      newId[v] = 0;
    }
  }
  std::vector<Vec3> points;
  for (size_t v = 0; v < surface.points.size(); ++v) {
    if (newId[v] == 0) {
      newId[v] = static_cast<int>(points.size());
      points.push_back(surface.points[v]);
    }
  }
  for (auto& t : kept) {
    for (int& v : t) {
      v = newId[v];
    }
  }
  surface.points = std::move(points);
  surface.triangles = std::move(kept);
  return result;
}

}  // namespace geolattice
