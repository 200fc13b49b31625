/**
 * @class   vtkGLSkeletonTree
 * @brief   The skeleton tree of the lattice sub-graphs G_{i,j}: one node per connected
 *          sub-graph, an edge between adjacent sub-graphs of consecutive layers.
 *
 * Paper Section 2.3 (Algorithm 2, Figs. 9-10), core/skeleton/SkeletonTree.h: G_{i,j} and
 * G_{i+1,k} are adjacent iff they bound the same connected piece of the slab
 * φ_i <= γ <= φ_{i+1} of the tet mesh (decided volumetrically instead of by the paper's steepest
 * ascent/descent paths). The result is a DAG: where branches merge again a node has two lower
 * nodes. It drives the printing order (vtkGLPrintSequencer).
 *
 * Input port 0: vtkPolyData, the output of vtkGLLatticeInfill (line cells with cell arrays
 *         `SubgraphId`, `LayerId`, point arrays `NozzleAxis`, `Gamma`).
 * Input port 1: vtkUnstructuredGrid of tets with point array `Gamma` (the output of
 *         vtkGLGeodesicDistanceFields that the layers were sliced from).
 * Output: vtkPolyData, one point per node (node index = sub-graph id) at the length-weighted
 *   centroid of its sub-graph, one line cell (lower, upper) per edge, with
 *   - point data `NodeId` (int), `LayerId` (int: lattice layer 0..L-1, i.e. the rank of the
 *     sub-graph's LayerId among the lattice's LayerId values), `SubgraphId` (int, = NodeId),
 *     `Gamma` (φ of the layer, mm), `SubgraphLength` (mm), `LowerCount`, `UpperCount` (int:
 *     adjacent nodes on the layers below and above);
 *   - field data `SkeletonRoots` (nodes without lower node), `SkeletonFloatingNodes` (roots
 *     above the lowest layer, whose support was dropped by the lattice), `SkeletonMergeNodes` (more than
 *     one lower node), `SkeletonSplitNodes` (more than one upper node), `SkeletonSeconds` (wall
 *     time) and `LayerValues` (φ per lattice layer, mm).
 * Parameters: none. Connect the lattice with SetInputConnection(0, ...) and the tet mesh with
 * SetInputConnection(1, ...).
 * Errors (missing inputs or arrays, an empty lattice, sub-graph ids that are not 0..K-1,
 * non-tet cells, a sub-graph that lies in no tet of its layer's γ range) are reported with
 * vtkErrorMacro and give an empty output.
 */
#ifndef vtkGLSkeletonTree_h
#define vtkGLSkeletonTree_h

#include "GeoLatticeFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class GEOLATTICEFILTERS_EXPORT vtkGLSkeletonTree : public vtkPolyDataAlgorithm {
public:
  static vtkGLSkeletonTree* New();
  vtkTypeMacro(vtkGLSkeletonTree, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkGLSkeletonTree();
  ~vtkGLSkeletonTree() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkGLSkeletonTree(const vtkGLSkeletonTree&) = delete;
  void operator=(const vtkGLSkeletonTree&) = delete;
};

#endif
