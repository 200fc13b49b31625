// Lattice infill graph (paper Section 2.2, Algorithm 1, Eqs. 6-13) with analytic fields, where
// the expected graph is known exactly: a 40 x 40 x 60 box with γ = z, α = 40 - y, β = 40 - x
// gives a rectangular grid on every layer, also when the iso-values hit layer points or
// layer-mesh edges exactly. Plus hand-made layer meshes for ridges, nearly parallel isolines,
// several sub-graphs, the graded lattice, the levels, and bad input.
#include "LatticeInfillChecks.h"

#include "common/Error.h"
#include "lattice/LatticeInfill.h"
#include "lattice/LatticeLevels.h"
#include "mesh/AnalyticShapes.h"
#include "slicer/CurvedLayerSlicer.h"

#include "../common/ErrorOf.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <set>

using namespace geolattice;
using namespace geolattice::testing;

namespace {

using Field = std::function<double(const Vec3&)>;

struct BoxFields {
  TetMesh mesh;
  Eigen::VectorXd gamma, alpha, beta;
};

BoxFields boxFields(int nx, int ny, int nz, const Field& alpha, const Field& beta) {
  BoxFields b;
  b.mesh = boxTetMesh(Vec3(40, 40, 60), nx, ny, nz);
  const auto n = static_cast<Eigen::Index>(b.mesh.points.size());
  b.gamma.resize(n);
  b.alpha.resize(n);
  b.beta.resize(n);
  for (Eigen::Index v = 0; v < n; ++v) {
    const Vec3& p = b.mesh.points[v];
    b.gamma[v] = p.z();
    b.alpha[v] = alpha(p);
    b.beta[v] = beta(p);
  }
  return b;
}

CurvedLayers sliceBox(const BoxFields& b, double interval, double offset) {
  SlicerOptions o;
  o.interval = interval;
  o.firstLayerOffset = offset;
  return sliceCurvedLayers(b.mesh, b.gamma, b.alpha, b.beta,
                           vertexGradientDirections(b.mesh, b.gamma), o);
}

const Field kAlphaOfBox = [](const Vec3& p) {
  return 40 - p.y();
};
const Field kBetaOfBox = [](const Vec3& p) {
  return 40 - p.x();
};

/// Levels of a uniform lattice strictly inside (0, 40).
int interiorLevels(double width, double phase) {
  int n = 0;
  for (double c : uniformLatticeLevels(0, 40, width, phase)) {
    n += c > 0 && c < 40;
  }
  return n;
}

struct GridReport {
  int layers = 0;
  int crossingsPerLayer = -1;   ///< the same on every layer, else -1
  double maxSpacingError = 0;   ///< |spacing of neighbouring lines - width| (mm)
  double maxLineDeviation = 0;  ///< distance of a vertex from its straight line (mm)
};

/// Every layer of the box is the rectangular grid of lines y = 40 - φ^α_j, x = 40 - φ^β_k.
GridReport expectRectangularGrid(const LatticeGraph& g, double width, double alphaPhase,
                                 double betaPhase) {
  GridReport r;
  const int na = interiorLevels(width, alphaPhase), nb = interiorLevels(width, betaPhase);
  const StructureReport s = checkStructure(g, 1e-9);
  EXPECT_EQ(s.irregularVertices, 0);
  EXPECT_EQ(g.stats.irregularVertices, 0);
  EXPECT_EQ(s.duplicateVertices, 0);
  EXPECT_EQ(s.zeroLengthEdges, 0);
  EXPECT_EQ(s.oddBoundaryHitSubgraphs, 0);
  const int L = static_cast<int>(g.layerValues.size());
  r.layers = L;
  for (int l = 0; l < L; ++l) {
    EXPECT_EQ(g.layerSubgraphOffset[l + 1] - g.layerSubgraphOffset[l], 1) << "layer " << l;
    std::set<std::pair<int, int>> crossings;
    std::map<int, double> alphaLineY, betaLineX;
    int hits = 0;
    double isolineLength = 0, boundaryLength = 0;
    for (int v = g.layerVertexOffset[l]; v < g.layerVertexOffset[l + 1]; ++v) {
      EXPECT_NEAR(g.points[v].z(), g.layerValues[l], 1e-9);
      EXPECT_EQ(g.gamma[v], g.layerValues[l]);
      if (g.vertexKind[v] == LatticeVertexKind::Crossing) {
        EXPECT_TRUE(crossings.insert({g.alphaLevel[v], g.betaLevel[v]}).second)
            << "two crossings of the same lines";
        EXPECT_NEAR(g.points[v].x(), 40 - g.betaLevels[g.betaLevel[v]], 1e-9);
        EXPECT_NEAR(g.points[v].y(), 40 - g.alphaLevels[g.alphaLevel[v]], 1e-9);
      }
      hits += g.vertexKind[v] == LatticeVertexKind::BoundaryHit;
    }
    // The lines: every α-edge lies on y = 40 - its level, every β-edge on x = 40 - its level.
    for (int e = g.layerEdgeOffset[l]; e < g.layerEdgeOffset[l + 1]; ++e) {
      const Vec3& p = g.points[g.edges[e][0]];
      const Vec3& q = g.points[g.edges[e][1]];
      if (g.edgeKind[e] == LatticeEdgeKind::Alpha) {
        const double y = 40 - g.alphaLevels[g.edgeLevel[e]];
        r.maxLineDeviation =
            std::max({r.maxLineDeviation, std::abs(p.y() - y), std::abs(q.y() - y)});
        alphaLineY[g.edgeLevel[e]] = y;
      } else if (g.edgeKind[e] == LatticeEdgeKind::Beta) {
        const double x = 40 - g.betaLevels[g.edgeLevel[e]];
        r.maxLineDeviation =
            std::max({r.maxLineDeviation, std::abs(p.x() - x), std::abs(q.x() - x)});
        betaLineX[g.edgeLevel[e]] = x;
      }
      (g.edgeKind[e] == LatticeEdgeKind::Boundary ? boundaryLength : isolineLength) +=
          (q - p).norm();
    }
    const int nc = static_cast<int>(crossings.size());
    r.crossingsPerLayer = l == 0 ? nc : (r.crossingsPerLayer == nc ? nc : -1);
    EXPECT_EQ(nc, na * nb) << "layer " << l;
    EXPECT_EQ(hits, 2 * na + 2 * nb) << "layer " << l;
    EXPECT_EQ(static_cast<int>(alphaLineY.size()), na);
    EXPECT_EQ(static_cast<int>(betaLineX.size()), nb);
    EXPECT_NEAR(isolineLength, 40.0 * (na + nb), 1e-9) << "layer " << l;
    EXPECT_NEAR(boundaryLength, 160.0, 1e-9) << "layer " << l;
    for (const auto* lines : {&alphaLineY, &betaLineX}) {
      std::vector<double> pos;
      for (const auto& [k, c] : *lines)
        pos.push_back(c);
      std::sort(pos.begin(), pos.end());
      for (size_t i = 1; i < pos.size(); ++i) {
        r.maxSpacingError = std::max(r.maxSpacingError, std::abs(pos[i] - pos[i - 1] - width));
      }
    }
  }
  EXPECT_LT(r.maxLineDeviation, 1e-9);
  EXPECT_LT(r.maxSpacingError, 0.01 * width);
  return r;
}

void printGrid(const char* name, const GridReport& r, const LatticeGraph& g) {
  std::printf(
      "[lattice] %s: %d layers, crossings/layer %d, spacing error %.2e mm, line deviation %.2e mm, "
      "V %zu E %zu, point crossings %d, edge crossings %d, boundary segments %d, touching %d, "
      "merged diagonal points %d\n",
      name, r.layers, r.crossingsPerLayer, r.maxSpacingError, r.maxLineDeviation, g.points.size(),
      g.edges.size(), g.stats.pointCrossings, g.stats.edgeCrossings, g.stats.boundarySegments,
      g.stats.touchingSegments, g.stats.mergedDiagonalPoints);
}

/// A hand-made layer set: each layer is a union of axis-aligned rectangles triangulated as
/// regular grids (squares split along the (1,1) diagonal), at z = layer index.
struct Rect {
  double x0, y0, w, h;
  int nx, ny;
};

CurvedLayers gridLayers(const std::vector<std::vector<Rect>>& spec, const Field& alpha,
                        const Field& beta) {
  CurvedLayers c;
  c.layerPointOffset.push_back(0);
  c.layerTriangleOffset.push_back(0);
  for (size_t l = 0; l < spec.size(); ++l) {
    for (const Rect& r : spec[l]) {
      const int base = static_cast<int>(c.points.size());
      for (int j = 0; j <= r.ny; ++j) {
        for (int i = 0; i <= r.nx; ++i) {
          const Vec3 p(r.x0 + i * (r.w / r.nx), r.y0 + j * (r.h / r.ny), static_cast<double>(l));
          c.points.push_back(p);
          c.alpha.push_back(alpha(p));
          c.beta.push_back(beta(p));
          c.normals.push_back(Vec3::UnitZ());
          c.pointLayer.push_back(static_cast<int>(l));
        }
      }
      auto id = [&](int i, int j) {
        return base + i + (r.nx + 1) * j;
      };
      for (int j = 0; j < r.ny; ++j) {
        for (int i = 0; i < r.nx; ++i) {
          c.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
          c.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
          c.triangleLayer.push_back(static_cast<int>(l));
          c.triangleLayer.push_back(static_cast<int>(l));
        }
      }
    }
    c.layerPointOffset.push_back(static_cast<int>(c.points.size()));
    c.layerTriangleOffset.push_back(static_cast<int>(c.triangles.size()));
    c.layerValues.push_back(static_cast<double>(l));
    c.layerIndex.push_back(static_cast<int>(l));
  }
  return c;
}

LatticeOptions phases(double a, double b) {
  LatticeOptions o;
  o.alphaPhase = a;
  o.betaPhase = b;
  return o;
}

/// The lattice at phases (a, b) of the 20 x 20 x 30 mm box sliced at mid-cell heights (2 mm
/// cells, layers at t = 0.5: 30 of them), checked as a rectangular 4 mm grid and printed under
/// `label`.
struct BoxGrid {
  LatticeGraph graph;
  GridReport report;
};
BoxGrid midCellBoxGrid(double a, double b, const char* label) {
  const CurvedLayers layers = sliceBox(boxFields(20, 20, 30, kAlphaOfBox, kBetaOfBox), 2.0, 1.0);
  EXPECT_EQ(layers.layerValues.size(), 30u);
  BoxGrid grid{buildLatticeGraph(layers, phases(a, b)), {}};
  grid.report = expectRectangularGrid(grid.graph, 4.0, a, b);
  printGrid(label, grid.report, grid.graph);
  return grid;
}

}  // namespace

