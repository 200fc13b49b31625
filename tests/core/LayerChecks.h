#pragma once
// Shared checks of curved layers (core tests): edge-manifold and consistently oriented layers.
#include "slicer/CurvedLayerSlicer.h"

#include <gtest/gtest.h>

#include <map>

namespace geolattice {

/// Every directed edge of the layer's triangles appears once, and every undirected edge in at
/// most two triangles, which then traverse it in opposite directions (consistent orientation).
inline void expectEdgeManifoldAndOriented(const CurvedLayers& layers, int layer) {
  std::map<std::pair<int, int>, int> directed;
  for (int k = layers.layerTriangleOffset[layer]; k < layers.layerTriangleOffset[layer + 1]; ++k) {
    const auto& t = layers.triangles[k];
    for (int e = 0; e < 3; ++e) {
      ++directed[{t[e], t[(e + 1) % 3]}];
    }
  }
  for (const auto& [edge, count] : directed) {
    ASSERT_EQ(count, 1) << "directed edge used twice in layer " << layer;
    const auto reverse = directed.find({edge.second, edge.first});
    ASSERT_LE(count + (reverse == directed.end() ? 0 : reverse->second), 2);
  }
}

}  // namespace geolattice
