#include "toolpath/PathObstacleTrees.h"

#include <algorithm>

namespace geolattice {

void PathObstacleTrees::index(const std::vector<Vec3>& points, const std::vector<char>& material,
                              const std::vector<Vec3>* fixed) {
  const size_t N = points.size();
  const std::vector<Vec3> noFixed;
  const std::vector<Vec3>& fixedPoints = fixed ? *fixed : noFixed;
  baseNow_.assign(N, 0);
  addedPoints_.clear();
  addedTime_.clear();
  // The base material found again in order (greedily: a point equal to the next base point is
  // taken as it; with equal coordinates either choice gives each station the same obstacles).
  bool reuse = base_ && basePoints_.size() - baseMaterial_ == fixedPoints.size() &&
               std::equal(fixedPoints.begin(), fixedPoints.end(),
                          basePoints_.begin() + static_cast<long>(baseMaterial_));
  if (reuse) {
    size_t matched = 0;
    for (size_t k = 0; k < N; ++k) {
      baseNow_[k] = static_cast<int>(matched);
      if (!material[k]) {
        continue;
      }
      if (matched < baseMaterial_ && points[k] == basePoints_[matched]) {
        ++matched;
      } else {
        addedPoints_.push_back(points[k]);
        addedTime_.push_back(static_cast<int>(k));
      }
    }
    reuse = matched == baseMaterial_ &&
            addedPoints_.size() <= std::max<size_t>(1024, baseMaterial_ / 8);
  }
  if (reuse) {
    ++reuses;
  } else {
    ++builds;
    added_.reset();
    base_.reset();
    addedPoints_.clear();
    addedTime_.clear();
    basePoints_.clear();
    baseTime_.clear();
    for (size_t k = 0; k < N; ++k) {
      baseNow_[k] = static_cast<int>(basePoints_.size());
      if (material[k]) {
        baseTime_.push_back(static_cast<int>(basePoints_.size()));
        basePoints_.push_back(points[k]);
      }
    }
    baseMaterial_ = basePoints_.size();
    basePoints_.insert(basePoints_.end(), fixedPoints.begin(), fixedPoints.end());
    baseTime_.resize(basePoints_.size(), -1);
    base_ = std::make_unique<TimedPointTree>(basePoints_, baseTime_);
  }
  added_ = std::make_unique<TimedPointTree>(addedPoints_, addedTime_);
}

}  // namespace geolattice
