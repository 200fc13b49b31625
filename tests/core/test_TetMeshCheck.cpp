#include "common/Error.h"
#include "gdf/TetLaplacian.h"
#include "mesh/AnalyticShapes.h"
#include "mesh/TetMeshCheck.h"

#include "../common/ErrorOf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace geolattice;

TEST(TetMeshCheck, BoxMeshIsValid) {
  const TetMesh m = boxTetMesh(Vec3(4, 3, 6), 4, 3, 5);
  const TetMeshCheckReport r = checkTetMesh(m);
  EXPECT_TRUE(r.isValid());
  EXPECT_EQ(r.tetCount, 360);
  EXPECT_EQ(r.invertedTets, 0);
  EXPECT_EQ(r.zeroVolumeTets, 0);
  EXPECT_EQ(r.nonManifoldFaces, 0);
  EXPECT_EQ(r.unusedPoints, 0);
  EXPECT_NEAR(r.totalVolume, 72.0, 1e-9);
  EXPECT_NO_THROW(requireValidTetMesh(m));
}

TEST(TetMeshCheck, InvertedTetsAreCountedWithTheFirstIndex) {
  TetMesh m = boxTetMesh(Vec3(1, 1, 1), 3, 3, 3);
  for (int t : {17, 40, 99, 100, 101}) {
    std::swap(m.tets[t][0], m.tets[t][1]);
  }
  const TetMeshCheckReport r = checkTetMesh(m);
  EXPECT_EQ(r.invertedTets, 5);
  EXPECT_EQ(r.firstInvertedTet, 17);
  EXPECT_FALSE(r.isValid());
  EXPECT_EQ(errorOf([&] { requireValidTetMesh(m); }),
            "tet mesh has 5 inverted tets (first: tet 17)");
  // A mix of orientations is not a convention: orientTetsPositively leaves it alone.
  const TetMesh before = m;
  EXPECT_EQ(orientTetsPositively(m), 0);
  EXPECT_EQ(m.tets, before.tets);
}

TEST(TetMeshCheck, AllNegativeMeshIsFlippedExplicitly) {
  TetMesh m = boxTetMesh(Vec3(2, 2, 2), 2, 2, 2);
  for (auto& t : m.tets) {
    std::swap(t[1], t[3]);
  }
  EXPECT_EQ(checkTetMesh(m).invertedTets, static_cast<int>(m.tets.size()));
  EXPECT_NE(errorOf([&] { requireValidTetMesh(m); }).find("all tets are negatively oriented"),
            std::string::npos);
  EXPECT_EQ(orientTetsPositively(m), static_cast<int>(m.tets.size()));
  EXPECT_TRUE(checkTetMesh(m).isValid());
  EXPECT_NEAR(checkTetMesh(m).totalVolume, 8.0, 1e-12);
  EXPECT_EQ(orientTetsPositively(m), 0);
}

TEST(TetMeshCheck, ZeroVolumeTetsAreRejected) {
  TetMesh m = boxTetMesh(Vec3(1, 1, 1), 1, 1, 1);
  // Four coplanar points on the bottom face (all are vertices of the mesh).
  m.tets.push_back({0, 1, 3, 2});
  const TetMeshCheckReport r = checkTetMesh(m);
  EXPECT_EQ(r.zeroVolumeTets, 1);
  EXPECT_EQ(r.firstZeroVolumeTet, 6);
  EXPECT_EQ(r.invertedTets, 0);
  EXPECT_EQ(errorOf([&] { requireValidTetMesh(m); }),
            "tet mesh has 1 zero-volume tets (first: tet 6)");
  TetMesh repeated = boxTetMesh(Vec3(1, 1, 1), 1, 1, 1);
  repeated.tets[2][3] = repeated.tets[2][0];
  EXPECT_EQ(checkTetMesh(repeated).zeroVolumeTets, 1);
}

TEST(TetMeshCheck, DuplicatedTetMakesNonManifoldFaces) {
  TetMesh m = boxTetMesh(Vec3(1, 1, 1), 1, 1, 1);
  m.tets.push_back(m.tets[0]);  // its 2 interior faces are now in 3 tets
  const TetMeshCheckReport r = checkTetMesh(m);
  EXPECT_EQ(r.nonManifoldFaces, 2);
  EXPECT_EQ(errorOf([&] { requireValidTetMesh(m); }),
            "tet mesh has 2 faces shared by more than two tets (overlapping tets)");
}

TEST(TetMeshCheck, UnusedVertexIsRejected) {
  TetMesh m = boxTetMesh(Vec3(1, 1, 1), 1, 1, 1);
  m.points.push_back(Vec3(5, 5, 5));
  const TetMeshCheckReport r = checkTetMesh(m);
  EXPECT_EQ(r.unusedPoints, 1);
  EXPECT_EQ(r.firstUnusedPoint, 8);
  EXPECT_EQ(errorOf([&] { requireValidTetMesh(m); }),
            "tet mesh has 1 vertices used by no tet (first: vertex 8)");
}

