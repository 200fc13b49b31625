#include "collision/TimedPointTree.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <numeric>

namespace geolattice {

using Vec = Eigen::Vector3d;

TimedPointTree::TimedPointTree(const std::vector<Vec>& points, const std::vector<int>& time,
                               int split)
    : points_(points), time_(time) {
  order_.resize(points.size());
  std::iota(order_.begin(), order_.end(), 0);
  if (!order_.empty()) {
    const int n = static_cast<int>(order_.size());
    split_ = split > 0 && split < n;
    nodes_.resize(static_cast<size_t>(split_ ? 1 + subtreeNodes(split) + subtreeNodes(n - split)
                                             : subtreeNodes(n)));
    // Below this many points a second thread costs more than it saves.
    constexpr int kParallelPoints = 50000;
    build(0, 0, n, n >= kParallelPoints ? 1 : 0, split_ ? split : -1);
  }
}

int TimedPointTree::subtreeNodes(int n) {
  return n > kLeafSize ? 1 + subtreeNodes(n / 2) + subtreeNodes(n - n / 2) : 1;
}

int TimedPointTree::build(int id, int begin, int end, int parallelDepth, int split) {
  // Plain scalars and two independent maxima: with Eigen temporaries GCC kept the running
  // maximum on the stack, and the radius loop waited on store-to-load forwarding (a third of
  // the build). max is exact, so the tree is the same.
  constexpr double inf = std::numeric_limits<double>::infinity();
  double lx = inf, ly = inf, lz = inf, hx = -inf, hy = -inf, hz = -inf;
  int minTime = std::numeric_limits<int>::max();
  for (int i = begin; i < end; ++i) {
    const int q = order_[i];
    const Vec& p = points_[q];
    lx = std::min(lx, p.x());
    ly = std::min(ly, p.y());
    lz = std::min(lz, p.z());
    hx = std::max(hx, p.x());
    hy = std::max(hy, p.y());
    hz = std::max(hz, p.z());
    minTime = std::min(minTime, time_[q]);
  }
  const Vec lo(lx, ly, lz), hi(hx, hy, hz);
  const Vec centre = 0.5 * (lo + hi);
  const double cx = centre.x(), cy = centre.y(), cz = centre.z();
  auto squaredDistance = [&](int i) {
    const Vec& p = points_[order_[i]];
    const double dx = p.x() - cx, dy = p.y() - cy, dz = p.z() - cz;
    return dx * dx + dy * dy + dz * dz;
  };
  double r2a = 0, r2b = 0;
  int i = begin;
  for (; i + 1 < end; i += 2) {
    r2a = std::max(r2a, squaredDistance(i));
    r2b = std::max(r2b, squaredDistance(i + 1));
  }
  if (i < end) {
    r2a = std::max(r2a, squaredDistance(i));
  }
  const double r2 = std::max(r2a, r2b);
  int left = -1, right = -1, next = id + 1;
  if (split > begin || end - begin > kLeafSize) {
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const int mid = split > begin ? split : begin + (end - begin) / 2;
    if (split <= begin) {
      std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                       [&](int a, int b) { return points_[a][axis] < points_[b][axis]; });
    }
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
