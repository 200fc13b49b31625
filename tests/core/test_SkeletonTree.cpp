// Skeleton tree (Algorithm 2, volumetric adjacency): a chain on a box with analytic fields, a
// split on the branching Y, a split and a merge on a torus lying on its side, and the
// validation errors (cyclic or missing adjacency).
#include "../common/CoreStages.h"
#include "common/Error.h"
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "io/MeshReader.h"
#include "lattice/LatticeInfill.h"
#include "mesh/AnalyticShapes.h"
#include "mesh/TetMeshTopology.h"
#include "skeleton/SkeletonTree.h"
#include "slicer/CurvedLayerSlicer.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

using namespace geolattice;

namespace {

const std::string kData = GEOLATTICE_TESTDATA;

using Part = fixtures::CoreStages;  // mesh, fields and lattice (the tests build the skeleton)

Part buildPart(const TriangleSurface& surface, double edgeLength, double sourceTolerance,
               double latticeWidth) {
  fixtures::CoreStageOptions o;
  o.edgeLength = edgeLength;
  o.baseTolerance = sourceTolerance;
  o.latticeWidth = latticeWidth;
  o.until = fixtures::CoreStage::Lattice;
  return fixtures::runCoreStages(surface, o);
}

/// Structural invariants every skeleton must satisfy.
void expectConsistent(const SkeletonTree& tree, const LatticeGraph& lattice) {
  ASSERT_EQ(tree.nodes.size(), lattice.subgraphs.size());
  EXPECT_NO_THROW(validateSkeletonTree(tree));
  int roots = 0;
  for (size_t k = 0; k < tree.nodes.size(); ++k) {
    EXPECT_EQ(tree.nodes[k].layer, lattice.subgraphs[k].layer);
    roots += tree.nodes[k].lower.empty();
  }
  EXPECT_EQ(roots, tree.roots);
  for (const auto& e : tree.edges) {
    // Adjacent sub-graphs are close: their centroids are not farther apart than the part allows.
    EXPECT_EQ(tree.nodes[e[1]].layer, tree.nodes[e[0]].layer + 1);
  }
}

int nodesOnLayer(const SkeletonTree& tree, int layer) {
  int n = 0;
  for (const auto& node : tree.nodes) {
    n += node.layer == layer;
  }
  return n;
}

}  // namespace

TEST(SkeletonTree, BoxIsAChain) {
  // Structured box with the exact fields γ = z, α = y, β = x: every layer is one sub-graph, so
  // the skeleton is a path from bottom to top.
  Part p;
  p.mesh = boxTetMesh(Vec3(20, 20, 15.3), 8, 8, 10);
  const Eigen::Index n = static_cast<Eigen::Index>(p.mesh.points.size());
  p.fields.gamma.resize(n);
  p.fields.alpha.resize(n);
  p.fields.beta.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    p.fields.gamma[i] = p.mesh.points[i].z();
    p.fields.alpha[i] = p.mesh.points[i].y();
    p.fields.beta[i] = p.mesh.points[i].x();
  }
  const CurvedLayers layers =
      sliceCurvedLayers(p.mesh, p.fields.gamma, p.fields.alpha, p.fields.beta,
                        vertexGradientDirections(p.mesh, p.fields.gamma), SlicerOptions{});
  LatticeOptions o;
  o.alphaWidth = o.betaWidth = 5.0;
  o.alphaPhase = o.betaPhase = 1.3;
  p.lattice = buildLatticeGraph(layers, o);
  const SkeletonTree tree = buildSkeletonTree(p.mesh, p.fields.gamma, p.lattice);
  expectConsistent(tree, p.lattice);
  const int K = static_cast<int>(tree.nodes.size());
  EXPECT_EQ(K, static_cast<int>(p.lattice.layerValues.size()));
  EXPECT_EQ(static_cast<int>(tree.edges.size()), K - 1);
  EXPECT_EQ(tree.roots, 1);
  EXPECT_EQ(tree.splitNodes, 0);
  EXPECT_EQ(tree.mergeNodes, 0);
  EXPECT_EQ(tree.floatingNodes, 0);
}

namespace {

/// The part's skeleton, checked with expectConsistent and summed up on stdout.
SkeletonTree consistentSkeleton(const Part& p, const char* name) {
  const SkeletonTree tree = buildSkeletonTree(p.mesh, p.fields.gamma, p.lattice);
  expectConsistent(tree, p.lattice);
  std::printf("[skeleton] %s: %zu nodes, %zu edges, roots %d, split %d, merge %d, floating %d\n",
              name, tree.nodes.size(), tree.edges.size(), tree.roots, tree.splitNodes,
              tree.mergeNodes, tree.floatingNodes);
  return tree;
}

}  // namespace

TEST(SkeletonTree, YSplitsIntoTwoBranches) {
  Part p = buildPart(readObj(kData + "/y_shape.obj"), 2.0, 0.5, 4.0);
  const SkeletonTree tree = consistentSkeleton(p, "Y");
  EXPECT_EQ(tree.roots, 1);
  EXPECT_EQ(tree.floatingNodes, 0);
  EXPECT_GE(tree.splitNodes, 1);
  EXPECT_EQ(tree.mergeNodes, 0);  // the branches never meet again
  // Every node has exactly one lower node except the root: a tree.
  EXPECT_EQ(tree.edges.size(), tree.nodes.size() - 1);
  // Both branches reach the top layers: the highest layer with two sub-graphs is well above the split.
  int lastTwo = -1;
  for (int l = 0; l < static_cast<int>(p.lattice.layerValues.size()); ++l) {
    if (nodesOnLayer(tree, l) == 2) {
      lastTwo = l;
    }
  }
  EXPECT_GT(lastTwo, static_cast<int>(p.lattice.layerValues.size()) / 2);
}

