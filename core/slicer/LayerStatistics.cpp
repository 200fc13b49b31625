#include "slicer/LayerStatistics.h"

#include "common/ParallelFor.h"
#include "common/Progress.h"
#include "common/UnionFind.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace geolattice {

namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using Triangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 toPoint(const Vec3& p) {
  return {p.x(), p.y(), p.z()};
}
}  // namespace

int layerComponents(const CurvedLayers& layers, int l, std::vector<int>& triangleComponent) {
  const int p0 = layers.layerPointOffset[l], np = layers.layerPointOffset[l + 1] - p0;
  UnionFind sets(np);
  const int t0 = layers.layerTriangleOffset[l], t1 = layers.layerTriangleOffset[l + 1];
  for (int k = t0; k < t1; ++k) {
    const auto& t = layers.triangles[k];
    sets.unite(t[0] - p0, t[1] - p0);
    sets.unite(t[0] - p0, t[2] - p0);
  }
  // Number the components by first use in triangle order.
  std::vector<int> label(np, -1);
  int count = 0;
  triangleComponent.resize(t1 - t0);
  for (int k = t0; k < t1; ++k) {
    const int r = sets.find(layers.triangles[k][0] - p0);
    if (label[r] < 0) {
      label[r] = count++;
    }
    triangleComponent[k - t0] = label[r];
  }
  return count;
}

namespace {
/// The triangles of layer l as CGAL triangles.
std::vector<Triangle> layerTriangles(const CurvedLayers& layers, int l) {
  std::vector<Triangle> out;
  out.reserve(layers.layerTriangleOffset[l + 1] - layers.layerTriangleOffset[l]);
  for (int k = layers.layerTriangleOffset[l]; k < layers.layerTriangleOffset[l + 1]; ++k) {
    const auto& t = layers.triangles[k];
    out.emplace_back(toPoint(layers.points[t[0]]), toPoint(layers.points[t[1]]),
                     toPoint(layers.points[t[2]]));
  }
  return out;
}

/// Spacing of layer l to layer l + 1 (min, mean, max of the point-to-surface distances of
/// layer l's points); the statistics must already hold the point and triangle counts.
void layerSpacing(const CurvedLayers& layers, int l, std::vector<LayerStatistics>& stats) {
  const int L = static_cast<int>(stats.size());
  LayerStatistics& s = stats[l];
  if (l + 1 == L || stats[l + 1].triangles == 0 || s.points == 0) {
    s.spacingMin = s.spacingMean = s.spacingMax = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  const std::vector<Triangle> next = layerTriangles(layers, l + 1);
  Tree tree(next.cbegin(), next.cend());
  tree.accelerate_distance_queries();
  s.spacingMin = std::numeric_limits<double>::infinity();
  s.spacingMax = 0;
  double sum = 0;
  for (int p = layers.layerPointOffset[l]; p < layers.layerPointOffset[l + 1]; ++p) {
    const double d = std::sqrt(tree.squared_distance(toPoint(layers.points[p])));
    s.spacingMin = std::min(s.spacingMin, d);
    s.spacingMax = std::max(s.spacingMax, d);
    sum += d;
  }
  s.spacingMean = sum / s.points;
}
}  // namespace

std::vector<LayerStatistics> computeLayerStatistics(const CurvedLayers& layers, int threads,
                                                    const std::function<void(double)>& progress,
                                                    const std::function<bool()>& shouldAbort) {
  const int L = static_cast<int>(layers.layerValues.size());
  std::vector<LayerStatistics> stats(L);
  std::vector<int> components;
  for (int l = 0; l < L; ++l) {
    LayerStatistics& s = stats[l];
    s.value = layers.layerValues[l];
    s.triangles = layers.layerTriangleOffset[l + 1] - layers.layerTriangleOffset[l];
    s.points = layers.layerPointOffset[l + 1] - layers.layerPointOffset[l];
    s.components = layerComponents(layers, l, components);
    for (int k = layers.layerTriangleOffset[l]; k < layers.layerTriangleOffset[l + 1]; ++k) {
      const auto& t = layers.triangles[k];
      const Vec3& a = layers.points[t[0]];
      s.area += 0.5 * (layers.points[t[1]] - a).cross(layers.points[t[2]] - a).norm();
    }
  }
  // The spacing (an AABB tree of the next layer and a distance query per point) is most of the
  // cost: layers are independent, so the workers take them one at a time. Each layer is computed
  // exactly as on one thread, so the result does not depend on the thread count.
  const ProgressReporter report(progress, shouldAbort, "layer statistics");
  parallelFor(
      static_cast<size_t>(L), threads,
      [&](size_t l, int) { layerSpacing(layers, static_cast<int>(l), stats); },
      [&](size_t done) {
        if (done % 64 == 0 || done == static_cast<size_t>(L)) {
          report.report(static_cast<double>(done) / L);
        }
      });
  return stats;
}

}  // namespace geolattice
