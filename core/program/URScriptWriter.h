#pragma once
/// @file URScriptWriter.h
/// @brief The UR program that prints a toolpath in the robot cell (paper Section 4, Fig. 19):
/// `def print_part(): … end` with set_tcp, time-based movel per toolpath segment, blending,
/// extrusion synchronised with the motion, retractions and air moves; split into numbered
/// programs below a size limit (only at air moves) because UR controllers reject very large
/// scripts.
///
/// Motion: the TCP is the part frame on the flange (RobotCell::partOnFlange), so every target is
/// the part pose that puts the toolpath point at the nozzle tip (RobotPath joints through FK).
/// Segment time t = max(L / f, max_j |Δq_j| / (speedFactor · q̇max_j)), L the toolpath segment
/// length and f its feed rate, so no joint exceeds its speed limit (rotation steps at one
/// position get their time from the joints). Where the robot path adds waypoints between two
/// points (RobotPath::via: the wrist near its singularity), the segment is one movel per
/// waypoint, each timed so, its share of L by the move parameter, after a comment line
/// "# K waypoint(s) between toolpath points i-1 and i". Blend radius = min(maxBlend, 0.4 ×
/// the shorter neighbouring TCP segment), 0 at the ends of print runs and air moves.
/// Extrusion (wiring assumption, documented in the user guide): the extruder driver follows
/// standard analog output 0 (relative level 0..1, i.e. 0-10 V) = 0..maxFilamentRate mm/s of filament; before each movel
/// the program sets it to ΔE / t of that segment (0 on air moves; retraction and prime are
/// separate moves of the extruder: set_standard_digital_out(0/1) pulses are not used). Numbers
/// are printed with at most 6 decimals.
/// Reconfigurations of the robot path (RobotPathSolver.h, step 4) are written where they happen:
/// movel straight away from the nozzle, movej (a = 1 rad/s², v = min(0.5 rad/s, speedFactor ×
/// the slowest joint's limit)) to the new configuration, movel to the next point, the extruder
/// off, with a
/// comment line naming the branches, the distance and the clearance.
#include "robot/RobotPathSolver.h"

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace geolattice {

struct URScriptOptions {
  double maxBlend = 0.0005;         ///< m
  double blendFraction = 0.4;       ///< of the shorter neighbouring segment
  double speedFactor = 0.5;         ///< fraction of the joint speed limits used
  double maxFilamentRate = 5.0;     ///< mm/s of filament at 10 V
  double retractionRate = 20.0;     ///< mm/s of filament while retracting / priming
  size_t maxFileBytes = 4'000'000;  ///< split programs below this size (at air moves)
  std::string programName = "print_part";
  /// Comment lines written after the first line of every program file (e.g. the cell layout the
  /// path solver chose). Optional.
  std::vector<std::string> headerComments;
};

/// What one toolpath point needs (part units, see Toolpath).
struct ProgramInput {
  const std::vector<Eigen::Vector3d>* points = nullptr;
  const std::vector<double>* extrusion = nullptr;  ///< cumulative E (mm)
  const std::vector<double>* feedRate = nullptr;   ///< part units / s
  const std::vector<int>* kind = nullptr;          ///< 0 print, 1 perimeter, 2 air
};

struct ProgramStats {
  size_t files = 0;
  size_t moves = 0;
  double maxJointSpeedDegS = 0;  ///< with the computed segment times
  double duration = 0;           ///< s, sum of segment times
  size_t maxLineLength = 0;
};

/// Writes the programs; openFile(k) returns the stream for program file k (0, 1, …). Throws
/// GeoLatticeError for mismatched sizes, an empty path or bad options.
ProgramStats writeURScript(const RobotCell& cell, const RobotPath& robotPath,
                           const ProgramInput& input, const URScriptOptions& options,
                           const std::function<std::ostream&(size_t)>& openFile);

/// The number formatted with at most 6 decimals, no trailing zeros, no "-0".
std::string urNumber(double v);

}  // namespace geolattice
