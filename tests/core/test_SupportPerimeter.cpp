// The support perimeter (core/toolpath/SupportPerimeter.h) on hand-built flat layers: a strip of
// the given width with α-isolines across it every millimetre, its boundary a rectangle.
#include "toolpath/SupportPerimeter.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace geolattice;

namespace {

/// One layer at z = 0, normals +z: the rectangle [0, length] x [0, width] with an isoline across
/// at every integer x in (0, length). Every edge is kept (nothing trimmed).
LatticeGraph strip(int length, double width) {
  LatticeGraph g;
  auto vertex = [&](double x, double y) {
    g.points.emplace_back(x, y, 0.0);
    g.normals.emplace_back(0.0, 0.0, 1.0);
    g.vertexSubgraph.push_back(0);
    return static_cast<int>(g.points.size()) - 1;
  };
  auto edge = [&](int a, int b, LatticeEdgeKind kind) {
    g.edges.push_back({a, b});
    g.edgeKind.push_back(kind);
    g.edgeSubgraph.push_back(0);
  };
  std::vector<int> bottom, top;
  for (int x = 0; x <= length; ++x) {
    bottom.push_back(vertex(x, 0.0));
    top.push_back(vertex(x, width));
  }
  for (int x = 0; x < length; ++x) {
    edge(bottom[x], bottom[x + 1], LatticeEdgeKind::Boundary);
    edge(top[x], top[x + 1], LatticeEdgeKind::Boundary);
  }
  edge(bottom[0], top[0], LatticeEdgeKind::Boundary);
  edge(bottom[length], top[length], LatticeEdgeKind::Boundary);
  for (int x = 1; x < length; ++x) {
    edge(bottom[x], top[x], LatticeEdgeKind::Alpha);
  }
  return g;
}

/// The smallest and largest y of the perimeter points of the vertices along the long sides
/// (a corner's point is offset along the bisector of its two sides).
std::pair<double, double> yRange(const LatticeGraph& g, const PerimeterResult& r, int length) {
  double lo = 1e9, hi = -1e9;
  for (const PerimeterLoop& loop : r.loops) {
    for (size_t i = 0; i < loop.points.size(); ++i) {
      const double x = g.points[loop.nearVertex[i]].x();
      if (x > 0 && x < length) {
        lo = std::min(lo, loop.points[i].y());
        hi = std::max(hi, loop.points[i].y());
      }
    }
  }
  return {lo, hi};
}

}  // namespace

TEST(SupportPerimeter, WideRegionIsOffsetByThePathWidth) {
  const LatticeGraph g = strip(10, 5.0);
  const PerimeterResult r = supportPerimeters(g, std::vector<char>(g.edges.size(), 1), 0.6, 1.2);
  ASSERT_EQ(r.loops.size(), 1u);
  const auto [lo, hi] = yRange(g, r, 10);
  EXPECT_NEAR(lo, 0.6, 1e-9);
  EXPECT_NEAR(hi, 5.0 - 0.6, 1e-9);
}

// A layer region narrower than two path widths (a sliver where a layer meets the surface almost
// tangentially): offset by the full width the perimeter would lie beyond the far side, outside
// the part; it runs along the middle instead.
TEST(SupportPerimeter, NarrowRegionKeepsThePerimeterInside) {
  const double width = 0.2;
  const LatticeGraph g = strip(10, width);
  const PerimeterResult r = supportPerimeters(g, std::vector<char>(g.edges.size(), 1), 0.6, 1.2);
  ASSERT_EQ(r.loops.size(), 1u);
  const auto [lo, hi] = yRange(g, r, 10);
  EXPECT_GE(lo, 0.0);
  EXPECT_LE(hi, width);
  EXPECT_NEAR(lo, 0.5 * width, 1e-9);
  EXPECT_NEAR(hi, 0.5 * width, 1e-9);
}

TEST(SupportPerimeter, BadInput) {
  LatticeGraph g = strip(3, 1.0);
  const std::vector<char> kept(g.edges.size(), 1);
  EXPECT_THROW(supportPerimeters(g, kept, 0.0, 1.2), GeoLatticeError);
  EXPECT_THROW(supportPerimeters(g, std::vector<char>(2, 1), 0.6, 1.2), GeoLatticeError);
  g.edgeSubgraph.pop_back();
  EXPECT_THROW(supportPerimeters(g, kept, 0.6, 1.2), GeoLatticeError);
}
