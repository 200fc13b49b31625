#include "mesh/AnalyticShapes.h"

#include "common/Error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>

namespace geolattice {

namespace {

void requirePositiveSize(const Vec3& size, const char* function) {
  for (int a = 0; a < 3; ++a) {
    if (!(size[a] > 0.0) || !std::isfinite(size[a])) {
      throw GeoLatticeError(std::string(function) +
                            ": box size must be positive and finite, got (" +
                            std::to_string(size.x()) + ", " + std::to_string(size.y()) + ", " +
                            std::to_string(size.z()) + ") mm");
    }
  }
}

}  // namespace

TriangleSurface boxSurface(const Vec3& size, double maxEdge) {
  requirePositiveSize(size, "boxSurface");
  if (!(maxEdge > 0.0) || !std::isfinite(maxEdge)) {
    throw GeoLatticeError("boxSurface: maxEdge must be positive and finite, got " +
                          std::to_string(maxEdge) + " mm");
  }
  // A right triangle with legs h_u, h_v has hypotenuse sqrt(h_u^2 + h_v^2) <= maxEdge when
  // both legs are <= maxEdge / sqrt(2).
  const double maxStep = maxEdge / std::sqrt(2.0);
  std::array<int64_t, 3> n;
  for (int a = 0; a < 3; ++a) {
    const double cells = std::ceil(size[a] / maxStep - 1e-9);
    if (cells > 1e6) {
      throw GeoLatticeError("boxSurface: maxEdge " + std::to_string(maxEdge) +
                            " mm is too small for a " + std::to_string(size[a]) + " mm side");
    }
    n[a] = std::max<int64_t>(1, static_cast<int64_t>(cells));
  }
  const int64_t surfaceVertices =
      2 * ((n[0] + 1) * (n[1] + 1) + (n[0] + 1) * (n[2] + 1) + (n[1] + 1) * (n[2] + 1));
  if (surfaceVertices > std::numeric_limits<int>::max() / 2) {
    throw GeoLatticeError("boxSurface: too many vertices (" + std::to_string(surfaceVertices) +
                          ")");
  }

  TriangleSurface surface;
  // Lattice point (i,j,k) -> vertex id; only boundary lattice points are ever created.
  std::unordered_map<int64_t, int> ids;
  ids.reserve(static_cast<size_t>(surfaceVertices));
  auto vertex = [&](const std::array<int64_t, 3>& ijk) {
    const int64_t key = ijk[0] + (n[0] + 1) * (ijk[1] + (n[1] + 1) * ijk[2]);
    auto it = ids.find(key);
    if (it != ids.end()) {
      return it->second;
    }
    const int id = static_cast<int>(surface.points.size());
    // Exact coordinates at the far faces: i == n maps to size, not to n * step.
    surface.points.emplace_back(size[0] * static_cast<double>(ijk[0]) / static_cast<double>(n[0]),
                                size[1] * static_cast<double>(ijk[1]) / static_cast<double>(n[1]),
                                size[2] * static_cast<double>(ijk[2]) / static_cast<double>(n[2]));
    ids.emplace(key, id);
    return id;
  };

  // Face with fixed axis `w` at lattice coordinate `wValue`, spanned by axes u, v with
  // e_u x e_v = outward normal: triangles counter-clockwise in (u, v) are outward.
  auto face = [&](int w, int64_t wValue, int u, int v) {
    for (int64_t j = 0; j < n[v]; ++j) {
      for (int64_t i = 0; i < n[u]; ++i) {
        auto at = [&](int64_t du, int64_t dv) {
          std::array<int64_t, 3> ijk;
          ijk[w] = wValue;
          ijk[u] = i + du;
          ijk[v] = j + dv;
          return vertex(ijk);
        };
        const int a = at(0, 0), b = at(1, 0), c = at(1, 1), d = at(0, 1);
        surface.triangles.push_back({a, b, c});
        surface.triangles.push_back({a, c, d});
      }
    }
  };
  face(0, 0, 2, 1);     // x = 0,  normal -x = z cross y
  face(0, n[0], 1, 2);  // x = sx, normal +x = y cross z
  face(1, 0, 0, 2);     // y = 0,  normal -y = x cross z
  face(1, n[1], 2, 0);  // y = sy, normal +y = z cross x
  face(2, 0, 1, 0);     // z = 0,  normal -z = y cross x
  face(2, n[2], 0, 1);  // z = sz, normal +z = x cross y
  return surface;
}

TriangleSurface torusSurface(const Vec3& centre, double majorRadius, double minorRadius,
                             int majorSegments, int minorSegments) {
  if (!(minorRadius > 0.0) || !(majorRadius > minorRadius) || !std::isfinite(majorRadius)) {
    throw GeoLatticeError("torusSurface: need 0 < minor radius < major radius, got " +
                          std::to_string(minorRadius) + " and " + std::to_string(majorRadius) +
                          " mm");
  }
  if (majorSegments < 3 || minorSegments < 3 || majorSegments > 4096 || minorSegments > 4096) {
    throw GeoLatticeError("torusSurface: segment counts must be in 3..4096");
  }
  TriangleSurface s;
  const int nu = majorSegments, nv = minorSegments;
  for (int i = 0; i < nu; ++i) {
    const double u = 2.0 * M_PI * i / nu;
    const Vec3 radial(std::cos(u), 0.0, std::sin(u));
    for (int j = 0; j < nv; ++j) {
      const double v = 2.0 * M_PI * j / nv;
      s.points.push_back(centre + (majorRadius + minorRadius * std::cos(v)) * radial +
                         minorRadius * std::sin(v) * Vec3::UnitY());
    }
  }
  auto id = [&](int i, int j) {
    return ((i + nu) % nu) * nv + (j + nv) % nv;
  };
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      // (d/du) x (d/dv) points inwards for this parametrisation, so the quads run (i, j+1, i+1).
      s.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
    }
  }
  return s;
}

