/**
 * @class   vtkGLCurvedLayerSlicer
 * @brief   Curved printing layers: the iso-surfaces γ = φ_i of the geodesic distance field.
 *
 * Marching tetrahedra on the tet grid (core/slicer/CurvedLayerSlicer.h, paper Section 2.2): each
 * layer is a triangle mesh with shared points (exact topology), oriented with normals along +∇γ,
 * the nozzle direction. φ_i = FirstLayerOffset + i * LayerInterval for i = 0, 1, ... while
 * φ_i <= max γ, so there are floor((max γ - offset) / interval) + 1 layers.
 *
 * Input:  vtkUnstructuredGrid of tets with point arrays `Gamma`, `Alpha`, `Beta` (the output of
 *         vtkGLGeodesicDistanceFields).
 * Output port 0 (all layers) and port 1 (only the layer SelectedLayer, for browsing layers in the
 * GUI: drag the slider or animate the property), both vtkPolyData with
 *   - point data `Gamma` (= φ_i), `Alpha`, `Beta`, `Normals` (unit nozzle direction, set as the
 *     active normals), `SourceEdge` (the tet-mesh edge a point lies on, 2 ids) and
 *     `EdgeParameter` (t along that edge);
 *   - cell data `LayerId` (index i of the layer) and `LayerComponent` (connected piece within
 *     the layer);
 *   - field data `LayerValues` (φ_i of each extracted layer), and when ComputeStatistics is on,
 *     per layer `LayerArea` (mm²), `LayerComponents`, `LayerSpacingMin`/`Mean`/`Max` (distance
 *     from the layer's points to the next layer, mm; NaN for the last layer).
 * Parameters: LayerInterval (mm, default 0.6, > 0), FirstLayerOffset (mm, default 0.6, > 0),
 *   FirstLayer / LastLayer (index range; LastLayer -1 = to the top), SelectedLayer (default 0),
 *   ComputeStatistics (default on), MaximumElements (default 40e6: more estimated layer points
 *   + triangles is refused before slicing, see core/common/WorkLimit.h).
 * Errors (missing arrays, interval <= 0, an offset above max γ so that there is no layer,
 * non-tet cells) are reported with vtkErrorMacro and give empty outputs.
 */
#ifndef vtkGLCurvedLayerSlicer_h
#define vtkGLCurvedLayerSlicer_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLOptionMacros.h"
#include "vtkPolyDataAlgorithm.h"

#include "slicer/CurvedLayerSlicer.h"  // SlicerOptions: the parameters and their defaults

class GEOLATTICEFILTERS_EXPORT vtkGLCurvedLayerSlicer : public vtkPolyDataAlgorithm {
public:
  static vtkGLCurvedLayerSlicer* New();
  vtkTypeMacro(vtkGLCurvedLayerSlicer, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// γ distance between consecutive layers (mm, default 0.6).
  vtkGLOptionMacro(LayerInterval, double, interval);
  ///@}

  ///@{
  /// γ of the first layer (mm, default 0.6).
  vtkGLOptionMacro(FirstLayerOffset, double, firstLayerOffset);
  ///@}

  ///@{
  /// Bound against runaway work (core/common/WorkLimit.h): an output estimated to have more
  /// elements than this is refused before it is built (default 40e6, about 8 GB).
  vtkGLOptionClampMacro(MaximumElements, double, maxElements, 1.0, VTK_DOUBLE_MAX);
  ///@}

  ///@{
  /// Range of layer indices to extract (default 0 .. -1 = all).
  vtkGLOptionMacro(FirstLayer, int, firstLayer);
  vtkGLOptionMacro(LastLayer, int, lastLayer);
  ///@}

  ///@{
  /// Layer index shown on output port 1 (default 0). Out of range gives an empty port 1.
  vtkSetMacro(SelectedLayer, int);
  vtkGetMacro(SelectedLayer, int);
  ///@}

  ///@{
  /// Compute per-layer area, components and spacing (default on).
  vtkSetMacro(ComputeStatistics, vtkTypeBool);
  vtkGetMacro(ComputeStatistics, vtkTypeBool);
  vtkBooleanMacro(ComputeStatistics, vtkTypeBool);
  ///@}

protected:
  vtkGLCurvedLayerSlicer();
  ~vtkGLCurvedLayerSlicer() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  geolattice::SlicerOptions Options;  ///< the parameters, defaults from core
  int SelectedLayer = 0;
  vtkTypeBool ComputeStatistics = true;

private:
  vtkGLCurvedLayerSlicer(const vtkGLCurvedLayerSlicer&) = delete;
  void operator=(const vtkGLCurvedLayerSlicer&) = delete;
};

#endif
