/**
 * @class   vtkGLPedestal
 * @brief   Raises the part on a printed pedestal of its own footprint, so that what bulges out
 *          right above the build plate can be printed from below.
 *
 * core/pedestal/Pedestal.h: the faces that touch the plate (within ContactHeight of the lowest
 * point, facing down; the same contact as GL Auto Orient's base area) are moved Height mm down
 * and joined to the part by vertical walls: a column of the contact area, printed with the part
 * (planar layers in it, a vertical nozzle) and cut off afterwards. With Height 0 (the default) the
 * surface passes unchanged. Why: curved layers curl around the base's rim, and where the part
 * bulges out just above the plate the nozzle would have to enter the plate to print them (the
 * collision verifier's plate stations); on a pedestal it has Height mm of room under them.
 *
 * Input:  vtkPolyData, the placed (and oriented) closed triangle surface, standing on z = 0.
 * Output: vtkPolyData, the part on its pedestal, the pedestal's bottom on z = 0 (x, y unchanged;
 *   the part is Height mm higher). Point and cell data are not kept (new points); the input's
 *   field data is, plus `PedestalHeight` (mm), `PedestalFootprintArea` (mm²) and
 *   `PedestalFootprintPieces` (boundary loops of the footprint).
 *
 * Parameters (core/pedestal/Pedestal.h, defaults there): Height (mm, default 0, in [0, 500]),
 * ContactHeight (mm, default 0.3, > 0), UseOrientation (default on): when the input comes from
 * GL Auto Orient's search (field data `OrientPedestalHeight`), the pedestal it chose for that
 * orientation (height and `OrientPedestalContactHeight`) replaces Height and ContactHeight, so
 * the part is built as it was scored (0: none); HeightOverride (mm, default -1 = none): the
 * height used in place of both (GLPrintPipeline::RaisePedestalByToolpath).
 *
 * Errors (vtkErrorMacro, empty output, RequestData returns 0): a bad parameter, an empty or
 * non-triangle input, a part that touches the plate at a tip or an edge only (no footprint:
 * orient it on a flat side first).
 */
#ifndef vtkGLPedestal_h
#define vtkGLPedestal_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLOptionMacros.h"
#include "vtkPolyDataAlgorithm.h"

#include "pedestal/Pedestal.h"  // PedestalOptions: the parameters and their defaults

class GEOLATTICEFILTERS_EXPORT vtkGLPedestal : public vtkPolyDataAlgorithm {
public:
  static vtkGLPedestal* New();
  vtkTypeMacro(vtkGLPedestal, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// How far the part is raised on its pedestal (mm, default 0 = no pedestal, in [0, 500]).
  vtkGLOptionMacro(Height, double, height);
  ///@}

  ///@{
  /// The footprint: faces within this height of the lowest point that face down (mm, default
  /// 0.3, > 0).
  vtkGLOptionMacro(ContactHeight, double, contactHeight);
  ///@}

  ///@{
  /// Build the pedestal GL Auto Orient chose when the input carries one (default on).
  vtkSetMacro(UseOrientation, bool);
  vtkGetMacro(UseOrientation, bool);
  vtkBooleanMacro(UseOrientation, bool);
  ///@}

  ///@{
  /// The height used in place of Height and of the orientation's choice (mm, default -1 = none;
  /// the footprint stays the orientation's). Not a user setting: GLPrintPipeline::
  /// RaisePedestalByToolpath sets it when a taller pedestal keeps the nozzle off the plate.
  vtkSetClampMacro(HeightOverride, double, -1.0, 500.0);
  vtkGetMacro(HeightOverride, double);
  ///@}

  /// The height of the pedestal this filter builds for `input` (mm; 0: it passes it through).
  double HeightFor(vtkDataObject* input);

  /// The stage's core options as the parameters set them (C++ only: a core type).
  VTK_WRAPEXCLUDE const geolattice::PedestalOptions& GetOptions() const { return this->Options; }

protected:
  vtkGLPedestal();
  ~vtkGLPedestal() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  geolattice::PedestalOptions Options;
  bool UseOrientation = true;
  double HeightOverride = -1.0;

private:
  vtkGLPedestal(const vtkGLPedestal&) = delete;
  void operator=(const vtkGLPedestal&) = delete;
};

#endif
