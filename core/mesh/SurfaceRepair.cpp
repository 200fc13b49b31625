#include "mesh/SurfaceRepair.h"

#include "common/GridHash.h"
#include "common/UnionFind.h"
#include "mesh/CgalSurfaceMesh.h"
#include "mesh/OverlappingBodies.h"
#include "mesh/ShellNesting.h"
#include "mesh/SurfaceCheck.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace geolattice {

bool cyclicParity(const std::array<int, 3>& t) {
  const int first = static_cast<int>(std::min_element(t.begin(), t.end()) - t.begin());
  return t[(first + 1) % 3] < t[(first + 2) % 3];
}

int weldOpenSeams(TriangleSurface& surface) {
  const SurfaceCheckReport before = checkSurface(surface);
  const double tolerance = 1e-6 * before.bboxDiagonal;
  if (before.boundaryEdges == 0 || !(tolerance > 0) || before.outOfRangeTriangles > 0) {
    return 0;
  }
  // The vertices of the open edges (the check lists them).
  std::vector<int> open;
  {
    std::vector<char> isOpen(surface.points.size(), 0);
    for (const SurfaceDefectEdge& e : before.defectEdges) {
      if (e.kind == SurfaceDefectEdge::Boundary) {
        isOpen[e.lo] = isOpen[e.hi] = 1;
      }
    }
    for (size_t v = 0; v < isOpen.size(); ++v) {
      if (isOpen[v]) {
        open.push_back(static_cast<int>(v));
      }
    }
  }
  // Weld those within the tolerance: a grid of cells as large as it, each vertex against the
  // cells its tolerance box overlaps.
  std::unordered_map<uint64_t, std::vector<int>> grid;
  for (const int v : open) {
    grid[gridCellKey(gridCell(surface.points[v], tolerance))].push_back(v);
  }
  UnionFind weld(static_cast<int>(surface.points.size()));
  int welded = 0;
  for (const int v : open) {
    const Vec3& p = surface.points[v];
    const Vec3 reach = Vec3::Constant(tolerance);
    forEachGridCell(p - reach, p + reach, tolerance, [&](uint64_t key) {
      const auto cell = grid.find(key);
      if (cell == grid.end()) {
        return;
      }
      for (const int w : cell->second) {
        if (w != v && (surface.points[w] - p).norm() <= tolerance && weld.find(w) != weld.find(v)) {
          weld.unite(w, v);
          ++welded;
        }
      }
    });
  }
  if (welded == 0) {
    return 0;
  }
  TriangleSurface welds;
  welds.points = surface.points;
  for (const auto& t : surface.triangles) {
    const std::array<int, 3> r{weld.find(t[0]), weld.find(t[1]), weld.find(t[2])};
    if (r[0] != r[1] && r[1] != r[2] && r[0] != r[2]) {  // else collapsed onto an edge of the seam
      welds.triangles.push_back(r);
    }
  }
  TriangleSurface out = withoutUnusedPoints(welds);
  const SurfaceCheckReport after = checkSurface(out);
  if (after.boundaryEdges >= before.boundaryEdges ||
      after.nonManifoldEdges > before.nonManifoldEdges) {
    return 0;
  }
  surface = std::move(out);
  return welded;
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

namespace {

/// One pass of removeDegenerateTriangles; false when it could not run (nothing degenerate, or
/// a surface CGAL cannot take).
bool mendDegenerateTriangles(TriangleSurface& surface) {
  const SurfaceCheckReport check = checkSurface(surface);
  if (check.degenerateTriangles == 0) {
    return false;
  }
  // SurfaceCheck's tolerance, relative to the same origin (the box centre).
  const double tolerance = 1e-12 * check.bboxDiagonal * check.bboxDiagonal;
  cgal::SurfaceMesh mesh;
  try {
    mesh = cgal::toSurfaceMesh(surface, "degenerate triangles");
  } catch (const GeoLatticeError&) {
    return false;  // not a 2-manifold or a repeated vertex: the caller's check names it
  }
  std::vector<cgal::SurfaceMesh::Face_index> degenerate;
  for (size_t t = 0; t < surface.triangles.size(); ++t) {
    const auto& tri = surface.triangles[t];
    const Vec3 a = surface.points[tri[0]], b = surface.points[tri[1]], c = surface.points[tri[2]];
    if (!(0.5 * (b - a).cross(c - a).norm() > tolerance)) {
      degenerate.push_back(cgal::SurfaceMesh::Face_index(static_cast<uint32_t>(t)));
    }
  }
  const double capCosine = std::cos(160.0 * M_PI / 180.0);  // CGAL's example thresholds
  const double needleRatio = 4.0;
  namespace PMP = CGAL::Polygon_mesh_processing;
  PMP::experimental::remove_almost_degenerate_faces(degenerate, mesh, capCosine, needleRatio,
                                                    0.0 /* any edge length */);
  // Left: tiny triangles of a good shape (marching cubes near a grid vertex: edges of 1e-5 mm),
  // neither needle nor cap; their shortest edge is collapsed to its midpoint where that keeps
  // the surface a 2-manifold (the link condition).
  for (cgal::SurfaceMesh::Face_index f : degenerate) {
    if (mesh.is_removed(f)) {
      continue;
    }
    auto h = mesh.halfedge(f);
    const auto length2 = [&mesh](cgal::SurfaceMesh::Halfedge_index e) {
      return CGAL::squared_distance(mesh.point(mesh.source(e)), mesh.point(mesh.target(e)));
    };
    const auto& p0 = mesh.point(mesh.source(h));
    const auto& p1 = mesh.point(mesh.target(h));
    const auto& p2 = mesh.point(mesh.target(mesh.next(h)));
    if (std::sqrt(CGAL::squared_area(p0, p1, p2)) > tolerance) {
      continue;  // CGAL's pass mended it
    }
    for (auto e : {mesh.next(mesh.halfedge(f)), mesh.prev(mesh.halfedge(f))}) {
      if (length2(e) < length2(h)) {
        h = e;
      }
    }
    const cgal::SurfaceMesh::Edge_index e = mesh.edge(h);
    if (CGAL::Euler::does_satisfy_link_condition(e, mesh)) {
      const auto mid = CGAL::midpoint(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)));
      mesh.point(CGAL::Euler::collapse_edge(e, mesh)) = mid;
    }
  }
  mesh.collect_garbage();
  surface = cgal::toTriangleSurface(mesh);
  return true;
}

}  // namespace

