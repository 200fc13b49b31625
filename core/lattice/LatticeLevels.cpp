#include "lattice/LatticeLevels.h"

#include "common/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace geolattice {

namespace {

void requireWidth(double width, double phase) {
  if (!(width > 0) || !std::isfinite(width)) {
    throw GeoLatticeError("lattice width must be > 0 mm and finite (got " + std::to_string(width) +
                          ")");
  }
  if (!std::isfinite(phase)) {
    throw GeoLatticeError("lattice phase must be finite");
  }
}

void requireLevelCount(double span, double width) {
  if (span / width > kMaxLatticeLevels) {
    throw GeoLatticeError("lattice width " + std::to_string(width) + " mm gives more than " +
                          std::to_string(kMaxLatticeLevels) + " isolines over a field range of " +
                          std::to_string(span) + " mm");
  }
}

}  // namespace

std::vector<double> uniformLatticeLevels(double lo, double hi, double width, double phase) {
  requireWidth(width, phase);
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) {
    throw GeoLatticeError("invalid field range [" + std::to_string(lo) + ", " + std::to_string(hi) +
                          "]");
  }
  requireLevelCount(hi - lo, width);
  std::vector<double> levels;
  auto value = [&](double j) {
    return phase + j * width;
  };
  double j = std::floor((lo - phase) / width) - 1;
  while (value(j) <= lo) {
    j += 1;
  }
  for (; value(j) <= hi; j += 1) {
    levels.push_back(value(j));
  }
  return levels;
}

std::vector<double> gradedLatticeLevels(const std::vector<double>& f,
                                        const std::vector<double>& scale, double width,
                                        double phase) {
  requireWidth(width, phase);
  if (f.size() != scale.size()) {
    throw GeoLatticeError("width scale has " + std::to_string(scale.size()) + " values for " +
                          std::to_string(f.size()) + " layer points");
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, sMin = lo;
  for (size_t p = 0; p < f.size(); ++p) {
    if (!std::isfinite(f[p])) {
      throw GeoLatticeError("field value of layer point " + std::to_string(p) + " is not finite");
    }
    if (!(scale[p] > 0) || !std::isfinite(scale[p])) {
      throw GeoLatticeError("width scale must be > 0 and finite (layer point " + std::to_string(p) +
                            " has " + std::to_string(scale[p]) + ")");
    }
    lo = std::min(lo, f[p]);
    hi = std::max(hi, f[p]);
    sMin = std::min(sMin, scale[p]);
  }
  if (f.empty() || !(hi > lo)) {
    return {};
  }
  const double span = hi - lo;
  requireLevelCount(span / sMin, width);
  // Bins of width h; their count is capped, which only coarsens the sampling of s.
  const double binsWanted = std::ceil(span / (width * sMin) * kGradingBinsPerSpacing);
  const int n =
      static_cast<int>(std::clamp(binsWanted, 1.0, static_cast<double>(kMaxLatticeLevels)));
  const double h = span / n;
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> sBar(n, inf);
  for (size_t p = 0; p < f.size(); ++p) {
    const int b = std::min(n - 1, static_cast<int>((f[p] - lo) / h));
    sBar[b] = std::min(sBar[b], scale[p]);
  }
  // Empty bins: the nearest non-empty bin (the smaller value on a tie).
  std::vector<int> left(n, -1), right(n, -1);
  for (int b = 0, last = -1; b < n; ++b) {
    if (sBar[b] < inf) {
      last = b;
    }
    left[b] = last;
  }
  for (int b = n - 1, last = -1; b >= 0; --b) {
    if (sBar[b] < inf) {
      last = b;
    }
    right[b] = last;
  }
  std::vector<double> filled(n);
  for (int b = 0; b < n; ++b) {
    if (sBar[b] < inf) {
      filled[b] = sBar[b];
      continue;
    }
    const int l = left[b], r = right[b];
    if (l < 0) {
      filled[b] = sBar[r];
    } else if (r < 0) {
      filled[b] = sBar[l];
    } else if (b - l != r - b) {
      filled[b] = b - l < r - b ? sBar[l] : sBar[r];
    } else {
      filled[b] = std::min(sBar[l], sBar[r]);
    }
  }
  // G at the bin boundaries: G[0] = lo, G[b + 1] = G[b] + h / s̄_b.
  std::vector<double> G(n + 1);
  G[0] = lo;
  for (int b = 0; b < n; ++b) {
    G[b + 1] = G[b] + h / filled[b];
  }
  const std::vector<double> targets = uniformLatticeLevels(G[0], G[n], width, phase);
  std::vector<double> levels;
  levels.reserve(targets.size());
  int b = 0;
  for (double target : targets) {
    while (b < n - 1 && G[b + 1] < target) {
      ++b;
    }
    double value = lo + b * h + (target - G[b]) * filled[b];
    value = std::min(value, hi);
    if (value > lo && (levels.empty() || value > levels.back())) {
      levels.push_back(value);
    }
  }
  return levels;
}

}  // namespace geolattice
