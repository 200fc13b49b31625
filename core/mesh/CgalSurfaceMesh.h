#pragma once
/// @file CgalSurfaceMesh.h
/// @brief The one conversion between core's TriangleSurface and CGAL's Surface_mesh (EPICK
/// kernel), for the stages that use CGAL's mesh processing (simplification, printhead checks).
#include "common/Error.h"
#include "mesh/TetMesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

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

}  // namespace geolattice::cgal
