// The orientation search (core/orient/AutoOrient.h) on a part built so that one orientation is
// printable: a flat-topped mushroom (a 20 mm stem under a 50 mm wide, 4 mm thick flange). Stem
// down, the flange overhangs 15 mm: its curved layers lean out sideways and the nozzle meets the
// build plate. Flange down, it lies flat and the stem grows straight up: no collision.
#include "common/Error.h"
#include "common/ParallelFor.h"
#include "orient/AutoOrient.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <vector>

using namespace geolattice;

namespace {

/// A closed surface of revolution about z from a profile (r, z), first and last point on the
/// axis (r = 0), outward for a profile that runs from the bottom pole outwards and up.
TriangleSurface revolve(const std::vector<std::pair<double, double>>& profile, int segments) {
  TriangleSurface s;
  const int rings = static_cast<int>(profile.size()) - 2;  // without the two poles
  s.points.emplace_back(0, 0, profile.front().second);
  for (int i = 1; i <= rings; ++i) {
    for (int k = 0; k < segments; ++k) {
      const double a = 2 * M_PI * k / segments;
      s.points.emplace_back(profile[i].first * std::cos(a), profile[i].first * std::sin(a),
                            profile[i].second);
    }
  }
  s.points.emplace_back(0, 0, profile.back().second);
  const int top = static_cast<int>(s.points.size()) - 1;
  auto ring = [segments](int i, int k) {
    return 1 + (i - 1) * segments + (k % segments);
  };
  for (int k = 0; k < segments; ++k) {
    s.triangles.push_back({0, ring(1, k + 1), ring(1, k)});
    for (int i = 1; i < rings; ++i) {
      s.triangles.push_back({ring(i, k), ring(i, k + 1), ring(i + 1, k + 1)});
      s.triangles.push_back({ring(i, k), ring(i + 1, k + 1), ring(i + 1, k)});
    }
    s.triangles.push_back({top, ring(rings, k), ring(rings, k + 1)});
  }
  return s;
}

TriangleSurface flatMushroom() {
  return revolve({{0, 0}, {10, 0}, {10, 26}, {25, 26}, {25, 30}, {0, 30}}, 48);
}

}  // namespace

TEST(AutoOrient, FindsTheOnlyPrintableOrientation) {
  OrientOptions o;
  o.sphereCandidates = 40;
  o.hullCandidates = 8;
  const OrientResult r = searchOrientation(flatMushroom(), o);
  const OrientCandidate& keep = r.candidates[0];
  const OrientCandidate& best = r.candidates[r.best];
  EXPECT_EQ(keep.source, "keep");
  EXPECT_GT(keep.collidingStations, 0);  // stem down: the flange's layers reach the plate
  EXPECT_EQ(best.collidingStations, 0);
  EXPECT_TRUE(best.feasible);
  // The flange side (+z of the part as modelled) faces down, within a few degrees.
  EXPECT_GT(best.down.dot(Vec3::UnitZ()), std::cos(5 * M_PI / 180)) << best.down.transpose();
  EXPECT_NEAR(best.baseArea, M_PI * 25 * 25, 0.05 * M_PI * 25 * 25);
  EXPECT_EQ(best.rank, 0);
  // The rotation turns the chosen side onto -z.
  EXPECT_NEAR((best.rotation * best.down - (-Vec3::UnitZ())).norm(), 0.0, 1e-12);
  // Oriented, the part stands on z = 0 with the same x/y centre.
  const TriangleSurface placed = orientSurface(flatMushroom(), best.rotation);
  double zmin = 1e9;
  for (const Vec3& p : placed.points) {
    zmin = std::min(zmin, p.z());
  }
  EXPECT_NEAR(zmin, 0.0, 1e-9);
}

TEST(AutoOrient, NoOrientationWithTheBaseAreaIsAClearError) {
  OrientOptions o;
  o.sphereCandidates = 12;
  o.hullCandidates = 4;
  o.minBaseArea = 1e5;  // more than the flange
  try {
    searchOrientation(flatMushroom(), o);
    FAIL() << "expected an error";
  } catch (const GeoLatticeError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("no orientation has a base contact area of 100000 mm^2"), std::string::npos)
        << m;
    EXPECT_NE(m.find("the largest is"), std::string::npos) << m;
  }
  OrientOptions bad;
  bad.minBaseArea = -1;
  EXPECT_THROW(searchOrientation(flatMushroom(), bad), GeoLatticeError);
}

TEST(AutoOrient, BaseContactArea) {
  const TriangleSurface s = flatMushroom();
  // Stem down: the 10 mm disc; flange down: the 25 mm disc; on its side: one facet of the
  // 48-sided rim and of the stem, a small fraction.
  EXPECT_NEAR(baseContactArea(s, Eigen::Matrix3d::Identity(), 0.3), M_PI * 100, 0.05 * M_PI * 100);
  EXPECT_NEAR(baseContactArea(s, rotationTakingDownToMinusZ(Vec3::UnitZ()), 0.3), M_PI * 625,
              0.05 * M_PI * 625);
  EXPECT_LT(baseContactArea(s, rotationTakingDownToMinusZ(Vec3::UnitX()), 0.3), 0.05 * M_PI * 625);
}

TEST(ParallelFor, EveryItemOnceErrorsAndProgressOnTheCallingThread) {
  std::vector<std::atomic<int>> seen(1000);
  const std::thread::id caller = std::this_thread::get_id();
  size_t last = 0;
  bool onCaller = true;
  parallelFor(
      seen.size(), 2,
      [&](size_t i, int worker) {
        ASSERT_LT(worker, 2);
        ++seen[i];
      },
      [&](size_t done) {
        onCaller = onCaller && std::this_thread::get_id() == caller;
        EXPECT_GE(done, last);
        last = done;
      });
  for (const auto& s : seen) {
    EXPECT_EQ(s.load(), 1);
  }
  EXPECT_TRUE(onCaller);
  EXPECT_THROW(parallelFor(100, 2,
                           [](size_t i, int) {
                             if (i == 37) {
                               throw std::runtime_error("item 37");
                             }
                           }),
               std::runtime_error);
  // An exception from the progress callback (an abort) stops the workers and is rethrown.
  EXPECT_THROW(parallelFor(
                   100000, 2, [](size_t, int) {},
                   [](size_t done) {
                     if (done > 10) {
                       throw GeoLatticeError("aborted");
                     }
                   }),
               GeoLatticeError);
}
