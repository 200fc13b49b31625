// Curved layer slicer: exact planes on a box with γ = z (including iso-values that hit mesh
// vertices exactly), layer counts, topology and orientation, and bad options.
#include "common/Error.h"
#include "mesh/AnalyticShapes.h"
#include "slicer/CurvedLayerSlicer.h"
#include "slicer/LayerStatistics.h"

#include "LayerChecks.h"
#include "../common/ErrorOf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace geolattice;

namespace {

struct ZField {
  Eigen::VectorXd gamma, alpha, beta;
  std::vector<Vec3> normals;
};

ZField heightField(const TetMesh& mesh) {
  ZField f;
  const auto n = static_cast<Eigen::Index>(mesh.points.size());
  f.gamma.resize(n);
  f.alpha.resize(n);
  f.beta.resize(n);
  for (Eigen::Index v = 0; v < n; ++v) {
    f.gamma[v] = mesh.points[v].z();
    f.alpha[v] = 40 - mesh.points[v].y();
    f.beta[v] = 40 - mesh.points[v].x();
  }
  f.normals = vertexGradientDirections(mesh, f.gamma);
  return f;
}

double triangleArea(const CurvedLayers& layers, const std::array<int, 3>& t) {
  const Vec3& a = layers.points[t[0]];
  return 0.5 * (layers.points[t[1]] - a).cross(layers.points[t[2]] - a).norm();
}

}  // namespace

TEST(CurvedLayerSlicer, LayerCountFormula) {
  SlicerOptions o;
  o.interval = 0.6;
  o.firstLayerOffset = 0.6;
  EXPECT_EQ(layerCount(60.0, o), 100);  // floor((60 - 0.6) / 0.6) + 1
  EXPECT_EQ(layerCount(0.59, o), 0);
  EXPECT_EQ(layerCount(0.6, o), 1);
  o.firstLayerOffset = 0.25;
  o.interval = 0.5;
  EXPECT_EQ(layerCount(10.0, o), 20);
  EXPECT_EQ(layerCount(10.25, o), 21);
}

TEST(CurvedLayerSlicer, BoxLayersArePlanesEvenThroughMeshVertices) {
  // z levels of the mesh vertices are multiples of 2 mm; φ = 0.5 k hits them every 4th layer.
  const TetMesh mesh = boxTetMesh(Vec3(40, 40, 60), 10, 10, 30);
  const ZField f = heightField(mesh);
  SlicerOptions o;
  o.interval = 0.5;
  o.firstLayerOffset = 0.5;
  const CurvedLayers layers = sliceCurvedLayers(mesh, f.gamma, f.alpha, f.beta, f.normals, o);
  ASSERT_EQ(static_cast<int>(layers.layerValues.size()), layerCount(60.0, o));
  ASSERT_EQ(layers.layerValues.size(), 120u);  // the top face z = 60 is the last layer
  for (size_t l = 0; l < layers.layerValues.size(); ++l) {
    const int L = static_cast<int>(l);
    double area = 0;
    for (int k = layers.layerTriangleOffset[L]; k < layers.layerTriangleOffset[L + 1]; ++k) {
      const double a = triangleArea(layers, layers.triangles[k]);
      ASSERT_GT(a, 0.0);
      area += a;
      const auto& t = layers.triangles[k];
      const Vec3 n = (layers.points[t[1]] - layers.points[t[0]])
                         .cross(layers.points[t[2]] - layers.points[t[0]]);
      ASSERT_GT(n.z(), 0.0) << "triangle normals follow +∇γ";
    }
    EXPECT_NEAR(area, 1600.0, 1e-8) << "layer " << l << " at z = " << layers.layerValues[l];
    for (int p = layers.layerPointOffset[L]; p < layers.layerPointOffset[L + 1]; ++p) {
      ASSERT_EQ(layers.pointLayer[p], L);
      ASSERT_NEAR(layers.points[p].z(), layers.layerValues[l], 1e-6);
      ASSERT_NEAR(layers.alpha[p], 40 - layers.points[p].y(), 1e-9);
      ASSERT_NEAR(layers.normals[p].z(), 1.0, 1e-9);
    }
    expectEdgeManifoldAndOriented(layers, L);
  }
  EXPECT_GT(layers.droppedDegenerateTriangles, 0);  // the exact hits did occur
}