// Layers through the tet vertices (z = 4k with 4 mm cells): every layer mesh is the 10 x 10 grid
// of the cell faces and every isoline runs along layer-mesh edges through layer points.
TEST(LatticeInfill, BoxGridWithIsolinesAlongLayerMeshEdges) {
  const BoxFields b = boxFields(10, 10, 15, kAlphaOfBox, kBetaOfBox);
  const CurvedLayers layers = sliceBox(b, 4.0, 4.0);
  ASSERT_EQ(layers.layerValues.size(), 15u);
  const LatticeGraph g = buildLatticeGraph(layers);
  const GridReport r = expectRectangularGrid(g, 4.0, 0.0, 0.0);
  printGrid("box, levels on layer points and edges", r, g);
  EXPECT_EQ(r.crossingsPerLayer, 81);
  EXPECT_EQ(g.stats.pointCrossings, 81 * 15);  // every crossing is an exact hit at a layer point
  EXPECT_GT(g.stats.boundarySegments, 0);  // α = 40 (y = 0) and β = 40 (x = 0) lie on the boundary
  EXPECT_EQ(g.stats.crossings, 81 * 15);
  EXPECT_EQ(g.stats.boundaryHits, 36 * 15);
}

// Layers at mid-cell heights (t = 0.5 exactly, 2 mm cells): levels y = 4k hit layer points.
TEST(LatticeInfill, BoxGridWithLevelsThroughLayerPoints) {
  const auto [g, r] = midCellBoxGrid(0.0, 0.0, "box, mid-cell layers, levels through layer points");
  EXPECT_EQ(r.crossingsPerLayer, 81);
  EXPECT_GT(g.stats.pointCrossings, 0);
}

