#pragma once
/// @file LayerStatistics.h
/// @brief Per-layer area, connected components and the actual spacing to the next layer, to show
/// where geodesic layers thin or thicken (issue "Curved layers", item 4).
#include "slicer/CurvedLayerSlicer.h"

#include <functional>
#include <vector>

namespace geolattice {

/// @brief Statistics of one extracted layer.
struct LayerStatistics {
  double value = 0;  ///< φ_i (mm)
  double area = 0;   ///< mm^2
  int triangles = 0;
  int points = 0;
  int components = 0;  ///< connected pieces (triangles sharing vertices)
  /// Distance from this layer's points to the next layer's surface (mm); NaN for the last layer
  /// or when the next layer is empty. Uniform layers give min ≈ mean ≈ max ≈ interval.
  double spacingMin = 0, spacingMean = 0, spacingMax = 0;
};

/// Statistics of every layer of `layers` (AABB trees of CGAL for the spacing, O(n log n)).
/// The spacing is computed on `threads` worker threads over layers (0 = hardware concurrency);
/// the result is the same for every thread count. progress (fraction of layers done) and
/// shouldAbort (true stops with "layer statistics aborted") are optional, as in common/Progress.h.
std::vector<LayerStatistics> computeLayerStatistics(
    const CurvedLayers& layers, int threads = 0, const std::function<void(double)>& progress = {},
    const std::function<bool()>& shouldAbort = {});

/// Component id (0..count-1) of every triangle of layer l; returns the count.
int layerComponents(const CurvedLayers& layers, int l, std::vector<int>& triangleComponent);

}  // namespace geolattice