TEST(CurvedLayerSlicer, PointsKeepTheirSourceEdgeAndExactGamma) {
  const TetMesh mesh = boxTetMesh(Vec3(10, 10, 10), 4, 4, 4);
  ZField f = heightField(mesh);
  // A non-linear γ so the layers are curved: γ = z + 0.05 (x^2 + y^2).
  for (size_t v = 0; v < mesh.points.size(); ++v) {
    const Vec3& p = mesh.points[v];
    f.gamma[v] = p.z() + 0.05 * (p.x() * p.x() + p.y() * p.y());
  }
  f.normals = vertexGradientDirections(mesh, f.gamma);
  SlicerOptions o;
  o.interval = 0.7;
  o.firstLayerOffset = 0.3;
  const CurvedLayers layers = sliceCurvedLayers(mesh, f.gamma, f.alpha, f.beta, f.normals, o);
  const double gmax = f.gamma.maxCoeff();
  ASSERT_EQ(static_cast<int>(layers.layerValues.size()), layerCount(gmax, o));
  for (size_t p = 0; p < layers.points.size(); ++p) {
    const auto [a, b] = layers.sourceEdge[p];
    const double t = layers.edgeParameter[p];
    const double g = (1 - t) * f.gamma[a] + t * f.gamma[b];
    ASSERT_LT(std::abs(g - layers.layerValues[layers.pointLayer[p]]), 1e-9 * gmax);
    ASSERT_LT((layers.points[p] - ((1 - t) * mesh.points[a] + t * mesh.points[b])).norm(), 1e-12);
  }
  for (size_t l = 0; l < layers.layerValues.size(); ++l) {
    expectEdgeManifoldAndOriented(layers, static_cast<int>(l));
  }
}

TEST(CurvedLayerSlicer, LayerRangeSelectsASubset) {
  const TetMesh mesh = boxTetMesh(Vec3(4, 4, 10), 2, 2, 5);
  const ZField f = heightField(mesh);
  SlicerOptions o;
  o.interval = 1.0;
  o.firstLayerOffset = 0.5;
  o.firstLayer = 3;
  o.lastLayer = 5;
  const CurvedLayers layers = sliceCurvedLayers(mesh, f.gamma, f.alpha, f.beta, f.normals, o);
  ASSERT_EQ(layers.layerValues.size(), 3u);
  EXPECT_EQ(layers.layerIndex.front(), 3);
  EXPECT_DOUBLE_EQ(layers.layerValues.front(), 3.5);
  for (const Vec3& p : layers.points) {
    EXPECT_GE(p.z(), 3.5 - 1e-12);
    EXPECT_LE(p.z(), 5.5 + 1e-12);
  }
}

TEST(CurvedLayerSlicer, BadOptionsAreReported) {
  const TetMesh mesh = boxTetMesh(Vec3(4, 4, 10), 2, 2, 5);
  const ZField f = heightField(mesh);
  SlicerOptions o;
  o.interval = 0;
  EXPECT_THROW(sliceCurvedLayers(mesh, f.gamma, f.alpha, f.beta, f.normals, o), GeoLatticeError);
  o.interval = -1;
  EXPECT_THROW(sliceCurvedLayers(mesh, f.gamma, f.alpha, f.beta, f.normals, o), GeoLatticeError);
  o = SlicerOptions{};
  o.interval = 20;  // larger than γ_max = 10 with offset = interval: no layer
  o.firstLayerOffset = 20;
  const std::string m =
      expectedErrorOf([&] { sliceCurvedLayers(mesh, f.gamma, f.alpha, f.beta, f.normals, o); });
  EXPECT_NE(m.find("no layer"), std::string::npos) << m;
  o = SlicerOptions{};
  o.firstLayer = 1000;
  EXPECT_THROW(sliceCurvedLayers(mesh, f.gamma, f.alpha, f.beta, f.normals, o), GeoLatticeError);
  EXPECT_THROW(
      sliceCurvedLayers(mesh, f.gamma.head(3), f.alpha, f.beta, f.normals, SlicerOptions{}),
      GeoLatticeError);
  EXPECT_THROW(sliceCurvedLayers(TetMesh{}, f.gamma, f.alpha, f.beta, f.normals, SlicerOptions{}),
               GeoLatticeError);
}

