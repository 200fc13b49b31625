#include "pedestal/Pedestal.h"

#include "common/Error.h"
#include "mesh/SurfaceRepair.h"
#include "mesh/SurfaceCheck.h"
#include "placement/PlaceOnPlatform.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <utility>

namespace geolattice {

void PedestalOptions::validate() const {
  if (!(height >= 0.0 && height <= 500.0)) {
    std::ostringstream s;
    s << "pedestal: the height must be in [0, 500] mm (got " << height << ")";
    throw GeoLatticeError(s.str());
  }
  if (!(contactHeight > 0.0) || !std::isfinite(contactHeight)) {
    std::ostringstream s;
    s << "pedestal: the contact height must be > 0 mm (got " << contactHeight << ")";
    throw GeoLatticeError(s.str());
  }
}

namespace {

/// Removes from `faces` those with a corner at a flagged vertex.
void removeFacesAt(const TriangleSurface& part, const std::vector<char>& flagged,
                   std::vector<int>& faces) {
  faces.erase(std::remove_if(faces.begin(), faces.end(),
                             [&](int f) {
                               const auto& t = part.triangles[f];
                               return flagged[t[0]] || flagged[t[1]] || flagged[t[2]];
                             }),
              faces.end());
}

/// The contact faces without pinch vertices: a vertex the region's boundary passes more than
/// once (two faces touching at a corner only, a deeper band reaching round a bump) would get one
/// column shared by four walls, a non-manifold edge. The faces at such a vertex leave the
/// footprint, until none is left (each round removes faces, so it ends).
std::vector<int> withoutPinches(const TriangleSurface& part, std::vector<int> faces) {
  for (;;) {
    std::map<std::pair<int, int>, int> directed;
    for (int f : faces) {
      const auto& t = part.triangles[f];
      for (int k = 0; k < 3; ++k) {
        directed[{t[k], t[(k + 1) % 3]}] = f;
      }
    }
    std::map<int, int> outgoing;  // boundary edges leaving each vertex
    for (const auto& [edge, face] : directed) {
      if (!directed.count({edge.second, edge.first})) {
        ++outgoing[edge.first];
      }
    }
    std::vector<char> pinch(part.points.size(), 0);
    bool any = false;
    for (const auto& [v, n] : outgoing) {
      if (n > 1) {
        pinch[v] = 1;
        any = true;
      }
    }
    if (!any) {
      return faces;
    }
    removeFacesAt(part, pinch, faces);
  }
}

/// The footprint's outline without spikes: where the contact faces at a boundary vertex span
/// less than kMinFootprintAngleDeg (seen from above), the column would get a vertical knife edge
/// as tall as the pedestal, and TetGen's quality refinement does not end near one (a dumbbell
/// standing on a ball, 1 mm reach: an 18° corner, no run finished within the time limit; 42° and
/// up mesh in seconds). The faces at such a vertex leave the footprint, round by round, pinches
/// removed each time; the footprint comes back as it was when nothing would be left.
std::vector<int> withoutSpikes(const TriangleSurface& part, const Eigen::Matrix3d& R,
                               const std::vector<int>& contact) {
  std::vector<int> faces = contact;
  for (;;) {
    faces = withoutPinches(part, std::move(faces));
    std::map<std::pair<int, int>, int> directed;
    std::map<int, double> span;  // per vertex: the contact faces' corner angles there, summed
    for (int f : faces) {
      const auto& t = part.triangles[f];
      for (int k = 0; k < 3; ++k) {
        directed[{t[k], t[(k + 1) % 3]}] = f;
        const Eigen::Vector2d u =
            (R.topRows<2>() * (part.points[t[(k + 1) % 3]] - part.points[t[k]]));
        const Eigen::Vector2d v =
            (R.topRows<2>() * (part.points[t[(k + 2) % 3]] - part.points[t[k]]));
        span[t[k]] += std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v));
      }
    }
    std::vector<char> spike(part.points.size(), 0);
    bool any = false;
    for (const auto& [edge, face] : directed) {
      if (!directed.count({edge.second, edge.first}) &&
          span[edge.first] < kMinFootprintAngleDeg * M_PI / 180.0) {
        spike[edge.first] = 1;
        any = true;
      }
    }
    if (!any) {
      return faces;
    }
    removeFacesAt(part, spike, faces);
    if (faces.empty()) {
      return withoutPinches(part, contact);
    }
  }
}

double facesArea(const TriangleSurface& part, const std::vector<int>& faces) {
  double area = 0;
  for (int f : faces) {
    const auto& t = part.triangles[f];
    area +=
        0.5 *
        (part.points[t[1]] - part.points[t[0]]).cross(part.points[t[2]] - part.points[t[0]]).norm();
  }
  return area;
}

}  // namespace

std::vector<int> pedestalFootprintFaces(const TriangleSurface& part, const Eigen::Matrix3d& R,
                                        double contactHeight) {
  return withoutSpikes(part, R, baseContactFaces(part, R, contactHeight));
}

double pedestalFootprintArea(const TriangleSurface& part, const Eigen::Matrix3d& R,
                             double contactHeight) {
  return facesArea(part, pedestalFootprintFaces(part, R, contactHeight));
}

