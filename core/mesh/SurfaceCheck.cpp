#include "mesh/SurfaceCheck.h"

#include "common/Error.h"
#include "mesh/SurfaceWrap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace geolattice {

namespace {

struct EdgeUse {
  int lo, hi;    // sorted vertex ids
  bool forward;  // traversed lo -> hi by its triangle
  bool operator<(const EdgeUse& o) const { return lo != o.lo ? lo < o.lo : hi < o.hi; }
};

std::string firstIndex(const char* what, int index) {
  return " (first: " + std::string(what) + " " + std::to_string(index) + ")";
}

}  // namespace

bool SurfaceCheckReport::isClosedManifold() const {
  return triangleCount > 0 && pointCount > 0 && outOfRangeTriangles == 0 && nonFinitePoints == 0 &&
         boundaryEdges == 0 && nonManifoldEdges == 0 && inconsistentEdges == 0 &&
         degenerateTriangles == 0;
}

SurfaceCheckReport checkSurface(const TriangleSurface& surface) {
  SurfaceCheckReport r;
  r.pointCount = static_cast<int>(surface.points.size());
  r.triangleCount = static_cast<int>(surface.triangles.size());

  const FinitePointScan scan = scanPoints(surface.points);
  r.nonFinitePoints = scan.nonFinite;
  r.firstNonFinitePoint = scan.firstNonFinite;
  r.bboxDiagonal = scan.diagonal();
  const Eigen::AlignedBox3d& box = scan.box;
  const double areaTolerance = 1e-12 * r.bboxDiagonal * r.bboxDiagonal;
  // Volume relative to the box centre keeps the sum well conditioned far from the origin.
  const Vec3 origin = box.isEmpty() ? Vec3(Vec3::Zero()) : Vec3(box.center());

  std::vector<char> used(surface.points.size(), 0);
  std::vector<EdgeUse> edges;
  edges.reserve(3 * surface.triangles.size());
  double volume6 = 0.0;
  for (int t = 0; t < r.triangleCount; ++t) {
    const auto& tri = surface.triangles[t];
    bool inRange = true;
    for (int v : tri) {
      inRange = inRange && v >= 0 && v < r.pointCount;
    }
    if (!inRange) {
      if (r.outOfRangeTriangles++ == 0) {
        r.firstOutOfRangeTriangle = t;
      }
      continue;
    }
    for (int v : tri) {
      used[v] = 1;
    }
    const Vec3 a = surface.points[tri[0]] - origin, b = surface.points[tri[1]] - origin,
               c = surface.points[tri[2]] - origin;
    const bool repeated = tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    if (repeated || !(area > areaTolerance)) {
      if (r.degenerateTriangles++ == 0) {
        r.firstDegenerateTriangle = t;
      }
    }
    if (a.allFinite() && b.allFinite() && c.allFinite()) {
      volume6 += a.dot(b.cross(c));
    }
    for (int k = 0; k < 3; ++k) {
      const int u = tri[k], w = tri[(k + 1) % 3];
      if (u != w) {  // a repeated vertex has no real edge there; it is counted as degenerate
        edges.push_back({std::min(u, w), std::max(u, w), u < w});
      }
    }
  }
  r.signedVolume = volume6 / 6.0;
  r.unusedPoints = static_cast<int>(std::count(used.begin(), used.end(), 0));

  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size();) {
    size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) {
      ++j;
    }
    const size_t uses = j - i;
    if (uses == 1) {
      if (r.boundaryEdges++ == 0) {
        r.firstBoundaryEdge = {edges[i].lo, edges[i].hi};
      }
      r.defectEdges.push_back({edges[i].lo, edges[i].hi, SurfaceDefectEdge::Boundary});
    } else if (uses > 2) {
      if (r.nonManifoldEdges++ == 0) {
        r.firstNonManifoldEdge = {edges[i].lo, edges[i].hi};
      }
      r.defectEdges.push_back({edges[i].lo, edges[i].hi, SurfaceDefectEdge::NonManifold});
    } else if (edges[i].forward == edges[i + 1].forward) {
      ++r.inconsistentEdges;
      r.defectEdges.push_back({edges[i].lo, edges[i].hi, SurfaceDefectEdge::Inconsistent});
    }
    i = j;
  }
  return r;
}

