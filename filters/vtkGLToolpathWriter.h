/**
 * @class   vtkGLToolpathWriter
 * @brief   Base of the machine-program writers (GL URScript Writer, GL G-Code Writer, GL Waypoint
 *          CSV Writer): a toolpath input, a file name, and the safety gate.
 *
 * Input: vtkPolyData, the output of vtkGLToolpathPlanner (point arrays NozzleAxis, Extrusion,
 * FeedRate, MoveKind, LayerId; field data ToolpathCollisionFree, the planner's verdict). A
 * time-dependent input (the planner's replay) is written whole.
 *
 * Safety gate: a toolpath whose ToolpathCollisionFree is 0 (the nozzle or the build plate would
 * hit printed material) or that carries no verdict is refused with an error naming the colliding
 * station count, and nothing is written, unless AllowCollisions is on (then the program is
 * written and a warning says so).
 *
 * Parameters are checked in the information pass (CheckParameters), before any upstream filter
 * computes data: a bad writer parameter fails a pipeline update at once.
 */
#ifndef vtkGLToolpathWriter_h
#define vtkGLToolpathWriter_h

#include "GeoLatticeFiltersModule.h"
#include "vtkWriter.h"

class vtkPolyData;

class GEOLATTICEFILTERS_EXPORT vtkGLToolpathWriter : public vtkWriter {
public:
  vtkTypeMacro(vtkGLToolpathWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to write.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Write the program even if the toolpath collides or carries no collision verdict (default
  /// off: such a toolpath is refused).
  vtkSetMacro(AllowCollisions, vtkTypeBool);
  vtkGetMacro(AllowCollisions, vtkTypeBool);
  vtkBooleanMacro(AllowCollisions, vtkTypeBool);
  ///@}

protected:
  vtkGLToolpathWriter();
  ~vtkGLToolpathWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
                             vtkInformationVector* outputVector) override;

  /// Throws GeoLatticeError naming the first writer parameter out of its range (none here);
  /// called on the information request and again by WriteData.
  virtual void CheckParameters() {}
  /// Throws GeoLatticeError (naming `what`, e.g. "URScript writer") unless the toolpath passed
  /// the collision check or AllowCollisions is on; warns in the latter case.
  void CheckCollisionVerdict(vtkPolyData* toolpath, const char* what);
  /// Throws GeoLatticeError naming `what` when FileName is empty.
  void CheckFileName(const char* what);

  char* FileName = nullptr;
  vtkTypeBool AllowCollisions = false;

private:
  vtkGLToolpathWriter(const vtkGLToolpathWriter&) = delete;
  void operator=(const vtkGLToolpathWriter&) = delete;
};

#endif