// With phases the levels miss every layer point and edge: 10 x 10 lines.
TEST(LatticeInfill, BoxGridWithPhaseAvoidingExactHits) {
  const auto [g, r] = midCellBoxGrid(1.3, 2.1, "box, phase (1.3, 2.1)");
  EXPECT_EQ(r.crossingsPerLayer, 100);
  EXPECT_EQ(g.stats.pointCrossings, 0);
  EXPECT_EQ(g.stats.edgeCrossings, 0);
  EXPECT_EQ(g.stats.touchingSegments + g.stats.boundarySegments + g.stats.ridgeSegments, 0);
  EXPECT_GT(g.stats.mergedDiagonalPoints, 0);
}

// α-lines along layer-mesh edges (phase 0), β-lines through edge interiors (phase 1.3): each
// crossing is the β-point on the edge the α-segment runs along.
TEST(LatticeInfill, BoxGridWithOneFieldAlongEdgesAndTheOtherGeneric) {
  for (const auto& [pa, pb] : {std::pair{0.0, 1.3}, std::pair{1.3, 0.0}}) {
    const auto [g, r] =
        midCellBoxGrid(pa, pb, pa == 0 ? "box, phase (0, 1.3)" : "box, phase (1.3, 0)");
    EXPECT_EQ(r.crossingsPerLayer, 90);
    EXPECT_EQ(g.stats.pointCrossings, 0);
  }
}