TriangleSurface sphereSurface(const Vec3& centre, double radius, int subdivisionLevel) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw GeoLatticeError("sphereSurface: radius must be positive and finite, got " +
                          std::to_string(radius) + " mm");
  }
  if (subdivisionLevel < 0 || subdivisionLevel > 10) {
    throw GeoLatticeError("sphereSurface: subdivision level must be in 0..10, got " +
                          std::to_string(subdivisionLevel));
  }
  // Unit icosahedron, outward counter-clockwise triangles.
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> p = {Vec3(-1, t, 0), Vec3(1, t, 0), Vec3(-1, -t, 0), Vec3(1, -t, 0),
                         Vec3(0, -1, t), Vec3(0, 1, t), Vec3(0, -1, -t), Vec3(0, 1, -t),
                         Vec3(t, 0, -1), Vec3(t, 0, 1), Vec3(-t, 0, -1), Vec3(-t, 0, 1)};
  for (Vec3& q : p) {
    q.normalize();
  }
  std::vector<std::array<int, 3>> tris = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < subdivisionLevel; ++level) {
    std::map<std::pair<int, int>, int> midpoints;  // one new vertex per edge, shared by both sides
    auto midpoint = [&](int a, int b) {
      const std::pair<int, int> key(std::min(a, b), std::max(a, b));
      auto it = midpoints.find(key);
      if (it != midpoints.end()) {
        return it->second;
      }
      const int id = static_cast<int>(p.size());
      p.push_back((p[a] + p[b]).normalized());
      midpoints.emplace(key, id);
      return id;
    };
    std::vector<std::array<int, 3>> next;
    next.reserve(tris.size() * 4);
    for (const auto& tri : tris) {
      const int ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]),
                ca = midpoint(tri[2], tri[0]);
      next.push_back({tri[0], ab, ca});
      next.push_back({tri[1], bc, ab});
      next.push_back({tri[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    tris.swap(next);
  }
  TriangleSurface surface;
  surface.points.reserve(p.size());
  for (const Vec3& q : p) {
    surface.points.push_back(centre + radius * q);
  }
  surface.triangles = std::move(tris);
  return surface;
}

TriangleSurface revolvedSurface(const std::vector<std::pair<double, double>>& profile,
                                int segments) {
  if (profile.size() < 3 || segments < 3) {
    throw GeoLatticeError("surface of revolution: needs at least 3 profile points and 3 segments");
  }
  TriangleSurface s;
  const int rings = static_cast<int>(profile.size()) - 2;  // the circles between the poles
  s.points.emplace_back(0, 0, profile.front().second);
  for (int i = 1; i <= rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      const double a = 2 * M_PI * j / segments, r = profile[i].first;
      s.points.emplace_back(r * std::cos(a), r * std::sin(a), profile[i].second);
    }
  }
  const int top = static_cast<int>(s.points.size());
  s.points.emplace_back(0, 0, profile.back().second);
  auto ring = [segments](int i, int j) {
    return 1 + (i - 1) * segments + (j % segments);
  };
  for (int j = 0; j < segments; ++j) {
    s.triangles.push_back({0, ring(1, j + 1), ring(1, j)});
    for (int i = 1; i < rings; ++i) {
      s.triangles.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)});
      s.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
    }
    s.triangles.push_back({ring(rings, j), ring(rings, j + 1), top});
  }
  return s;
}