TEST(LayerStatistics, SpacingOfPlanesAndTheSameForEveryThreadCount) {
  // Planar layers 0.5 mm apart: spacing 0.5 everywhere, NaN for the last layer.
  const TetMesh box = boxTetMesh(Vec3(20, 20, 10), 5, 5, 5);
  const ZField planes = heightField(box);
  SlicerOptions o;
  o.interval = 0.5;
  o.firstLayerOffset = 0.5;
  const CurvedLayers flat =
      sliceCurvedLayers(box, planes.gamma, planes.alpha, planes.beta, planes.normals, o);
  const std::vector<LayerStatistics> s = computeLayerStatistics(flat);
  ASSERT_EQ(s.size(), flat.layerValues.size());
  for (size_t l = 0; l + 1 < s.size(); ++l) {
    EXPECT_NEAR(s[l].spacingMin, 0.5, 1e-9) << "layer " << l;
    EXPECT_NEAR(s[l].spacingMax, 0.5, 1e-9) << "layer " << l;
    EXPECT_NEAR(s[l].area, 400.0, 1e-8) << "layer " << l;
    EXPECT_EQ(s[l].components, 1);
  }
  EXPECT_TRUE(std::isnan(s.back().spacingMean));

  // Curved layers (γ = distance from a point below the box): every thread count gives
  // bit-identical statistics (layers are computed independently, each as on one thread).
  const TetMesh mesh = boxTetMesh(Vec3(30, 30, 20), 8, 8, 6);
  ZField f = heightField(mesh);
  for (Eigen::Index v = 0; v < f.gamma.size(); ++v) {
    f.gamma[v] = (mesh.points[v] - Vec3(15, 15, -10)).norm() - 10.0;
  }
  f.normals = vertexGradientDirections(mesh, f.gamma);
  o.interval = 0.7;
  o.firstLayerOffset = 0.7;
  const CurvedLayers layers = sliceCurvedLayers(mesh, f.gamma, f.alpha, f.beta, f.normals, o);
  ASSERT_GT(layers.layerValues.size(), 20u);
  const std::vector<LayerStatistics> one = computeLayerStatistics(layers, 1);
  for (int threads : {0, 2, 3, 64}) {
    const std::vector<LayerStatistics> many = computeLayerStatistics(layers, threads);
    ASSERT_EQ(many.size(), one.size());
    for (size_t l = 0; l < one.size(); ++l) {
      for (auto field :
           {&LayerStatistics::value, &LayerStatistics::area, &LayerStatistics::spacingMin,
            &LayerStatistics::spacingMean, &LayerStatistics::spacingMax}) {
        EXPECT_EQ(std::memcmp(&(one[l].*field), &(many[l].*field), sizeof(double)), 0)
            << "layer " << l << ", " << threads << " threads";
      }
      EXPECT_EQ(one[l].triangles, many[l].triangles);
      EXPECT_EQ(one[l].points, many[l].points);
      EXPECT_EQ(one[l].components, many[l].components);
    }
  }
  EXPECT_GT(one.front().spacingMax, one.front().spacingMin) << "curved layers: the spacing varies";
}
