#include "mesh/TetMeshTopology.h"

#include "common/Error.h"
#include "mesh/AnalyticShapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <random>
#include <vector>

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

TEST(TetMeshTopology, MatchesFacesLikeAMapOfSortedTriples) {
  // A voxel block with its tets and vertex ids shuffled, two tets repeated (non-manifold faces)
  // and one inverted: the topology against a std::map of every face's sorted vertex triple.
  TetMesh m = boxTetMesh(Vec3(3, 2, 2), 6, 4, 5);
  std::mt19937 rng(7);
  std::vector<int> relabel(m.points.size());
  std::iota(relabel.begin(), relabel.end(), 0);
  std::shuffle(relabel.begin(), relabel.end(), rng);
  std::vector<Vec3> points(m.points.size());
  for (size_t v = 0; v < m.points.size(); ++v) {
    points[relabel[v]] = m.points[v];
  }
  m.points = points;
  for (auto& tet : m.tets) {
    for (int& v : tet) {
      v = relabel[v];
    }
  }
  std::shuffle(m.tets.begin(), m.tets.end(), rng);
  m.tets.push_back(m.tets[17]);
  m.tets.push_back(m.tets[90]);
  std::swap(m.tets[5][0], m.tets[5][1]);

  constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  std::map<std::array<int, 3>, std::vector<std::pair<int, int>>> faces;
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t) {
    for (int k = 0; k < 4; ++k) {
      std::array<int, 3> key = {m.tets[t][kFace[k][0]], m.tets[t][kFace[k][1]],
                                m.tets[t][kFace[k][2]]};
      std::sort(key.begin(), key.end());
      faces[key].emplace_back(t, k);
    }
  }
  const TetMeshTopology topo(m);
  int boundary = 0, nonManifold = 0;
  for (const auto& [key, sides] : faces) {
    if (sides.size() == 1) {
      ++boundary;
      EXPECT_EQ(topo.neighbor(sides[0].first, sides[0].second), -1);
    } else if (sides.size() == 2) {
      EXPECT_EQ(topo.neighbor(sides[0].first, sides[0].second), sides[1].first);
      EXPECT_EQ(topo.neighbor(sides[1].first, sides[1].second), sides[0].first);
    } else {
      ++nonManifold;
    }
  }
  EXPECT_GE(nonManifold, 6);  // the repeated tets' inner faces (a boundary face makes a pair)
  EXPECT_EQ(topo.nonManifoldFaceCount(), nonManifold);
  ASSERT_EQ(static_cast<int>(topo.boundaryFaces().size()), boundary);
  for (size_t i = 1; i < topo.boundaryFaces().size(); ++i) {  // by tet, then face
    const BoundaryFace& a = topo.boundaryFaces()[i - 1];
    const BoundaryFace& b = topo.boundaryFaces()[i];
    EXPECT_TRUE(a.tet < b.tet || (a.tet == b.tet && a.localFace < b.localFace));
  }
}

TEST(TetMeshTopology, RefusesANegativeVertexIndex) {
  TetMesh m = twoTets();
  m.tets[1][2] = -1;
  EXPECT_THROW(TetMeshTopology{m}, GeoLatticeError);
}
