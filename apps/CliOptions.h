#pragma once
/// @file CliOptions.h
/// @brief Command-line pieces shared by `geolattice run` and `geolattice verify`: usage errors,
/// number parsing, the nozzle options that both the sequencer and the verifier take, the
/// toolpath options and the robot program options.
#include "JsonWriter.h"

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace geolattice {

/// Bad command line: reported on one line, exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Parses a finite number or throws UsageError naming the flag.
double parseNumber(const std::string& flag, const std::string& text);

/// Parses `count` comma-separated finite numbers (e.g. X,Y,Z) or throws UsageError naming the
/// flag and `form` ("X,Y,Z").
std::vector<double> parseNumbers(const std::string& flag, const std::string& text, size_t count,
                                 const char* form);

/// @brief Nozzle model and material sampling (core/sequence/NozzleModel.h); 0 length = cone only.
struct NozzleOptions {
  double angle = 45.0;
  double length = 0.0;
  double holderRadius = 0.0;
  double tipClearance = 0.1;
  double tipFaceRadius = 0.5;
  double sampleSpacing = 1.0;

  /// Consumes --nozzle-angle, --nozzle-length, --holder-radius, --tip-clearance,
  /// --tip-face-radius and --sample-spacing (value() returns the option's argument); false for
  /// any other flag.
  bool parse(const std::string& flag, const std::function<std::string()>& value);

  /// Sets the nozzle properties of vtkGLPrintSequencer, vtkGLCollisionVerifier or
  /// vtkGLToolpathPlanner.
  template <class Filter>
  void applyNozzle(Filter* f) const {
    f->SetNozzleAngle(angle);
    f->SetNozzleLength(length);
    f->SetHolderRadius(holderRadius);
    f->SetTipClearance(tipClearance);
    f->SetTipFaceRadius(tipFaceRadius);
  }

  /// The nozzle and the sample spacing of vtkGLPrintSequencer or vtkGLCollisionVerifier.
  template <class Filter>
  void apply(Filter* f) const {
    applyNozzle(f);
    f->SetSampleSpacing(sampleSpacing);
  }

  /// Writes nozzle_angle_deg, nozzle_length_mm, holder_radius_mm, tip_clearance_mm,
  /// tip_face_radius_mm and sample_spacing_mm into a report section.
  void report(JsonObject& section) const;
};

/// @brief Toolpath parameters (core/toolpath/ToolpathPlanner.h) as command-line options.
struct ToolpathCliOptions {
  double pathWidth = 0.6;
  double filamentDiameter = 1.75;
  double flow = 0.95;
  double printSpeed = 10.0;
  double airSpeed = 50.0;
  double thicknessCap = 1.5;
  double maxTurn = 5.0;
  double safeMargin = 5.0;
  double lift = 2.0;
  double retraction = 1.0;
  double toothLength = 0.0;
  double maxSegment = 1.0;
  double maxTilt = 15.0;
  double tiltBlend = 5.0;
  bool perimeter = true;
  int replaySteps = 50;

  /// Consumes --path-width, --filament-diameter, --flow, --print-speed, --air-speed,
  /// --thickness-cap, --max-turn, --safe-margin, --lift, --retraction, --tooth-length,
  /// --max-segment, --max-tilt, --tilt-blend, --no-perimeter and --replay-steps (an integer >= 0, else UsageError); false for any other flag.
  bool parse(const std::string& flag, const std::function<std::string()>& value);

  /// Sets the properties of vtkGLToolpathPlanner.
  template <class Filter>
  void apply(Filter* f) const {
    f->SetPathWidth(pathWidth);
    f->SetFilamentDiameter(filamentDiameter);
    f->SetFlowCorrection(flow);
    f->SetPrintFeedRate(printSpeed);
    f->SetAirFeedRate(airSpeed);
    f->SetThicknessCap(thicknessCap);
    f->SetMaxTurnAngle(maxTurn);
    f->SetSafeMargin(safeMargin);
    f->SetLift(lift);
    f->SetRetraction(retraction);
    f->SetToothLength(toothLength);
    f->SetMaxSegmentLength(maxSegment);
    f->SetMaxAxisTilt(maxTilt);
    f->SetTiltBlendLength(tiltBlend);
    f->SetSupportPerimeter(perimeter);
  }

  /// Writes the parameters (path_width_mm, filament_diameter_mm, flow, print_speed_mm_s,
  /// air_speed_mm_s, thickness_cap, max_turn_deg, safe_margin_mm, lift_mm, retraction_mm,
  /// tooth_length_mm, max_segment_mm, max_tilt_deg, tilt_blend_mm, support_perimeter) into a
  /// report section.
  void report(JsonObject& section) const;
};

/// @brief The program stage (core/robot, core/program): the UR robot cell and the URScript
/// options (vtkGLURScriptWriter), the 5-axis G-code (vtkGLGCodeWriter) and its machine.
struct ProgramCliOptions {
  std::string robot = "ur5";
  double nozzleTip[3] = {0.0, -0.40, 0.30};  ///< m, robot base frame
  double nozzleAxis[3] = {0.0, 0.0, 1.0};
  double partOnFlange[6] = {0.0, 0.0, 0.04, 0.0, 0.0, 0.0};  ///< URScript pose (m, rad)
  double maxScriptBytes = 4000000;
  double speedFactor = 0.5;
  double maxFilamentRate = 5.0;  ///< mm/s of filament at 10 V
  double maxBlend = 0.0005;      ///< m
  double maxJointStep = 20.0;    ///< degrees
  bool allowUnreachable = false;
  std::string gcode = "ac";                 ///< ac | bc | none
  double gcodePivot[3] = {0.0, 0.0, 0.0};   ///< mm
  double gcodeOffset[3] = {0.0, 0.0, 0.0};  ///< mm
  double tiltLimits[2] = {-120.0, 120.0};   ///< degrees

  /// Consumes --robot (ur5 | ur5e), --nozzle-tip X,Y,Z, --nozzle-axis X,Y,Z, --part-offset Z,
  /// --part-on-flange X,Y,Z,RX,RY,RZ (not both of these two), --max-script-bytes (a whole number
  /// >= 10000), --speed-factor, --max-filament-rate, --max-blend, --max-joint-step, --allow-unreachable, --gcode
  /// (ac | bc | none), --gcode-pivot X,Y,Z, --gcode-offset X,Y,Z and --tilt-limits MIN,MAX;
  /// UsageError for a malformed value; false for any other flag.
  bool parse(const std::string& flag, const std::function<std::string()>& value);

  /// Sets the properties of vtkGLURScriptWriter (not the file name).
  template <class Writer>
  void applyScript(Writer* w) const {
    w->SetRobot(robot.c_str());
    w->SetNozzleTip(nozzleTip);
    w->SetNozzleAxis(nozzleAxis);
    w->SetPartOnFlange(partOnFlange);
    w->SetMaxFileBytes(static_cast<long long>(maxScriptBytes));
    w->SetSpeedFactor(speedFactor);
    w->SetMaxFilamentRate(maxFilamentRate);
    w->SetMaxBlend(maxBlend);
    w->SetMaxJointStep(maxJointStep);
    w->SetAllowUnreachable(allowUnreachable);
  }

  /// Sets the properties of vtkGLGCodeWriter (not the file name); gcode must not be "none".
  template <class Writer>
  void applyGCode(Writer* w) const {
    w->SetKinematics(gcode == "bc" ? 1 : 0);
    w->SetPivot(gcodePivot);
    w->SetPartOffset(gcodeOffset);
    w->SetTiltLimits(tiltLimits);
  }

  /// Writes robot, nozzle_tip_m, nozzle_axis, part_on_flange, max_script_bytes, speed_factor,
  /// max_filament_rate_mm_s, max_blend_m, max_joint_step_limit_deg and allow_unreachable into a
  /// report section.
  void report(JsonObject& section) const;

private:
  bool partOffsetGiven = false, partOnFlangeGiven = false;
};

}  // namespace geolattice