PedestalResult addPedestal(const TriangleSurface& input, const PedestalOptions& o) {
  o.validate();
  PedestalResult result;
  // Bodies that touch along a face (welded by the reader) stand on it as one solid.
  TriangleSurface part = input;
  repairSurface(part);
  const std::vector<int> contact =
      pedestalFootprintFaces(part, Eigen::Matrix3d::Identity(), o.contactHeight);
  result.footprintArea = facesArea(part, contact);
  if (o.height == 0.0) {
    result.surface = part;
    return result;
  }
  if (contact.empty()) {
    throw GeoLatticeError(
        "pedestal: no face of the part touches the plate (it stands on a tip or an edge), so "
        "there is no footprint to raise it on; orient it on a flat side (--orient auto) or use "
        "no pedestal");
  }
  double zmin = std::numeric_limits<double>::infinity();
  for (const Vec3& p : part.points) {
    zmin = std::min(zmin, p.z());
  }
  const double bottom = zmin - o.height;

  std::vector<char> inContact(part.triangles.size(), 0);
  for (int f : contact) {
    inContact[f] = 1;
  }
  // Directed edges of the contact faces; a boundary edge is one whose reverse is not among them.
  std::map<std::pair<int, int>, int> directed;
  for (int f : contact) {
    const auto& t = part.triangles[f];
    for (int k = 0; k < 3; ++k) {
      directed[{t[k], t[(k + 1) % 3]}] = f;
    }
  }
  std::vector<std::pair<int, int>> boundary;
  double boundaryLength = 0;
  for (const auto& [edge, face] : directed) {
    if (!directed.count({edge.second, edge.first})) {
      boundary.push_back(edge);
      boundaryLength += (part.points[edge.first] - part.points[edge.second]).norm();
    }
  }

  TriangleSurface& out = result.surface;
  out.points = part.points;
  // The moved copy of every contact vertex, on the bottom plane.
  std::map<int, int> bottomOf;
  auto bottomCopy = [&](int v) {
    const auto it = bottomOf.find(v);
    if (it != bottomOf.end()) {
      return it->second;
    }
    const int id = static_cast<int>(out.points.size());
    out.points.push_back(Vec3(part.points[v].x(), part.points[v].y(), bottom));
    bottomOf[v] = id;
    return id;
  };
  for (size_t f = 0; f < part.triangles.size(); ++f) {
    const auto& t = part.triangles[f];
    out.triangles.push_back(
        inContact[f] ? std::array<int, 3>{bottomCopy(t[0]), bottomCopy(t[1]), bottomCopy(t[2])}
                     : t);
  }
  // Walls: rings about as tall as the boundary edges are long.
  const double edge = boundaryLength / static_cast<double>(boundary.size());
  const int rings = std::max(1, static_cast<int>(std::lround(o.height / std::max(edge, 1e-3))));
  result.wallRings = rings;
  std::map<int, std::vector<int>> column;  // per boundary vertex: its ring vertices, top to bottom
  auto columnOf = [&](int v) -> const std::vector<int>& {
    auto it = column.find(v);
    if (it != column.end()) {
      return it->second;
    }
    std::vector<int> c{v};
    const Vec3& top = part.points[v];
    for (int r = 1; r < rings; ++r) {
      const double s = static_cast<double>(r) / rings;
      c.push_back(static_cast<int>(out.points.size()));
      out.points.push_back(Vec3(top.x(), top.y(), (1 - s) * top.z() + s * bottom));
    }
    c.push_back(bottomCopy(v));
    return column.emplace(v, std::move(c)).first->second;
  };
  for (const auto& [a, b] : boundary) {
    // The contact face runs a -> b; the part's face beside it b -> a; the wall runs a -> b on
    // top and b' -> a' at the bottom, where the moved contact face runs a' -> b'.
    const std::vector<int> ca = columnOf(a);
    const std::vector<int>& cb = columnOf(b);
    for (int r = 0; r < rings; ++r) {
      out.triangles.push_back({ca[r], cb[r], cb[r + 1]});
      out.triangles.push_back({ca[r], cb[r + 1], ca[r + 1]});
    }
  }
  // Loops of the footprint's boundary (each column's outline and any holes in it).
  std::map<int, int> next;
  for (const auto& [a, b] : boundary) {
    next[a] = b;
  }
  std::map<int, char> seen;
  for (const auto& [a, b] : boundary) {
    if (seen[a]) {
      continue;
    }
    ++result.footprintPieces;
    for (int v = a; !seen[v] && next.count(v); v = next[v]) {
      seen[v] = 1;
    }
  }

  // Drop the part's contact vertices no face uses any more, then stand it on z = 0.
  std::vector<int> newId(out.points.size(), -1);
  for (const auto& t : out.triangles) {
    for (int v : t) {
      newId[v] = 0;
    }
  }
  TriangleSurface compact;
  for (size_t v = 0; v < out.points.size(); ++v) {
    if (newId[v] == 0) {
      newId[v] = static_cast<int>(compact.points.size());
      compact.points.push_back(out.points[v] - Vec3(0, 0, bottom));
    }
  }
  for (const auto& t : out.triangles) {
    compact.triangles.push_back({newId[t[0]], newId[t[1]], newId[t[2]]});
  }
  out = std::move(compact);
  SurfaceCheckReport check = checkSurface(out);
  if (check.degenerateTriangles > 0) {
    // A triangle's "zero area" is relative to the bounding box, which the column makes larger:
    // slivers of the part (a marching-cubes spring: 4.6e-9 mm²) fall under it on the pedestal.
    removeDegenerateTriangles(out);
    check = checkSurface(out);
  }
  if (!check.isClosedManifold() || !(check.signedVolume > 0)) {
    std::ostringstream s;
    s << "pedestal: the part on its pedestal is not a closed, outward surface ("
      << check.boundaryEdges << " open edges, " << check.nonManifoldEdges << " non-manifold edges, "
      << check.degenerateTriangles << " degenerate triangles, volume " << check.signedVolume
      << " mm^3); the part's contact region with the plate is not a simple footprint";
    throw GeoLatticeError(s.str());
  }
  return result;
}

}  // namespace geolattice