// Phase 1: the crossings (odd x, odd y) are the centres of the 2 mm cells, which are layer points
// (midpoints of the Kuhn cells' main diagonals).
TEST(LatticeInfill, BoxGridWithCrossingsOnInteriorLayerPoints) {
  const auto [g, r] = midCellBoxGrid(1.0, 1.0, "box, phase (1, 1)");
  EXPECT_EQ(r.crossingsPerLayer, 100);
  EXPECT_EQ(g.stats.pointCrossings, 100 * 30);
}

// Hand-made grid of 2 mm squares split along (1,1): with phase 1 every crossing lies at the
// middle of a diagonal edge, where the α- and β-point coincide exactly (one vertex).
TEST(LatticeInfill, CrossingsExactlyOnLayerMeshEdgesAreOneVertex) {
  const CurvedLayers layers =
      gridLayers({{{0, 0, 40, 40, 20, 20}}, {{0, 0, 40, 40, 20, 20}}}, kAlphaOfBox, kBetaOfBox);
  const LatticeGraph g = buildLatticeGraph(layers, phases(1.0, 1.0));
  const GridReport r = expectRectangularGrid(g, 4.0, 1.0, 1.0);
  printGrid("grid, crossings on diagonal edges", r, g);
  EXPECT_EQ(r.crossingsPerLayer, 100);
  EXPECT_EQ(g.stats.edgeCrossings, 200);
}

// Removing the points on the quad diagonals changes neither the crossings nor the lines, and
// leaves exactly the paper's vertices: one per (tet face cut by the layer, level crossing it).
TEST(LatticeInfill, QuadDiagonalPointsAreMergedIntoThePapersGraph) {
  const BoxFields b = boxFields(20, 20, 30, kAlphaOfBox, kBetaOfBox);
  const CurvedLayers layers = sliceBox(b, 2.0, 1.0);
  LatticeOptions keep = phases(1.3, 2.1), merge = keep;
  keep.mergeQuadDiagonalPoints = false;
  const LatticeGraph gk = buildLatticeGraph(layers, keep);
  const LatticeGraph gm = buildLatticeGraph(layers, merge);
  EXPECT_EQ(gk.stats.mergedDiagonalPoints, 0);
  EXPECT_GT(gm.stats.mergedDiagonalPoints, 0);
  EXPECT_EQ(gk.points.size(), gm.points.size() + gm.stats.mergedDiagonalPoints);
  EXPECT_EQ(gk.edges.size(), gm.edges.size() + gm.stats.mergedDiagonalPoints);
  EXPECT_EQ(gk.stats.crossings, gm.stats.crossings);
  double lk = 0, lm = 0;
  for (const auto& s : gk.subgraphs)
    lk += s.length;
  for (const auto& s : gm.subgraphs)
    lm += s.length;
  EXPECT_NEAR(lk, lm, 1e-9 * lk);
  long onFaces = 0;
  for (size_t v = 0; v < gm.points.size(); ++v) {
    onFaces += gm.vertexKind[v] == LatticeVertexKind::IsolinePoint ||
               gm.vertexKind[v] == LatticeVertexKind::BoundaryHit;
  }
  EXPECT_EQ(onFaces, paperFacePointCount(b.mesh, b.gamma, b.alpha, b.beta, gm));
  std::printf(
      "[lattice] diagonal merge: %zu -> %zu vertices, %ld isoline points on tet faces (paper "
      "count)\n",
      gk.points.size(), gm.points.size(), onFaces);
}

// α = 20 - |y - 20| has a ridge at y = 20 where it equals the level 20 exactly: both triangles
// along the ridge would emit the segment; the touch is dropped and every other level appears twice.
TEST(LatticeInfill, RidgeAtALevelIsDropped) {
  const Field ridge = [](const Vec3& p) {
    return 20 - std::abs(p.y() - 20);
  };
  const CurvedLayers layers = gridLayers({{{0, 0, 40, 40, 20, 20}}}, ridge, kBetaOfBox);
  const LatticeGraph g = buildLatticeGraph(layers);
  const StructureReport s = checkStructure(g, 1e-9);
  EXPECT_EQ(s.irregularVertices, 0);
  EXPECT_EQ(s.duplicateVertices, 0);
  EXPECT_EQ(g.stats.ridgeSegments, 2 * 20);  // 20 edges along y = 20, each from both sides
  std::set<double> alphaLines;
  for (size_t e = 0; e < g.edges.size(); ++e) {
    if (g.edgeKind[e] == LatticeEdgeKind::Alpha) {
      alphaLines.insert(g.points[g.edges[e][0]].y());
      alphaLines.insert(g.points[g.edges[e][1]].y());
    }
  }
  EXPECT_EQ(alphaLines, (std::set<double>{4, 8, 12, 16, 24, 28, 32, 36}));
  EXPECT_EQ(g.stats.crossings, 8 * 9);
}

