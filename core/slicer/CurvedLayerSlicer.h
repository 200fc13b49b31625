#pragma once
/// @file CurvedLayerSlicer.h
/// @brief Curved layers S_i = {γ = φ_i} of a tet mesh by marching tetrahedra (paper Section 2.2,
/// the γ-IGDSs), with exact shared topology.
///
/// Data flow: tet mesh + vertex fields γ, α, β (GDF stage) -> unique mesh edges -> for each
/// edge the contiguous range of layers crossing it, one layer point per (edge, layer) at a
/// precomputed index (no hashing) -> per tet and crossing layer 1 or 2 triangles -> triangles
/// sorted by layer, points renumbered by layer.
///
/// Exact hits: a vertex with γ == φ_i counts as above the layer; every crossing that lands on
/// it becomes the one layer point of that vertex, so no duplicate points arise and triangles
/// that collapse onto it are dropped (never emitted with zero area). A mesh face that lies in
/// the layer is emitted once, or not at all when it only touches the layer from one side.
#include "common/WorkLimit.h"
#include "mesh/TetMesh.h"

#include <Eigen/Core>
#include <array>
#include <functional>
#include <vector>

namespace geolattice {

/// @brief Which layers to extract: φ_i = firstLayerOffset + i * interval (mm), i >= 0.
struct SlicerOptions {
  double interval = 0.6;          ///< γ distance between layers (mm, > 0)
  double firstLayerOffset = 0.6;  ///< γ of layer 0 (mm, > 0)
  int firstLayer = 0;             ///< first layer index to extract (>= 0)
  int lastLayer = -1;             ///< last layer index to extract; -1 = up to the top
  /// Bound against runaway work (common/WorkLimit.h): more estimated layer points + triangles
  /// (three per tet-edge crossing) than this is refused before any is made (> 0).
  double maxElements = kDefaultMaxElements;
  /// Called on the calling thread with the fraction of sliceCurvedLayers() done. Optional.
  std::function<void(double)> progress;
  /// Polled where progress is reported; true stops with a GeoLatticeError "curved layer slicing
  /// aborted". Optional.
  std::function<bool()> shouldAbort;
  /// Throws GeoLatticeError naming the first parameter out of its range (cheap: no data).
  void validate() const;
};

/// Number of layers φ_i <= γ_max: floor((γ_max - offset) / interval) + 1 (0 if offset > γ_max).
int layerCount(double gammaMax, const SlicerOptions& options);
/// φ_i, computed the same way everywhere so comparisons are exact.
inline double layerValue(int i, const SlicerOptions& options) {
  return options.firstLayerOffset + static_cast<double>(i) * options.interval;
}

/// @brief All extracted layers in one mesh; triangles and points are grouped by layer.
struct CurvedLayers {
  std::vector<double> layerValues;  ///< #L φ_i of the extracted layers (mm)
  std::vector<int> layerIndex;      ///< #L the index i of each extracted layer
  std::vector<Vec3> points;         ///< #P positions (mm)
  std::vector<double> alpha, beta;  ///< #P α, β interpolated along the tet edge (mm)
  std::vector<Vec3> normals;        ///< #P unit nozzle direction (∇γ, towards increasing γ)
  std::vector<int> pointLayer;      ///< #P layer (0..L-1, into layerValues)
  std::vector<std::array<int, 2>>
      sourceEdge;  ///< #P tet-mesh edge (a, b), γ(a) < γ(b); a == b for a vertex hit
  std::vector<double> edgeParameter;          ///< #P t: point = (1 - t) p_a + t p_b
  std::vector<std::array<int, 3>> triangles;  ///< #F, counter-clockwise seen from +∇γ
  std::vector<int> triangleLayer;             ///< #F layer (0..L-1)
  std::vector<int> layerTriangleOffset;       ///< #L+1: layer l owns triangles [off[l], off[l+1])
  std::vector<int> layerPointOffset;          ///< #L+1: layer l owns points [off[l], off[l+1])
  int droppedDegenerateTriangles = 0;         ///< collapsed onto exact vertex hits
  int droppedDuplicateFaces = 0;              ///< mesh faces touching a layer from one side
};

/// Slices the tet mesh. gamma, alpha, beta have one value per mesh vertex. vertexNormals: unit
/// ∇γ per vertex (see vertexGradientDirections). Throws GeoLatticeError for bad options, sizes
/// that do not match, non-finite γ, or when the options select no layer.
CurvedLayers sliceCurvedLayers(const TetMesh& mesh, const Eigen::VectorXd& gamma,
                               const Eigen::VectorXd& alpha, const Eigen::VectorXd& beta,
                               const std::vector<Vec3>& vertexNormals,
                               const SlicerOptions& options = {});

/// Unit volume-weighted average of the per-tet gradients of f at each vertex (zero where the
/// gradient vanishes). Used as the nozzle direction ∇γ/|∇γ| at layer points.
std::vector<Vec3> vertexGradientDirections(const TetMesh& mesh, const Eigen::VectorXd& f);

}  // namespace geolattice
