#pragma once
/// @file ToolpathOutput.h
/// @brief The toolpath stage's files: the print replay (toolpath.pvd) of vtkGLToolpathPlanner's
/// output, as small as the toolpath itself.
///
/// Step k of S adds the piece of the path printed between progress (k - 1) / S and k / S
/// (toolpath/step_000k.vtp: its points, the first one shared with the previous piece so the line
/// is continuous, and the parts of the cells between them, with every array of toolpath.vtp).
/// toolpath.pvd lists, at time k / S, the pieces 1..k as parts 0..k-1 and toolpath/empty.vtp (no
/// points, the same arrays) as the parts k..S-1: ParaView 5.11's PVD reader takes the number of
/// parts from the first time step, so every step lists S parts; it shows a multiblock of S blocks
/// and, stepping forward, reads only the new piece. The files hold the toolpath's points once
/// (plus S - 1 shared ones), whatever the number of steps; the .pvd has S² entries, hence the
/// option's limit (kMaxReplaySteps).
#include <string>
#include <vector>

class vtkPolyData;

namespace geolattice {

/// Largest --replay-steps: the .pvd lists steps² data sets (500: 250 000 lines, ~18 MB).
constexpr int kMaxReplaySteps = 500;

/// Number of replay steps for a toolpath of `points` points: maxSteps, but no more than the
/// path has segments (at least 1); 0 when maxSteps is 0.
int replayStepCount(long long points, int maxSteps);

/// Writes OUTDIR/toolpath/step_0001.vtp .. step_NNNN.vtp (step k: the points
/// round((k - 1) / steps (N - 1)) .. round(k / steps (N - 1)) of the toolpath's N, the rule of
/// vtkGLToolpathReplay), OUTDIR/toolpath/empty.vtp and OUTDIR/toolpath.pvd (timestep k / steps:
/// the pieces up to k, so ParaView shows at time t what GL Toolpath Replay shows). Every file is
/// written atomically, the .pvd last; step files of an earlier run beyond the new count are
/// removed, and with steps == 0 the .pvd and every step file. Throws GeoLatticeError on a write
/// failure or a toolpath without points.
void writeToolpathReplay(vtkPolyData* toolpath, const std::string& outDir, int steps);

}  // namespace geolattice