TEST(TetMeshCheck, OutOfRangeIndexIsRejectedWithoutCrashing) {
  TetMesh m = boxTetMesh(Vec3(1, 1, 1), 1, 1, 1);
  m.tets[3][2] = 8;
  m.tets[4][0] = -3;
  const TetMeshCheckReport r = checkTetMesh(m);
  EXPECT_EQ(r.outOfRangeTets, 2);
  EXPECT_EQ(r.firstOutOfRangeTet, 3);
  EXPECT_EQ(errorOf([&] { requireValidTetMesh(m); }),
            "tet mesh has 2 tets with a vertex index outside 0..7 (first: tet 3)");
  EXPECT_EQ(orientTetsPositively(m), 0);
}

TEST(TetMeshCheck, NonFinitePointIsRejected) {
  TetMesh m = boxTetMesh(Vec3(1, 1, 1), 1, 1, 1);
  m.points[5].x() = INFINITY;
  EXPECT_EQ(checkTetMesh(m).nonFinitePoints, 1);
  EXPECT_NE(
      errorOf([&] { requireValidTetMesh(m); }).find("NaN or infinite coordinates (first: point 5)"),
      std::string::npos);
}

TEST(TetMeshCheck, EmptyMeshIsRejected) {
  EXPECT_EQ(errorOf([] { requireValidTetMesh(TetMesh{}); }), "empty tet mesh: 0 points, 0 tets");
  TetMesh pointsOnly;
  pointsOnly.points = {Vec3(0, 0, 0)};
  EXPECT_FALSE(checkTetMesh(pointsOnly).isValid());
  EXPECT_NE(errorOf([&] { requireValidTetMesh(pointsOnly); }).find("empty tet mesh"),
            std::string::npos);
}

TEST(TetMeshCheck, FlatnessIsRelativeToTheTetsOwnSize) {
  // A 100 mm box and, beside it, a 0.02 mm one: the tiny tets are well shaped (TetGen makes
  // such where a pedestal meets a tilted part). A bound relative to the part's size (1e-12 of
  // its diagonal cubed, 5e-6 mm^3 here) called all of them flat, and dropping them cut the mesh
  // into islands ("the part has 3 separate bodies").
  TetMesh mesh = boxTetMesh(Vec3(100, 100, 100), 2, 2, 2);
  const TetMesh tiny = boxTetMesh(Vec3(0.02, 0.02, 0.02), 1, 1, 1);
  const int offset = static_cast<int>(mesh.points.size());
  for (const Vec3& p : tiny.points) {
    mesh.points.push_back(p + Vec3(120, 0, 0));
  }
  for (auto t : tiny.tets) {
    for (int& v : t) {
      v += offset;
    }
    mesh.tets.push_back(t);
  }
  EXPECT_TRUE(checkTetMesh(mesh).isValid());
  EXPECT_EQ(removeFlatTets(mesh), 0u);
  EXPECT_NO_THROW(buildTetOperators(mesh));
  // Four coplanar corners of the tiny box are still a flat tet.
  mesh.tets.push_back({offset + 0, offset + 1, offset + 3, offset + 2});
  EXPECT_EQ(checkTetMesh(mesh).zeroVolumeTets, 1);
  EXPECT_NE(errorOf([&] { buildTetOperators(mesh); }).find("zero-volume tet"), std::string::npos);
  EXPECT_EQ(removeFlatTets(mesh), 1u);
}

TEST(TetMeshCheck, FlatTetsAndTheirOwnPointsAreRemoved) {
  // A box mesh plus a flat sliver on one of its faces (four corners in the plane z = 0, one of
  // them a new point nothing else uses): the sliver and that point go, the box stays valid.
  TetMesh mesh = boxTetMesh(Vec3(2, 2, 2), 2, 2, 2);
  const size_t tets = mesh.tets.size(), points = mesh.points.size();
  mesh.points.push_back(Vec3(0.5, 0.5, 0.0));
  mesh.tets.push_back({0, 1, 3, static_cast<int>(points)});  // corners (0,0,0) (1,0,0) (0,1,0)
  EXPECT_EQ(checkTetMesh(mesh).zeroVolumeTets, 1);
  EXPECT_EQ(removeFlatTets(mesh), 1u);
  EXPECT_EQ(mesh.tets.size(), tets);
  EXPECT_EQ(mesh.points.size(), points);
  EXPECT_NO_THROW(requireValidTetMesh(mesh));
  EXPECT_EQ(removeFlatTets(mesh), 0u);  // nothing left to remove
}
