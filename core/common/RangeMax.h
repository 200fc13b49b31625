#pragma once
/// @file RangeMax.h
/// @brief The largest of a fixed array's values over an index range in O(1) (a sparse table:
/// O(n log n) set-up). Used for the printhead's radius and clear-angle profiles.
#include <algorithm>
#include <vector>

namespace geolattice {

class RangeMax {
public:
  RangeMax() = default;
  explicit RangeMax(const std::vector<double>& values) {
    levels_.push_back(values);
    const int n = static_cast<int>(values.size());
    for (int w = 1; 2 * w <= n; w *= 2) {
      const std::vector<double>& prev = levels_.back();
      std::vector<double> next(n - 2 * w + 1);
      for (size_t i = 0; i < next.size(); ++i) {
        next[i] = std::max(prev[i], prev[i + w]);
      }
      levels_.push_back(std::move(next));
    }
  }
  /// The largest value with index in [i0, i1] (clamped to the array); the first value for an
  /// empty array is undefined, so callers keep i0 <= i1 within it.
  double operator()(int i0, int i1) const {
    const int last = static_cast<int>(levels_[0].size()) - 1;
    i0 = std::clamp(i0, 0, last);
    i1 = std::clamp(i1, i0, last);
    const int level = 31 - __builtin_clz(static_cast<unsigned>(i1 - i0 + 1));  // floor(log2)
    return std::max(levels_[level][i0], levels_[level][i1 - (1 << level) + 1]);
  }

private:
  std::vector<std::vector<double>> levels_;
};

}  // namespace geolattice
