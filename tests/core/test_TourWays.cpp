// Tours tried in other ways (core/toolpath/TourWays.h): each tour with a colliding station
// keeps the way where fewest of its own stations collide, the path is kept only where fewer
// collide in all, open runs and air stations are left out, and a path far from printable is
// not retried.
#include "toolpath/TourWays.h"

#include <gtest/gtest.h>

#include <map>
#include <utility>

using namespace geolattice;

namespace {

/// A stand-in for the planner: tour t prints walk t (10 material stations each, then one air
/// station); colliding[{walk, way}] of a walk's material stations collide printed that way (the
/// first ones), plus `air` colliding air stations before walk 0.
struct FakePlanner {
  std::map<std::pair<int, int>, int> colliding;
  int walks = 3;
  int air = 0;
  int extraStations = 0;  ///< non-colliding material stations added to the path
  int passes = 0;

  std::vector<int> plan(Toolpath& path, std::vector<int>& walkOfTour,
                        const std::vector<int>& wayOf) {
    ++passes;
    path = Toolpath{};
    walkOfTour.clear();
    std::vector<int> uncleared;
    auto add = [&](MoveKind kind, int tour, bool collides) {
      if (collides) {
        uncleared.push_back(static_cast<int>(path.points.size()));
      }
      path.points.push_back(Vec3::Zero());
      path.kind.push_back(kind);
      path.pathIndex.push_back(tour);
    };
    for (int t = 0; t < walks; ++t) {
      walkOfTour.push_back(t);
      for (int i = 0; i < (t == 0 ? air : 1); ++i) {
        add(MoveKind::Air, t, t == 0);
      }
      const auto at = colliding.find({t, wayOf[static_cast<size_t>(t)]});
      const int c = at == colliding.end() ? 0 : at->second;
      for (int i = 0; i < 10; ++i) {
        add(MoveKind::Print, t, i < c);
      }
    }
    for (int i = 0; i < extraStations; ++i) {
      add(MoveKind::Print, walks - 1, false);
    }
    return uncleared;
  }
};

struct Retried {
  Toolpath path;
  std::vector<int> uncleared, walkOfTour, wayOf;
  TourWayRetry retry;
};

Retried retry(FakePlanner& f, const std::vector<char>& closed) {
  Retried r;
  r.wayOf.assign(static_cast<size_t>(f.walks), 0);
  r.uncleared = f.plan(r.path, r.walkOfTour, r.wayOf);
  f.passes = 0;
  r.retry = retryTourWays(r.path, r.uncleared, r.walkOfTour, r.wayOf, closed,
                          [&] { return f.plan(r.path, r.walkOfTour, r.wayOf); });
  return r;
}

}  // namespace

TEST(TourWays, TheWaysAreForwardsBackwardsAndFromHalfway) {
  EXPECT_FALSE(tourWay(0).fromHalfway);
  EXPECT_FALSE(tourWay(0).backwards);
  EXPECT_TRUE(tourWay(1).backwards);
  EXPECT_FALSE(tourWay(1).fromHalfway);
  EXPECT_TRUE(tourWay(2).fromHalfway);
  EXPECT_FALSE(tourWay(2).backwards);
  EXPECT_TRUE(tourWay(3).fromHalfway && tourWay(3).backwards);
  EXPECT_THROW(tourWay(kTourWays), GeoLatticeError);
  EXPECT_THROW(tourWay(-1), GeoLatticeError);
}

TEST(TourWays, EachTourKeepsTheWayWhereFewestOfItsStationsCollide) {
  FakePlanner f;
  f.colliding = {{{0, 0}, 4}, {{0, 1}, 1}, {{0, 2}, 3}, {{0, 3}, 2},   // walk 0: backwards best
                 {{1, 0}, 0}, {{1, 1}, 5},                             // walk 1: clear, untouched
                 {{2, 0}, 3}, {{2, 1}, 6}, {{2, 2}, 6}, {{2, 3}, 0}};  // walk 2: half-way back
  f.extraStations = 10000;  // below the fraction that is retried
  const Retried r = retry(f, {1, 1, 1});
  EXPECT_EQ(r.wayOf, (std::vector<int>{1, 0, 3}));
  EXPECT_EQ(r.retry.retriedTours, 2);
  EXPECT_EQ(r.retry.reorderedTours, 2);
  EXPECT_EQ(r.retry.before, 7);
  EXPECT_EQ(r.retry.after, 1);
  EXPECT_EQ(r.uncleared.size(), 1u);
  EXPECT_EQ(r.retry.passes, kTourWays);  // three trial passes and the path kept
  EXPECT_EQ(f.passes, kTourWays);
}