int removeDegenerateTriangles(TriangleSurface& surface) {
  // A collapse can line a neighbour up into a new sliver (a cap, flipped by the next pass).
  const int before = checkSurface(surface).degenerateTriangles;
  int left = before;
  for (int pass = 0; pass < 3 && left > 0 && mendDegenerateTriangles(surface); ++pass) {
    const int now = checkSurface(surface).degenerateTriangles;
    if (now >= left) {
      break;
    }
    left = now;
  }
  return before - left;
}

SurfaceRepairCounts repairSurface(TriangleSurface& surface) {
  SurfaceRepairCounts counts;
  SurfaceCheckReport check = checkSurface(surface);
  if (check.boundaryEdges > 0) {
    counts.weldedVertices = weldOpenSeams(surface);
    if (counts.weldedVertices > 0) {
      check = checkSurface(surface);
    }
  }
  if (check.nonManifoldEdges > 0 || check.inconsistentEdges > 0) {
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
    if (counts.any()) {
      check = checkSurface(surface);
    }
  }
  if (check.degenerateTriangles > 0) {  // holes and the rest are not repaired here
    counts.degenerateTriangles = removeDegenerateTriangles(surface);
    check = checkSurface(surface);
  }
  if (check.boundaryEdges == 0 && check.nonManifoldEdges == 0 && check.inconsistentEdges == 0 &&
      check.outOfRangeTriangles == 0 && check.nonFinitePoints == 0) {
    counts.invertedBodies = orientInvertedBodies(surface);
  }
  return counts;
}

int orientInvertedBodies(TriangleSurface& surface) {
  const ShellNesting nesting = nestShells(surface);
  const int shells = nesting.shells;
  if (shells < 2) {
    return 0;
  }
  const auto& inside = nesting.inside;
  const auto& volume6 = nesting.volume6;
  std::vector<int> invertedBodies;
  bool anOutwardBody = false;
  for (int s = 0; s < shells; ++s) {
    if (!inside[s].empty()) {
      continue;
    }
    if (volume6[s] < 0) {
      invertedBodies.push_back(s);
    } else {
      anOutwardBody = true;
    }
  }
  if (invertedBodies.empty() || !anOutwardBody) {
    return 0;
  }
  std::vector<char> turn(shells, 0);
  for (int body : invertedBodies) {
    turn[body] = 1;
  }
  for (int s = 0; s < shells; ++s) {
    for (int o : inside[s]) {
      turn[s] |= inside[o].empty() && volume6[o] < 0 ? 1 : 0;
    }
  }
  for (size_t f = 0; f < surface.triangles.size(); ++f) {
    if (turn[nesting.shellOf[f]]) {
      std::swap(surface.triangles[f][1], surface.triangles[f][2]);
    }
  }
  return static_cast<int>(invertedBodies.size());
}

std::vector<RepairNote> describeRepairs(const SurfaceRepairCounts& c) {
  // Each repair's sentence: the words before its count, after it for one and for many, the rest.
  struct Phrase {
    int count;
    const char *before, *one, *many, *rest, *reportKey;
  };
  const Phrase phrases[] = {
      {c.weldedVertices, "", " vertex", " vertices",
       " of the surface welded across seams as wide as rounding (open edges whose two sides "
       "differ in the last digits, as float32 STL corners do)",
       "welded_vertices"},
      {c.mergedBodies, "bodies of the surface touch or cross each other; meshed as their union (",
       " fewer body)", " fewer bodies)", "", "merged_bodies"},
      {c.duplicateTriangles, "", " triangle of the surface repeats",
       " triangles of the surface repeat",
       " another one (the same face twice); meshed without the copies", "duplicate_triangles"},
      {c.reorientedTriangles, "", " triangle of the surface ran against its neighbours",
       " triangles of the surface ran against their neighbours", "; turned to agree with them",
       "reoriented_triangles"},
      {c.invertedBodies, "", " body of the surface was", " bodies of the surface were",
       " written inside out (its triangles facing inward) beside bodies facing outward; turned "
       "outward",
       "inverted_bodies"},
      {c.degenerateTriangles, "", " degenerate triangle", " degenerate triangles",
       " of the surface (area ~0, e.g. marching-cubes slivers) mended by collapsing or flipping "
       "an edge",
       "degenerate_triangles"},
  };
  std::vector<RepairNote> notes;
  for (const Phrase& p : phrases) {
    if (p.count > 0) {
      notes.push_back(
          {p.before + std::to_string(p.count) + (p.count == 1 ? p.one : p.many) + p.rest,
           p.reportKey});
    }
  }
  return notes;
}

}  // namespace geolattice
