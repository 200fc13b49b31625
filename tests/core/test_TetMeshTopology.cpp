#include "mesh/TetMeshTopology.h"

#include <gtest/gtest.h>

using namespace geolattice;

namespace {
// Two positively oriented tets sharing face (1,2,3).
TetMesh twoTets() {
  TetMesh m;
  m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1)};
  m.tets = {{0, 1, 2, 3}, {4, 1, 3, 2}};
  return m;
}
}  // namespace

TEST(TetMeshTopology, NeighboursAndOutwardBoundary) {
  const TetMesh m = twoTets();
  ASSERT_GT(signedTetVolume(m.points[4], m.points[1], m.points[3], m.points[2]), 0);
  TetMeshTopology topo(m);
  EXPECT_EQ(topo.neighbor(0, 0), 1);
  EXPECT_EQ(topo.neighbor(1, 0), 0);
  EXPECT_EQ(topo.neighbor(0, 1), -1);
  EXPECT_EQ(topo.boundaryFaces().size(), 6u);
  EXPECT_EQ(topo.nonManifoldFaceCount(), 0);
  // Outward: the normal of every boundary face points away from the centroid of its tet.
  for (const BoundaryFace& f : topo.boundaryFaces()) {
    Vec3 c = Vec3::Zero();
    for (int v : m.tets[f.tet]) {
      c += m.points[v] / 4.0;
    }
    const Vec3& a = m.points[f.vertices[0]];
    const Vec3 n = (m.points[f.vertices[1]] - a).cross(m.points[f.vertices[2]] - a);
    EXPECT_GT(n.dot(a - c), 0);
  }
}

TEST(TetMeshTopology, CountsNonManifoldFaces) {
  TetMesh m = twoTets();
  m.points.push_back(Vec3(-1, -1, -1) * 0.1 + Vec3(0.3, 0.3, 0.3));
  m.tets.push_back({5, 1, 2, 3});  // a third tet on face (1,2,3)
  TetMeshTopology topo(m);
  EXPECT_EQ(topo.nonManifoldFaceCount(), 1);
}
