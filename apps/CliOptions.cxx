#include "CliOptions.h"

#include <cmath>
#include <cstdlib>

namespace geolattice {

double parseNumber(const std::string& flag, const std::string& text)
{
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v))
  {
    throw UsageError(flag + " expects a number, got '" + text + "'");
  }
  return v;
}

bool NozzleOptions::parse(const std::string& flag, const std::function<std::string()>& value)
{
  double* target = flag == "--nozzle-angle" ? &angle
    : flag == "--nozzle-length"            ? &length
    : flag == "--holder-radius"            ? &holderRadius
    : flag == "--tip-clearance"            ? &tipClearance
    : flag == "--sample-spacing"           ? &sampleSpacing
                                           : nullptr;
  if (!target)
  {
    return false;
  }
  // Ranges are checked by the filters (same messages as in ParaView).
  *target = parseNumber(flag, value());
  return true;
}

void NozzleOptions::report(JsonObject& s) const
{
  s.set("nozzle_angle_deg", angle);
  s.set("nozzle_length_mm", length);
  s.set("holder_radius_mm", holderRadius);
  s.set("tip_clearance_mm", tipClearance);
  s.set("sample_spacing_mm", sampleSpacing);
}

bool ToolpathCliOptions::parse(const std::string& flag, const std::function<std::string()>& value)
{
  if (flag == "--no-perimeter")
  {
    perimeter = false;
    return true;
  }
  if (flag == "--replay-steps")
  {
    const std::string text = value();
    const double v = parseNumber(flag, text);
    if (v < 0 || v != std::floor(v) || v > 9999)
    {
      throw UsageError(flag + " expects a whole number from 0 to 9999, got '" + text + "'");
    }
    replaySteps = static_cast<int>(v);
    return true;
  }
  double* target = flag == "--path-width"   ? &pathWidth
    : flag == "--filament-diameter"         ? &filamentDiameter
    : flag == "--flow"                      ? &flow
    : flag == "--print-speed"               ? &printSpeed
    : flag == "--air-speed"                 ? &airSpeed
    : flag == "--thickness-cap"             ? &thicknessCap
    : flag == "--max-turn"                  ? &maxTurn
    : flag == "--safe-margin"               ? &safeMargin
    : flag == "--lift"                      ? &lift
    : flag == "--retraction"                ? &retraction
    : flag == "--tooth-length"              ? &toothLength
                                            : nullptr;
  if (!target)
  {
    return false;
  }
  // Ranges are checked by the planner filter (same messages as in ParaView).
  *target = parseNumber(flag, value());
  return true;
}

void ToolpathCliOptions::report(JsonObject& s) const
{
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
  s.set("support_perimeter", perimeter);
}

} // namespace geolattice
