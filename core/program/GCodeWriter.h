#pragma once
/// @file GCodeWriter.h
/// @brief 5-axis G-code for tilting-rotary table machines with a fixed vertical nozzle (tool
/// axis +Z): A–C (tilt about X, then rotary C about the table normal) or B–C (tilt about Y).
///
/// For a toolpath point p (part frame, mm) with nozzle axis n, the table angles turn n onto +Z:
/// n' = R_C(c)·n must lie in the tilt plane (A–C: n'x = 0, c = atan2(nx, ny); B–C: n'y = 0,
/// c = atan2(-ny, nx)), then the tilt brings it up (A–C: a = atan2(ρ, nz); B–C: b = atan2(-ρ, nz),
/// ρ = |n_xy|). The second branch is (c + π, −tilt). The branch is chosen once per path segment
/// by continuity and the tilt limits; C is unwrapped (no ±180° jumps). Near the pole C is
/// ill-conditioned: C may deviate from its exact value while the axis stays within
/// axisToleranceDeg (reported as maxAxisErrorDeg), and within those tubes C is chosen to turn by
/// at most maxRotaryStepDeg per point wherever possible (forward pass of reachable intervals,
/// backward pass of least motion; points where C must turn faster are counted), so the table
/// does not spin while it is almost flat.
///
/// Positions (the tool centre point): with ToolCentrePoint::Controller the program holds part
/// coordinates X Y Z = p + partOffset (partOffset: the part frame origin relative to the rotary
/// centre on the table) and the controller's table kinematics turns them into joint positions
/// (LinuxCNC's xyzac-trt-kins / xyzbc-trt-kins, whose rotation point is set in the machine's
/// INI; machines/linuxcnc/). With ToolCentrePoint::Cam the program holds the machine positions
/// X Y Z = pivot + R_tilt·R_C·(p + partOffset), pivot the machine position of the intersection of
/// the two rotary axes (a machine with trivial kinematics). The rotations are the machine's:
/// machine = R_tilt · R_C · part, so the nozzle axis in part coordinates is
/// (sin C sin A, cos C sin A, cos A) for A–C and (−cos C sin B, sin C sin B, cos B) for B–C.
///
/// Flavors (docs/user-guide.md, "G-code for 5-axis machines"):
///   - LinuxCNC: RS274NGC as LinuxCNC 2.9's interpreter reads it: G21 G90 G93, inverse-time feed
///     with F (1 / minutes) on every G1, extrusion as the absolute position of an extra axis
///     (default U), rapid G0 for air moves, comments in ( ), program end G94 M2. No E, no M83.
///   - RepRap: RepRapFirmware 3: G21 G90 M83 (relative extrusion, E), the rotary axes as further
///     axis letters (A/B and C, configured with M584 ... R1), feed in mm/min chosen so the
///     nozzle moves at the print speed relative to the part (the machine XYZ displacement of a
///     move divided by its planned time; deg/min for a move that only turns the table). Only
///     ToolCentrePoint::Cam (RepRapFirmware has no tilting-table kinematics). Not verified on a
///     machine: checked against RepRapFirmware's documented syntax only.
#include <Eigen/Core>

#include <ostream>
#include <string>
#include <vector>

namespace geolattice {

enum class TableKinematics { AC = 0, BC = 1 };
enum class GCodeFlavor { LinuxCNC = 0, RepRap = 1 };
enum class ToolCentrePoint { Controller = 0, Cam = 1 };

/// "linuxcnc", "reprap" <-> flavor; "controller", "cam" <-> tool centre point. The parsers throw
/// GeoLatticeError naming the valid values.
GCodeFlavor parseGCodeFlavor(const std::string& name);
const char* gcodeFlavorName(GCodeFlavor flavor);
ToolCentrePoint parseToolCentrePoint(const std::string& name);
const char* toolCentrePointName(ToolCentrePoint tcp);

struct GCodeOptions {
  TableKinematics kinematics = TableKinematics::AC;
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();       ///< mm, machine coordinates
  Eigen::Vector3d partOffset = Eigen::Vector3d::Zero();  ///< mm, in the table (C) frame
  double tiltMinDeg = -120.0, tiltMaxDeg = 120.0;        ///< A or B limits
  double poleToleranceDeg = 0.01;                        ///< |tilt| below this: C is kept
  /// Near the pole C is ill-conditioned (a 0.5° tilt in a random direction asks for any C). C
  /// may then deviate from its exact value as long as the tool axis stays within this angle of
  /// the nozzle axis (the tilt is re-optimised for that C).
  double axisToleranceDeg = 1.0;
  /// Largest change of C between consecutive points wherever the axis tolerance allows it.
  double maxRotaryStepDeg = 5.0;
  GCodeFlavor flavor = GCodeFlavor::LinuxCNC;
  ToolCentrePoint toolCentrePoint = ToolCentrePoint::Controller;  ///< Cam for RepRap
  /// LinuxCNC: the axis that carries the extruder's absolute filament position (mm). One of
  /// U V W, or the free rotary letter (B on an A–C table, A on a B–C table); not X Y Z, the tilt
  /// axis or C.
  char extrusionAxis = 'U';
  double retractionSeconds = 0.05;  ///< time of a retract or prime move (s, > 0)
  /// Throws GeoLatticeError naming a bad option (an extrusion axis the table uses, Controller
  /// with RepRap, limits min > max, ...).
  void validate() const;
};

struct GCodeStats {
  size_t moves = 0;
  size_t outOfLimits = 0;  ///< points whose tilt exceeds the limits on both branches
  double maxRotaryStepDeg = 0;
  size_t branchFlips = 0;
  double maxAxisErrorDeg = 0;    ///< from the C deviations near the pole (at most axisToleranceDeg)
  size_t forcedRotarySteps = 0;  ///< points where C had to turn by more than maxRotaryStepDeg
};

/// Rotary angles (degrees) for one axis direction: (tilt, c) of the branch nearest to
/// previousC (two branches: see the file comment).
void tableAngles(TableKinematics k, const Eigen::Vector3d& n, double previousC,
                 double poleToleranceDeg, double& tilt, double& c);

/// Writes the program. points/normals/extrusion/feedRate/kind as in Toolpath (kind 2 = air,
/// rapid G0 without E). Throws GeoLatticeError for mismatched sizes, an empty path or NaN data.
GCodeStats writeGCode(const std::vector<Eigen::Vector3d>& points,
                      const std::vector<Eigen::Vector3d>& normals,
                      const std::vector<double>& extrusion, const std::vector<double>& feedRate,
                      const std::vector<int>& kind, const GCodeOptions& options, std::ostream& out);

}  // namespace geolattice
