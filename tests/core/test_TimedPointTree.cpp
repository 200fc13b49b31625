// TimedPointTree: every point a query must see is reported, on trees built on one thread and on
// two (the root's halves are built side by side from 50,000 points on), and with groups pruned
// whole.
#include "collision/TimedPointTree.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace geolattice;

namespace {

/// A ball as the bound: a node may touch it when the spheres overlap.
struct BallBound {
  Eigen::Vector3d centre;
  double radius;
  bool mayTouch(const Eigen::Vector3d& c, double r) const {
    return (c - centre).norm() <= radius + r;
  }
};

/// The points the tree reports at time `now` in its subtree `root` that lie in the ball.
template <class Prune = TimedPointTree::KeepEveryGroup>
std::set<int> pointsInBall(const TimedPointTree& tree, const std::vector<Eigen::Vector3d>& points,
                           const BallBound& ball, int now, int root = 0,
                           const Prune& prune = Prune{}) {
  std::set<int> found;
  tree.forEachCandidate(
      ball, now,
      [&](int i) {
        if ((points[static_cast<size_t>(i)] - ball.centre).norm() <= ball.radius) {
          found.insert(i);
        }
        return false;
      },
      root, prune);
  return found;
}

}  // namespace

TEST(TimedPointTree, ReportsEveryEarlierPointInTheBoundOnSmallAndLargeTrees) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(0.0, 100.0);
  for (const int n : {1, 9, 5000, 120000}) {  // 120,000: built on two threads
    SCOPED_TRACE(n);
    std::vector<Eigen::Vector3d> points(static_cast<size_t>(n));
    std::vector<int> time(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
      points[i] = {coordinate(rng), coordinate(rng), coordinate(rng)};
      time[i] = static_cast<int>(i);
    }
    const TimedPointTree tree(points, time);
    for (int q = 0; q < 20; ++q) {
      const BallBound ball{{coordinate(rng), coordinate(rng), coordinate(rng)}, 6.0};
      const int now = n / 2 + q;
      const std::set<int> reported = pointsInBall(tree, points, ball, now);
      std::set<int> expected;
      for (int i = 0; i < n; ++i) {
        if (time[static_cast<size_t>(i)] < now &&
            (points[static_cast<size_t>(i)] - ball.centre).norm() <= ball.radius) {
          expected.insert(i);
        }
      }
      EXPECT_EQ(reported, expected) << "query " << q;
    }
  }
}

TEST(TimedPointTree, ASplitRootSearchesEachKindAloneAndBothTogether) {
  // Material above the plane z = 0 and a plate's samples below it, as the verifier builds them:
  // the root's children hold exactly the points before and after the split (on one thread and
  // on two), and the whole tree reports what a median-split tree reports.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(0.0, 100.0);
  for (const auto& [material, plate] : {std::pair<int, int>{5, 3}, {4000, 900}, {90000, 30000}}) {
    SCOPED_TRACE(material);
    std::vector<Eigen::Vector3d> points;
    std::vector<int> time;
    for (int i = 0; i < material; ++i) {
      points.emplace_back(coordinate(rng), coordinate(rng), 0.2 * coordinate(rng));
      time.push_back(i);
    }
    for (int i = 0; i < plate; ++i) {
      points.emplace_back(coordinate(rng), coordinate(rng), -0.05 * coordinate(rng));
      time.push_back(std::numeric_limits<int>::min());
    }
    const TimedPointTree split(points, time, material), plain(points, time);
    ASSERT_GE(split.firstChild(), 0);
    ASSERT_GE(split.secondChild(), 0);
    EXPECT_EQ(plain.firstChild(), -1);
    for (int q = 0; q < 20; ++q) {
      const BallBound ball{{coordinate(rng), coordinate(rng), 0.1 * coordinate(rng) - 2}, 8.0};
      const int now = material / 2 + q;
      auto search = [&](const TimedPointTree& tree, int root) {
        return pointsInBall(tree, points, ball, now, root);
      };
      const std::set<int> all = search(plain, 0);
      EXPECT_EQ(search(split, 0), all);
      std::set<int> first, second;
      for (int i : all) {
        (i < material ? first : second).insert(i);
      }
      EXPECT_EQ(search(split, split.firstChild()), first);
      EXPECT_EQ(search(split, split.secondChild()), second);
      // The nearest plate sample to the ball's centre, searched in the plate's subtree alone.
      const int nearest = split.nearestCandidate(
          ball, ball.centre, now, -1,
          [&](int i) { return (points[static_cast<size_t>(i)] - ball.centre).norm() <= 8.0; },
          split.secondChild());
      int expected = -1;
      for (int i : second) {
        if (expected < 0 ||
            (points[static_cast<size_t>(i)] - ball.centre).squaredNorm() <
                (points[static_cast<size_t>(expected)] - ball.centre).squaredNorm()) {
          expected = i;
        }
      }
      EXPECT_EQ(nearest, expected);
    }
  }
}

