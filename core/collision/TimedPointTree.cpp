#include "collision/TimedPointTree.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <numeric>

namespace geolattice {

using Vec = Eigen::Vector3d;

TimedPointTree::TimedPointTree(const std::vector<Vec>& points, const std::vector<int>& time,
                               int split, const std::vector<int>* group)
    : points_(points), time_(time) {
  order_.resize(points.size());
  std::iota(order_.begin(), order_.end(), 0);
  if (order_.empty()) {
    return;
  }
  const int n = static_cast<int>(order_.size());
  split_ = split > 0 && split < n;
  const int groupedEnd = split_ ? split : n;
  if (group) {
    orderByGroup(*group, groupedEnd);
  } else {
    runs_ = {{0, groupedEnd, kNoGroup, Vec::Zero()}};
  }
  const int groups = static_cast<int>(runs_.size());
  nodes_.resize(static_cast<size_t>(split_ ? 1 + groupsNodes(0, groups) + subtreeNodes(n - split)
                                           : groupsNodes(0, groups)));
  // Below this many points a second thread costs more than it saves.
  constexpr int kParallelPoints = 50000;
  const int parallelDepth = n >= kParallelPoints ? 1 : 0;
  if (!split_) {
    buildGroups(0, 0, groups, parallelDepth);
    return;
  }
  int axis = 0;
  enclose(0, 0, n, &axis);
  Node& root = nodes_[0];
  root.left = 1;
  root.right = 1 + groupsNodes(0, groups);
  const int right = root.right;
  if (parallelDepth > 0) {  // disjoint ranges of order_ and nodes_
    std::future<int> leftDone =
        std::async(std::launch::async, [this, groups] { return buildGroups(1, 0, groups, 0); });
    build(right, split, n, 0, kNoGroup);
    leftDone.get();
  } else {
    buildGroups(1, 0, groups, 0);
    build(right, split, n, 0, kNoGroup);
  }
}

int TimedPointTree::subtreeNodes(int n) {
  return n > kLeafSize ? 1 + subtreeNodes(n / 2) + subtreeNodes(n - n / 2) : 1;
}

int TimedPointTree::groupsNodes(int first, int last) const {
  if (last - first == 1) {
    const Run& r = runs_[static_cast<size_t>(first)];
    return subtreeNodes(r.end - r.begin);
  }
  const int mid = first + (last - first) / 2;
  return 1 + groupsNodes(first, mid) + groupsNodes(mid, last);
}

void TimedPointTree::orderByGroup(const std::vector<int>& group, int end) {
  std::sort(order_.begin(), order_.begin() + end, [&](int a, int b) {
    return std::make_pair(group[a], a) < std::make_pair(group[b], b);
  });
  runs_.clear();
  for (int i = 0; i < end; ++i) {
    const int q = order_[i];
    if (runs_.empty() || runs_.back().group != group[q]) {
      runs_.push_back({i, i, group[q], Vec::Zero()});
    }
    runs_.back().end = i + 1;
    runs_.back().centroid += points_[q];
  }
  for (Run& r : runs_) {
    r.centroid /= r.end - r.begin;
  }
}

void TimedPointTree::enclose(int id, int begin, int end, int* axis) {
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
  (hi - lo).maxCoeff(axis);
  Node& n = nodes_[static_cast<size_t>(id)];
  n.centre = centre;
  n.radius = std::sqrt(std::max(r2a, r2b));
  n.minTime = minTime;
  n.begin = begin;
  n.end = end;
}

int TimedPointTree::build(int id, int begin, int end, int parallelDepth, int group) {
  int axis = 0;
  enclose(id, begin, end, &axis);
  int left = -1, right = -1, next = id + 1;
  if (end - begin > kLeafSize) {
    const int mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](int a, int b) { return points_[a][axis] < points_[b][axis]; });
    left = id + 1;
    if (parallelDepth > 0) {  // disjoint ranges of order_ and nodes_
      right = left + subtreeNodes(mid - begin);
      std::future<int> leftDone =
          std::async(std::launch::async, [this, left, begin, mid, parallelDepth, group] {
            return build(left, begin, mid, parallelDepth - 1, group);
          });
      next = build(right, mid, end, parallelDepth - 1, group);
      leftDone.get();
    } else {
      right = build(left, begin, mid, 0, group);
      next = build(right, mid, end, 0, group);
    }
  }
  Node& n = nodes_[static_cast<size_t>(id)];
  n.left = left;
  n.right = right;
  n.group = group;
  return next;
}

int TimedPointTree::buildGroups(int id, int first, int last, int parallelDepth) {
  const int begin = runs_[static_cast<size_t>(first)].begin;
  const int end = runs_[static_cast<size_t>(last - 1)].end;
  if (last - first == 1) {
    return build(id, begin, end, parallelDepth, runs_[static_cast<size_t>(first)].group);
  }
  int axis = 0;
  enclose(id, begin, end, &axis);
  // A kd-tree over the groups: their centroids split in halves (by count: the depth stays
  // log2(groups)) across the longest axis, so a node's groups lie together in space.
  const auto firstRun = runs_.begin() + first, lastRun = runs_.begin() + last;
  const int mid = first + (last - first) / 2;
  std::nth_element(firstRun, runs_.begin() + mid, lastRun, [axis](const Run& a, const Run& b) {
    return a.centroid[axis] < b.centroid[axis];
  });
  std::vector<int> moved;
  moved.reserve(static_cast<size_t>(end - begin));
  for (auto r = firstRun; r != lastRun; ++r) {
    moved.insert(moved.end(), order_.begin() + r->begin, order_.begin() + r->end);
    const int size = r->end - r->begin;
    r->begin = begin + static_cast<int>(moved.size()) - size;
    r->end = r->begin + size;
  }
  std::copy(moved.begin(), moved.end(), order_.begin() + begin);
  const int left = id + 1;
  const int right = left + groupsNodes(first, mid);
  int next = 0;
  if (parallelDepth > 0) {  // disjoint ranges of order_, runs_ and nodes_
    std::future<int> leftDone = std::async(
        std::launch::async, [this, left, first, mid] { return buildGroups(left, first, mid, 0); });
    next = buildGroups(right, mid, last, 0);
    leftDone.get();
  } else {
    buildGroups(left, first, mid, 0);
    next = buildGroups(right, mid, last, 0);
  }
  Node& n = nodes_[static_cast<size_t>(id)];
  n.left = left;
  n.right = right;
  n.group = kNoGroup;
  return next;
}

}  // namespace geolattice
