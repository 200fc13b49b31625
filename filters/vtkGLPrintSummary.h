/**
 * @class   vtkGLPrintSummary
 * @brief   The numbers a slicer shows before printing, as a table: layers, sub-graphs, lengths,
 *          estimated print time, filament length and mass, and the strict collision verdict.
 *
 * core/summary/PrintSummary.h. ParaView shows the output in a spreadsheet view.
 *
 * Input 0: vtkPolyData, the toolpath (vtkGLToolpathPlanner's output: point arrays FeedRate,
 *   MoveKind, LayerId, SubgraphId, Extrusion; field data ToolpathTours, ToolpathRetractions,
 *   ToolpathFilament, ToolpathFilamentDiameter, ToolpathMaxAxisTilt, ToolpathCollisionFree,
 *   ToolpathUnclearedStations).
 * Input 1 (optional): vtkPolyData, GL Collision Verifier on that toolpath (field data
 *   CollisionFree, CollisionStations, CollisionViolatingStations, CollisionPlateStations): the
 *   strict, independent verdict; without it the planner's own final check is shown.
 * Output: vtkTable, one row per quantity, columns `Quantity` (what), `Value`, `Unit` and `Key`
 *   (the name in the CLI's report.json "summary" section): layers, sub-graphs, toolpath points,
 *   tours, retractions, print length (mm), air length (mm), estimated print time (min: Σ length /
 *   feed rate, no acceleration), filament length (m) and mass (g), largest nozzle axis tilt
 *   (degrees), collision-free (1/0), colliding stations, stations at the build plate, stations
 *   checked. Field data `SummaryVerdict` (one string: the verdict in words, for an annotation).
 *
 * Parameters: FilamentDensity (g/cm³, default 1.24 = PLA, > 0).
 *
 * Errors (vtkErrorMacro, empty output, RequestData returns 0): an empty toolpath, a missing
 * point array, a bad parameter.
 */
#ifndef vtkGLPrintSummary_h
#define vtkGLPrintSummary_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLOptionMacros.h"
#include "vtkTableAlgorithm.h"

#include "summary/PrintSummary.h"  // PrintSummaryOptions: the parameters and their defaults

class GEOLATTICEFILTERS_EXPORT vtkGLPrintSummary : public vtkTableAlgorithm {
public:
  static vtkGLPrintSummary* New();
  vtkTypeMacro(vtkGLPrintSummary, vtkTableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Density of the filament (g/cm³, default 1.24 = PLA, > 0).
  vtkGLOptionMacro(FilamentDensity, double, filamentDensity);
  ///@}

protected:
  vtkGLPrintSummary();
  ~vtkGLPrintSummary() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  geolattice::PrintSummaryOptions Options;  ///< the parameters, defaults from core

private:
  vtkGLPrintSummary(const vtkGLPrintSummary&) = delete;
  void operator=(const vtkGLPrintSummary&) = delete;
};

#endif