TEST(TimedPointTree, GroupedPointsArePrunedByGroupAndEveryOtherPointIsReported) {
  // Points in layered sheets (a group per sheet and quarter, as sub-graphs of curved layers), a
  // plate below them: a grouped tree reports exactly the points of the groups the query keeps,
  // whole groups are skipped, and every node knows its group (one built on one thread, one on
  // two; with and without the plate split off at its root).
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coordinate(0.0, 100.0);
  for (const int material : {40, 3000, 80000}) {
    SCOPED_TRACE(material);
    std::vector<Eigen::Vector3d> points;
    std::vector<int> time, group;
    for (int i = 0; i < material; ++i) {
      const double x = coordinate(rng), y = coordinate(rng), z = 0.3 * coordinate(rng);
      points.emplace_back(x, y, z);
      const int layer = static_cast<int>(z / 0.6);
      group.push_back(4 * layer + (x < 50) + 2 * (y < 50));
      time.push_back(group.back());
    }
    const int plate = material / 4;
    for (int i = 0; i < plate; ++i) {
      points.emplace_back(coordinate(rng), coordinate(rng), -0.05 * coordinate(rng));
      time.push_back(std::numeric_limits<int>::min());
      group.push_back(TimedPointTree::kNoGroup);
    }
    const TimedPointTree grouped(points, time, -1, &group);
    const TimedPointTree split(points, time, material, &group);
    ASSERT_GE(split.firstChild(), 0);
    for (const TimedPointTree* tree : {&grouped, &split}) {
      // Depth first over the nodes: a node with a group holds only that group's points.
      std::vector<int> open{0};
      int withGroup = 0;
      while (!open.empty()) {
        const TimedPointTree::Node& n = tree->node(open.back());
        open.pop_back();
        if (n.group != TimedPointTree::kNoGroup) {
          ++withGroup;
          for (int i = n.begin; i < n.end; ++i) {
            ASSERT_EQ(group[static_cast<size_t>(tree->pointAt(i))], n.group);
          }
        }
        if (n.left >= 0) {
          open.push_back(n.left);
          open.push_back(n.right);
        }
      }
      EXPECT_GT(withGroup, 0);
    }
    int asked = 0;  // groups asked about over all queries
    for (int q = 0; q < 20; ++q) {
      const BallBound ball{{coordinate(rng), coordinate(rng), 0.3 * coordinate(rng)}, 12.0};
      const int now = static_cast<int>(rng() % 250);
      const int odd = static_cast<int>(rng() % 2);
      auto prune = [&](int g) {
        return g % 2 == odd;  // half of the groups, e.g. a station's ancestors
      };
      std::set<int> expected;
      for (size_t i = 0; i < points.size(); ++i) {
        if (time[i] < now && (points[i] - ball.centre).norm() <= ball.radius &&
            (group[i] == TimedPointTree::kNoGroup || !prune(group[i]))) {
          expected.insert(static_cast<int>(i));
        }
      }
      auto search = [&](const TimedPointTree& tree, int root) {
        return pointsInBall(tree, points, ball, now, root, [&](int g) {
          ++asked;
          return prune(g);
        });
      };
      EXPECT_EQ(search(grouped, 0), expected) << "query " << q;
      EXPECT_EQ(search(split, 0), expected);
      std::set<int> materialOnly;
      for (int i : expected) {
        if (i < material) {
          materialOnly.insert(i);
        }
      }
      EXPECT_EQ(search(split, split.firstChild()), materialOnly);
      // The nearest kept point to the ball's centre, whole groups pruned on the way.
      int nearest = -1;
      for (int i : materialOnly) {
        if (nearest < 0 || (points[static_cast<size_t>(i)] - ball.centre).squaredNorm() <
                               (points[static_cast<size_t>(nearest)] - ball.centre).squaredNorm()) {
          nearest = i;
        }
      }
      EXPECT_EQ(split.nearestCandidate(
                    ball, ball.centre, now, -1,
                    [&](int i) {
                      return (points[static_cast<size_t>(i)] - ball.centre).norm() <= ball.radius;
                    },
                    split.firstChild(), prune),
                nearest);
    }
    EXPECT_GT(asked, 0);
  }
}
