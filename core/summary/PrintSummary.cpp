#include "summary/PrintSummary.h"

#include "common/Error.h"

#include <cmath>
#include <set>
#include <string>

namespace geolattice {

void PrintSummaryOptions::validate() const {
  if (!(filamentDensity > 0) || !std::isfinite(filamentDensity)) {
    throw GeoLatticeError("print summary: filament density must be > 0 g/cm^3 (got " +
                          std::to_string(filamentDensity) + ")");
  }
}

PrintSummary summarizePrint(const PrintSummaryInput& in, const PrintSummaryOptions& options) {
  options.validate();
  const size_t n = in.points.size();
  if (in.feedRate.size() != n || in.moveKind.size() != n || in.layer.size() != n ||
      in.subgraph.size() != n) {
    throw GeoLatticeError("print summary: the toolpath's point arrays have different lengths");
  }
  PrintSummary s;
  s.points = static_cast<long long>(n);
  std::set<int> layers, subgraphs;
  for (size_t i = 0; i < n; ++i) {
    if (in.layer[i] >= 0) {
      layers.insert(in.layer[i]);
    }
    if (in.subgraph[i] >= 0) {
      subgraphs.insert(in.subgraph[i]);
    }
    if (i == 0) {
      continue;
    }
    const double length =
        std::hypot(in.points[i][0] - in.points[i - 1][0], in.points[i][1] - in.points[i - 1][1],
                   in.points[i][2] - in.points[i - 1][2]);
    if (length == 0.0) {
      continue;
    }
    if (!(in.feedRate[i] > 0) || !std::isfinite(in.feedRate[i])) {
      throw GeoLatticeError("print summary: toolpath point " + std::to_string(i) +
                            " has feed rate " + std::to_string(in.feedRate[i]) +
                            " (mm/s, must be > 0)");
    }
    const bool air = in.moveKind[i] == 2;
    (air ? s.airLength : s.printLength) += length;
    (air ? s.airSeconds : s.printSeconds) += length / in.feedRate[i];
  }
  s.layers = static_cast<int>(layers.size());
  s.subgraphs = static_cast<int>(subgraphs.size());
  s.filamentLength = in.filamentLength;
  const double radius = 0.5 * in.filamentDiameter;
  // mm³ -> cm³: 1e-3.
  s.filamentMass = in.filamentLength * M_PI * radius * radius * 1e-3 * options.filamentDensity;
  return s;
}

}  // namespace geolattice
