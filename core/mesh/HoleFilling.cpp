#include "mesh/HoleFilling.h"

// Fairing solves a sparse system: CGAL's default solver for it is Eigen's.
#ifndef CGAL_EIGEN3_ENABLED
#define CGAL_EIGEN3_ENABLED
#endif

#include "common/Error.h"
#include "mesh/CgalSurfaceMesh.h"

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <iterator>
#include <string>
#include <tuple>
#include <vector>

namespace geolattice {

namespace PMP = CGAL::Polygon_mesh_processing;

HoleFillingResult fillHoles(TriangleSurface& surface) {
  HoleFillingResult result;
  cgal::SurfaceMesh mesh = cgal::toSurfaceMesh(surface, "filling the holes");
  std::vector<cgal::SurfaceMesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  if (cycles.empty()) {
    return result;
  }
  const size_t facesBefore = mesh.number_of_faces();
  for (const cgal::SurfaceMesh::Halfedge_index h : cycles) {
    std::vector<cgal::SurfaceMesh::Face_index> patch;
    std::vector<cgal::SurfaceMesh::Vertex_index> inner;
    bool faired = false;
    try {
      faired = std::get<0>(PMP::triangulate_refine_and_fair_hole(mesh, h, std::back_inserter(patch),
                                                                 std::back_inserter(inner)));
    } catch (const std::exception&) {
      faired = false;
    }
    if (!faired) {
      // The hole is triangulated and refined before the fairing fails; without a patch yet,
      // triangulate and refine it alone.
      if (patch.empty()) {
        PMP::triangulate_and_refine_hole(mesh, h, std::back_inserter(patch),
                                         std::back_inserter(inner));
      }
      if (patch.empty()) {
        throw GeoLatticeError("filling the holes: CGAL could not close a hole of " +
                              std::to_string(CGAL::halfedges_around_face(h, mesh).size()) +
                              " edges");
      }
    }
    ++result.holes;
  }
  result.addedTriangles = static_cast<int>(mesh.number_of_faces() - facesBefore);
  surface = cgal::toTriangleSurface(mesh);
  return result;
}

}  // namespace geolattice
