// Eulerian trimming and crossover-free Euler tours (paper Section 3.2, Figs. 14-15): on the
// analytic box lattice, on the real three-branch tree and bunny lattices, and on hand-built
// graphs for the odd-loop fallback and bad input.
#include "../common/CoreStages.h"
#include "common/Error.h"
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "io/MeshReader.h"
#include "lattice/LatticeInfill.h"
#include "mesh/AnalyticShapes.h"
#include "slicer/CurvedLayerSlicer.h"
#include "tetrahedralize/TetrahedralizeSurface.h"
#include "toolpath/EulerTour.h"
#include "toolpath/EulerianTrimming.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>

using namespace geolattice;

namespace {

LatticeGraph boxLattice() {
  const TetMesh mesh = boxTetMesh(Vec3(20, 20, 6), 10, 10, 3);
  Eigen::VectorXd gamma(mesh.points.size()), alpha(mesh.points.size()), beta(mesh.points.size());
  for (size_t i = 0; i < mesh.points.size(); ++i) {
    gamma[i] = mesh.points[i].z();
    alpha[i] = mesh.points[i].y();
    beta[i] = mesh.points[i].x();
  }
  const CurvedLayers layers = sliceCurvedLayers(
      mesh, gamma, alpha, beta, vertexGradientDirections(mesh, gamma), SlicerOptions{});
  LatticeOptions o;
  o.alphaWidth = o.betaWidth = 4.0;
  o.alphaPhase = o.betaPhase = 1.1;
  return buildLatticeGraph(layers, o);
}

LatticeGraph realLattice(const std::string& file, double size, double edge, double width) {
  fixtures::CoreStageOptions o;
  o.edgeLength = edge;
  o.latticeWidth = width;
  o.until = fixtures::CoreStage::Lattice;
  return fixtures::runCoreStages(fixtures::scaledModel(file, size), o).lattice;
}

/// Every acceptance property of trimming + tours on a lattice.
void expectPrintable(const char* name, const LatticeGraph& g) {
  const auto t0 = std::chrono::steady_clock::now();
  const TrimResult trim = trimToEulerian(g);
  const EulerTours tours = nonCrossingEulerTours(g, trim.kept);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Only boundary edges are trimmed (unless the odd-loop fallback ran).
  int keptEdges = 0;
  for (size_t e = 0; e < g.edges.size(); ++e) {
    keptEdges += trim.kept[e];
    if (!trim.kept[e] && trim.tJoinEdges == 0) {
      EXPECT_EQ(g.edgeKind[e], LatticeEdgeKind::Boundary);
    }
  }
  // Every kept edge exactly once, deleted ones never.
  std::vector<int> uses(g.edges.size(), 0);
  for (const auto& t : tours.edges) {
    for (int e : t)
      ++uses[e];
  }
  for (size_t e = 0; e < g.edges.size(); ++e) {
    ASSERT_EQ(uses[e], trim.kept[e] ? 1 : 0) << name << " edge " << e;
  }
  // Tours are closed walks along edges.
  for (size_t t = 0; t < tours.edges.size(); ++t) {
    const auto& vs = tours.vertices[t];
    ASSERT_EQ(vs.front(), vs.back());
    for (size_t i = 0; i < tours.edges[t].size(); ++i) {
      const auto& e = g.edges[tours.edges[t][i]];
      ASSERT_TRUE((e[0] == vs[i] && e[1] == vs[i + 1]) || (e[1] == vs[i] && e[0] == vs[i + 1]));
    }
  }
  // One tour per sub-graph piece: retractions = sub-graphs - 1 unless a split is reported.
  int pieces = 0;
  for (int c : trim.componentCount)
    pieces += c;
  EXPECT_EQ(static_cast<int>(tours.edges.size()), pieces) << name;
  EXPECT_EQ(countTourCrossovers(g, tours), 0) << name;
  std::printf(
      "[toolpath] %s: %zu sub-graphs, %zu edges (%d kept), trimmed %d boundary edges (%.1f mm), "
      "odd loops %d, "
      "T-join edges %d, split %d, %zu tours, %d switches, %d high-degree vertices, %.3f s\n",
      name, g.subgraphs.size(), g.edges.size(), keptEdges, trim.trimmedEdges, trim.trimmedLength,
      trim.oddLoops, trim.tJoinEdges, trim.splitSubgraphs, tours.edges.size(), tours.switches,
      tours.highDegreeVertices, seconds);
}

/// A square ring of boundary edges around (cx, cy), z = 0, with `n` points per side.
int addSquareLoop(LatticeGraph& g, double cx, double cy, double half, int n, int sub) {
  const int first = static_cast<int>(g.points.size());
  for (int side = 0; side < 4; ++side) {
    for (int i = 0; i < n; ++i) {
      const double t = -half + 2 * half * i / n;
      const Vec3 p = side == 0   ? Vec3(cx + t, cy - half, 0)
                     : side == 1 ? Vec3(cx + half, cy + t, 0)
                     : side == 2 ? Vec3(cx - t, cy + half, 0)
                                 : Vec3(cx - half, cy - t, 0);
      g.points.push_back(p);
    }
  }
  const int count = 4 * n;
  for (int i = 0; i < count; ++i) {
    g.edges.push_back({first + i, first + (i + 1) % count});
    g.edgeKind.push_back(LatticeEdgeKind::Boundary);
    g.edgeSubgraph.push_back(sub);
  }
  return first;
}

void finish(LatticeGraph& g, int subgraphs) {
  g.normals.assign(g.points.size(), Vec3::UnitZ());
  g.vertexSubgraph.assign(g.points.size(), 0);
  g.subgraphs.resize(subgraphs);
}

}  // namespace

