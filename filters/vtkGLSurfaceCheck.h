/**
 * @class   vtkGLSurfaceCheck
 * @brief   Shows why a surface cannot be tetrahedralized: its boundary, non-manifold and
 *          inconsistently oriented edges, and the verdict GL Tetrahedralize Surface would give.
 *
 * core/mesh/SurfaceCheck.h (checkSurface, requireClosedManifold) on the input as GL Tetrahedralize
 * Surface receives it. A diagnostic, not a stage: a surface with defects is its normal input, so
 * defects are no error; apply it where GL Tetrahedralize Surface (or GL Print Part) refuses a part
 * and colour the edges by DefectKind to see where to repair (ParaView's Fill Holes closes small
 * holes; a CAD tool repairs the rest).
 *
 * Input:  vtkPolyData, a triangle surface (any units).
 * Output: vtkPolyData, the input's points and one line cell per defect edge, cell data
 *   `DefectKind` (0 boundary: used by one triangle, a hole; 1 non-manifold: used by more than
 *   two; 2 inconsistently oriented: both of its triangles traverse it the same way); empty for a
 *   closed manifold. Field data: `SurfaceClosed` (1: closed, manifold, consistently oriented, no
 *   degenerate triangles, encloses a volume: GL Tetrahedralize Surface accepts it), the counts
 *   `BoundaryEdges`, `NonManifoldEdges`, `InconsistentEdges`, `DegenerateTriangles`,
 *   `SignedVolume` (input units³; < 0: inward, which GL Tetrahedralize Surface flips), and
 *   `SurfaceVerdict` (string: "closed manifold" or the refusal with where and how to repair).
 *
 * Parameters: none.
 *
 * Errors (vtkErrorMacro, empty output, RequestData returns 0): an input without triangles, a
 * polygon that is not a triangle.
 */
#ifndef vtkGLSurfaceCheck_h
#define vtkGLSurfaceCheck_h

#include "GeoLatticeFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class GEOLATTICEFILTERS_EXPORT vtkGLSurfaceCheck : public vtkPolyDataAlgorithm {
public:
  static vtkGLSurfaceCheck* New();
  vtkTypeMacro(vtkGLSurfaceCheck, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkGLSurfaceCheck() = default;
  ~vtkGLSurfaceCheck() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkGLSurfaceCheck(const vtkGLSurfaceCheck&) = delete;
  void operator=(const vtkGLSurfaceCheck&) = delete;
};

#endif
