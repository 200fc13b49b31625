#include "mesh/OverlappingBodies.h"

#include "common/Error.h"
#include "mesh/SurfaceWrap.h"
#include "common/UnionFind.h"
#include "mesh/CgalSurfaceMesh.h"
#include "mesh/SurfaceCheck.h"
#include "mesh/SurfaceRepair.h"

#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace geolattice {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Mesh = cgal::SurfaceMesh;
using Box = Eigen::AlignedBox3d;

/// Component of every triangle (union-find over the vertices the triangles share; unused points
/// are components without triangles and are not counted).
std::vector<int> triangleComponents(const TriangleSurface& s, int& count) {
  UnionFind sets(static_cast<int>(s.points.size()));
  for (const auto& t : s.triangles) {
    sets.unite(t[0], t[1]);
    sets.unite(t[0], t[2]);
  }
  std::vector<int> vertexSet;
  sets.labels(vertexSet);
  std::vector<int> label(s.points.size(), -1), out;
  out.reserve(s.triangles.size());
  count = 0;
  for (const auto& t : s.triangles) {
    int& l = label[vertexSet[t[0]]];
    if (l < 0) {
      l = count++;
    }
    out.push_back(l);
  }
  return out;
}

struct Body {
  TriangleSurface surface;
  Box box;
};

std::vector<Body> splitBodies(const TriangleSurface& s, const std::vector<int>& component,
                              int count) {
  std::vector<Body> bodies(count);
  std::vector<int> local(s.points.size(), -1);
  for (size_t t = 0; t < s.triangles.size(); ++t) {
    Body& b = bodies[component[t]];
    std::array<int, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      int& id = local[s.triangles[t][k]];
      if (id < 0) {
        id = static_cast<int>(b.surface.points.size());
        b.surface.points.push_back(s.points[s.triangles[t][k]]);
        b.box.extend(s.points[s.triangles[t][k]]);
      }
      tri[k] = id;
    }
    b.surface.triangles.push_back(tri);
  }
  return bodies;
}

std::string where(const Box& box) {
  const Vec3 c = box.center();
  char text[96];
  std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", c.x(), c.y(), c.z());
  return text;
}

}  // namespace

