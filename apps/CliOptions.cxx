#include "CliOptions.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace geolattice {

double parseNumber(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) {
    throw UsageError(flag + " expects a number, got '" + text + "'");
  }
  return v;
}

std::vector<double> parseNumbers(const std::string& flag, const std::string& text, size_t count,
                                 const char* form) {
  std::vector<double> out;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string part =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    char* end = nullptr;
    const double v = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !std::isfinite(v) || out.size() == count) {
      throw UsageError(flag + " expects " + form + ", got '" + text + "'");
    }
    out.push_back(v);
    if (comma == std::string::npos) {
      break;
    }
    start = comma + 1;
  }
  if (out.size() != count) {
    throw UsageError(flag + " expects " + form + ", got '" + text + "'");
  }
  return out;
}

bool NozzleOptions::parse(const std::string& flag, const std::function<std::string()>& value) {
  double* target = flag == "--nozzle-angle"      ? &angle
                   : flag == "--nozzle-length"   ? &length
                   : flag == "--holder-radius"   ? &holderRadius
                   : flag == "--tip-clearance"   ? &tipClearance
                   : flag == "--tip-face-radius" ? &tipFaceRadius
                   : flag == "--sample-spacing"  ? &sampleSpacing
                                                 : nullptr;
  if (!target) {
    return false;
  }
  // Ranges are checked by the filters (same messages as in ParaView).
  *target = parseNumber(flag, value());
  return true;
}

void NozzleOptions::report(JsonObject& s) const {
  s.set("nozzle_angle_deg", angle);
  s.set("nozzle_length_mm", length);
  s.set("holder_radius_mm", holderRadius);
  s.set("tip_clearance_mm", tipClearance);
  s.set("tip_face_radius_mm", tipFaceRadius);
  s.set("sample_spacing_mm", sampleSpacing);
}

bool ToolpathCliOptions::parse(const std::string& flag, const std::function<std::string()>& value) {
  if (flag == "--no-perimeter") {
    perimeter = false;
    return true;
  }
  if (flag == "--replay-steps") {
    const std::string text = value();
    const double v = parseNumber(flag, text);
    if (v < 0 || v != std::floor(v) || v > 9999) {
      throw UsageError(flag + " expects a whole number from 0 to 9999, got '" + text + "'");
    }
    replaySteps = static_cast<int>(v);
    return true;
  }
  double* target = flag == "--path-width"          ? &pathWidth
                   : flag == "--filament-diameter" ? &filamentDiameter
                   : flag == "--flow"              ? &flow
                   : flag == "--print-speed"       ? &printSpeed
                   : flag == "--air-speed"         ? &airSpeed
                   : flag == "--thickness-cap"     ? &thicknessCap
                   : flag == "--max-turn"          ? &maxTurn
                   : flag == "--safe-margin"       ? &safeMargin
                   : flag == "--lift"              ? &lift
                   : flag == "--retraction"        ? &retraction
                   : flag == "--tooth-length"      ? &toothLength
                   : flag == "--max-segment"       ? &maxSegment
                   : flag == "--max-tilt"          ? &maxTilt
                   : flag == "--tilt-blend"        ? &tiltBlend
                                                   : nullptr;
  if (!target) {
    return false;
  }
  // Ranges are checked by the planner filter (same messages as in ParaView).
  *target = parseNumber(flag, value());
  return true;
}

void ToolpathCliOptions::report(JsonObject& s) const {
  s.set("path_width_mm", pathWidth);
  s.set("filament_diameter_mm", filamentDiameter);
  s.set("flow", flow);
  s.set("print_speed_mm_s", printSpeed);
  s.set("air_speed_mm_s", airSpeed);
  s.set("thickness_cap", thicknessCap);
  s.set("max_turn_deg", maxTurn);
  s.set("safe_margin_mm", safeMargin);
  s.set("lift_mm", lift);
  s.set("retraction_mm", retraction);
  s.set("tooth_length_mm", toothLength);
  s.set("max_segment_mm", maxSegment);
  s.set("max_tilt_deg", maxTilt);
  s.set("tilt_blend_mm", tiltBlend);
  s.set("support_perimeter", perimeter);
}

