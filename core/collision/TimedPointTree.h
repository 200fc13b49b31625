#pragma once
/// @file TimedPointTree.h
/// @brief A static kd-tree over printed points whose nodes know their bounding sphere and the
/// earliest print time below them, so a nozzle query at time t skips material printed later and
/// space outside a cone that bounds the nozzle (nozzle/NozzleBound.h). Used by the collision
/// verifier and by the toolpath's nozzle axis clearance.
///
/// Optionally the points carry groups (e.g. their sub-graph): then the tree's top levels split
/// between groups, each group has a subtree of its own, and a query can prune whole groups (the
/// verifier skips a skeleton ancestor's material, which no printing order keeps out of a
/// nozzle, without visiting it point by point).
#include "nozzle/NozzleBound.h"

#include <Eigen/Core>
#include <array>
#include <limits>
#include <utility>
#include <vector>

namespace geolattice {

class TimedPointTree {
public:
  struct Node {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double radius = 0;
    int minTime = 0;
    int begin = 0, end = 0;  ///< range in order()
    int left = -1, right = -1;
    int group = kNoGroup;  ///< the group of every point below, or kNoGroup
  };
  /// A node's group when its points have none or several.
  static constexpr int kNoGroup = std::numeric_limits<int>::min();
  /// The default prune: no group is skipped.
  struct KeepEveryGroup {
    bool operator()(int) const { return false; }
  };

  /// time: one entry per point; a point with time INT_MAX is never reported (not material).
  /// Both vectors must outlive the tree. split in (0, size): the root's children hold the
  /// points [0, split) and [split, size) (firstChild(), secondChild()), e.g. material and the
  /// build plate's samples, so either kind can be searched alone in the one tree; otherwise
  /// (and below the root always) the tree splits at medians. group (optional, one entry per
  /// point, read only here): the points before the split (all without one) are grouped, each
  /// group in a subtree whose nodes know it (Node::group), above those subtrees a kd-tree of
  /// the groups' centroids; a point with group kNoGroup is never pruned. The points after the
  /// split have no group.
  TimedPointTree(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& time,
                 int split = -1, const std::vector<int>* group = nullptr);

  /// The subtrees of a split root (see the constructor), or -1 without one.
  int firstChild() const { return split_ ? nodes_[0].left : -1; }
  int secondChild() const { return split_ ? nodes_[0].right : -1; }

  /// Calls visit(q) for every point q with time[q] < now in a leaf whose sphere the bound may
  /// touch (candidates: the caller applies its exact test); stops when visit returns true.
  /// Bound: anything with `bool mayTouch(centre, radius) const`, e.g. NozzleBound. root: the
  /// subtree searched (0: the whole tree). prune(group) true: the points of that group are
  /// skipped (asked once per query and group subtree reached).
  template <class Bound, class Visit, class Prune = KeepEveryGroup>
  void forEachCandidate(const Bound& bound, int now, Visit&& visit, int root = 0,
                        const Prune& prune = Prune{}) const {
    forEachCluster(
        bound, now, [](const Eigen::Vector3d&, double) { return false; },
        [&](const Node& leaf) {
          for (int i = leaf.begin; i < leaf.end; ++i) {
            const int q = order_[i];
            if (time_[q] < now && visit(q)) {
              return true;
            }
          }
          return false;
        },
        root, prune);
  }

