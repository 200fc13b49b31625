#pragma once
/// @file CgalSurfaceMesh.h
/// @brief The one conversion between core's TriangleSurface and CGAL's Surface_mesh (EPICK
/// kernel), for the stages that use CGAL's mesh processing (simplification, printhead checks).
#include "common/Error.h"
#include "mesh/TetMesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>

#include <string>
#include <vector>

namespace geolattice::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

/// Throws GeoLatticeError("<what>: the surface is not an oriented 2-manifold") when a triangle
/// cannot be added (CGAL refuses non-manifold or inconsistently oriented faces).
inline SurfaceMesh toSurfaceMesh(const TriangleSurface& s, const std::string& what) {
  SurfaceMesh m;
  std::vector<SurfaceMesh::Vertex_index> v;
  v.reserve(s.points.size());
  for (const Vec3& p : s.points) {
    v.push_back(m.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
  }
  for (const auto& t : s.triangles) {
    if (m.add_face(v[t[0]], v[t[1]], v[t[2]]) == SurfaceMesh::null_face()) {
      throw GeoLatticeError(what + ": the surface is not an oriented 2-manifold");
    }
  }
  return m;
}

/// The triangles of a triangle mesh `m` (removed elements skipped, points renumbered densely).
inline TriangleSurface toTriangleSurface(const SurfaceMesh& m) {
  TriangleSurface s;
  std::vector<int> id(m.num_vertices(), -1);  // by index, removed vertices included
  s.points.reserve(m.number_of_vertices());
  for (SurfaceMesh::Vertex_index v : m.vertices()) {
    id[v.idx()] = static_cast<int>(s.points.size());
    const Kernel::Point_3& p = m.point(v);
    s.points.emplace_back(p.x(), p.y(), p.z());
  }
  s.triangles.reserve(m.number_of_faces());
  for (SurfaceMesh::Face_index f : m.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m)) {
      if (k < 3) {
        t[k] = id[v.idx()];
      }
      ++k;
    }
    if (k != 3) {
      throw GeoLatticeError("a face of the mesh has " + std::to_string(k) + " vertices, not 3");
    }
    s.triangles.push_back(t);
  }
  return s;
}

}  // namespace geolattice::cgal
