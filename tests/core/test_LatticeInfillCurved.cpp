// Lattice infill graph on real geodesic distance fields: surface -> TetGen -> GDF (heat method)
// -> curved layers -> lattice, on a ball, the bunny (curved layers, several sub-graphs) and a
// TetGen box (the grid of the analytic test, now with the solved fields). Checks: vertices on
// their layer surface and on their isoline's level, no two edges of a layer meeting except at a
// shared vertex, connected sub-graphs with an even number of boundary hits, the degree rules, and
// the vertex count of the paper's per-tet construction (Eqs. 6-9 on the tet faces).
#include "LatticeInfillChecks.h"

#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "io/MeshReader.h"
#include "lattice/LatticeInfill.h"
#include "mesh/AnalyticShapes.h"
#include "slicer/CurvedLayerSlicer.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <string>

using namespace geolattice;
using namespace geolattice::testing;

namespace {

const std::string kData = GEOLATTICE_TESTDATA;

struct Pipeline {
  TetMesh mesh;
  GeodesicFields fields;
  CurvedLayers layers;
  double diagonal = 0;  ///< bounding-box diagonal of the part (mm)
};

Pipeline runPipeline(const TriangleSurface& surface, double edgeLength, double sourceTolerance,
                     const SlicerOptions& slicer) {
  Pipeline p;
  TetrahedralizeOptions t;
  t.targetEdgeLength = edgeLength;
  p.mesh = tetrahedralizeSurface(surface, t).mesh;
  p.fields = computeGeodesicDistanceFields(p.mesh, sourcesNearLowestZ(p.mesh, sourceTolerance));
  p.layers = sliceCurvedLayers(p.mesh, p.fields.gamma, p.fields.alpha, p.fields.beta,
                               vertexGradientDirections(p.mesh, p.fields.gamma), slicer);
  Vec3 lo = Vec3::Constant(1e300), hi = -lo;
  for (const Vec3& q : p.mesh.points) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  p.diagonal = (hi - lo).norm();
  return p;
}

struct Timed {
  LatticeGraph graph;
  double seconds = 0;
};

Timed timedLattice(const CurvedLayers& layers, const LatticeOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  Timed t{buildLatticeGraph(layers, options)};
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

/// All structural and geometric checks of a lattice on real fields; prints the numbers.
void expectValidLattice(const char* name, const Pipeline& p, const Timed& t) {
  const LatticeGraph& g = t.graph;
  const double tol = 1e-9 * p.diagonal;
  const StructureReport s = checkStructure(g, tol);
  const GeometryReport geo = checkGeometry(g, p.layers, tol);
  const long paper = paperFacePointCount(p.mesh, p.fields.gamma, p.fields.alpha, p.fields.beta, g);
  long onFaces = 0;
  for (size_t v = 0; v < g.points.size(); ++v) {
    onFaces += g.vertexKind[v] == LatticeVertexKind::IsolinePoint ||
               g.vertexKind[v] == LatticeVertexKind::BoundaryHit;
  }
  std::printf(
      "[lattice] %s: %zu tets, %zu layers (%zu triangles), lattice %zu vertices %zu edges, %d "
      "crossings, "
      "%d boundary hits, %zu sub-graphs, irregular %d, %.3f s; max distance to layer %.2e mm, max "
      "level error "
      "%.2e mm, min separation of disjoint edges %.2e mm, tet-face points %ld (paper count %ld), "
      "merged "
      "diagonal points %d\n",
      name, p.mesh.tets.size(), g.layerValues.size(), p.layers.triangles.size(), g.points.size(),
      g.edges.size(), g.stats.crossings, g.stats.boundaryHits, g.subgraphs.size(),
      g.stats.irregularVertices, t.seconds, geo.maxSurfaceDistance, geo.maxLevelError,
      geo.minSeparation, onFaces, paper, g.stats.mergedDiagonalPoints);
  EXPECT_GT(g.stats.crossings, 0);
  EXPECT_EQ(s.irregularVertices, 0);
  EXPECT_EQ(g.stats.irregularVertices, 0);
  EXPECT_EQ(s.duplicateVertices, 0);
  EXPECT_EQ(s.zeroLengthEdges, 0);
  EXPECT_EQ(s.oddBoundaryHitSubgraphs, 0);
  EXPECT_EQ(s.crossings, g.stats.crossings);
  EXPECT_LT(geo.maxSurfaceDistance, 1e-6 * p.diagonal);
  EXPECT_LT(geo.maxLevelError, 1e-6 * p.diagonal);
  EXPECT_EQ(geo.intersectingEdgePairs, 0);
  EXPECT_EQ(g.stats.openBoundaryChains, 0);
  // Generic data: no exact hits, and the graph is the paper's (one vertex per tet face and level).
  EXPECT_EQ(g.stats.pointCrossings + g.stats.edgeCrossings + g.stats.ridgeSegments +
                g.stats.boundarySegments,
            0);
  EXPECT_EQ(onFaces, paper);
}

}  // namespace

TEST(LatticeInfillCurved, BallWithGeodesicLayers) {
  SlicerOptions slicer;
  slicer.interval = 1.0;
  slicer.firstLayerOffset = 0.5;
  const Pipeline p = runPipeline(sphereSurface(Vec3(0, 0, 20), 20, 3), 2.5, 1.0, slicer);
  const Timed t = timedLattice(p.layers, LatticeOptions{});
  expectValidLattice("ball r = 20 mm, width 4", p, t);
  // Each layer of a convex ball is one disc: one sub-graph per non-empty layer.
  for (size_t l = 0; l < t.graph.layerValues.size(); ++l) {
    EXPECT_LE(t.graph.layerSubgraphOffset[l + 1] - t.graph.layerSubgraphOffset[l], 1)
        << "layer " << l;
  }
}

TEST(LatticeInfillCurved, BunnyWithSeveralSubgraphsPerLayer) {
  TriangleSurface bunny = readObj(kData + "/bunny.obj");
  double zMin = 1e300, zMax = -1e300;
  for (const Vec3& q : bunny.points) {
    zMin = std::min(zMin, q.z());
    zMax = std::max(zMax, q.z());
  }
  for (Vec3& q : bunny.points) {
    q = 80.0 / (zMax - zMin) * (q - Vec3(0, 0, zMin));
  }
  SlicerOptions slicer;
  slicer.interval = 1.0;
  slicer.firstLayerOffset = 1.0;
  const Pipeline p = runPipeline(bunny, 4.0, 0.5, slicer);
  LatticeOptions o;
  o.alphaWidth = o.betaWidth = 6.0;  // the paper's bunny (Table 1)
  const Timed t = timedLattice(p.layers, o);
  expectValidLattice("bunny 80 mm, width 6", p, t);
  int multi = 0;
  for (size_t l = 0; l < t.graph.layerValues.size(); ++l) {
    multi += t.graph.layerSubgraphOffset[l + 1] - t.graph.layerSubgraphOffset[l] > 1;
  }
  std::printf("[lattice] bunny: %d layers with more than one sub-graph\n", multi);
  EXPECT_GT(multi, 0);  // ears
  // Dropping short sub-graphs.
  o.minimumSubgraphLength = 30;
  const LatticeGraph dropped = buildLatticeGraph(p.layers, o);
  EXPECT_GT(dropped.stats.droppedSubgraphs, 0);
  EXPECT_EQ(dropped.subgraphs.size() + dropped.stats.droppedSubgraphs, t.graph.subgraphs.size());
  for (const LatticeSubgraph& s : dropped.subgraphs) {
    EXPECT_GE(s.length, 30.0);
  }
  std::printf("[lattice] bunny: minimum sub-graph length 30 mm drops %d sub-graphs (%.1f mm)\n",
              dropped.stats.droppedSubgraphs, dropped.stats.droppedLength);
}

TEST(LatticeInfillCurved, BranchingYSplitsIntoSubgraphsPerBranch) {
  const TriangleSurface y = readObj(kData + "/y_shape.obj");  // generated, base on z = 0, mm
  SlicerOptions slicer;                                       // 0.6 mm layers
  const Pipeline p = runPipeline(y, 2.0, 0.05, slicer);
  const Timed t = timedLattice(p.layers, LatticeOptions{});
  expectValidLattice("branching Y, width 4", p, t);
  // Above the fork every layer has one piece per branch.
  int split = 0;
  for (size_t l = 0; l < t.graph.layerValues.size(); ++l) {
    split += t.graph.layerSubgraphOffset[l + 1] - t.graph.layerSubgraphOffset[l] == 2;
  }
  std::printf("[lattice] branching Y: %d of %zu layers have two sub-graphs\n", split,
              t.graph.layerValues.size());
  EXPECT_GT(split, 10);
}

// The analytic grid test with the solved fields of a TetGen box: α ≈ 40 - y, β ≈ 40 - x. Phase 2
// keeps the lines 2 mm away from the walls, so each layer is the 10 x 10 grid.
TEST(LatticeInfillCurved, TetGenBoxGivesTheGrid) {
  SlicerOptions slicer;
  slicer.interval = 2.0;
  slicer.firstLayerOffset = 1.0;
  slicer.lastLayer = 26;  // z <= 53: away from the top face
  const Pipeline p = runPipeline(boxSurface(Vec3(40, 40, 60), 3.0), 3.0, 1e-6, slicer);
  LatticeOptions o;
  o.alphaPhase = o.betaPhase = 2.0;
  const Timed t = timedLattice(p.layers, o);
  expectValidLattice("TetGen box 40x40x60, GDF, width 4, phase 2", p, t);
  const LatticeGraph& g = t.graph;
  double worstSpacing = 0, worstLine = 0, sumSpacing = 0;
  int gaps = 0;
  for (size_t l = 0; l < g.layerValues.size(); ++l) {
    EXPECT_EQ(g.layerSubgraphOffset[l + 1] - g.layerSubgraphOffset[l], 1);
    int crossings = 0, hits = 0;
    for (int v = g.layerVertexOffset[l]; v < g.layerVertexOffset[l + 1]; ++v) {
      crossings += g.vertexKind[v] == LatticeVertexKind::Crossing;
      hits += g.vertexKind[v] == LatticeVertexKind::BoundaryHit;
    }
    EXPECT_EQ(crossings, 100) << "layer " << l;
    EXPECT_EQ(hits, 40) << "layer " << l;
    // Mean position of each line (length-weighted over its edges) and its straightness.
    std::map<int, std::pair<double, double>> alphaY, betaX;  // level -> (sum len*pos, sum len)
    for (int e = g.layerEdgeOffset[l]; e < g.layerEdgeOffset[l + 1]; ++e) {
      const Vec3& a = g.points[g.edges[e][0]];
      const Vec3& b = g.points[g.edges[e][1]];
      const double len = (b - a).norm();
      if (g.edgeKind[e] == LatticeEdgeKind::Alpha) {
        alphaY[g.edgeLevel[e]].first += len * 0.5 * (a.y() + b.y());
        alphaY[g.edgeLevel[e]].second += len;
        worstLine = std::max(worstLine, std::abs(a.y() - (40 - g.alphaLevels[g.edgeLevel[e]])));
      } else if (g.edgeKind[e] == LatticeEdgeKind::Beta) {
        betaX[g.edgeLevel[e]].first += len * 0.5 * (a.x() + b.x());
        betaX[g.edgeLevel[e]].second += len;
        worstLine = std::max(worstLine, std::abs(a.x() - (40 - g.betaLevels[g.edgeLevel[e]])));
      }
    }
    for (const auto* lines : {&alphaY, &betaX}) {
      ASSERT_EQ(lines->size(), 10u);
      std::vector<double> pos;
      for (const auto& [k, sum] : *lines)
        pos.push_back(sum.first / sum.second);
      std::sort(pos.begin(), pos.end());
      for (size_t i = 1; i < pos.size(); ++i) {
        const double error = std::abs(pos[i] - pos[i - 1] - 4.0) / 4.0;
        worstSpacing = std::max(worstSpacing, error);
        sumSpacing += error;
        ++gaps;
      }
    }
  }
  std::printf(
      "[lattice] TetGen box: spacing error of the mean line positions: mean %.3g %%, worst %.3g %% "
      "(%d gaps); "
      "worst vertex offset from the analytic line %.3g mm\n",
      100 * sumSpacing / gaps, 100 * worstSpacing, gaps, worstLine);
  // The lattice reproduces the fields' isolines exactly (level error above); what remains is the
  // GDF's own error (α, β within ~0.3 mm of 40 - y, 40 - x on this 3 mm mesh).
  EXPECT_LT(sumSpacing / gaps, 0.005);
  EXPECT_LT(worstSpacing, 0.02);
  EXPECT_LT(worstLine, 0.5);
}
