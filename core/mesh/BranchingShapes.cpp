// CGAL translation unit (slow to compile): keep CGAL code of core/mesh here only.
#include "mesh/BranchingShapes.h"

#include "common/Error.h"
#include "mesh/CgalSurfaceMesh.h"
#include "mesh/SurfaceCheck.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace geolattice {

namespace {

using Kernel = cgal::Kernel;
using Mesh = cgal::SurfaceMesh;
namespace PMP = CGAL::Polygon_mesh_processing;

constexpr double kPi = 3.14159265358979323846;

/// Closed capsule-like mesh along the unit axis `axis` from `base` to `base + length * axis`,
/// radius `radius`: a flat disk at the base (fan around its centre) and a hemisphere at the
/// end. Rings of `segments` vertices at angles 2*pi*i/segments around the axis measured from
/// `u` (unit, perpendicular to axis) towards axis x u; the axial and latitude ring spacing
/// follow the circumferential edge length. Triangles are counter-clockwise seen from outside.
Mesh capsule(const Vec3& base, const Vec3& axis, const Vec3& u, double length, double radius,
             int segments) {
  const Vec3 v = axis.cross(u);
  const double edge = 2.0 * kPi * radius / segments;
  const int axialSteps = std::max(1, static_cast<int>(std::ceil(length / edge - 1e-9)));
  const int latitudeSteps =
      std::max(2, static_cast<int>(std::ceil(0.5 * kPi * radius / edge - 1e-9)));
  const Vec3 tip = base + length * axis;

  Mesh mesh;
  auto add = [&](const Vec3& p) {
    return mesh.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
  };
  std::vector<std::vector<Mesh::Vertex_index>> rings;
  auto addRing = [&](const Vec3& centre, double ringRadius) {
    std::vector<Mesh::Vertex_index> ring(segments);
    for (int i = 0; i < segments; ++i) {
      const double t = 2.0 * kPi * i / segments;
      ring[i] = add(centre + ringRadius * (std::cos(t) * u + std::sin(t) * v));
    }
    rings.push_back(std::move(ring));
  };
  for (int j = 0; j <= axialSteps; ++j) {
    addRing(base + (length * j / axialSteps) * axis, radius);
  }
  for (int k = 1; k < latitudeSteps; ++k) {
    const double phi = 0.5 * kPi * k / latitudeSteps;  // latitude above the end ring
    addRing(tip + radius * std::sin(phi) * axis, radius * std::cos(phi));
  }
  const Mesh::Vertex_index bottom = add(base);
  const Mesh::Vertex_index pole = add(tip + radius * axis);

  // (ring j, i), (ring j, i+1), (ring j+1, i+1): edge along +angle then along +axis gives
  // (axis x u) x axis = u, the outward radial direction.
  for (size_t j = 0; j + 1 < rings.size(); ++j) {
    for (int i = 0; i < segments; ++i) {
      const int n = (i + 1) % segments;
      mesh.add_face(rings[j][i], rings[j][n], rings[j + 1][n]);
      mesh.add_face(rings[j][i], rings[j + 1][n], rings[j + 1][i]);
    }
  }
  for (int i = 0; i < segments; ++i) {
    const int n = (i + 1) % segments;
    mesh.add_face(bottom, rings.front()[n], rings.front()[i]);  // normal -axis
    mesh.add_face(rings.back()[i], rings.back()[n], pole);
  }
  return mesh;
}

std::string fmt(double value) {
  return std::to_string(value);
}

void requireRange(double value, double lo, double hi, const char* name, const char* unit) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw GeoLatticeError(std::string("branching shape: ") + name + " must be in [" + fmt(lo) +
                          ", " + fmt(hi) + "] " + unit + ", got " + fmt(value));
  }
}

void validate(const BranchingShapeParameters& p) {
  if (!std::isfinite(p.trunkRadius) || !(p.trunkRadius > 0.0) || p.trunkRadius > 1e5) {
    throw GeoLatticeError(
        "branching shape: trunkRadius must be positive and finite (<= 1e5 mm), got " +
        fmt(p.trunkRadius) + " mm");
  }
  requireRange(p.trunkHeight, p.trunkRadius * (1.0 + 1e-6), 1e6, "trunkHeight (> trunkRadius)",
               "mm");
  if (!std::isfinite(p.branchRadius) || !(p.branchRadius > 0.0) ||
      p.branchRadius > 0.9 * p.trunkRadius) {
    throw GeoLatticeError("branching shape: branchRadius must be in (0, 0.9 * trunkRadius = " +
                          fmt(0.9 * p.trunkRadius) +
                          "] mm so that a branch starts inside the joint sphere, got " +
                          fmt(p.branchRadius) + " mm");
  }
  requireRange(p.branchLength, p.trunkRadius, 1e6, "branchLength (>= trunkRadius)", "mm");
  requireRange(p.branchLeanDeg, 10.0, 80.0, "branchLeanDeg", "degrees");
  if (!std::isfinite(p.firstAzimuthDeg)) {
    throw GeoLatticeError("branching shape: firstAzimuthDeg must be finite, got " +
                          fmt(p.firstAzimuthDeg));
  }
  if (p.segments < 8 || p.segments > 256) {
    throw GeoLatticeError("branching shape: segments must be in [8, 256], got " +
                          std::to_string(p.segments));
  }
  requireRange(p.surfaceEdgeLength, p.branchRadius / 50.0, p.branchRadius, "surfaceEdgeLength",
               "mm");
}