TEST(EulerTour, BoxLatticeOneTourPerSubgraph) {
  LatticeGraph g = boxLattice();
  // Levels 1.1 + 4k cross exactly on the Kuhn mesh's diagonals: crossings duplicate isoline
  // points there (zero-length edges). Trimming refuses them; the documented repair contracts them.
  EXPECT_THROW(trimToEulerian(g), GeoLatticeError);
  const size_t before = g.edges.size();
  const int counted = countShortEdges(g, 1e-9);  // what the planner asks before copying g
  EXPECT_EQ(g.edges.size(), before);
  const int contracted = contractShortEdges(g, 1e-9);
  EXPECT_GT(contracted, 0);
  EXPECT_EQ(counted, contracted);
  EXPECT_EQ(countShortEdges(g, 1e-9), 0);
  EXPECT_EQ(g.edges.size(), before - contracted);
  for (size_t v = 0; v < g.points.size(); ++v) {
    EXPECT_TRUE(g.degree[v] == 0 || g.degree[v] == 2 || g.degree[v] == 3 || g.degree[v] == 4);
  }
  expectPrintable("box", g);
  const TrimResult trim = trimToEulerian(g);
  EXPECT_EQ(trim.oddLoops, 0);
  EXPECT_EQ(trim.splitSubgraphs, 0);
  EXPECT_EQ(trim.tJoinEdges, 0);
  EXPECT_GT(trim.trimmedEdges, 0);
}

TEST(EulerTour, ThreeBranchTree) {
  expectPrintable("three-branch tree", realLattice("three_branch_tree.obj", 54.0, 2.0, 4.0));
}

TEST(EulerTour, Bunny) {
  expectPrintable("bunny 80 mm", realLattice("bunny.obj", 80.0, 2.5, 6.0));
}

TEST(EulerTour, RingWithOneSpokeIsSplitAndReported) {
  // Outer and inner loop joined by one isoline: each loop has one odd vertex, so chains cannot
  // fix them; the T-join deletes the spoke (the only path between them) and the two loops are
  // printed as two tours.
  LatticeGraph g;
  const int outer = addSquareLoop(g, 0, 0, 10, 4, 0);
  const int inner = addSquareLoop(g, 0, 0, 4, 4, 0);
  g.edges.push_back({outer + 2, inner + 2});  // bottom side midpoints (x = cx)
  g.edgeKind.push_back(LatticeEdgeKind::Alpha);
  g.edgeSubgraph.push_back(0);
  finish(g, 1);
  const TrimResult trim = trimToEulerian(g);
  EXPECT_EQ(trim.oddLoops, 2);
  EXPECT_EQ(trim.tJoinEdges, 1);
  EXPECT_EQ(trim.splitSubgraphs, 1);
  EXPECT_EQ(trim.componentCount[0], 2);
  const EulerTours tours = nonCrossingEulerTours(g, trim.kept);
  EXPECT_EQ(tours.edges.size(), 2u);
}

