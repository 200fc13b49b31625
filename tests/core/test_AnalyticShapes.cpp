#include "common/Error.h"
#include "mesh/AnalyticShapes.h"
#include "mesh/TetMeshTopology.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <utility>

using namespace geolattice;

namespace {

// Independent closedness check: every undirected edge is used by exactly two triangles, once
// in each direction (consistent orientation). Returns the number of violating edges.
int badEdgeCount(const TriangleSurface& s) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : s.triangles) {
    for (int k = 0; k < 3; ++k) {
      ++directed[{t[k], t[(k + 1) % 3]}];
    }
  }
  int bad = 0;
  for (const auto& [edge, count] : directed) {
    auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) {
      ++bad;
    }
  }
  return bad;
}

double enclosedVolume(const TriangleSurface& s) {
  double v = 0;
  for (const auto& t : s.triangles) {
    v += s.points[t[0]].dot(s.points[t[1]].cross(s.points[t[2]])) / 6.0;
  }
  return v;
}

double maxEdgeLength(const TriangleSurface& s) {
  double m = 0;
  for (const auto& t : s.triangles) {
    for (int k = 0; k < 3; ++k) {
      m = std::max(m, (s.points[t[k]] - s.points[t[(k + 1) % 3]]).norm());
    }
  }
  return m;
}

int duplicatePointCount(const TriangleSurface& s) {
  std::set<std::array<double, 3>> seen;
  int dup = 0;
  for (const Vec3& p : s.points) {
    if (!seen.insert({p.x(), p.y(), p.z()}).second) {
      ++dup;
    }
  }
  return dup;
}

}  // namespace

TEST(AnalyticShapes, BoxSurfaceIsClosedOutwardAndFine) {
  const Vec3 size(40, 40, 60);
  for (double maxEdge : {100.0, 7.0, 1.5}) {
    const TriangleSurface s = boxSurface(size, maxEdge);
    ASSERT_FALSE(s.triangles.empty());
    EXPECT_EQ(badEdgeCount(s), 0) << "maxEdge " << maxEdge;
    EXPECT_EQ(duplicatePointCount(s), 0) << "maxEdge " << maxEdge;
    EXPECT_NEAR(enclosedVolume(s), 96000.0, 1e-9 * 96000.0) << "maxEdge " << maxEdge;
    EXPECT_LE(maxEdgeLength(s), maxEdge * (1 + 1e-12)) << "maxEdge " << maxEdge;
    // Euler characteristic of a sphere: V - E + F = 2 with E = 3F/2.
    EXPECT_EQ(static_cast<long>(s.points.size()) - static_cast<long>(s.triangles.size()) / 2, 2);
    for (const Vec3& p : s.points) {  // all vertices on the box boundary
      const bool onFace = p.x() == 0 || p.y() == 0 || p.z() == 0 || p.x() == size.x() ||
                          p.y() == size.y() || p.z() == size.z();
      EXPECT_TRUE(onFace);
    }
  }
  // The coarsest box: one cell per face -> 8 corners, 12 triangles.
  const TriangleSurface coarse = boxSurface(Vec3(1, 2, 3), 10.0);
  EXPECT_EQ(coarse.points.size(), 8u);
  EXPECT_EQ(coarse.triangles.size(), 12u);
}

TEST(AnalyticShapes, BoxSurfaceRejectsBadArguments) {
  EXPECT_THROW(boxSurface(Vec3(1, 0, 1), 0.1), GeoLatticeError);
  EXPECT_THROW(boxSurface(Vec3(1, -1, 1), 0.1), GeoLatticeError);
  EXPECT_THROW(boxSurface(Vec3(1, 1, 1), 0.0), GeoLatticeError);
  EXPECT_THROW(boxSurface(Vec3(1, 1, 1), -2.0), GeoLatticeError);
  EXPECT_THROW(boxSurface(Vec3(1, 1, NAN), 0.5), GeoLatticeError);
  EXPECT_THROW(boxSurface(Vec3(1e9, 1, 1), 1e-3), GeoLatticeError);
}

TEST(AnalyticShapes, SphereSurfaceIsClosedAndConvergesToTheBall) {
  const Vec3 centre(5, -3, 2);
  const double r = 10.0;
  for (int level = 0; level <= 4; ++level) {
    const TriangleSurface s = sphereSurface(centre, r, level);
    EXPECT_EQ(s.triangles.size(), 20u << (2 * level));
    EXPECT_EQ(s.points.size(), 10u * (1u << (2 * level)) + 2u);
    EXPECT_EQ(badEdgeCount(s), 0) << "level " << level;
    EXPECT_EQ(duplicatePointCount(s), 0);
    for (const Vec3& p : s.points) {
      EXPECT_NEAR((p - centre).norm(), r, 1e-9);
    }
    EXPECT_GT(enclosedVolume(s), 0) << "level " << level;  // outward orientation
  }
  const double exact = 4.0 / 3.0 * M_PI * r * r * r;
  const double v4 = enclosedVolume(sphereSurface(centre, r, 4));
  EXPECT_LT(v4, exact);  // inscribed polyhedron
  EXPECT_NEAR(v4, exact, 0.01 * exact);
}

TEST(AnalyticShapes, SphereSurfaceRejectsBadArguments) {
  EXPECT_THROW(sphereSurface(Vec3::Zero(), 0.0, 2), GeoLatticeError);
  EXPECT_THROW(sphereSurface(Vec3::Zero(), 1.0, -1), GeoLatticeError);
  EXPECT_THROW(sphereSurface(Vec3::Zero(), 1.0, 11), GeoLatticeError);
}

TEST(AnalyticShapes, BoxTetMeshIsPositiveConformingAndExact) {
  const Vec3 size(4, 3, 6);
  const int nx = 4, ny = 3, nz = 5;
  const TetMesh m = boxTetMesh(size, nx, ny, nz);
  ASSERT_EQ(m.points.size(), static_cast<size_t>((nx + 1) * (ny + 1) * (nz + 1)));
  ASSERT_EQ(m.tets.size(), static_cast<size_t>(6 * nx * ny * nz));
  double total = 0;
  const double cellVolume = size.prod() / (nx * ny * nz);
  for (const auto& t : m.tets) {
    const double v =
        signedTetVolume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]);
    EXPECT_NEAR(v, cellVolume / 6.0, 1e-12);
    total += v;
  }
  EXPECT_NEAR(total, size.prod(), 1e-9 * size.prod());
  // Conforming: no face in more than two tets, and the boundary is exactly the box surface
  // (2 triangles per boundary cell face, all of them closed and enclosing the box volume).
  TetMeshTopology topo(m);
  EXPECT_EQ(topo.nonManifoldFaceCount(), 0);
  EXPECT_EQ(topo.boundaryFaces().size(), static_cast<size_t>(4 * (nx * ny + ny * nz + nx * nz)));
  const TriangleSurface boundary = boundarySurface(m, topo);
  EXPECT_EQ(badEdgeCount(boundary), 0);
  EXPECT_NEAR(enclosedVolume(boundary), size.prod(), 1e-9 * size.prod());
}

TEST(AnalyticShapes, BoxTetMeshRejectsBadArguments) {
  EXPECT_THROW(boxTetMesh(Vec3(1, 1, 1), 0, 1, 1), GeoLatticeError);
  EXPECT_THROW(boxTetMesh(Vec3(1, 1, -1), 1, 1, 1), GeoLatticeError);
  EXPECT_THROW(boxTetMesh(Vec3(1, 1, 1), 2000, 2000, 2000), GeoLatticeError);
}