/// The corefinement cuts faces along the intersection curves and leaves needles and caps
/// there (some below SurfaceCheck's degeneracy bound, and rounded intersection points on
/// needles make the next union fold faces). Isotropic remeshing replaces them; creases (the
/// branch/trunk junctions, the bottom rim) are constrained polylines, so the shape keeps its
/// sharp features. Vertices are projected back onto the input, so the bottom stays in the
/// plane z = 0 up to rounding (snapped by the caller).
void remesh(Mesh& mesh, double edgeLength) {
  auto sharp = mesh.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
  PMP::detect_sharp_edges(mesh, 30.0, sharp);
  // relax_constraints stays false: relaxing the bottom rim along its polyline chamfered it.
  PMP::isotropic_remeshing(
      faces(mesh), edgeLength, mesh,
      PMP::parameters::number_of_iterations(5).edge_is_constrained_map(sharp).relax_constraints(
          false));
  mesh.remove_property_map(sharp);
  mesh.collect_garbage();
}

/// Trunk capsule (flat bottom disk at z = 0, joint sphere on top) united with `branchCount`
/// branch capsules spread evenly in azimuth.
TriangleSurface branchingSurface(const BranchingShapeParameters& p, int branchCount,
                                 const char* name) {
  validate(p);
  const Vec3 ez(0, 0, 1);
  Mesh result = capsule(Vec3(0, 0, 0), ez, Vec3(1, 0, 0), p.trunkHeight, p.trunkRadius, p.segments);
  const Vec3 joint(0, 0, p.trunkHeight);
  const double lean = p.branchLeanDeg * kPi / 180.0;
  for (int k = 0; k < branchCount; ++k) {
    const double azimuth = (p.firstAzimuthDeg + 360.0 * k / branchCount) * kPi / 180.0;
    const Vec3 axis(std::sin(lean) * std::cos(azimuth), std::sin(lean) * std::sin(azimuth),
                    std::cos(lean));
    const Vec3 u(-std::sin(azimuth), std::cos(azimuth), 0.0);  // horizontal, perpendicular to axis
    // The branch starts a little behind the joint centre (its start disk stays inside the joint
    // sphere: sqrt(0.25^2 + 0.9^2) < 0.94), so that the start disks of different branches do
    // not share the centre point: coincident vertices are degenerate input for the union.
    const double back = 0.25 * p.trunkRadius;
    Mesh branch =
        capsule(joint - back * axis, axis, u, p.branchLength + back, p.branchRadius, p.segments);
    bool ok = false;
    try {
      ok = PMP::corefine_and_compute_union(result, branch, result);
    } catch (const std::exception& e) {
      throw GeoLatticeError(std::string(name) + ": CGAL union with branch " + std::to_string(k) +
                            " failed: " + e.what());
    }
    if (!ok) {
      throw GeoLatticeError(std::string(name) + ": CGAL union with branch " + std::to_string(k) +
                            " did not produce a closed manifold result");
    }
    // The union's intersection points are rounded to doubles; a fold would make the next union
    // (whose inputs must not self-intersect) and TetGen fail.
    if (PMP::does_self_intersect(result)) {
      throw GeoLatticeError(std::string(name) + ": the union with branch " + std::to_string(k) +
                            " has self-intersections after rounding");
    }
    // Clean input for the next union, and the final triangle quality.
    remesh(result, p.surfaceEdgeLength);
  }
  result.collect_garbage();
  if (!CGAL::is_closed(result) || !CGAL::is_triangle_mesh(result)) {
    throw GeoLatticeError(std::string(name) + ": the union is not a closed triangle mesh");
  }
  const double snap = 1e-9 * p.trunkHeight;
  for (Mesh::Vertex_index vi : result.vertices()) {
    const Kernel::Point_3 q = result.point(vi);
    if (q.z() < snap) {
      if (q.z() < -snap) {
        throw GeoLatticeError(std::string(name) +
                              ": a vertex lies below the platform (z = " + fmt(q.z()) + ")");
      }
      result.point(vi) = Kernel::Point_3(q.x(), q.y(), 0.0);
    }
  }
  if (PMP::does_self_intersect(result)) {
    throw GeoLatticeError(std::string(name) + ": the remeshed surface has self-intersections");
  }

  const TriangleSurface surface = cgal::toTriangleSurface(result);
  const SurfaceCheckReport report = checkSurface(surface);
  if (!report.isClosedManifold()) {
    throw GeoLatticeError(std::string(name) +
                          ": the generated surface is not a valid closed manifold (" +
                          std::to_string(report.degenerateTriangles) + " degenerate triangles, " +
                          std::to_string(report.boundaryEdges) + " boundary edges, " +
                          std::to_string(report.nonManifoldEdges) + " non-manifold edges)");
  }
  return surface;
}

}  // namespace

BranchingShapeParameters yShapeDefaults() {
  return BranchingShapeParameters{};
}

BranchingShapeParameters threeBranchTreeDefaults() {
  BranchingShapeParameters p;
  p.trunkRadius = 7.0;
  p.trunkHeight = 30.0;
  p.branchRadius = 5.0;
  p.branchLength = 30.0;
  p.branchLeanDeg = 50.0;
  p.firstAzimuthDeg = 90.0;
  return p;
}

TriangleSurface yShapeSurface(const BranchingShapeParameters& parameters) {
  return branchingSurface(parameters, 2, "yShapeSurface");
}

TriangleSurface threeBranchTreeSurface(const BranchingShapeParameters& parameters) {
  return branchingSurface(parameters, 3, "threeBranchTreeSurface");
}

}  // namespace geolattice