TEST(EulerTour, CrossingTurnsInsteadOfGoingStraight) {
  // A loop with a plus inside: 4 boundary hits, a crossing in the middle. After trimming, the
  // tour passes the crossing twice and must turn both times.
  LatticeGraph g;
  const int loop = addSquareLoop(g, 0, 0, 10, 2, 0);  // side midpoints at loop + 1, 3, 5, 7
  const int centre = static_cast<int>(g.points.size());
  g.points.push_back(Vec3(0, 0, 0));
  for (int k : {1, 3, 5, 7}) {
    g.edges.push_back({loop + k, centre});
    g.edgeKind.push_back(k % 4 == 1 ? LatticeEdgeKind::Alpha : LatticeEdgeKind::Beta);
    g.edgeSubgraph.push_back(0);
  }
  finish(g, 1);
  const TrimResult trim = trimToEulerian(g);
  EXPECT_EQ(trim.trimmedEdges, 4);  // two of the four corner chains (2 edges each)
  const EulerTours tours = nonCrossingEulerTours(g, trim.kept);
  ASSERT_EQ(tours.edges.size(), 1u);
  EXPECT_EQ(countTourCrossovers(g, tours), 0);
  // A tour forced straight through the centre would be found by the checker.
  EulerTours straight = tours;
  const auto& vs = tours.vertices[0];
  for (size_t i = 1; i + 1 < vs.size(); ++i) {
    if (vs[i] == centre) {
      // Swap the two passes' outgoing halves: turning pairs become straight ones.
      std::vector<int> e = tours.edges[0];
      size_t second = i + 1;
      while (second + 1 < vs.size() && vs[second] != centre)
        ++second;
      ASSERT_LT(second + 1, vs.size());
      std::reverse(e.begin() + i, e.begin() + second);
      std::vector<int> v(vs.begin(), vs.end());
      std::reverse(v.begin() + i + 1, v.begin() + second);
      straight.edges[0] = e;
      straight.vertices[0] = v;
      break;
    }
  }
  EXPECT_GT(countTourCrossovers(g, straight), 0);
}

TEST(EulerTour, BadInput) {
  LatticeGraph g;
  addSquareLoop(g, 0, 0, 5, 2, 0);
  finish(g, 1);
  g.edges.push_back({0, 3});  // a chord: vertices 0 and 3 get degree 3
  g.edgeKind.push_back(LatticeEdgeKind::Alpha);
  g.edgeSubgraph.push_back(0);
  EXPECT_THROW(nonCrossingEulerTours(g, {}), GeoLatticeError);  // odd degree without trimming
  LatticeGraph zero = g;
  zero.points[3] = zero.points[0];  // zero-length edge
  EXPECT_THROW(trimToEulerian(zero), GeoLatticeError);
  LatticeGraph plus;
  const int loop = addSquareLoop(plus, 0, 0, 10, 2, 0);
  const int centre = static_cast<int>(plus.points.size());
  plus.points.push_back(Vec3::Zero());
  for (int k : {1, 3, 5, 7}) {
    plus.edges.push_back({loop + k, centre});
    plus.edgeKind.push_back(LatticeEdgeKind::Alpha);
    plus.edgeSubgraph.push_back(0);
  }
  finish(plus, 1);
  plus.normals[centre] = Vec3::Zero();  // missing normal at the crossing
  EXPECT_THROW(nonCrossingEulerTours(plus, trimToEulerian(plus).kept), GeoLatticeError);
  LatticeGraph sizes = g;
  sizes.edgeSubgraph.pop_back();
  EXPECT_THROW(trimToEulerian(sizes), GeoLatticeError);
}
