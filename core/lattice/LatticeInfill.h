#pragma once
/// @file LatticeInfill.h
/// @brief The lattice infill pattern G_i(V_i, E_i) of every curved layer S_i (paper Section 2.2,
/// Algorithm 1, Eqs. 6-13, Figs. 2-5) and its connected sub-graphs G_{i,j} (Section 2.3).
///
/// Data flow: CurvedLayers (slicer: one triangle mesh per layer, α and β per point) + levels
/// Ψ^α, Ψ^β (LatticeLevels.h) -> per layer, independently (std::thread over layers):
///   1. unique layer-mesh edges; the isoline points α = φ_j^α and β = φ_k^β on each edge
///      (Eqs. 6-9: a layer-mesh edge is the segment PQ where the layer cuts a tet face);
///   2. per triangle, one α-segment per α-level crossing it (likewise β); an α- and a β-segment
///      cross iff their end points interleave along the triangle's boundary (decided
///      combinatorially), the crossing is placed by Eq. 11 and splits both segments (Eq. 10);
///   3. the layer boundary (layer-mesh edges used by one triangle = where S_i meets the part
///      surface, Eqs. 12-13) split at the isoline points on it;
///   4. points on quad diagonals removed (see below), vertex kinds and degrees, connected
///      sub-graphs (union-find), sub-graphs shorter than a minimum length dropped, boundary loops.
///
/// Robustness (exact arithmetic is not needed; every decision is combinatorial):
///  - Vertices are keyed by the mesh element they lie on, never found by geometry: an isoline
///    point inside a layer-mesh edge by (edge, field, level); a field value exactly equal to a
///    level at a layer point counts as "above" (simulation of simplicity, like the slicer's
///    exact γ hits) and every isoline through that point uses the one vertex of that point,
///    which is also the boundary vertex there. An α- and a β-point at exactly the same
///    parameter on an edge are one vertex (a crossing on the edge). Hence no duplicate vertices.
///  - A segment whose two ends are the same vertex (the isoline touches the layer at a point) is
///    dropped. A segment along a layer-mesh edge (both ends exact hits, the third corner below)
///    is kept once: it is dropped when it lies on the layer boundary (it coincides with the
///    boundary edge) and when the triangle on the other side also emits it (a ridge where the
///    field touches the level from below on both sides: the perturbed isoline is a loop of zero
///    width). Its crossings are the β-points (α-points) on that edge.
///  - Crossings are decided from the order of the end points along the triangle boundary: the
///    order of points on an edge is their rank in that edge's globally sorted list, so the two
///    triangles of an edge always agree; segments of the same field never cross (distinct
///    levels of a linear function).
///  - Crossing position (Eq. 11): on the α-segment AB at s = (φ^β - β_A) / (β_B - β_A) clamped to
///    [0, 1], so nearly parallel α and β lines still give one vertex inside the triangle.
/// Result: crossing vertices have degree 4, boundary hits 3, all others 2, except at exact
/// tangential touches (a level equal to the field at a saddle point, an isoline tangent to the
/// boundary at a layer point, two isolines crossing exactly on the boundary) and at
/// non-manifold layer points; those are counted in LatticeStatistics::irregularVertices.
///
/// Same graph as the paper's per-tet construction: the slicer splits the quad in which a layer
/// cuts a tet into two triangles. α and β are linear in the tet, so an isoline crosses the quad
/// diagonal without bending; with mergeQuadDiagonalPoints (default) those degree-2 points are
/// removed and their two edges joined, so V_i and E_i are exactly the paper's (points on tet
/// faces, crossings inside tets, boundary points). Needs CurvedLayers::sourceEdge (a diagonal
/// joins two layer points on disjoint tet edges).
#include "common/WorkLimit.h"
#include "slicer/CurvedLayerSlicer.h"

#include <array>
#include <functional>
#include <vector>