// A documented exception to the degree rules: α = 100 + ((x - 20)^2 - (y - 20)^2) / 100 equals
// the level 100 on the two diagonals through the saddle point (20, 20), a layer point whose link
// alternates above / below twice: that isoline point has degree 4 and is counted as irregular.
// (With the saddle's zero lines along the axes instead, the (1,1)-split grid resolves it: the
// isolines cut the corner along a mesh diagonal and every degree is regular.)
TEST(LatticeInfill, LevelThroughASaddlePointIsCountedAsIrregular) {
  const Field saddle = [](const Vec3& p) {
    return 100 + 0.01 * ((p.x() - 20) * (p.x() - 20) - (p.y() - 20) * (p.y() - 20));
  };
  const CurvedLayers layers = gridLayers({{{0, 0, 40, 40, 20, 20}}}, saddle, kBetaOfBox);
  const LatticeGraph g = buildLatticeGraph(layers, phases(0.0, 1.3));
  const StructureReport s = checkStructure(g, 1e-9);
  EXPECT_EQ(s.irregularVertices, 1);
  EXPECT_EQ(g.stats.irregularVertices, 1);
  EXPECT_EQ(s.duplicateVertices, 0);
  EXPECT_EQ(s.oddBoundaryHitSubgraphs, 0);
  int found = 0;
  for (size_t v = 0; v < g.points.size(); ++v) {
    if (g.vertexKind[v] == LatticeVertexKind::IsolinePoint && g.degree[v] == 4) {
      ++found;
      EXPECT_EQ(g.points[v], Vec3(20, 20, 0));
    }
  }
  EXPECT_EQ(found, 1);
  EXPECT_EQ(g.stats.crossings, 20);     // each β-line crosses both diagonals
  EXPECT_EQ(g.stats.boundaryHits, 24);  // 4 arms of the α-cross + 2 x 10 β-ends
  EXPECT_GT(g.stats.touchingSegments, 0);
}

// β-isolines at 0.057° to the α-isolines, on a mesh (37 x 37 squares) whose rows miss the levels: each β-line
// crosses one α-line inside a thin sliver of a triangle; the crossing is found once, inside.
TEST(LatticeInfill, NearlyParallelIsolinesCrossOnce) {
  const Field alpha = [](const Vec3& p) {
    return p.y();
  };
  const Field beta = [](const Vec3& p) {
    return p.y() + 0.001 * p.x();
  };
  const CurvedLayers layers = gridLayers({{{0, 0, 40, 40, 37, 37}}}, alpha, beta);
  const LatticeGraph g = buildLatticeGraph(layers, phases(2.0, 2.02));
  const StructureReport s = checkStructure(g, 1e-12);
  EXPECT_EQ(s.irregularVertices, 0);
  EXPECT_EQ(s.duplicateVertices, 0);
  EXPECT_EQ(s.oddBoundaryHitSubgraphs, 0);
  const GeometryReport geo = checkGeometry(g, layers, 1e-12);
  EXPECT_EQ(geo.intersectingEdgePairs, 0);
  EXPECT_LT(geo.maxLevelError, 1e-9);
  EXPECT_EQ(g.stats.crossings, 10);  // β = 4k + 2.02 crosses α = 4k + 2 at x = 20, k = 0..9
  EXPECT_EQ(g.stats.boundaryHits, 40);
  for (size_t v = 0; v < g.points.size(); ++v) {
    if (g.vertexKind[v] == LatticeVertexKind::Crossing) {
      EXPECT_NEAR(g.points[v].x(), 20.0, 1e-6);
      EXPECT_NEAR(g.points[v].y(), g.alphaLevels[g.alphaLevel[v]], 1e-9);
    }
  }
  std::printf(
      "[lattice] nearly parallel lines: %d crossings, min separation of disjoint edges %.3g mm\n",
      g.stats.crossings, geo.minSeparation);
}