TEST(SkeletonTree, TorusOnItsSideSplitsAndMerges) {
  // Layers grow from the bottom point up both halves of the ring and meet at the top.
  const TriangleSurface torus = torusSurface(Vec3(0, 0, 16), 12.0, 4.0, 96, 32);
  Part p = buildPart(torus, 1.5, 0.3, 3.0);
  const SkeletonTree tree = consistentSkeleton(p, "torus");
  EXPECT_GE(tree.splitNodes, 1);
  EXPECT_GE(tree.mergeNodes, 1);  // a DAG: the two arcs have one common upper node
  EXPECT_EQ(tree.floatingNodes, 0);
  // The merge node's lower nodes lie on opposite sides of the ring (x < 0 and x > 0).
  for (const auto& node : tree.nodes) {
    if (node.lower.size() == 2) {
      EXPECT_LT(tree.nodes[node.lower[0]].centroid.x() * tree.nodes[node.lower[1]].centroid.x(),
                0.0);
    }
  }
}

TEST(SkeletonTree, AGivenAdjacencyGivesTheSameTreeAndAnotherMeshsIsRefused) {
  Part p = buildPart(readObj(kData + "/y_shape.obj"), 2.0, 0.5, 4.0);
  const SkeletonTree own = buildSkeletonTree(p.mesh, p.fields.gamma, p.lattice);
  const TetMeshTopology topology(p.mesh);
  SkeletonTreeOptions given;
  given.topology = &topology;
  const SkeletonTree shared = buildSkeletonTree(p.mesh, p.fields.gamma, p.lattice, given);
  EXPECT_EQ(shared.edges, own.edges);
  ASSERT_EQ(shared.nodes.size(), own.nodes.size());
  for (size_t k = 0; k < own.nodes.size(); ++k) {
    EXPECT_EQ(shared.nodes[k].lower, own.nodes[k].lower) << k;
  }
  TetMesh smaller = p.mesh;
  smaller.tets.pop_back();
  const TetMeshTopology other(smaller);
  given.topology = &other;
  try {
    buildSkeletonTree(p.mesh, p.fields.gamma, p.lattice, given);
    FAIL() << "another mesh's adjacency was accepted";
  } catch (const GeoLatticeError& e) {
    EXPECT_NE(std::string(e.what()).find("adjacency is of another mesh"), std::string::npos)
        << e.what();
  }
}

TEST(SkeletonTree, ValidationNamesBadAdjacency) {
  SkeletonTree tree;
  tree.nodes.resize(3);
  tree.nodes[0].layer = 0;
  tree.nodes[1].layer = 1;
  tree.nodes[2].layer = 2;
  tree.edges = {{0, 2}};  // skips a layer
  tree.nodes[0].upper = {2};
  tree.nodes[2].lower = {0};
  EXPECT_THROW(validateSkeletonTree(tree), GeoLatticeError);
  tree.edges = {{1, 0}};  // downwards: would make a cycle with 0 -> 1
  tree.nodes[0] = SkeletonNode{};
  tree.nodes[2] = SkeletonNode{};
  tree.nodes[2].layer = 2;
  tree.nodes[1].upper = {0};
  tree.nodes[0].lower = {1};
  EXPECT_THROW(validateSkeletonTree(tree), GeoLatticeError);
  tree.edges = {{0, 1}};  // lists that do not match the edges (missing adjacency)
  tree.nodes[1].upper.clear();
  tree.nodes[0].lower.clear();
  EXPECT_THROW(validateSkeletonTree(tree), GeoLatticeError);
  EXPECT_THROW(validateSkeletonTree(SkeletonTree{}), GeoLatticeError);
}

TEST(SkeletonTree, BadInput) {
  const TetMesh box = boxTetMesh(Vec3(10, 10, 10), 2, 2, 2);
  Eigen::VectorXd gamma(box.points.size());
  for (size_t i = 0; i < box.points.size(); ++i) {
    gamma[i] = box.points[i].z();
  }
  const std::vector<double> phi = {2.0, 4.0};
  EXPECT_THROW(buildSkeletonTree(box, gamma, phi, {}), GeoLatticeError);  // no sub-graph
  EXPECT_THROW(buildSkeletonTree(TetMesh{}, gamma, phi, {{0, Vec3(5, 5, 2)}}),
               GeoLatticeError);  // empty mesh
  EXPECT_THROW(buildSkeletonTree(box, gamma, {4.0, 2.0}, {{0, Vec3(5, 5, 2)}}),
               GeoLatticeError);  // descending
  EXPECT_THROW(buildSkeletonTree(box, gamma, phi, {{5, Vec3(5, 5, 2)}}),
               GeoLatticeError);  // layer out of range
  EXPECT_THROW(buildSkeletonTree(box, gamma, phi, {{0, Vec3(50, 5, 2)}}),
               GeoLatticeError);  // outside the part
  const SkeletonTree ok =
      buildSkeletonTree(box, gamma, phi, {{0, Vec3(5, 5, 2)}, {1, Vec3(3, 3, 4)}});
  EXPECT_EQ(ok.edges.size(), 1u);
}
