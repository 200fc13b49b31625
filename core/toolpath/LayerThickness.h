#pragma once
/// @file LayerThickness.h
/// @brief Local layer thickness of every lattice vertex (paper Eq. 15, Fig. 17): the shortest
/// distance from the vertex to the lattice of its lower adjacent sub-graph(s) in the skeleton,
/// capped at λ·φ_i, where φ_i is the γ interval to the layer below; on the first layer the
/// height above the platform (z), capped the same way.
///
/// The paper traverses all edges of G_{i-1} for every vertex (O(n·m)) and notes a kd-tree would
/// give O(n log m). Here the edges of each sub-graph go into a bounding-sphere tree of segments,
/// built once; a vertex queries the trees of its node's lower nodes (nearest segment, pruned by
/// sphere distance), O(log m) per vertex. A node without lower node above the first layer (its
/// support was dropped) gets λ·φ_i and is counted.
#include "lattice/LatticeInfill.h"
#include "skeleton/SkeletonTree.h"

#include <vector>

namespace geolattice {

/// Deviation e = (h - φ)/φ over the vertices of one layer (Fig. 17).
struct LayerThicknessDeviation {
  double min = 0, mean = 0, max = 0;
  int vertices = 0;
};

struct LayerThicknessResult {
  std::vector<double> thickness;                  ///< #V h (mm); 0 for vertices without sub-graph
  std::vector<LayerThicknessDeviation> perLayer;  ///< #L
  double deviationMin = 0, deviationMax = 0;      ///< over all layers
  int cappedVertices = 0;                         ///< h was above λ·φ
  int unsupportedVertices = 0;                    ///< no lower node above the first layer
};

/// lambda > 1 (the paper uses 1.5). Throws GeoLatticeError for lambda <= 0, a skeleton that does
/// not match the lattice's sub-graphs, or a lattice without layer values.
LayerThicknessResult computeLayerThickness(const LatticeGraph& g, const SkeletonTree& tree,
                                           double lambda = 1.5);

}  // namespace geolattice