namespace geolattice {

/// Vertex kinds (values are stored in the VTK output array VertexKind).
enum class LatticeVertexKind : int {
  IsolinePoint = 0,  ///< an α- or β-isoline point on a layer-mesh edge or layer point (degree 2)
  Crossing = 1,      ///< α-isoline meets β-isoline (Eqs. 10-11, degree 4)
  BoundaryHit = 2,   ///< an isoline meets the layer boundary (degree 3)
  Boundary = 3,      ///< a layer point on the layer boundary (Eqs. 12-13, degree 2)
};

/// Edge kinds (values are stored in the VTK output array EdgeKind).
enum class LatticeEdgeKind : int {
  Alpha = 0,     ///< piece of an α-isoline
  Beta = 1,      ///< piece of a β-isoline
  Boundary = 2,  ///< piece of the layer boundary
};

/// @brief Parameters of buildLatticeGraph().
struct LatticeOptions {
  double alphaWidth = 4.0;  ///< a: distance between α-isolines (mm, > 0)
  double betaWidth = 4.0;   ///< b: distance between β-isolines (mm, > 0)
  double alphaPhase = 0.0;  ///< α-levels are j·a + alphaPhase (mm)
  double betaPhase = 0.0;   ///< β-levels are k·b + betaPhase (mm)
  double minimumSubgraphLength =
      0.0;  ///< sub-graphs with a shorter total edge length are dropped (mm, >= 0)
  /// Graded lattice: empty (uniform lattice) or one factor per layer point (> 0) that scales
  /// the local line spacing (0.5 = twice as dense). See LatticeLevels.h for the remapping.
  std::vector<double> widthScale;
  bool mergeQuadDiagonalPoints = true;  ///< see the file comment; needs CurvedLayers::sourceEdge
  int threads = 0;                      ///< worker threads over layers; 0 = hardware concurrency
  /// Bound against runaway work: a lattice estimated (estimateLatticeSize) to have more vertices
  /// plus edges than this is refused before it is built (common/WorkLimit.h; > 0).
  double maxElements = kDefaultMaxElements;
  /// Polled on the calling thread after each layer it builds; true stops with a GeoLatticeError
  /// "lattice infill aborted". Optional.
  std::function<bool()> shouldAbort;
  /// Called on the calling thread with the fraction of layers done. Optional.
  std::function<void(double)> progress;
  /// Throws GeoLatticeError naming the first parameter out of its range (cheap: no data).
  void validate() const;
};

/// @brief A closed boundary loop of a sub-graph as a vertex sequence (the first vertex is not
/// repeated at the end). closed == false only for a non-manifold layer boundary.
struct LatticeBoundaryLoop {
  std::vector<int> vertices;
  bool closed = true;
};

/// @brief A connected sub-graph G_{i,j}.
struct LatticeSubgraph {
  int id = 0;            ///< index into LatticeGraph::subgraphs
  int layer = 0;         ///< 0..L-1 (into LatticeGraph::layerValues)
  int indexInLayer = 0;  ///< j of G_{i,j}, 0-based
  int vertexCount = 0;
  int edgeCount = 0;
  int isolineEdgeCount = 0;  ///< α + β edges
  int crossingCount = 0;
  int boundaryHitCount = 0;
  double length = 0;             ///< total edge length (mm)
  Vec3 centroid = Vec3::Zero();  ///< length-weighted mean of the edge midpoints (mm)
  std::vector<LatticeBoundaryLoop> boundaryLoops;
};

/// @brief Counters of the whole run (sums over layers).
struct LatticeStatistics {
  int crossings = 0;
  int boundaryHits = 0;
  int isolineEdges = 0;  ///< α + β edges: 0 = empty lattice (e.g. widths larger than the part)
  int irregularVertices =
      0;  ///< degree != 4 / 3 / 2 for crossing / boundary hit / other (see file comment)
  int droppedSubgraphs = 0;  ///< shorter than minimumSubgraphLength
  double droppedLength = 0;  ///< their total length (mm)
  int touchingSegments =
      0;  ///< isoline segments collapsed onto one exact-hit layer point (dropped)
  int boundarySegments = 0;  ///< isoline segments lying on the layer boundary (dropped)
  int ridgeSegments = 0;     ///< isoline segments along an edge emitted by both triangles (dropped)
  int edgeCrossings = 0;   ///< α- and β-point at the same parameter of a layer-mesh edge (merged)
  int pointCrossings = 0;  ///< α and β both exactly at a level at a layer point
  int duplicateEdges = 0;  ///< edges joining the same two vertices (kept once)
  int mergedDiagonalPoints = 0;  ///< isoline points on quad diagonals removed
  int openBoundaryChains = 0;    ///< boundary walks that did not close (non-manifold layers)
};

/// @brief The lattice of all layers; vertices, edges and sub-graphs are grouped by layer.
struct LatticeGraph {
  std::vector<double> layerValues;       ///< #L φ_i (mm), copied from CurvedLayers
  std::vector<int> layerIndex;           ///< #L layer index i, copied from CurvedLayers
  std::vector<int> layerVertexOffset;    ///< #L+1: layer l owns vertices [off[l], off[l+1])
  std::vector<int> layerEdgeOffset;      ///< #L+1
  std::vector<int> layerSubgraphOffset;  ///< #L+1
  std::vector<double> alphaLevels;       ///< Ψ^α used (mm, ascending); alphaLevel indexes it
  std::vector<double> betaLevels;        ///< Ψ^β used (mm, ascending)

