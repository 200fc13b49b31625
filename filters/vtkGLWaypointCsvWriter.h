/**
 * @class   vtkGLWaypointCsvWriter
 * @brief   Writes a toolpath as a waypoint table (CSV) for other robot or machine software.
 *
 * core/program/WaypointCsvWriter.h (writeWaypointCsv): the header `x,y,z,nx,ny,nz,e,kind,layer` and
 * one row per toolpath point in printing order: position (mm, platform frame), unit nozzle axis,
 * cumulative filament E (mm), MoveKind (0 print, 1 perimeter, 2 air) and the lattice's LayerId
 * (-1 on air moves); numbers with at most 6 decimals.
 *
 * Input: vtkPolyData, the output of vtkGLToolpathPlanner (points in point order = printing
 *   order, point arrays `NozzleAxis`, `Extrusion`, `FeedRate`, `MoveKind`, `LayerId`; see
 *   vtkGLURScriptWriter). A time-dependent input is requested at the end of its time range:
 *   the whole toolpath.
 * Output: FileName (e.g. waypoints.csv), written to a temporary name first and renamed when
 *   complete: on an error no file (nor partial file) is left and an earlier file of that name
 *   is untouched.
 * Results of the last Write(): GetNumberOfRows (waypoints written, 0 after an error).
 * Errors (no FileName, an empty toolpath, missing arrays, a NaN point or a NaN / zero normal, a
 *   file that cannot be written) are reported with vtkErrorMacro; Write() then returns 0.
 */
#ifndef vtkGLWaypointCsvWriter_h
#define vtkGLWaypointCsvWriter_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLToolpathWriter.h"

class GEOLATTICEFILTERS_EXPORT vtkGLWaypointCsvWriter : public vtkGLToolpathWriter {
public:
  static vtkGLWaypointCsvWriter* New();
  vtkTypeMacro(vtkGLWaypointCsvWriter, vtkGLToolpathWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Waypoints written by the last Write() (0 after an error).
  vtkIdType GetNumberOfRows() const { return this->NumberOfRows; }

protected:
  vtkGLWaypointCsvWriter();
  ~vtkGLWaypointCsvWriter() override;

  void WriteData() override;

private:
  vtkGLWaypointCsvWriter(const vtkGLWaypointCsvWriter&) = delete;
  void operator=(const vtkGLWaypointCsvWriter&) = delete;

  vtkIdType NumberOfRows = 0;
};

#endif
