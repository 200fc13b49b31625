#include "collision/TimedPointTree.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <numeric>

namespace geolattice {

using Vec = Eigen::Vector3d;

TimedPointTree::TimedPointTree(const std::vector<Vec>& points, const std::vector<int>& time)
    : points_(points), time_(time) {
  order_.resize(points.size());
  std::iota(order_.begin(), order_.end(), 0);
  if (!order_.empty()) {
    const int n = static_cast<int>(order_.size());
    nodes_.resize(static_cast<size_t>(subtreeNodes(n)));
    // Below this many points a second thread costs more than it saves.
    constexpr int kParallelPoints = 50000;
    build(0, 0, n, n >= kParallelPoints ? 1 : 0);
  }
}

int TimedPointTree::subtreeNodes(int n) {
  return n > kLeafSize ? 1 + subtreeNodes(n / 2) + subtreeNodes(n - n / 2) : 1;
}

int TimedPointTree::build(int id, int begin, int end, int parallelDepth) {
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
  int left = -1, right = -1, next = id + 1;
  if (end - begin > kLeafSize) {
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const int mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](int a, int b) { return points_[a][axis] < points_[b][axis]; });
    left = id + 1;
    if (parallelDepth > 0) {  // disjoint ranges of order_ and nodes_
      right = left + subtreeNodes(mid - begin);
      std::future<int> leftDone =
          std::async(std::launch::async, [this, left, begin, mid, parallelDepth] {
            return build(left, begin, mid, parallelDepth - 1);
          });
      next = build(right, mid, end, parallelDepth - 1);
      leftDone.get();
    } else {
      right = build(left, begin, mid, 0);
      next = build(right, mid, end, 0);
    }
  }
  Node& n = nodes_[static_cast<size_t>(id)];
  n.centre = centre;
  n.radius = std::sqrt(r2);
  n.minTime = minTime;
  n.begin = begin;
  n.end = end;
  n.left = left;
  n.right = right;
  return next;
}

}  // namespace geolattice