bool ProgramCliOptions::parse(const std::string& flag, const std::function<std::string()>& value) {
  auto copy = [](const std::vector<double>& from, double* to) {
    std::copy(from.begin(), from.end(), to);
  };
  if (flag == "--robot") {
    robot = value();
    if (robot != "ur5" && robot != "ur5e") {
      throw UsageError("--robot must be ur5 or ur5e (got '" + robot + "')");
    }
  } else if (flag == "--nozzle-tip")
    copy(parseNumbers(flag, value(), 3, "X,Y,Z (m)"), nozzleTip);
  else if (flag == "--nozzle-axis")
    copy(parseNumbers(flag, value(), 3, "X,Y,Z"), nozzleAxis);
  else if (flag == "--part-offset" || flag == "--part-on-flange") {
    const bool offset = flag == "--part-offset";
    if (offset ? partOnFlangeGiven : partOffsetGiven) {
      throw UsageError("--part-offset and --part-on-flange exclude each other");
    }
    if (offset) {
      const double z = parseNumber(flag, value());
      const double pose[6] = {0.0, 0.0, z, 0.0, 0.0, 0.0};
      std::copy(pose, pose + 6, partOnFlange);
      partOffsetGiven = true;
    } else {
      copy(parseNumbers(flag, value(), 6, "X,Y,Z,RX,RY,RZ (m, rad)"), partOnFlange);
      partOnFlangeGiven = true;
    }
  } else if (flag == "--max-script-bytes") {
    const std::string text = value();
    const double v = parseNumber(flag, text);
    if (v < 10000 || v != std::floor(v) || v > 1e12) {
      throw UsageError(flag + " expects a whole number of bytes >= 10000, got '" + text + "'");
    }
    maxScriptBytes = v;
  } else if (flag == "--speed-factor")
    speedFactor = parseNumber(flag, value());
  else if (flag == "--max-filament-rate")
    maxFilamentRate = parseNumber(flag, value());
  else if (flag == "--max-blend")
    maxBlend = parseNumber(flag, value());
  else if (flag == "--max-joint-step")
    maxJointStep = parseNumber(flag, value());
  else if (flag == "--allow-unreachable")
    allowUnreachable = true;
  else if (flag == "--gcode") {
    gcode = value();
    if (gcode != "ac" && gcode != "bc" && gcode != "none") {
      throw UsageError("--gcode must be ac, bc or none (got '" + gcode + "')");
    }
  } else if (flag == "--gcode-pivot")
    copy(parseNumbers(flag, value(), 3, "X,Y,Z (mm)"), gcodePivot);
  else if (flag == "--gcode-offset")
    copy(parseNumbers(flag, value(), 3, "X,Y,Z (mm)"), gcodeOffset);
  else if (flag == "--tilt-limits")
    copy(parseNumbers(flag, value(), 2, "MIN,MAX (degrees)"), tiltLimits);
  else
    return false;
  // Ranges are checked by the writers (same messages as in ParaView).
  return true;
}

void ProgramCliOptions::report(JsonObject& s) const {
  s.set("robot", robot);
  s.set("nozzle_tip_m", std::vector<double>(nozzleTip, nozzleTip + 3));
  s.set("nozzle_axis", std::vector<double>(nozzleAxis, nozzleAxis + 3));
  s.set("part_on_flange", std::vector<double>(partOnFlange, partOnFlange + 6));
  s.set("max_script_bytes", static_cast<long long>(maxScriptBytes));
  s.set("speed_factor", speedFactor);
  s.set("max_filament_rate_mm_s", maxFilamentRate);
  s.set("max_blend_m", maxBlend);
  s.set("max_joint_step_limit_deg", maxJointStep);
  s.set("allow_unreachable", allowUnreachable);
}

}  // namespace geolattice
