#pragma once
/// @file SkeletonTree.h
/// @brief The skeleton tree of the connected lattice sub-graphs G_{i,j} (paper Section 2.3,
/// Algorithm 2, Figs. 9-10): one node per sub-graph, an edge between G_{i,j} and G_{i+1,k}
/// when the two are adjacent through the part.
///
/// Adjacency is decided volumetrically instead of by the paper's steepest ascent/descent paths
/// on the boundary surface (Fig. 10), which can miss a neighbour when both paths leave through
/// another branch and depend on a randomly chosen start edge. Here: the slab
/// R_i = {x : φ_i <= γ(x) <= φ_{i+1}} between two consecutive lattice layers is cut into its
/// connected components, and G_{i,j} and G_{i+1,k} are adjacent iff they bound the same
/// component. γ is linear in each tet, so a tet meets R_i in one convex piece; the pieces of two
/// face-adjacent tets touch iff their shared face meets R_i (union-find over (tet, slab) pairs,
/// O(T · slabs per tet)). Each sub-graph lies on one connected layer patch, whose triangles all
/// lie in face-connected slab pieces, so one point of the sub-graph (located in a tet whose γ
/// range contains φ_i) identifies its component below and above.
///
/// It is a DAG, not always a tree: where branches merge again (an arch, a torus on its side) a
/// node has two lower nodes. Sub-graphs dropped by the lattice (minimum length) leave gaps; a
/// node above the first layer without lower node is counted in floatingNodes.
#include "lattice/LatticeInfill.h"
#include "mesh/TetMesh.h"

#include <Eigen/Core>
#include <array>
#include <functional>
#include <vector>

namespace geolattice {

class TetMeshTopology;

/// @brief One node = one connected sub-graph G_{i,j}; node index == sub-graph id.
struct SkeletonNode {
  int layer = 0;                 ///< lattice layer (0..L-1)
  int indexInLayer = 0;          ///< j of G_{i,j}
  Vec3 centroid = Vec3::Zero();  ///< length-weighted centroid of the sub-graph (mm)
  double length = 0;             ///< total edge length of the sub-graph (mm)
  std::vector<int> lower;  ///< adjacent nodes on layer i-1 (printed before this one), ascending
  std::vector<int> upper;  ///< adjacent nodes on layer i+1, ascending
};

/// @brief The skeleton DAG. edges are (lower, upper) node pairs, sorted.
struct SkeletonTree {
  std::vector<SkeletonNode> nodes;
  std::vector<std::array<int, 2>> edges;
  std::vector<double> layerValues;  ///< φ_i of the lattice layers (mm)
  int roots = 0;                    ///< nodes without lower node
  int floatingNodes = 0;            ///< roots above lattice layer 0 (their support was dropped)
  int mergeNodes = 0;               ///< nodes with more than one lower node (branches merge)
  int splitNodes = 0;               ///< nodes with more than one upper node (branches split)
  int slabComponents = 0;           ///< connected slab pieces summed over all slabs
};

/// A point of one sub-graph and its layer, used to place the sub-graph in the tet mesh.
struct SkeletonAnchor {
  int layer = 0;
  Vec3 point = Vec3::Zero();
};

/// @brief Optional inputs of buildSkeletonTree() (the result does not depend on them).
struct SkeletonTreeOptions {
  /// The mesh's face adjacency, if the caller has it already (the orientation search builds one
  /// skeleton per candidate on one mesh); else it is built here. Must be the mesh's own.
  const TetMeshTopology* topology = nullptr;
  /// Called on the calling thread with the fraction done. Optional.
  std::function<void(double)> progress;
  /// Polled where progress is reported; true stops with a GeoLatticeError "skeleton tree
  /// aborted". Optional.
  std::function<bool()> shouldAbort;
};

/// Builds the skeleton from the tet mesh with vertex field γ, the lattice layer values φ_i
/// (ascending) and one anchor per sub-graph (node i <-> anchors[i]); centroid and length of
/// the nodes are left 0. Throws GeoLatticeError for empty input, sizes that do not match,
/// layer values that are not strictly ascending, an anchor layer out of range, or an anchor
/// that lies in no tet whose γ range contains its layer value.
SkeletonTree buildSkeletonTree(const TetMesh& mesh, const Eigen::VectorXd& gamma,
                               const std::vector<double>& layerValues,
                               const std::vector<SkeletonAnchor>& anchors,
                               const SkeletonTreeOptions& options = {});

/// Same, with anchors, centroids and lengths taken from the lattice's sub-graphs. Throws
/// GeoLatticeError also for a lattice without sub-graphs.
SkeletonTree buildSkeletonTree(const TetMesh& mesh, const Eigen::VectorXd& gamma,
                               const LatticeGraph& lattice,
                               const SkeletonTreeOptions& options = {});

/// Sorts tree.edges and derives what follows from them: every node's lower and upper lists
/// (sorted) and the tree's counts (roots, floating, merge and split nodes; floating: a root above
/// the lowest layer that has a node). buildSkeletonTree ends with it; a tree read from elsewhere
/// (the filters' VTK input) is completed with it.
void linkSkeletonEdges(SkeletonTree& tree);

/// @brief Transitive "must be printed before" relation of a skeleton: a is an ancestor of b
/// iff a chain of edges leads upwards from a to b (Criterion 1 then forces a before b in every
/// order). Bit sets per node, built bottom-up in O(K² / 64 + E·K / 64).
class SkeletonAncestry {
public:
  explicit SkeletonAncestry(const SkeletonTree& tree);
  bool isAncestor(int a, int b) const { return (bits_[b][a >> 6] >> (a & 63)) & 1u; }

private:
  std::vector<std::vector<unsigned long long>> bits_;  ///< bits_[b]: ancestors of b
};

/// Checks that edges join consecutive layers, that lower/upper lists match the edges and that
/// every node index is valid; throws GeoLatticeError naming the first problem ("cyclic or
/// missing adjacency"). Used by the sequencer on trees that come from outside (VTK input).
void validateSkeletonTree(const SkeletonTree& tree);

}  // namespace geolattice
