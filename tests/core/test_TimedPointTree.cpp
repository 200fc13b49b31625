// TimedPointTree: every point a query must see is reported, on trees built on one thread and on
// two (the root's halves are built side by side from 50,000 points on).
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
      std::set<int> reported, expected;
      tree.forEachCandidate(ball, now, [&](int i) {
        if ((points[static_cast<size_t>(i)] - ball.centre).norm() <= ball.radius) {
          reported.insert(i);
        }
        return false;
      });
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
        std::set<int> found;
        tree.forEachCandidate(
            ball, now,
            [&](int i) {
              if ((points[static_cast<size_t>(i)] - ball.centre).norm() <= ball.radius) {
                found.insert(i);
              }
              return false;
            },
            root);
        return found;
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