// Two parts in one layer: a 40 x 40 square and a 2 x 2 square (no isoline, boundary only).
TEST(LatticeInfill, SubgraphsAndMinimumLength) {
  const std::vector<std::vector<Rect>> spec = {{{0, 0, 40, 40, 20, 20}, {50, 0, 2, 2, 2, 2}}};
  const CurvedLayers layers = gridLayers(spec, kAlphaOfBox, kBetaOfBox);
  const LatticeGraph all = buildLatticeGraph(layers, phases(1.3, 2.1));
  ASSERT_EQ(all.subgraphs.size(), 2u);
  const LatticeSubgraph& big = all.subgraphs[0];
  const LatticeSubgraph& small = all.subgraphs[1];
  EXPECT_EQ(big.crossingCount, 100);
  EXPECT_EQ(big.boundaryHitCount, 40);
  EXPECT_NEAR(big.length, 160 + 20 * 40, 1e-9);
  // Boundary (160 mm around (20, 20)), α-lines y = 38.7 - 4k (mean 20.7), β-lines x = 37.9 - 4k (mean 19.9).
  EXPECT_NEAR(big.centroid.x(), (160 * 20 + 400 * 20 + 400 * 19.9) / 960, 1e-9);
  EXPECT_NEAR(big.centroid.y(), (160 * 20 + 400 * 20.7 + 400 * 20) / 960, 1e-9);
  ASSERT_EQ(big.boundaryLoops.size(), 1u);
  EXPECT_EQ(big.boundaryLoops[0].vertices.size(),
            20u * 4 + 40);  // grid points + hits on the boundary
  EXPECT_EQ(small.isolineEdgeCount, 0);
  EXPECT_NEAR(small.length, 8.0, 1e-12);
  EXPECT_EQ(small.boundaryLoops.size(), 1u);
  EXPECT_EQ(all.stats.droppedSubgraphs, 0);

  LatticeOptions o = phases(1.3, 2.1);
  o.minimumSubgraphLength = 10;
  const LatticeGraph kept = buildLatticeGraph(layers, o);
  EXPECT_EQ(kept.subgraphs.size(), 1u);
  EXPECT_EQ(kept.stats.droppedSubgraphs, 1);
  EXPECT_NEAR(kept.stats.droppedLength, 8.0, 1e-12);
  EXPECT_EQ(kept.points.size(), all.points.size() - static_cast<size_t>(small.vertexCount));
  EXPECT_EQ(checkStructure(kept, 1e-9).irregularVertices, 0);
}

// Threads only distribute the layers: the graph is the same with 1 and 2 threads.
TEST(LatticeInfill, ThreadCountDoesNotChangeTheGraph) {
  const BoxFields b = boxFields(20, 20, 30, kAlphaOfBox, kBetaOfBox);
  const CurvedLayers layers = sliceBox(b, 2.0, 1.0);
  LatticeOptions one = phases(1.3, 2.1), two = one;
  one.threads = 1;
  two.threads = 2;
  const LatticeGraph a = buildLatticeGraph(layers, one);
  const LatticeGraph c = buildLatticeGraph(layers, two);
  ASSERT_EQ(a.points.size(), c.points.size());
  ASSERT_EQ(a.edges, c.edges);
  for (size_t v = 0; v < a.points.size(); ++v) {
    ASSERT_EQ(a.points[v], c.points[v]);
  }
}

TEST(LatticeInfill, ProgressAndAbort) {
  const BoxFields b = boxFields(10, 10, 15, kAlphaOfBox, kBetaOfBox);
  const CurvedLayers layers = sliceBox(b, 4.0, 4.0);
  LatticeOptions o;
  o.threads = 1;
  std::vector<double> progress;
  o.progress = [&](double f) {
    progress.push_back(f);
  };
  buildLatticeGraph(layers, o);
  ASSERT_EQ(progress.size(), layers.layerValues.size());
  EXPECT_DOUBLE_EQ(progress.back(), 1.0);
  o.shouldAbort = [] {
    return true;
  };
  EXPECT_NE(errorOf([&] { buildLatticeGraph(layers, o); }).find("aborted"), std::string::npos);
}

