/**
 * @class   vtkGLToolpathReplay
 * @brief   The print replay of a toolpath: at time t, the part of it printed so far.
 *
 * GL Toolpath Planner's output is always the whole toolpath (what Apply shows); this filter adds
 * the time for ParaView's animation controls (Play, the time slider), as a slicer's preview does.
 *
 * Input:  vtkPolyData, the output of vtkGLToolpathPlanner: points in printing order, polyline
 *   cells in printing order, point and cell array `LayerId` (-1 on air moves).
 * Output: vtkPolyData, the toolpath printed up to the requested time, with the input's field data
 *   plus `ReplayLastPoint` (the last printed point index, -1 before the first):
 *   - StepBy Points (default): NumberOfTimeSteps time steps p = k / (NumberOfTimeSteps - 1) in
 *     [0, 1], the print progress by point count: at p the points 0 .. round(p (N - 1)) are
 *     printed, i.e. the cells that start before the last of them, the last cell cut there.
 *   - StepBy Layers: one time step per LayerId of the toolpath (t = the LayerId): the print cells
 *     (LayerId >= 0) of the layers <= t, as a slicer's layer slider (air moves are not shown).
 *   Without a time request (e.g. a plain Update()), the whole toolpath.
 *   KeepUnprintedPoints (default 1): every point and point array of the input is kept (a shallow
 *   copy, so a step costs only its cells) and only the cells are cut, so a point array's range -
 *   the colour map's range in ParaView - is that of the whole print at every step. 0: only the
 *   printed points (StepBy Points only; smaller files: the CLI's toolpath.pvd).
 *
 * Parameters: StepBy (0 Points, 1 Layers; default 0), NumberOfTimeSteps (default 200, >= 2;
 *   StepBy Points), KeepUnprintedPoints (default 1).
 *
 * Errors (vtkErrorMacro, empty output, RequestData returns 0): an input without points or line
 * cells, a missing LayerId array with StepBy Layers.
 */
#ifndef vtkGLToolpathReplay_h
#define vtkGLToolpathReplay_h

#include "GeoLatticeFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <vector>

class GEOLATTICEFILTERS_EXPORT vtkGLToolpathReplay : public vtkPolyDataAlgorithm {
public:
  static vtkGLToolpathReplay* New();
  vtkTypeMacro(vtkGLToolpathReplay, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum StepByModes { Points = 0, Layers = 1 };

  ///@{
  /// What a time step advances by: 0 Points (print progress), 1 Layers (default 0).
  vtkSetClampMacro(StepBy, int, Points, Layers);
  vtkGetMacro(StepBy, int);
  ///@}

  ///@{
  /// Time steps of StepBy Points (default 200, at least 2).
  vtkSetClampMacro(NumberOfTimeSteps, int, 2, 100000);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

  ///@{
  /// Keep the unprinted points (default 1: constant colour ranges); 0: the printed ones only.
  vtkSetMacro(KeepUnprintedPoints, vtkTypeBool);
  vtkGetMacro(KeepUnprintedPoints, vtkTypeBool);
  vtkBooleanMacro(KeepUnprintedPoints, vtkTypeBool);
  ///@}

protected:
  vtkGLToolpathReplay() = default;
  ~vtkGLToolpathReplay() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int StepBy = Points;
  int NumberOfTimeSteps = 200;
  vtkTypeBool KeepUnprintedPoints = 1;

private:
  vtkGLToolpathReplay(const vtkGLToolpathReplay&) = delete;
  void operator=(const vtkGLToolpathReplay&) = delete;
};

#endif