SurfaceCheckReport requireClosedManifold(const TriangleSurface& surface) {
  const SurfaceCheckReport r = checkSurface(surface);
  if (r.triangleCount == 0 || r.pointCount == 0) {
    throw GeoLatticeError("empty surface: " + std::to_string(r.pointCount) + " points, " +
                          std::to_string(r.triangleCount) + " triangles");
  }
  if (r.outOfRangeTriangles > 0) {
    throw GeoLatticeError("invalid surface: " + std::to_string(r.outOfRangeTriangles) +
                          " triangles reference a vertex index outside 0.." +
                          std::to_string(r.pointCount - 1) +
                          firstIndex("triangle", r.firstOutOfRangeTriangle));
  }
  if (r.nonFinitePoints > 0) {
    throw GeoLatticeError("invalid surface: " + std::to_string(r.nonFinitePoints) +
                          " points have NaN or infinite coordinates" +
                          firstIndex("point", r.firstNonFinitePoint));
  }
  // Where the first bad edge is (its midpoint, in the input's units) and how to fix it.
  auto at = [&](const std::array<int, 2>& e) {
    const Vec3 m = 0.5 * (surface.points[e[0]] + surface.points[e[1]]);
    char text[160];
    std::snprintf(text, sizeof text,
                  "; the first is between points %d and %d, at (%.4g, %.4g, %.4g)", e[0], e[1],
                  m.x(), m.y(), m.z());
    return std::string(text);
  };
  if (r.boundaryEdges > 0) {
    throw GeoLatticeError("open surface: " + std::to_string(r.boundaryEdges) +
                          " boundary edges (the surface must be closed / watertight)" +
                          at(r.firstBoundaryEdge) +
                          ". Close the holes: GL Place On Platform's Fill Holes (geolattice run "
                          "--fill-holes), or repair the part in its CAD tool and export it again");
  }
  if (r.nonManifoldEdges > 0) {
    throw GeoLatticeError("non-manifold surface: " + std::to_string(r.nonManifoldEdges) +
                          " edges shared by more than two triangles" + at(r.firstNonManifoldEdge) +
                          ". Separate the touching bodies or merge them into one solid in the "
                          "CAD tool (a Boolean union)" +
                          kWrapHint);
  }
  if (r.inconsistentEdges > 0) {
    throw GeoLatticeError(
        "inconsistently oriented triangles: " + std::to_string(r.inconsistentEdges) +
        " edges are traversed in the same direction by both of their triangles "
        "(the surface is not consistently oriented, or not orientable)");
  }
  if (r.degenerateTriangles > 0) {
    throw GeoLatticeError("degenerate surface: " + std::to_string(r.degenerateTriangles) +
                          " zero-area triangles" +
                          firstIndex("triangle", r.firstDegenerateTriangle));
  }
  const double volumeTolerance = 1e-12 * std::pow(r.bboxDiagonal, 3);
  if (!(std::abs(r.signedVolume) > volumeTolerance)) {
    throw GeoLatticeError("surface encloses no volume (signed volume " +
                          std::to_string(r.signedVolume) + " mm^3)");
  }
  return r;
}

int orientOutward(TriangleSurface& surface) {
  const SurfaceCheckReport r = checkSurface(surface);
  if (!(r.signedVolume < 0.0)) {
    return 0;
  }
  for (auto& tri : surface.triangles) {
    std::swap(tri[1], tri[2]);
  }
  return static_cast<int>(surface.triangles.size());
}

double windingNumber(const TriangleSurface& surface, const Vec3& q,
                     const std::vector<int>* triangles) {
  double total = 0.0;
  auto add = [&](const std::array<int, 3>& t) {
    const Vec3 a = surface.points[t[0]] - q, b = surface.points[t[1]] - q,
               c = surface.points[t[2]] - q;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2.0 * std::atan2(numerator, denominator);
  };
  if (triangles) {
    for (int f : *triangles) {
      add(surface.triangles[f]);
    }
  } else {
    for (const auto& t : surface.triangles) {
      add(t);
    }
  }
  return total / (4.0 * M_PI);
}

TriangleSurface withoutUnusedPoints(const TriangleSurface& surface) {
  TriangleSurface out;
  std::vector<int> newId(surface.points.size(), -1);
  out.triangles.reserve(surface.triangles.size());
  for (const auto& t : surface.triangles) {
    std::array<int, 3> tri;
    for (int k = 0; k < 3; ++k) {
      int& id = newId[t[k]];
      if (id < 0) {
        id = static_cast<int>(out.points.size());
        out.points.push_back(surface.points[t[k]]);
      }
      tri[k] = id;
    }
    out.triangles.push_back(tri);
  }
  return out;
}

}  // namespace geolattice
