// TimedPointTree: every point a query must see is reported, on trees built on one thread and on
// two (the root's halves are built side by side from 50,000 points on).
#include "collision/TimedPointTree.h"

#include <gtest/gtest.h>

#include <random>
#include <set>
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
