#pragma once
/// @file WorkLimit.h
/// @brief Bounds against runaway work. A stage whose output size follows from its parameters
/// (layer points from the layer interval, lattice vertices from the line widths, toolpath
/// stations from the segment length) estimates that size before it allocates anything and
/// refuses more than a limit, naming the estimate, the memory it would take and the parameter to
/// change. Without it a typo (0.001 mm for 1 mm) grows until the kernel kills the process.
#include "common/Error.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace geolattice {

/// Default limit of every stage's estimated output elements: 40 million elements at the ~200
/// bytes each carries through the later stages is ~8 GB, a third of a 24 GiB workstation.
constexpr double kDefaultMaxElements = 40e6;
/// Bytes an output element costs until the end of the pipeline (its own arrays, the VTK copy,
/// the next stage's working set); used only for the message.
constexpr double kBytesPerElement = 200;

/// Throws unless limit > 0 and finite (`what` names the option).
inline void requireValidWorkLimit(double limit, const char* what) {
  if (!(limit > 0) || !std::isfinite(limit)) {
    std::ostringstream s;
    s << what << " must be > 0 (got " << limit << ")";
    throw GeoLatticeError(s.str());
  }
}

/// Throws GeoLatticeError "<stage>: about N million <elements> (about G GB) <because>, more than
/// the limit of M million: <fix>" when estimate > limit. The fixes name the limit MaximumElements,
/// as the filters call it (the CLI turns it into --max-elements).
/// bytesPerElement 0 leaves the memory out (work that is time, not memory).
inline void requireWithinWorkLimit(double estimate, double limit, const std::string& stage,
                                   const std::string& elements, const std::string& because,
                                   const std::string& fix,
                                   double bytesPerElement = kBytesPerElement) {
  if (!(estimate > limit)) {
    return;
  }
  std::ostringstream s;
  s << stage << ": about " << std::llround(estimate / 1e6) << " million " << elements << ' ';
  if (bytesPerElement > 0) {
    s << "(about " << std::llround(estimate * bytesPerElement / 1e9) << " GB) ";
  }
  s << because << ", more than the limit of " << std::setprecision(3) << limit / 1e6
    << " million: " << fix;
  throw GeoLatticeError(s.str());
}

}  // namespace geolattice
