// TetLaplacian: the direct compressed-column assembly of K gives exactly the matrix of the
// textbook assembly (16 triplets per tet summed by setFromTriplets), including empty columns.
#include "gdf/TetLaplacian.h"
#include "mesh/AnalyticShapes.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <gtest/gtest.h>

using namespace geolattice;

namespace {

SparseMatrix tripletStiffness(const TetOperators& ops, const TetMesh& mesh) {
  std::vector<Eigen::Triplet<double>> triplets;
  for (size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& g = ops.basisGradients[t];
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        triplets.emplace_back(mesh.tets[t][i], mesh.tets[t][j], ops.tetVolumes[t] * g[i].dot(g[j]));
      }
    }
  }
  SparseMatrix K(static_cast<Eigen::Index>(mesh.points.size()),
                 static_cast<Eigen::Index>(mesh.points.size()));
  K.setFromTriplets(triplets.begin(), triplets.end());
  K.makeCompressed();
  return K;
}

void expectIdentical(const SparseMatrix& a, const SparseMatrix& b) {
  ASSERT_EQ(a.rows(), b.rows());
  ASSERT_EQ(a.cols(), b.cols());
  ASSERT_EQ(a.nonZeros(), b.nonZeros());
  for (Eigen::Index c = 0; c <= a.cols(); ++c) {
    ASSERT_EQ(a.outerIndexPtr()[c], b.outerIndexPtr()[c]) << "column " << c;
  }
  for (Eigen::Index k = 0; k < a.nonZeros(); ++k) {
    ASSERT_EQ(a.innerIndexPtr()[k], b.innerIndexPtr()[k]) << "entry " << k;
    ASSERT_EQ(a.valuePtr()[k], b.valuePtr()[k]) << "entry " << k;  // bit-identical sums
  }
}

}  // namespace

TEST(TetLaplacian, StiffnessIsExactlyTheTripletAssembly) {
  TetrahedralizeOptions options;
  options.targetEdgeLength = 3.0;
  const TetMesh mesh = tetrahedralizeSurface(sphereSurface(Vec3(1, 2, 3), 12.0, 3), options).mesh;
  ASSERT_GT(mesh.tets.size(), 1000u);
  const TetOperators ops = buildTetOperators(mesh);
  expectIdentical(ops.stiffness, tripletStiffness(ops, mesh));
  EXPECT_TRUE(ops.stiffness.isCompressed());
}

TEST(TetLaplacian, UnreferencedVertexGivesAnEmptyColumn) {
  TetMesh mesh;
  mesh.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(5, 5, 5),
                 Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1)};
  mesh.tets = {{0, 1, 3, 4}, {1, 5, 3, 4}};  // vertex 2 is in no tet
  ASSERT_GT(signedTetVolume(mesh.points[1], mesh.points[5], mesh.points[3], mesh.points[4]), 0);
  const TetOperators ops = buildTetOperators(mesh);
  EXPECT_EQ(ops.stiffness.col(2).nonZeros(), 0);
  EXPECT_EQ(ops.vertexVolumes[2], 0.0);
  expectIdentical(ops.stiffness, tripletStiffness(ops, mesh));
}
