#pragma once
/// @file Progress.h
/// @brief Optional progress and abort callbacks of the long core algorithms. Their options
/// structs carry `std::function<void(double)> progress` (fraction done, 0..1, non-decreasing)
/// and `std::function<bool()> shouldAbort` (polled; true stops the algorithm with a
/// GeoLatticeError "<what> aborted"), like LatticeOptions. The filters pass UpdateProgress and
/// GetAbortExecute; core stays free of VTK. Both callbacks run on the calling thread only.
#include "common/Error.h"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <string>

namespace geolattice {

/// @class ProgressReporter
/// @brief Maps the fractions of one part of an algorithm onto [lo, hi] of its progress callback
/// and polls the abort callback at the same points. Either callback may be empty.
class ProgressReporter {
public:
  ProgressReporter(const std::function<void(double)>& progress,
                   const std::function<bool()>& shouldAbort, const char* what, double lo = 0.0,
                   double hi = 1.0)
      : progress_(progress), shouldAbort_(shouldAbort), what_(what), lo_(lo), hi_(hi) {}

  /// The same callbacks for the sub-range [a, b] of this one's [0, 1].
  ProgressReporter part(double a, double b) const {
    return ProgressReporter(progress_, shouldAbort_, what_, lo_ + (hi_ - lo_) * a,
                            lo_ + (hi_ - lo_) * b);
  }

  /// Reports fraction f (0..1) of this part, then polls the abort callback; throws
  /// GeoLatticeError("<what> aborted") if it returns true.
  void report(double f) const {
    if (progress_) {
      progress_(lo_ + (hi_ - lo_) * std::clamp(f, 0.0, 1.0));
    }
    checkAbort();
  }

  /// In a loop over n items, at the start of item i: reports i / n every ceil(n / 64) items
  /// (and polls the abort callback there), so a loop costs at most 64 callbacks.
  void loop(size_t i, size_t n) const {
    const size_t stride = std::max<size_t>(1, (n + 63) / 64);
    if (i % stride == 0) {
      report(n > 0 ? static_cast<double>(i) / static_cast<double>(n) : 1.0);
    }
  }

  /// Throws GeoLatticeError("<what> aborted") if the abort callback returns true.
  void checkAbort() const {
    if (shouldAbort_ && shouldAbort_()) {
      throw GeoLatticeError(std::string(what_) + " aborted");
    }
  }

private:
  const std::function<void(double)>& progress_;
  const std::function<bool()>& shouldAbort_;
  const char* what_;
  double lo_, hi_;
};

}  // namespace geolattice