TetMesh boxTetMesh(const Vec3& size, int nx, int ny, int nz) {
  requirePositiveSize(size, "boxTetMesh");
  if (nx < 1 || ny < 1 || nz < 1) {
    throw GeoLatticeError("boxTetMesh: cell counts must be >= 1, got " + std::to_string(nx) +
                          " x " + std::to_string(ny) + " x " + std::to_string(nz));
  }
  const int64_t tetCount = int64_t{6} * nx * ny * nz;
  if (tetCount > std::numeric_limits<int>::max()) {
    throw GeoLatticeError("boxTetMesh: too many tets (" + std::to_string(tetCount) + ")");
  }
  TetMesh mesh;
  mesh.points.reserve(static_cast<size_t>(nx + 1) * (ny + 1) * (nz + 1));
  for (int k = 0; k <= nz; ++k) {
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i) {
        mesh.points.emplace_back(size.x() * i / nx, size.y() * j / ny, size.z() * k / nz);
      }
    }
  }
  auto id = [&](int i, int j, int k) {
    return i + (nx + 1) * (j + (ny + 1) * k);
  };
  // Kuhn split: one tet per axis order (a, b, c), along the path 0 -> e_a -> e_a+e_b -> 1,1,1.
  // Corner bit 1 = +x, 2 = +y, 4 = +z. Odd permutations give negative orientation, so two
  // vertices are swapped for them.
  constexpr int kPaths[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                                {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
  std::array<std::array<int, 4>, 6> local;
  for (int s = 0; s < 6; ++s) {
    std::array<Vec3, 4> c;
    for (int q = 0; q < 4; ++q) {
      c[q] = Vec3(kPaths[s][q] & 1, (kPaths[s][q] >> 1) & 1, (kPaths[s][q] >> 2) & 1);
    }
    local[s] = {kPaths[s][0], kPaths[s][1], kPaths[s][2], kPaths[s][3]};
    if (signedTetVolume(c[0], c[1], c[2], c[3]) < 0) {
      std::swap(local[s][2], local[s][3]);
    }
  }
  mesh.tets.reserve(static_cast<size_t>(tetCount));
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        for (const auto& tet : local) {
          std::array<int, 4> global;
          for (int q = 0; q < 4; ++q) {
            global[q] = id(i + (tet[q] & 1), j + ((tet[q] >> 1) & 1), k + ((tet[q] >> 2) & 1));
          }
          mesh.tets.push_back(global);
        }
      }
    }
  }
  return mesh;
}

TetMesh voxelTetMesh(const Vec3& size, int nx, int ny, int nz,
                     const std::function<bool(const Vec3&)>& keep) {
  const TetMesh box = boxTetMesh(size, nx, ny, nz);
  const Vec3 cell(size.x() / nx, size.y() / ny, size.z() / nz);
  TetMesh out;
  std::vector<int> id(box.points.size(), -1);
  for (const auto& t : box.tets) {
    const Vec3 centroid =
        0.25 * (box.points[t[0]] + box.points[t[1]] + box.points[t[2]] + box.points[t[3]]);
    Vec3 centre;
    for (int a = 0; a < 3; ++a) {
      centre[a] = (std::floor(centroid[a] / cell[a]) + 0.5) * cell[a];
    }
    if (!keep(centre)) {
      continue;
    }
    std::array<int, 4> tet;
    for (int k = 0; k < 4; ++k) {
      if (id[t[k]] < 0) {
        id[t[k]] = static_cast<int>(out.points.size());
        out.points.push_back(box.points[t[k]]);
      }
      tet[k] = id[t[k]];
    }
    out.tets.push_back(tet);
  }
  return out;
}

}  // namespace geolattice