OverlappingBodiesResult mergeOverlappingBodies(TriangleSurface& surface) {
  OverlappingBodiesResult r;
  const std::vector<int> component = triangleComponents(surface, r.bodies);
  if (r.bodies < 2) {
    return r;
  }
  std::vector<Body> bodies = splitBodies(surface, component, r.bodies);
  std::vector<Mesh> meshes(bodies.size());
  std::vector<char> converted(bodies.size(), 0), alive(bodies.size(), 1);
  auto mesh = [&](size_t i) -> Mesh& {
    if (!converted[i]) {
      meshes[i] = cgal::toSurfaceMesh(bodies[i].surface, "overlapping bodies");
      converted[i] = 1;
    }
    return meshes[i];
  };
  // Merge crossing pairs until none is left; a merged body is compared with every other again.
  for (bool again = true; again;) {
    again = false;
    for (size_t i = 0; i < bodies.size(); ++i) {
      for (size_t j = i + 1; alive[i] && j < bodies.size(); ++j) {
        if (!alive[j] || !bodies[i].box.intersects(bodies[j].box) ||
            !PMP::do_intersect(mesh(i), mesh(j),
                               CGAL::parameters::do_overlap_test_of_bounded_sides(false),
                               CGAL::parameters::do_overlap_test_of_bounded_sides(false))) {
          continue;
        }
        for (size_t k : {i, j}) {
          if (!(PMP::volume(mesh(k)) > 0)) {
            throw GeoLatticeError(
                "overlapping bodies: an inward-facing shell (a cavity) near " +
                where(bodies[k].box) +
                " crosses another body; repair the part in its CAD tool and export it again");
          }
          // The union needs bodies that do not cross themselves.
          if (PMP::does_self_intersect(mesh(k))) {
            throw GeoLatticeError("self-intersecting surface: the body near " +
                                  where(bodies[k].box) +
                                  " crosses itself (and another body); repair it in its CAD "
                                  "tool and export it again" +
                                  kWrapHint);
          }
        }
        Mesh united;
        bool ok = false;
        try {
          ok = PMP::corefine_and_compute_union(mesh(i), mesh(j), united);
        } catch (const std::exception& e) {
          throw GeoLatticeError("overlapping bodies near " + where(bodies[i].box) +
                                ": CGAL's union failed (" + e.what() + ")");
        }
        united.collect_garbage();
        // The union's new vertices are rounded to doubles: a fold there would be a new crossing.
        // Where that left slivers of area ~0 (mirror-image bodies, turned by the orientation
        // search), they are mended first: CGAL counts a degenerate face as self-intersecting.
        const auto clean = [](const Mesh& m) {
          return CGAL::is_closed(m) && !PMP::does_self_intersect(m);
        };
        if (ok && !clean(united)) {
          TriangleSurface s = cgal::toTriangleSurface(united);
          if (removeDegenerateTriangles(s) > 0) {
            try {
              united = cgal::toSurfaceMesh(s, "overlapping bodies");
            } catch (const GeoLatticeError&) {
              ok = false;  // the mended union is no 2-manifold: refused below
            }
          }
        }
        if (!ok || !clean(united)) {
          throw GeoLatticeError("overlapping bodies near " + where(bodies[i].box) +
                                ": their union is not a clean closed surface; merge them into "
                                "one solid in the CAD tool (a Boolean union)");
        }
        meshes[i] = std::move(united);
        bodies[i].box.extend(bodies[j].box);
        alive[j] = 0;
        meshes[j] = Mesh();
        ++r.merged;
        again = true;
      }
    }
  }
  if (r.merged == 0) {
    return r;
  }
  TriangleSurface out;
  for (size_t i = 0; i < bodies.size(); ++i) {
    if (!alive[i]) {
      continue;
    }
    const TriangleSurface part =
        converted[i] ? cgal::toTriangleSurface(meshes[i]) : bodies[i].surface;
    const int offset = static_cast<int>(out.points.size());
    out.points.insert(out.points.end(), part.points.begin(), part.points.end());
    for (auto t : part.triangles) {
      out.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
  }
  surface = std::move(out);
  return r;
}

namespace {

/// Drops the walls between bodies that touch along identically triangulated faces: pairs of
/// triangles on the same three vertices in opposite directions. Returns the wall patches
/// (connected sets of dropped pairs: one per contact), 0 when there is none.
int dropInnerWalls(TriangleSurface& surface) {
  std::map<std::array<int, 3>, std::vector<int>> byVertices;
  for (int t = 0; t < static_cast<int>(surface.triangles.size()); ++t) {
    std::array<int, 3> sorted = surface.triangles[t];
    std::sort(sorted.begin(), sorted.end());
    byVertices[sorted].push_back(t);
  }
  std::map<std::pair<int, int>, int> uses;  // undirected edge -> triangles on it
  for (const auto& t : surface.triangles) {
    for (int k = 0; k < 3; ++k) {
      ++uses[std::minmax(t[k], t[(k + 1) % 3])];
    }
  }
  // A wall between two bodies meets their other faces at each of its edges (4 uses or more); a
  // pair that is alone on an edge is a sheet of its own (a fin with nothing on either side),
  // which is not the part's and stays a defect.
  auto sheet = [&](const std::array<int, 3>& t) {
    for (int k = 0; k < 3; ++k) {
      if (uses[std::minmax(t[k], t[(k + 1) % 3])] == 2) {
        return true;
      }
    }
    return false;
  };
  std::vector<char> dropped(surface.triangles.size(), 0);
  std::vector<int> walls;  // one triangle of each dropped pair
  for (const auto& [vertices, list] : byVertices) {
    if (list.size() == 2 && !sheet(surface.triangles[list[0]]) &&
        cyclicParity(surface.triangles[list[0]]) != cyclicParity(surface.triangles[list[1]])) {
      dropped[list[0]] = dropped[list[1]] = 1;
      walls.push_back(list[0]);
    }
  }
  if (walls.empty()) {
    return 0;
  }
  UnionFind patches(static_cast<int>(walls.size()));
  std::map<std::pair<int, int>, int> wallOfEdge;
  for (int w = 0; w < static_cast<int>(walls.size()); ++w) {
    const auto& t = surface.triangles[walls[w]];
    for (int k = 0; k < 3; ++k) {
      const auto edge = std::minmax(t[k], t[(k + 1) % 3]);
      const auto [it, added] = wallOfEdge.try_emplace(edge, w);
      if (!added) {
        patches.unite(it->second, w);
      }
    }
  }
  std::vector<int> label;
  const int count = patches.labels(label);
  TriangleSurface kept;
  kept.points = std::move(surface.points);
  for (size_t t = 0; t < surface.triangles.size(); ++t) {
    if (!dropped[t]) {
      kept.triangles.push_back(surface.triangles[t]);
    }
  }
  // The walls' inner vertices go too: only the triangles' vertices are kept.
  surface = withoutUnusedPoints(kept);
  return count;
}

}  // namespace

int mergeTouchingBodies(TriangleSurface& surface) {
  if (checkSurface(surface).nonManifoldEdges == 0) {
    return 0;
  }
  // Faces triangulated alike on both sides (bodies split from one solid): the walls go.
  {
    TriangleSurface withoutWalls = surface;
    const int contacts = dropInnerWalls(withoutWalls);
    if (contacts > 0 && checkSurface(withoutWalls).isClosedManifold()) {
      surface = std::move(withoutWalls);
      return contacts;
    }
  }
  // Each undirected edge's uses: (triangle, +1 when it runs from the smaller vertex id).
  std::unordered_map<std::uint64_t, std::vector<std::pair<int, int>>> uses;
  auto key = [](int a, int b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
           static_cast<std::uint32_t>(std::max(a, b));
  };
  const int nt = static_cast<int>(surface.triangles.size());
  uses.reserve(3 * static_cast<size_t>(nt) / 2);
  for (int t = 0; t < nt; ++t) {
    const auto& tri = surface.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      uses[key(a, b)].emplace_back(t, a < b ? 1 : -1);
    }
  }
  // Non-manifold edges exist (checked above): bodies join across the others only.
  UnionFind bodies(nt);
  for (const auto& [edge, list] : uses) {
    if (list.size() == 2 && list[0].second != list[1].second) {
      bodies.unite(list[0].first, list[1].first);
    }
  }
  // Every body closed: each of its edges used once in each direction by its own triangles.
  for (const auto& [edge, list] : uses) {
    std::map<int, int> balance, count;  // body -> sum of directions, uses
    for (const auto& [t, direction] : list) {
      balance[bodies.find(t)] += direction;
      ++count[bodies.find(t)];
    }
    for (const auto& [body, n] : count) {
      if (n != 2 || balance[body] != 0) {
        return 0;
      }
    }
  }
  // Each body its own vertices.
  TriangleSurface separated;
  std::map<std::pair<int, int>, int> vertexOf;  // (body, input vertex) -> output vertex
  for (int t = 0; t < nt; ++t) {
    std::array<int, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const int v = surface.triangles[t][k];
      const auto [it, added] = vertexOf.try_emplace({bodies.find(t), v}, 0);
      if (added) {
        it->second = static_cast<int>(separated.points.size());
        separated.points.push_back(surface.points[v]);
      }
      tri[k] = it->second;
    }
    separated.triangles.push_back(tri);
  }
  try {
    orientOutward(separated);
    const int merged = mergeOverlappingBodies(separated).merged;
    if (merged == 0 || !checkSurface(separated).isClosedManifold()) {
      return 0;
    }
    surface = std::move(separated);
    return merged;
  } catch (const GeoLatticeError&) {
    return 0;  // no manifold union (touching along an edge): the caller reports the input's
  }
}

}  // namespace geolattice
