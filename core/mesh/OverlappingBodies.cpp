#include "mesh/OverlappingBodies.h"

#include "common/Error.h"
#include "common/UnionFind.h"
#include "mesh/CgalSurfaceMesh.h"

#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <Eigen/Geometry>
#include <string>
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
                                  "tool and export it again");
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
        if (!ok || !CGAL::is_closed(united) || PMP::does_self_intersect(united)) {
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

}  // namespace geolattice
