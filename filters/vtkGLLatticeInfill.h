/**
 * @class   vtkGLLatticeInfill
 * @brief   Lattice infill pattern G_i of every curved layer: α- and β-isolines, their crossings
 *          and the layer boundary, as a graph of line cells.
 *
 * Paper Section 2.2, Algorithm 1 (Eqs. 6-13), on the layer triangle meshes
 * (core/lattice/LatticeInfill.h): on each layer S_i the isolines α = j·AlphaWidth + AlphaPhase
 * and β = k·BetaWidth + BetaPhase, their crossings, and the layer boundary (where the layer meets
 * the part surface) split at the isoline hits; then the connected sub-graphs G_{i,j}. Iso-values
 * that hit layer points or edges exactly never create duplicate vertices or broken edges.
 *
 * Input:  vtkPolyData of triangles (the output of vtkGLCurvedLayerSlicer) with cell array
 *         `LayerId` and point arrays `Alpha`, `Beta` (required), `Gamma`, `Normals` and
 *         `SourceEdge` (optional: without Normals the area-weighted triangle normals are used;
 *         without Gamma the output has no Gamma array; with SourceEdge the isoline points on
 *         the slicer's quad diagonals are removed, which gives exactly the paper's graph).
 *         Vertex and line cells of the input are ignored; polygons must be triangles.
 * Output: vtkPolyData, one line cell per graph edge, points shared within a layer, with
 *   - point data `VertexKind` (int: 0 isoline point, 1 crossing, 2 boundary hit, 3 boundary;
 *     see geolattice::latticekind), `Degree` (int: 4 at crossings, 3 at boundary hits, 2
 *     elsewhere except at exact tangential touches), `NozzleAxis` (unit nozzle direction,
 *     interpolated), `Gamma` (φ_i of the layer, mm), `Alpha`, `Beta` (mm), `SubgraphId`;
 *   - cell data `EdgeKind` (int: 0 α, 1 β, 2 boundary), `LayerId` (layer index i),
 *     `SubgraphId` (connected sub-graph, numbered over all layers), `IsolineLevel` (mm, NaN on
 *     boundary edges);
 *   - field data `LatticeVertices`, `LatticeEdges`, `LatticeSubgraphs`, `LatticeCrossings`,
 *     `LatticeBoundaryHits`, `LatticeIsolineEdges`, `LatticeDroppedSubgraphs`,
 *     `LatticeIrregularVertices`, the levels `LatticeAlphaLevels`, `LatticeBetaLevels` (mm) and
 *     per sub-graph `SubgraphLayer`, `SubgraphLength` (mm), `SubgraphCentroid` (mm).
 * Parameters: AlphaWidth, BetaWidth (lattice widths a, b in mm, default 4, > 0), AlphaPhase,
 *   BetaPhase (offset of the levels in mm, default 0), MinimumSubgraphLength (mm, default 0 =
 *   keep all; shorter sub-graphs are dropped and counted), MaximumElements (default 40e6: a
 *   lattice estimated to have more vertices + edges is refused before it is built, ~8 GB down
 *   to the toolpath), NumberOfThreads (default 0 = all cores), and optionally a point array chosen with SetInputArrayToProcess(0, 0, 0,
 *   vtkDataObject::FIELD_ASSOCIATION_POINTS, name): a width scale per layer point (> 0; 0.5 =
 *   twice as dense) for a graded lattice (levels remapped along α and β, see
 *   core/lattice/LatticeLevels.h). No array or the name "None" gives the uniform lattice.
 * Errors (missing LayerId/Alpha/Beta, a selected width-scale array that is missing, widths <= 0,
 * non-triangle polygons, a layer mesh that is not edge-manifold) are reported with
 * vtkErrorMacro and give an empty output. Widths larger than the part are not an error: no
 * isoline crosses the layers, LatticeIsolineEdges is 0, a warning says so, and the output holds
 * only the layer boundaries.
 */
#ifndef vtkGLLatticeInfill_h
#define vtkGLLatticeInfill_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLOptionMacros.h"
#include "vtkPolyDataAlgorithm.h"

#include "lattice/LatticeInfill.h"  // LatticeOptions: the parameters and their defaults

class GEOLATTICEFILTERS_EXPORT vtkGLLatticeInfill : public vtkPolyDataAlgorithm {
public:
  static vtkGLLatticeInfill* New();
  vtkTypeMacro(vtkGLLatticeInfill, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Lattice widths a and b: distance between neighbouring α- (β-) isolines (mm, default 4,
  /// must be > 0; checked in RequestData so that a bad value is reported, not clamped).
  vtkGLOptionMacro(AlphaWidth, double, alphaWidth);
  vtkGLOptionMacro(BetaWidth, double, betaWidth);
  ///@}

  ///@{
  /// Offsets of the iso-values: α-levels are j·AlphaWidth + AlphaPhase (mm, default 0).
  vtkGLOptionMacro(AlphaPhase, double, alphaPhase);
  vtkGLOptionMacro(BetaPhase, double, betaPhase);
  ///@}

  ///@{
  /// Sub-graphs with a smaller total edge length are dropped (mm, default 0 = keep all).
  vtkGLOptionClampMacro(MinimumSubgraphLength, double, minimumSubgraphLength, 0.0, VTK_DOUBLE_MAX);
  ///@}

  ///@{
  /// Remove the isoline points on the slicer's quad diagonals (needs the SourceEdge array;
  /// default on). The removed points are straight-through points of one isoline.
  vtkGLOptionBooleanMacro(MergeQuadDiagonalPoints, mergeQuadDiagonalPoints);
  ///@}

  ///@{
  /// Bound against runaway work (core/common/WorkLimit.h): more estimated vertices + edges than
  /// this is refused before the lattice is built (default 40e6, about 8 GB).
  vtkGLOptionClampMacro(MaximumElements, double, maxElements, 1.0, VTK_DOUBLE_MAX);
  ///@}

  ///@{
  /// Worker threads over the layers (default 0 = hardware concurrency).
  vtkGLOptionClampMacro(NumberOfThreads, int, threads, 0, 256);
  ///@}

protected:
  vtkGLLatticeInfill();
  ~vtkGLLatticeInfill() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  geolattice::LatticeOptions Options;  ///< the parameters, defaults from core

private:
  vtkGLLatticeInfill(const vtkGLLatticeInfill&) = delete;
  void operator=(const vtkGLLatticeInfill&) = delete;
};

#endif