  std::vector<Vec3> points;         ///< #V positions (mm), on the layer surface
  std::vector<Vec3> normals;        ///< #V unit nozzle direction (interpolated)
  std::vector<double> gamma;        ///< #V γ = φ_i of the vertex's layer (mm)
  std::vector<double> alpha, beta;  ///< #V field values (exactly the level on an isoline)
  /// #V index of the α- (β-) level equal to the vertex's α (β), -1 if none. Set on every isoline
  /// point and crossing; also on an exact-hit layer point whose isoline was dropped there.
  std::vector<int> alphaLevel, betaLevel;
  std::vector<LatticeVertexKind> vertexKind;  ///< #V
  std::vector<int> degree;                    ///< #V
  std::vector<int> vertexLayer;               ///< #V 0..L-1
  std::vector<int> vertexSubgraph;            ///< #V into subgraphs

  std::vector<std::array<int, 2>> edges;  ///< #E vertex pairs
  std::vector<LatticeEdgeKind> edgeKind;  ///< #E
  std::vector<int> edgeLevel;             ///< #E level index of α/β edges, -1 for boundary edges
  std::vector<int> edgeLayer;             ///< #E 0..L-1
  std::vector<int> edgeSubgraph;          ///< #E into subgraphs

  std::vector<LatticeSubgraph> subgraphs;
  LatticeStatistics stats;
};

/// @brief An upper estimate of the lattice's size, from the levels crossing each layer triangle.
struct LatticeSizeEstimate {
  double segments = 0;   ///< α- and β-segments before crossings split them
  double crossings = 0;  ///< upper bound: n_α · n_β per triangle
  /// Vertices + edges: every segment brings two ends and an edge, every crossing a vertex and
  /// two more edges.
  double elements() const { return 2 * segments + 3 * crossings; }
};

/// Counts, per triangle, the levels between its smallest and largest corner value (binary search
/// in the sorted levels): O(F log n), no allocation.
LatticeSizeEstimate estimateLatticeSize(const CurvedLayers& layers,
                                        const std::vector<double>& alphaLevels,
                                        const std::vector<double>& betaLevels);

/// Builds G_i for every layer of `layers`. The levels are computed once from all layer points
/// (uniform, or graded when options.widthScale is set), so each isoline continues from layer to
/// layer. Throws GeoLatticeError for bad options (widths <= 0, ...), inconsistent `layers`
/// (sizes, offsets, a triangle using a point of another layer or the same point twice,
/// non-finite α or β), a layer mesh that is not edge-manifold (an edge of more than two
/// triangles), a lattice estimated larger than options.maxElements, or an abort.
LatticeGraph buildLatticeGraph(const CurvedLayers& layers, const LatticeOptions& options = {});

}  // namespace geolattice
