/**
 * @class   vtkGLPlaceOnPlatform
 * @brief   Scales a model uniformly and moves it so that its base sits on the platform z = 0.
 *
 * Printing starts from the platform: the later stages take the lowest part of the model as
 * the base (heat source of the γ field), so the model is placed with min z = 0, optionally
 * centred in x and y, and brought to millimetres by a uniform scale.
 *
 * Input:  any vtkPointSet (vtkPolyData surface or vtkUnstructuredGrid tet mesh), non-empty.
 * Output: the same type and topology with every point mapped to
 *   p_out = s * p_in + t,
 * where s = Scale, or FitSize / (largest bounding-box side) when FitSize > 0, and
 * t = (-s * cx, -s * cy, -s * zmin) with (cx, cy) the bounding-box centre in x, y if CenterXY,
 * else t = (0, 0, -s * zmin). Point and cell arrays are passed unchanged (a uniform positive
 * scale keeps directions). Output points are double precision, so min z = 0 and the FitSize
 * side hold to double rounding even for single-precision input.
 * Field data (added to the input's): `PlacementScale` (1 value: s) and
 * `PlacementTranslation` (3 values: t, mm), names in vtkGLArrayNames.h.
 *
 * Parameters (core/placement/PlaceOnPlatform.h, defaults there): Scale, FitSize, CenterXY,
 * FillHoles, FillCavities, Wrap (see the Set/Get blocks below). With FillHoles, a surface's holes are
 * closed first (core/mesh/HoleFilling.h; field data `FilledHoles`, `FilledHoleTriangles`), then
 * placed: the patches count in the bounding box. With FillCavities, its sealed voids are filled
 * (core/mesh/ShellNesting.h; field data `FilledCavities`). With Wrap > 0, a surface is replaced
 * by its alpha wrap after its holes are closed (with FillHoles) and before its cavities are
 * filled (core/mesh/SurfaceWrap.h; field data `WrapTriangles`: the wrap's triangles): closed
 * and free of crossing facets whatever the input's defects.
 *
 * Errors (vtkErrorMacro, empty output, RequestData returns 0): Scale <= 0, FitSize < 0, Wrap < 0,
 * a wrap estimated above the work limit, an empty input, FitSize > 0 for a model whose bounding box has no extent, non-finite coordinates, a
 * placed part whose largest side is outside 1 mm - 2 m (the likely unit mistake and its fix are
 * named: "is the file in metres? use Scale 1000 or FitSize MM"). Out-of-domain values are
 * reported rather than clamped so that a wrong unit is noticed.
 */
#ifndef vtkGLPlaceOnPlatform_h
#define vtkGLPlaceOnPlatform_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLOptionMacros.h"
#include "vtkPointSetAlgorithm.h"

#include "placement/PlaceOnPlatform.h"  // PlacementOptions: the parameters and their defaults

class GEOLATTICEFILTERS_EXPORT vtkGLPlaceOnPlatform : public vtkPointSetAlgorithm {
public:
  static vtkGLPlaceOnPlatform* New();
  vtkTypeMacro(vtkGLPlaceOnPlatform, vtkPointSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Uniform scale factor (default 1, > 0). Ignored when FitSize > 0.
  vtkGLOptionMacro(Scale, double, scale);
  ///@}

  ///@{
  /// Target largest bounding-box side after scaling (mm, default 0 = use Scale, >= 0).
  vtkGLOptionMacro(FitSize, double, fitSize);
  ///@}

  ///@{
  /// Centre the bounding box in x and y on the origin (default on).
  vtkGLOptionBooleanMacro(CenterXY, centerXY);
  ///@}

  ///@{
  /// Close the holes of a surface before placing it (default off; core/mesh/HoleFilling.h:
  /// CGAL's triangulate, refine and fair). Ignored for a tet mesh. The output is then the closed
  /// surface (new points and triangles: the input's point and cell arrays are not passed).
  vtkGLOptionBooleanMacro(FillHoles, fillHoles);
  ///@}

  ///@{
  /// Fill the closed inner cavities of a surface (default off; core/mesh/ShellNesting.h): the
  /// shells of sealed voids (and anything loose inside them) are removed, so the part is printed
  /// solid there; no nozzle reaches inside a sealed void. Ignored for a tet mesh. The output is
  /// then the welded, repaired surface (core/mesh/SurfaceRepair.h) without those shells.
  vtkGLOptionBooleanMacro(FillCavities, fillCavities);
  ///@}

  ///@{
  /// Replace a surface by its alpha wrap at this resolution before placing it (mm of the placed
  /// part, default 0 = off, >= 0; core/mesh/SurfaceWrap.h: CGAL::alpha_wrap_3, offset Wrap / 30
  /// outward). For surfaces nothing else repairs: facets crossing each other, non-manifold
  /// edges, overlapping or touching bodies, holes. The wrap approximates the part: features and
  /// gaps narrower than Wrap close, sealed voids fill; a hole wider than Wrap lets the wrap
  /// inside (a thin shell around an open sheet): close such holes with FillHoles, which runs
  /// first. Ignored for a tet mesh. The output is then the wrap (the input's point and cell
  /// arrays are not passed).
  vtkGLOptionMacro(Wrap, double, wrap);
  ///@}

protected:
  vtkGLPlaceOnPlatform();
  ~vtkGLPlaceOnPlatform() override = default;

  int ExecuteInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  geolattice::PlacementOptions Options;  ///< the parameters, defaults from core

private:
  vtkGLPlaceOnPlatform(const vtkGLPlaceOnPlatform&) = delete;
  void operator=(const vtkGLPlaceOnPlatform&) = delete;
};

#endif