  /// Calls visit(node) for clusters that hold every point with time < now in a leaf the bound
  /// may touch: a node is reported instead of being descended when it is a leaf or when
  /// small(centre, radius) says so. Its points are pointAt(i) for i in [node.begin, node.end)
  /// (some may have time >= now: the caller checks timeOf). Stops when visit returns true.
  /// prune: as in forEachCandidate.
  template <class Bound, class Small, class Visit, class Prune = KeepEveryGroup>
  void forEachCluster(const Bound& bound, int now, Small&& small, Visit&& visit, int root = 0,
                      const Prune& prune = Prune{}) const {
    if (nodes_.empty() || root < 0) {
      return;
    }
    // Depth first on a fixed stack (no allocation, no thread-local lookup per query): the tree
    // splits in halves (of the groups, then at medians), so it is at most log2(groups) +
    // log2(N / kLeafSize) + 3 < 60 deep, and the stack holds at most one entry more than the
    // depth. An entry ~id (negative) is a node whose group was asked already and kept.
    std::array<int, 64> stack;
    int top = 0;
    stack[top++] = root;
    while (top > 0) {
      const int entry = stack[--top];
      bool kept = entry < 0;
      const Node& node = nodes_[static_cast<size_t>(kept ? ~entry : entry)];
      if (node.minTime >= now || !bound.mayTouch(node.centre, node.radius)) {
        continue;
      }
      if (!kept && node.group != kNoGroup) {
        if (prune(node.group)) {
          continue;
        }
        kept = true;
      }
      if (node.left >= 0 && !small(node.centre, node.radius)) {
        stack[top++] = kept ? ~node.left : node.left;
        stack[top++] = kept ? ~node.right : node.right;
        continue;
      }
      if (visit(node)) {
        return;
      }
    }
  }
  /// Of the points q with time[q] < now in leaves the bound may touch and accepted by
  /// accept(q), the one nearest `from` (ties: the lowest index); `start` (such a point, or -1)
  /// bounds the search from the outset. Depth first, the nearer child first, skipping balls
  /// farther than the best point so far. Returns -1 if there is none. root: the subtree searched;
  /// prune: as in forEachCandidate (asked at every node with a group).
  template <class Bound, class Accept, class Prune = KeepEveryGroup>
  int nearestCandidate(const Bound& bound, const Eigen::Vector3d& from, int now, int start,
                       Accept&& accept, int root = 0, const Prune& prune = Prune{}) const {
    int best = start;
    double bestD2 = start >= 0 ? (points_[start] - from).squaredNorm()
                               : std::numeric_limits<double>::infinity();
    if (nodes_.empty() || root < 0) {
      return best;
    }
    auto lowerBound = [&](int id) {  // of the squared distance from `from` to node id's ball
      const Node& n = nodes_[static_cast<size_t>(id)];
      const double d = (n.centre - from).norm() - n.radius;
      return d > 0 ? d * d : 0.0;
    };
    std::array<std::pair<int, double>, 64> stack;  // (node, lower bound); depth as forEachCluster
    int top = 0;
    stack[top++] = {root, lowerBound(root)};
    while (top > 0) {
      const auto [id, lb] = stack[--top];
      const Node& node = nodes_[static_cast<size_t>(id)];
      if (lb > bestD2 || node.minTime >= now || !bound.mayTouch(node.centre, node.radius) ||
          (node.group != kNoGroup && prune(node.group))) {
        continue;
      }
      if (node.left >= 0) {
        const double l = lowerBound(node.left), r = lowerBound(node.right);
        const bool leftFirst = l <= r;
        stack[top++] = leftFirst ? std::make_pair(node.right, r) : std::make_pair(node.left, l);
        stack[top++] = leftFirst ? std::make_pair(node.left, l) : std::make_pair(node.right, r);
        continue;
      }
      for (int i = node.begin; i < node.end; ++i) {
        const int q = order_[i];
        if (time_[q] >= now) {
          continue;
        }
        const double d2 = (points_[q] - from).squaredNorm();
        if ((d2 < bestD2 || (d2 == bestD2 && q < best)) && accept(q)) {
          best = q;
          bestD2 = d2;
        }
      }
    }
    return best;
  }
  const Node& node(int id) const { return nodes_[static_cast<size_t>(id)]; }  ///< left, right
  int pointAt(int i) const { return order_[i]; }  ///< the point at position i of the tree's order
  int timeOf(int q) const { return time_[q]; }

private:
  /// Points per leaf: a nozzle query visits ~160 balls, most of them straddling the nozzle's
  /// bounding cone (no test rejects them), so fewer, larger leaves are cheaper; measured on the
  /// verifier and toolpath benchmarks, 32 beat 8 by 6-9 % (docs/performance.md).
  static constexpr int kLeafSize = 32;
  /// Nodes of the subtree over n points (its shape depends on n only: median splits).
  static int subtreeNodes(int n);
  /// Nodes of the subtree over the groups [first, last) (halves of the groups above, then each
  /// group's median subtree).
  int groupsNodes(int first, int last) const;
  /// Sorts order_[0, end) by group into runs (runs_, with their centroids).
  void orderByGroup(const std::vector<int>& group, int end);
  /// Node id's bounding sphere, earliest time and range [begin, end) of order_; the box's
  /// longest axis in *axis.
  void enclose(int id, int begin, int end, int* axis);
  /// Builds the subtree over order_[begin, end) into nodes_[id ...] in depth-first order and
  /// returns the id after it; the two halves of the top `parallelDepth` levels are built on two
  /// threads (the right half's first id from subtreeNodes). Every node gets `group`.
  int build(int id, int begin, int end, int parallelDepth, int group);
  /// The same over the groups runs_[first, last): halves of the groups, then build() per group.
  int buildGroups(int id, int first, int last, int parallelDepth);

  struct Run {  ///< a group's points: order_[begin, end)
    int begin, end, group;
    Eigen::Vector3d centroid;
  };

  const std::vector<Eigen::Vector3d>& points_;
  const std::vector<int>& time_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
  std::vector<Run> runs_;  ///< the groups' points (one run without groups), while building
  bool split_ = false;     ///< the root splits at the constructor's `split`
};

}  // namespace geolattice
