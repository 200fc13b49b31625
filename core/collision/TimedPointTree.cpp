#include "collision/TimedPointTree.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace geolattice {

using Vec = Eigen::Vector3d;

TimedPointTree::TimedPointTree(const std::vector<Vec>& points, const std::vector<int>& time)
    : points_(points), time_(time) {
  order_.resize(points.size());
  std::iota(order_.begin(), order_.end(), 0);
  if (!order_.empty()) {
    nodes_.reserve(2 * points.size() / kLeafSize + 2);
    build(0, static_cast<int>(order_.size()));
  }
}

int TimedPointTree::build(int begin, int end) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Vec lo = Vec::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  int minTime = std::numeric_limits<int>::max();
  for (int i = begin; i < end; ++i) {
    lo = lo.cwiseMin(points_[order_[i]]);
    hi = hi.cwiseMax(points_[order_[i]]);
    minTime = std::min(minTime, time_[order_[i]]);
  }
  const Vec centre = 0.5 * (lo + hi);
  double r2 = 0;
  for (int i = begin; i < end; ++i) {
    r2 = std::max(r2, (points_[order_[i]] - centre).squaredNorm());
  }
  int left = -1, right = -1;
  if (end - begin > kLeafSize) {
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const int mid = (begin + end) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](int a, int b) { return points_[a][axis] < points_[b][axis]; });
    left = build(begin, mid);
    right = build(mid, end);
  }
  Node& n = nodes_[id];
  n.centre = centre;
  n.radius = std::sqrt(r2);
  n.minTime = minTime;
  n.begin = begin;
  n.end = end;
  n.left = left;
  n.right = right;
  return id;
}

}  // namespace geolattice
