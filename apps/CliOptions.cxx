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

} // namespace geolattice