TEST(TourWays, AClearTourStopsBeingTried) {
  FakePlanner f;
  f.walks = 1;
  f.colliding = {{{0, 0}, 2}, {{0, 1}, 0}, {{0, 2}, 7}, {{0, 3}, 7}};
  f.extraStations = 10000;
  const Retried r = retry(f, {1});
  EXPECT_EQ(r.wayOf, std::vector<int>{1});
  EXPECT_EQ(r.retry.after, 0);
  // Backwards cleared it: no other way tried, and that pass's path is the one kept.
  EXPECT_EQ(r.retry.passes, 1);
  EXPECT_EQ(f.passes, 1);
}

TEST(TourWays, OpenRunsAndAirStationsAreNotRetried) {
  FakePlanner f;
  f.colliding = {{{0, 0}, 2}, {{0, 1}, 0}, {{1, 0}, 3}, {{1, 1}, 0}};
  f.air = 2;  // air stations before walk 0 collide in every way
  f.extraStations = 10000;
  const Retried r = retry(f, {0, 1, 1});  // walk 0 is an open run
  EXPECT_EQ(r.wayOf, (std::vector<int>{0, 1, 0}));
  EXPECT_EQ(r.retry.retriedTours, 1);
  EXPECT_EQ(r.retry.before, 7);
  EXPECT_EQ(r.retry.after, 4);  // walk 0's two and the two air stations stay
}

TEST(TourWays, ThePathIsKeptOnlyWhereFewerCollideInAll) {
  // Walk 0 collides less backwards, walk 1 from half-way, but the last pass (their ways chosen
  // together, a path no trial planned) collides more in all: the usual path is restored, with
  // its ways, stations and tours.
  FakePlanner f;
  f.walks = 2;
  f.colliding = {{{0, 0}, 3}, {{0, 1}, 1}, {{0, 2}, 3}, {{0, 3}, 3},
                 {{1, 0}, 3}, {{1, 1}, 3}, {{1, 2}, 1}, {{1, 3}, 3}};
  f.extraStations = 10000;
  Retried r;
  r.wayOf.assign(2, 0);
  r.uncleared = f.plan(r.path, r.walkOfTour, r.wayOf);
  const size_t stations = r.path.points.size();
  const std::vector<int> before = r.uncleared;
  int pass = 0;
  r.retry = retryTourWays(r.path, r.uncleared, r.walkOfTour, r.wayOf, {1, 1}, [&] {
    std::vector<int> u = f.plan(r.path, r.walkOfTour, r.wayOf);
    if (++pass == kTourWays) {  // the path with the chosen ways: more collide there
      for (int i = 0; i < 10; ++i) {
        u.push_back(static_cast<int>(stations) - 1 - i);
      }
    }
    return u;
  });
  EXPECT_EQ(pass, kTourWays);
  EXPECT_EQ(r.retry.reorderedTours, 0);
  EXPECT_EQ(r.retry.after, 6);
  EXPECT_EQ(r.uncleared, before);
  EXPECT_EQ(r.wayOf, (std::vector<int>{0, 0}));
  EXPECT_EQ(r.path.points.size(), stations);
}

TEST(TourWays, APathFarFromPrintableIsNotRetried) {
  FakePlanner f;
  f.colliding = {{{0, 0}, 5}, {{0, 1}, 0}};
  f.extraStations = 10;  // 5 colliding of 43 stations: above kMaxRetriedFraction
  const Retried r = retry(f, {1, 1, 1});
  EXPECT_EQ(r.retry.retriedTours, 0);
  EXPECT_EQ(r.retry.passes, 0);
  EXPECT_EQ(f.passes, 0);
  EXPECT_EQ(r.wayOf, (std::vector<int>{0, 0, 0}));
  EXPECT_EQ(r.uncleared.size(), 5u);
}
