/**
 * @class   vtkGLTetrahedralizeSurface
 * @brief   Quality tetrahedral mesh of the solid bounded by a closed triangle surface (TetGen).
 *
 * The geodesic distance fields of the paper (Li et al., Sec. 3) are computed on a tet mesh of
 * the part; this filter makes that mesh from the part's surface with TetGen 1.5 (constrained
 * Delaunay + Delaunay refinement, core/tetrahedralize/TetrahedralizeSurface.h). TetGen runs
 * in a child process, so a TetGen failure is reported instead of ending ParaView.
 *
 * Input:  vtkPolyData whose polygons are triangles forming a closed, edge-manifold,
 *         consistently oriented surface (mm). Several shells are allowed: disjoint parts are all
 *         meshed; an inner shell oriented inward is a cavity and stays empty. Bodies whose
 *         surfaces cross each other (an assembly exported as it is), or touch along a face (then
 *         welded into non-manifold edges by the reader), are meshed as their union
 *         (core/mesh/OverlappingBodies.h; field data `MergedBodies`, and a warning). A triangle
 *         that repeats another (the same vertices, the same way round) is dropped, triangles
 *         flipped against their neighbours are turned, degenerate triangles (area ~0: slivers
 *         of marching cubes or of the union's cuts) are removed by collapsing or flipping an
 *         edge (core/mesh/SurfaceRepair.h; field data `DuplicateTriangles`,
 *         `ReorientedTriangles`, `DegenerateTrianglesRemoved`, and a warning; open seams as wide
 *         as rounding, float32 STL corners, are welded: `WeldedVertices`). Closed
 *         cavities are counted in field data `CavityRegions`. An
 *         inward-oriented surface is flipped. Input arrays are not passed (the vertices change).
 * Output: vtkUnstructuredGrid of linear, positively oriented VTK_TETRA cells;
 *   - cell data `RadiusEdgeRatio` (arrays::TetQuality): circumradius / shortest edge per tet
 *     (0.612 for a regular tet; TetGen bounds it by RadiusEdgeRatio except near small input
 *     angles);
 *   - field data `TargetEdgeLength` (mm, the value used: set or automatic), `MeanEdgeLength`
 *     (mm), `TetCount`, `TetrahedralizeSeconds`, and of the surface simplification before TetGen
 *     `InputTriangles`, `MeshedTriangles`, `SimplificationDistance` (mm), `SimplificationSeconds`,
 *     `SimplificationEdgeLength` (mm, the edge the surface was prepared for: the target edge, or
 *     a shorter one (down to a third) when the remeshing for it was refused; 0 = the input as it is) and
 *     `SimplificationRefused` (vtkStringArray: why the target edge's remeshing was refused, empty
 *     if it was not) (names in vtkGLArrayNames.h).
 *
 * Parameters:
 *   - TargetEdgeLength: mm, default 0 = automatic (about TargetTetCount tets, see below);
 *     TetGen's volume bound is the regular-tet volume L^3 / (6 sqrt 2). Must be >= 0.
 *   - TargetTetCount: tet count the automatic edge length aims at (default 75000, must be in
 *     [1000, 5000000]); TetGen runs up to 4 times to get within a factor 1.25 of it. Up to
 *     250000, a 1.45x longer edge is meshed beside the first run, on the other core, and read
 *     first: within the tolerance it is the mesh (the first run is stopped), else it is the
 *     second run when the first gives too many tets (field data `TetGenSpeculativeRun`).
 *     The search stops early when a 1.3x longer edge leaves the count above 90 % of the last
 *     one: the surface sets the count (field data `TetGenSurfaceBoundCount`).
 *     A TetGen run that does not finish within its time limit (10 s + 40 us per expected
 *     tet of the TetGen process's own CPU time, so the machine's load does not matter; its
 *     refinement does not end near a knife edge or needle tip of the surface) is not
 *     retried at other edges: the surface is meshed without the quality and volume bounds
 *     (TetGen "pAQ", seconds), with a warning and field data `TetGenQualityBoundDropped` 1.
 *   - RadiusEdgeRatio: TetGen's quality bound -q (default 1.414, must be in [1.1, 10]; TetGen
 *     does not finish in practice below ~1.1).
 *
 * Errors (vtkErrorMacro, empty output): empty input, non-triangle polygons, an open /
 * non-manifold / inconsistently oriented / degenerate surface (the message counts the bad
 * edges or triangles), a self-intersecting surface, a TetGen failure, a parameter outside its
 * domain (or NaN), an edge length so small that more than 2e7 tets would result. Abort (ParaView's stop button) kills
 * TetGen and leaves the output empty.
 */
#ifndef vtkGLTetrahedralizeSurface_h
#define vtkGLTetrahedralizeSurface_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLOptionMacros.h"
#include "vtkUnstructuredGridAlgorithm.h"

#include "tetrahedralize/TetrahedralizeSurface.h"  // TetrahedralizeOptions: the parameters and their defaults

class GEOLATTICEFILTERS_EXPORT vtkGLTetrahedralizeSurface : public vtkUnstructuredGridAlgorithm {
public:
  static vtkGLTetrahedralizeSurface* New();
  vtkTypeMacro(vtkGLTetrahedralizeSurface, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // The setters do not clamp: an out-of-domain value is reported by RequestData (a negative
  // length is more likely a mistake than a request for "automatic"), like vtkGLPlaceOnPlatform.

  ///@{
  /// Target edge length (mm, default 0 = automatic from the enclosed volume and
  /// TargetTetCount; must be >= 0).
  vtkGLOptionMacro(TargetEdgeLength, double, targetEdgeLength);
  ///@}

  ///@{
  /// Tet count aimed at when TargetEdgeLength is 0 (default 75000, must be in [1000, 5000000]).
  vtkGLOptionMacro(TargetTetCount, int, autoTargetTets);
  ///@}

  ///@{
  /// Bound on circumradius / shortest edge of the tets, TetGen -q (default 1.414, must be in
  /// [1.1, 10]).
  vtkGLOptionMacro(RadiusEdgeRatio, double, radiusEdgeRatio);
  ///@}

protected:
  vtkGLTetrahedralizeSurface();
  ~vtkGLTetrahedralizeSurface() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  geolattice::TetrahedralizeOptions Options;  ///< the parameters, defaults from core

private:
  vtkGLTetrahedralizeSurface(const vtkGLTetrahedralizeSurface&) = delete;
  void operator=(const vtkGLTetrahedralizeSurface&) = delete;
};

#endif