// Graded lattice: half the width where y < 20 (α > 20). α-lines: 2 mm apart there, 4 mm above;
// β-lines take the smallest scale along each line (0.5 everywhere): 2 mm apart.
TEST(LatticeInfill, GradedLatticeFollowsTheWidthScale) {
  const BoxFields b = boxFields(20, 20, 30, kAlphaOfBox, kBetaOfBox);
  const CurvedLayers layers = sliceBox(b, 2.0, 1.0);
  LatticeOptions o = phases(1.0, 1.0);
  for (const Vec3& p : layers.points) {
    o.widthScale.push_back(p.y() < 20 ? 0.5 : 1.0);
  }
  const LatticeGraph g = buildLatticeGraph(layers, o);
  const StructureReport s = checkStructure(g, 1e-9);
  EXPECT_EQ(s.irregularVertices, 0);
  std::vector<double> alphaY, betaX;
  for (double c : g.alphaLevels) {
    if (c > 0 && c < 40)
      alphaY.push_back(40 - c);
  }
  for (double c : g.betaLevels) {
    if (c > 0 && c < 40)
      betaX.push_back(40 - c);
  }
  std::sort(alphaY.begin(), alphaY.end());
  std::sort(betaX.begin(), betaX.end());
  double worst = 0;
  for (size_t i = 1; i < alphaY.size(); ++i) {
    const double gap = alphaY[i] - alphaY[i - 1];
    if (alphaY[i] < 18) {
      worst = std::max(worst, std::abs(gap - 2) / 2);
    } else if (alphaY[i - 1] > 19.9) {
      worst = std::max(worst, std::abs(gap - 4) / 4);
    }
  }
  for (size_t i = 1; i < betaX.size(); ++i) {
    worst = std::max(worst, std::abs(betaX[i] - betaX[i - 1] - 2) / 2);
  }
  EXPECT_LT(worst, 0.01);
  EXPECT_EQ(betaX.size(), 20u);  // 0.5, 2.5, .., 39.5
  EXPECT_EQ(std::count_if(alphaY.begin(), alphaY.end(), [](double y) { return y < 18; }),
            9);  // 1.25, .., 17.25
  EXPECT_EQ(std::count_if(alphaY.begin(), alphaY.end(), [](double y) { return y > 19.9; }),
            5);  // 23, 27, .., 39
  // Every layer: crossings = α-lines x β-lines.
  EXPECT_EQ(g.stats.crossings, static_cast<int>(alphaY.size() * betaX.size()) * 30);
  std::printf(
      "[lattice] graded: %zu α-lines (2 mm below y = 20, 4 mm above), %zu β-lines, worst spacing "
      "error %.2g %%\n",
      alphaY.size(), betaX.size(), 100 * worst);
}

TEST(LatticeLevels, UniformLevels) {
  EXPECT_EQ(uniformLatticeLevels(0, 12, 4, 0),
            (std::vector<double>{4, 8, 12}));  // 0 = min is left out
  EXPECT_EQ(uniformLatticeLevels(-1, 12, 4, 0), (std::vector<double>{0, 4, 8, 12}));
  EXPECT_EQ(uniformLatticeLevels(0, 12, 4, 1.5), (std::vector<double>{1.5, 5.5, 9.5}));
  EXPECT_EQ(uniformLatticeLevels(0, 12, 4, -2.5), (std::vector<double>{1.5, 5.5, 9.5}));
  EXPECT_TRUE(uniformLatticeLevels(0, 40, 1000, 0).empty());
  EXPECT_TRUE(uniformLatticeLevels(3, 3, 4, 0).empty());
  EXPECT_THROW(uniformLatticeLevels(0, 1, 0, 0), GeoLatticeError);
  EXPECT_THROW(uniformLatticeLevels(0, 1, -4, 0), GeoLatticeError);
  EXPECT_THROW(uniformLatticeLevels(0, 1, std::nan(""), 0), GeoLatticeError);
  EXPECT_THROW(uniformLatticeLevels(0, 1e9, 1e-3, 0), GeoLatticeError);  // 1e12 levels
}

TEST(LatticeLevels, GradedLevelsWithUnitScaleAreTheUniformOnes) {
  std::vector<double> f, s;
  for (int i = 0; i <= 400; ++i) {
    f.push_back(0.1 * i);
    s.push_back(1.0);
  }
  const auto graded = gradedLatticeLevels(f, s, 4, 1.3);
  const auto uniform = uniformLatticeLevels(0, 40, 4, 1.3);
  ASSERT_EQ(graded.size(), uniform.size());
  for (size_t i = 0; i < graded.size(); ++i) {
    EXPECT_NEAR(graded[i], uniform[i], 1e-9);
  }
  std::fill(s.begin(), s.end(), 0.25);
  const auto dense = gradedLatticeLevels(f, s, 4, 0);
  ASSERT_EQ(dense.size(), 40u);
  EXPECT_NEAR(dense[0], 1.0, 1e-9);
  EXPECT_NEAR(dense[1] - dense[0], 1.0, 1e-9);
  s[7] = 0;
  EXPECT_NE(errorOf([&] { gradedLatticeLevels(f, s, 4, 0); }).find("point 7"), std::string::npos);
  s[7] = std::nan("");
  EXPECT_THROW(gradedLatticeLevels(f, s, 4, 0), GeoLatticeError);
  s.pop_back();
  EXPECT_THROW(gradedLatticeLevels(f, s, 4, 0), GeoLatticeError);
}

