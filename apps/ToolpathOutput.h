#pragma once
/// @file ToolpathOutput.h
/// @brief The toolpath stage's files: the print replay (toolpath.pvd with cumulative step files)
/// from vtkGLToolpathPlanner's output, cut by vtkGLToolpathReplay.
///
/// Why cumulative step files: a .pvd time series shows the data set(s) listed for the current
/// time, so replaying a growing print needs, per step, everything printed so far. Each step file
/// is a complete, standalone toolpath (vtkPolyData with the arrays of toolpath.vtp) that any VTK
/// reader opens. Alternatives: one toolpath.vtp referenced by every step shows the whole path at
/// every time; per-step pieces listed as parts 0..k do not work with ParaView 5.11's PVD reader
/// (it takes the output type from the first time step, one part = vtkPolyData, and then reads only
/// part 0), and padding every step to the same number of parts with placeholder files works but
/// gives a multiblock of `steps` blocks and steps² entries. The price of cumulative files is disk
/// space, about steps / 2 times toolpath.vtp, so their number is capped (replayStepCount).
#include <string>
#include <vector>

class vtkDataObject;
class vtkGLToolpathReplay;

namespace geolattice {

/// Number of replay steps for a toolpath of `points` points: maxSteps, but fewer when the
/// cumulative files would hold more than about 2 million points in total (at least 1);
/// 0 when maxSteps is 0.
int replayStepCount(long long points, int maxSteps);

/// Writes OUTDIR/toolpath/step_0001.vtp .. step_NNNN.vtp, step k holding the toolpath printed up
/// to progress k / steps (vtkGLToolpathReplay at that time, StepBy Points, the printed points
/// only), and OUTDIR/toolpath.pvd listing them with timestep = k / steps (the same times as the
/// filter's in ParaView; the last step is the whole path). Every file is written atomically, the
/// .pvd last; step files of an earlier run beyond the new count are removed, and with steps == 0
/// the .pvd and all step files. `replay` is the pipeline's (its input, the toolpath, updated
/// before); it is set to StepBy Points and the printed points only. Returns the paths written (the steps as one pattern). Throws
/// GeoLatticeError on a write failure or an empty step.
std::vector<std::string> writeToolpathReplay(vtkGLToolpathReplay* replay, const std::string& outDir,
                                             int steps);

}  // namespace geolattice
