// Sub-graph splitting (core/sequence/SubgraphSplitting.h): two ramps that block each other (each
// has material above the other's nozzle somewhere) force a step in any order of whole sub-graphs;
// cut into pieces, one ramp is printed in two parts around the other, the order is free of
// forced steps and the verifier agrees.
#include "collision/CollisionVerifier.h"
#include "sequence/SubgraphSplitting.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace geolattice;

namespace {

/// Adds a polyline sub-graph (one edge per segment) of `points` on layer 0, normals +z.
void addStrip(LatticeGraph& g, SkeletonTree& tree, const std::vector<Vec3>& points) {
  const int s = static_cast<int>(g.subgraphs.size());
  const int v0 = static_cast<int>(g.points.size());
  LatticeSubgraph sub;
  sub.id = s;
  SkeletonNode node;
  for (size_t i = 0; i < points.size(); ++i) {
    g.points.push_back(points[i]);
    g.normals.push_back(Vec3::UnitZ());
    g.vertexSubgraph.push_back(s);
    g.vertexLayer.push_back(0);
    if (i > 0) {
      g.edges.push_back({v0 + static_cast<int>(i) - 1, v0 + static_cast<int>(i)});
      g.edgeSubgraph.push_back(s);
      g.edgeLayer.push_back(0);
      g.edgeKind.push_back(LatticeEdgeKind::Alpha);
      const double len = (points[i] - points[i - 1]).norm();
      sub.length += len;
      node.length += len;
      node.centroid += len * 0.5 * (points[i] + points[i - 1]);
    }
  }
  node.centroid /= node.length;
  sub.centroid = node.centroid;
  g.subgraphs.push_back(sub);
  tree.nodes.push_back(node);
}

/// Ramp i rises along x (z = 0.8 x), ramp j 3 mm beside it falls (z = 8 - 0.8 x): i's stations
/// at small x see j above them, j's stations at large x see i above them (45° cone).
void twoRamps(LatticeGraph& g, SkeletonTree& tree) {
  std::vector<Vec3> rising, falling;
  for (int k = 0; k <= 40; ++k) {
    const double x = 0.25 * k;
    rising.emplace_back(x, 0, 0.8 * x);
    falling.emplace_back(x, 3, 8 - 0.8 * x);
  }
  addStrip(g, tree, rising);
  addStrip(g, tree, falling);
  tree.layerValues = {0.0};
}

}  // namespace

TEST(SubgraphSplitting, CuttingOneRampRemovesTheForcedStep) {
  LatticeGraph g;
  SkeletonTree tree;
  twoRamps(g, tree);
  NozzleModel nozzle;  // the 45° cone
  PotentialCollisionOptions pcg;
  pcg.threads = 1;
  SequenceOptions order;
  order.strategy = SequenceStrategy::Greedy;

  SplitOptions never;
  never.maxRounds = 0;
  const PieceSequence whole = sequencePieces(g, tree, 0.5, nozzle, pcg, order, never);
  EXPECT_EQ(whole.sequence.forcedSteps, 1);
  EXPECT_EQ(whole.pieceSubgraph.size(), 2u);
  EXPECT_EQ(whole.splitSubgraphs, 0);
  EXPECT_EQ(whole.edgePiece, g.edgeSubgraph);

  SplitOptions rounds;
  rounds.maxRounds = 3;
  const PieceSequence split = sequencePieces(g, tree, 0.5, nozzle, pcg, order, rounds);
  EXPECT_EQ(split.forcedStepsBefore, 1);
  EXPECT_EQ(split.sequence.forcedSteps, 0);
  EXPECT_EQ(split.splitSubgraphs, 1);
  ASSERT_EQ(split.pieceSubgraph.size(), 3u);
  // Every edge has a piece of its own sub-graph; each piece is one connected run of the ramp.
  for (size_t e = 0; e < g.edges.size(); ++e) {
    ASSERT_GE(split.edgePiece[e], 0);
    EXPECT_EQ(split.pieceSubgraph[split.edgePiece[e]], g.edgeSubgraph[e]);
  }
  for (int p = 0; p < 3; ++p) {
    std::set<int> vertices;
    int edges = 0;
    for (size_t e = 0; e < g.edges.size(); ++e) {
      if (split.edgePiece[e] == p) {
        vertices.insert(g.edges[e][0]);
        vertices.insert(g.edges[e][1]);
        ++edges;
      }
    }
    EXPECT_EQ(static_cast<int>(vertices.size()), edges + 1) << p;  // a path: one more vertex
  }
  // The piece order: a part of the split ramp, the other ramp, the rest of the split ramp.
  const std::vector<int>& o = split.sequence.order;
  EXPECT_EQ(split.pieceSubgraph[o[0]], split.pieceSubgraph[o[2]]);
  EXPECT_NE(split.pieceSubgraph[o[0]], split.pieceSubgraph[o[1]]);
  // The verifier on the piece order (time = the piece's position) finds no collision; on the
  // order of whole ramps it does.
  auto verify = [&](const PieceSequence& s) {
    std::vector<int> time(s.material.points.size());
    for (size_t i = 0; i < time.size(); ++i) {
      time[i] = s.sequence.printIndex[s.material.subgraph[i]];
    }
    return verifyNozzleClearance(s.material.points, s.material.normals, time, nozzle);
  };
  EXPECT_FALSE(verify(whole).collisionFree);
  EXPECT_TRUE(verify(split).collisionFree);
}

TEST(SubgraphSplitting, NoForcedStepMeansNoPieces) {
  LatticeGraph g;
  SkeletonTree tree;
  twoRamps(g, tree);
  NozzleModel slim;
  slim.halfAngleDeg = 5;  // too slim to see the other ramp
  SequenceOptions order;
  order.strategy = SequenceStrategy::Rollout;
  SplitOptions rounds;
  rounds.maxRounds = 3;
  const PieceSequence s = sequencePieces(g, tree, 0.5, slim, {}, order, rounds);
  EXPECT_EQ(s.sequence.forcedSteps, 0);
  EXPECT_EQ(s.pieceSubgraph.size(), 2u);
  EXPECT_EQ(s.rounds, 0);
  SplitOptions bad;
  bad.maxRounds = -1;
  EXPECT_THROW(sequencePieces(g, tree, 0.5, slim, {}, order, bad), GeoLatticeError);
  order.strategy = SequenceStrategy::LayerPriority;
  EXPECT_THROW(sequencePieces(g, tree, 0.5, slim, {}, order, SplitOptions{}), GeoLatticeError);
}