TEST(LatticeInfill, WidthLargerThanThePartGivesAnEmptyLattice) {
  const CurvedLayers layers = gridLayers({{{0, 0, 40, 40, 20, 20}}}, kAlphaOfBox, kBetaOfBox);
  LatticeOptions o;
  o.alphaWidth = o.betaWidth = 1000;
  const LatticeGraph g = buildLatticeGraph(layers, o);
  EXPECT_EQ(g.stats.isolineEdges, 0);
  EXPECT_EQ(g.stats.crossings, 0);
  EXPECT_EQ(g.stats.boundaryHits, 0);
  ASSERT_EQ(g.subgraphs.size(), 1u);  // the layer boundary alone remains
  EXPECT_NEAR(g.subgraphs[0].length, 160.0, 1e-9);
}

// The size estimate bounds the real graph from above, not by much, and refuses a runaway width
// before anything is built.
TEST(LatticeInfill, SizeEstimateBoundsTheGraphAndRefusesRunawayWidths) {
  const BoxFields b = boxFields(20, 20, 30, kAlphaOfBox, kBetaOfBox);
  const CurvedLayers layers = sliceBox(b, 2.0, 1.0);
  for (const double w : {1.0, 2.0, 4.0}) {
    LatticeOptions o = phases(0.3, 0.7);
    o.alphaWidth = o.betaWidth = w;
    const LatticeGraph g = buildLatticeGraph(layers, o);
    const double actual = static_cast<double>(g.points.size() + g.edges.size());
    const double estimate = estimateLatticeSize(layers, g.alphaLevels, g.betaLevels).elements();
    EXPECT_GE(estimate, 0.5 * actual) << w;
    EXPECT_LE(estimate, 4.0 * actual) << w;
  }
  LatticeOptions tiny;
  tiny.alphaWidth = tiny.betaWidth = 0.001;
  const std::string message = errorOf([&] { buildLatticeGraph(layers, tiny); });
  EXPECT_NE(message.find("million vertices and edges"), std::string::npos) << message;
  EXPECT_NE(message.find("limit of 40 million"), std::string::npos) << message;
  LatticeOptions bounded = phases(0.3, 0.7);
  bounded.maxElements = 100;
  EXPECT_NE(errorOf([&] { buildLatticeGraph(layers, bounded); }).find("limit"), std::string::npos);
}

TEST(LatticeInfill, BadInputIsReported) {
  const CurvedLayers good = gridLayers({{{0, 0, 8, 8, 2, 2}}}, kAlphaOfBox, kBetaOfBox);
  LatticeOptions o;
  o.alphaWidth = 0;
  EXPECT_NE(errorOf([&] { buildLatticeGraph(good, o); }).find("width must be > 0"),
            std::string::npos);
  o = LatticeOptions{};
  o.betaWidth = -1;
  EXPECT_THROW(buildLatticeGraph(good, o), GeoLatticeError);
  o = LatticeOptions{};
  o.alphaPhase = std::nan("");
  EXPECT_THROW(buildLatticeGraph(good, o), GeoLatticeError);
  o = LatticeOptions{};
  o.minimumSubgraphLength = -1;
  EXPECT_THROW(buildLatticeGraph(good, o), GeoLatticeError);
  o = LatticeOptions{};
  o.widthScale = {1.0, 2.0};
  EXPECT_NE(errorOf([&] { buildLatticeGraph(good, o); }).find("width scale has 2 values"),
            std::string::npos);

  CurvedLayers bad = good;
  bad.alpha.pop_back();
  EXPECT_THROW(buildLatticeGraph(bad), GeoLatticeError);
  bad = good;
  bad.beta[3] = std::nan("");
  EXPECT_NE(errorOf([&] { buildLatticeGraph(bad); }).find("point 3"), std::string::npos);
  bad = good;
  bad.triangles[1][2] = bad.triangles[1][0];
  EXPECT_NE(errorOf([&] { buildLatticeGraph(bad); }).find("triangle 1 uses a point twice"),
            std::string::npos);
  bad = good;
  bad.triangles[0][0] = 100;
  EXPECT_THROW(buildLatticeGraph(bad), GeoLatticeError);
  bad = good;
  bad.layerPointOffset.back() = 3;
  EXPECT_THROW(buildLatticeGraph(bad), GeoLatticeError);
  // A third triangle on an edge: not edge-manifold.
  bad = good;
  bad.triangles.push_back({0, 4, 2});  // (0, 4) is the diagonal of the first square
  bad.triangleLayer.push_back(0);
  bad.layerTriangleOffset.back() += 1;
  EXPECT_NE(errorOf([&] { buildLatticeGraph(bad); }).find("not edge-manifold"), std::string::npos);
  // No layers at all: an empty graph, not an error.
  CurvedLayers empty;
  empty.layerPointOffset = {0};
  empty.layerTriangleOffset = {0};
  const LatticeGraph none = buildLatticeGraph(empty);
  EXPECT_TRUE(none.points.empty());
}
