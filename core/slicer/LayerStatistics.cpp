#include "slicer/LayerStatistics.h"

#include "common/UnionFind.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <limits>

namespace geolattice {

namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using Triangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 toPoint(const Vec3& p) { return {p.x(), p.y(), p.z()}; }
} // namespace

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

std::vector<LayerStatistics> computeLayerStatistics(const CurvedLayers& layers) {
  const int L = static_cast<int>(layers.layerValues.size());
  std::vector<LayerStatistics> stats(L);
  std::vector<std::vector<Triangle>> triangles(L);
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
      triangles[l].emplace_back(toPoint(a), toPoint(layers.points[t[1]]), toPoint(layers.points[t[2]]));
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int l = 0; l < L; ++l) {
    LayerStatistics& s = stats[l];
    if (l + 1 == L || triangles[l + 1].empty() || s.points == 0) {
      s.spacingMin = s.spacingMean = s.spacingMax = nan;
      continue;
    }
    Tree tree(triangles[l + 1].cbegin(), triangles[l + 1].cend());
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
  return stats;
}

} // namespace geolattice
