// The independent collision verifier on hand-built cases: two towers printed in the wrong
// order must collide, layer by layer must not; the holder, the tip clearance and bad input.
#include <algorithm>
#include "collision/CollisionVerifier.h"
#include "common/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace geolattice;
using V = Eigen::Vector3d;

namespace {

/// Two vertical towers of points (x = 0 and x = gap), 0.6 mm apart in z, nozzle axis +z.
/// towerFirst: tower A completely, then B; otherwise layer by layer (A, B at each height).
struct Towers {
  std::vector<V> points, normals;
  std::vector<int> time;
};

Towers towers(double gap, int levels, bool towerFirst) {
  Towers t;
  for (int tower = 0; tower < 2; ++tower) {
    for (int k = 0; k < levels; ++k) {
      t.points.push_back(V(tower * gap, 0, 0.6 * k));
      t.normals.push_back(V(0, 0, 1));
      t.time.push_back(towerFirst ? tower * levels + k : 2 * k + tower);
    }
  }
  return t;
}

NozzleModel cone(double deg) {
  NozzleModel n;
  n.halfAngleDeg = deg;
  return n;
}

}  // namespace

TEST(CollisionVerifier, TowersInTheWrongOrderCollide) {
  const Towers t = towers(3.0, 20, true);
  const CollisionReport r = verifyNozzleClearance(t.points, t.normals, t.time, cone(60));
  EXPECT_FALSE(r.collisionFree);
  ASSERT_FALSE(r.violations.empty());
  // The first violation: printing the bottom of tower B, tower A stands inside the cone.
  const CollisionViolation& v = r.violations.front();
  EXPECT_EQ(v.station, 20);  // B's first point
  EXPECT_NEAR(v.stationPoint.x(), 3.0, 1e-12);
  EXPECT_NEAR(v.obstaclePoint.x(), 0.0, 1e-12);
  EXPECT_NEAR(v.radial, 3.0, 1e-12);
  EXPECT_GT(v.height, 3.0 / std::tan(60 * M_PI / 180));
  // Exactly the B points with A material higher than radial / tan(NA) above them collide:
  // A's top is at 11.4 mm; B at height z collides iff 11.4 - z > 3 / tan 60° = 1.732.
  int expected = 0;
  for (int k = 0; k < 20; ++k) {
    expected += 11.4 - 0.6 * k > 3.0 / std::tan(60 * M_PI / 180);
  }
  EXPECT_EQ(r.violatingStations, expected);
  EXPECT_EQ(r.stations, 40);
}

TEST(CollisionVerifier, TowersLayerByLayerDoNotCollide) {
  const Towers t = towers(3.0, 20, false);
  EXPECT_TRUE(verifyNozzleClearance(t.points, t.normals, t.time, cone(60)).collisionFree);
  EXPECT_TRUE(verifyNozzleClearance(t.points, t.normals, t.time, cone(89)).collisionFree);
}

TEST(CollisionVerifier, SlenderNozzleClearsTheOtherTower) {
  // 3 mm away, 11.4 mm high: inside a cone only if tan NA > 3 / 11.4, NA > 14.7°.
  const Towers t = towers(3.0, 20, true);
  EXPECT_TRUE(verifyNozzleClearance(t.points, t.normals, t.time, cone(14.5)).collisionFree);
  EXPECT_FALSE(verifyNozzleClearance(t.points, t.normals, t.time, cone(15.0)).collisionFree);
}

TEST(CollisionVerifier, HolderCollidesAboveTheNozzleLength) {
  const Towers t = towers(3.0, 20, true);
  NozzleModel n = cone(10);  // the cone alone clears tower A
  EXPECT_TRUE(verifyNozzleClearance(t.points, t.normals, t.time, n).collisionFree);
  n.length = 5.0;
  n.holderRadius = 2.9;  // holder just misses
  EXPECT_TRUE(verifyNozzleClearance(t.points, t.normals, t.time, n).collisionFree);
  n.holderRadius = 3.1;  // holder reaches tower A, which stands more than 5 mm above B's bottom
  const CollisionReport r = verifyNozzleClearance(t.points, t.normals, t.time, n);
  EXPECT_FALSE(r.collisionFree);
  EXPECT_GT(r.violations.front().height, 5.0);
}

TEST(CollisionVerifier, TiltedAxisAndTipClearance) {
  // One earlier point 1 mm above the tip and 1 mm to the side: 45° from +z.
  const std::vector<V> p = {V(1, 0, 1), V(0, 0, 0)};
  const std::vector<int> time = {0, 1};
  std::vector<V> n = {V(0, 0, 1), V(0, 0, 1)};
  EXPECT_TRUE(verifyNozzleClearance(p, n, time, cone(44.9)).collisionFree);
  EXPECT_FALSE(verifyNozzleClearance(p, n, time, cone(45.1)).collisionFree);
  n[1] = V(1, 0, 1);  // axis points at it (re-normalised)
  EXPECT_FALSE(verifyNozzleClearance(p, n, time, cone(1)).collisionFree);
  n[1] = V(-1, 0, 1);  // axis tilted away: 90° off
  EXPECT_TRUE(verifyNozzleClearance(p, n, time, cone(89)).collisionFree);
  NozzleModel c = cone(60);
  n[1] = V(0, 0, 1);
  c.tipClearance = 1.0;  // material at h = 1 is level with the clearance: ignored
  EXPECT_TRUE(verifyNozzleClearance(p, n, time, c).collisionFree);
  // Within the tip face radius: the bead under the nozzle's flat face, not an obstacle.
  c = cone(60);
  c.tipFaceRadius = std::sqrt(2.0) + 1e-9;
  EXPECT_TRUE(verifyNozzleClearance(p, n, time, c).collisionFree);
  c.tipFaceRadius = std::sqrt(2.0) - 1e-9;
  EXPECT_FALSE(verifyNozzleClearance(p, n, time, c).collisionFree);
  // Same print time: not an obstacle (a sub-graph is not tested against itself).
  EXPECT_TRUE(verifyNozzleClearance(p, n, {0, 0}, cone(60)).collisionFree);
  // Material printed later is not an obstacle.
  EXPECT_TRUE(verifyNozzleClearance(p, n, {1, 0}, cone(60)).collisionFree);
}

TEST(CollisionVerifier, ManyPointsMatchBruteForce) {
  // Random cloud with random axes: the kd-tree query must agree with an all-pairs check.
  std::srand(7);
  auto rnd = [] {
    return std::rand() / double(RAND_MAX);
  };
  std::vector<V> p, n;
  std::vector<int> time;
  for (int i = 0; i < 1500; ++i) {
    // Every third point has a close neighbour, so the tip clearance and face radius matter.
    p.push_back(i % 3 == 2 ? V(p.back() + 0.4 * V(rnd() - 0.5, rnd() - 0.5, rnd()))
                           : V(20 * rnd(), 20 * rnd(), 20 * rnd()));
    n.push_back(V(rnd() - 0.5, rnd() - 0.5, 1.0).normalized());
    time.push_back(static_cast<int>(30 * rnd()));
  }
  // An unbounded holder, and one that ends 4 + 6 mm above the tip (the printhead's top).
  for (const double holderLength : {std::numeric_limits<double>::infinity(), 6.0}) {
    NozzleModel nz = cone(20);
    nz.length = 4;
    nz.holderRadius = 3;
    nz.holderLength = holderLength;
    nz.tipClearance = 0.05;
    nz.tipFaceRadius = 0.2;
    // With an exemption (group g's obstacles from groups below g are unavoidable), the
    // reported obstacle is the nearest avoidable one, else the nearest exempt one.
    CollisionExemption exemption;
    for (size_t i = 0; i < p.size(); ++i) {
      exemption.group.push_back(static_cast<int>(i % 5));
    }
    exemption.unavoidable = [](int station, int obstacle) {
      return obstacle < station;
    };
    for (const CollisionExemption* judged : {static_cast<const CollisionExemption*>(nullptr),
                                             static_cast<const CollisionExemption*>(&exemption)}) {
      const CollisionReport r = verifyNozzleClearance(p, n, time, nz, 100000, judged);
      long long brute = 0, nearTip = 0, exempt = 0;
      const double c2 = std::pow(std::cos(20 * M_PI / 180), 2);
      // Per station: its obstacle nearest the tip, of the avoidable and of the exempt kind.
      std::vector<int> nearest(p.size(), -1), nearestExempt(p.size(), -1);
      for (size_t k = 0; k < p.size(); ++k) {
        for (size_t q = 0; q < p.size(); ++q) {
          if (time[q] >= time[k])
            continue;
          const V d = p[q] - p[k];
          const double h = d.dot(n[k]);
          if (h <= 0.05)
            continue;
          if (d.norm() <= 0.2) {
            nearTip += h * h > d.squaredNorm() * c2;  // inside the cone but under the tip face
            continue;
          }
          const double r2 = d.squaredNorm() - h * h;
          if (!(h <= 4 ? h * h > d.squaredNorm() * c2 : h <= 4 + holderLength && r2 < 9))
            continue;
          int& best = judged && exemption.unavoidable(exemption.group[k], exemption.group[q])
                          ? nearestExempt[k]
                          : nearest[k];
          if (best < 0 || d.squaredNorm() < (p[best] - p[k]).squaredNorm()) {
            best = static_cast<int>(q);
          }
        }
        brute += nearest[k] >= 0 || nearestExempt[k] >= 0;
        exempt += nearest[k] < 0 && nearestExempt[k] >= 0;
      }
      EXPECT_EQ(r.violatingStations, brute) << holderLength;
      EXPECT_EQ(r.unavoidableStations, exempt) << holderLength;
      // The reported obstacle is the one nearest the tip, whatever order the tree visits them
      // in, with its height along the axis and distance from it.
      ASSERT_EQ(static_cast<long long>(r.violations.size()), brute);
      for (const CollisionViolation& v : r.violations) {
        const int k = v.station;
        const int expected = nearest[k] >= 0 ? nearest[k] : nearestExempt[k];
        EXPECT_EQ(v.obstacle, expected) << "station " << k;
        EXPECT_EQ(v.unavoidable, nearest[k] < 0);
        const V d = p[expected] - p[k];
        EXPECT_NEAR(v.height, d.dot(n[k]), 1e-9);
        EXPECT_NEAR(v.radial, (d - d.dot(n[k]) * n[k]).norm(), 1e-9);
      }
      EXPECT_GT(nearTip, 0);  // the face radius was exercised
      EXPECT_GT(brute, 0);
      EXPECT_LT(brute, static_cast<long long>(p.size()));
      if (judged) {
        EXPECT_GT(exempt, 0);
        EXPECT_LT(exempt, brute);
      }
    }
  }
}

TEST(CollisionVerifier, BadInput) {
  const std::vector<V> p = {V(0, 0, 0), V(0, 0, 1)};
  const std::vector<V> n = {V(0, 0, 1), V(0, 0, 1)};
  EXPECT_THROW(verifyNozzleClearance(p, n, {0}, cone(45)), GeoLatticeError);  // sizes
  EXPECT_THROW(verifyNozzleClearance(p, {V(0, 0, 1), V::Zero()}, {0, 1}, cone(45)),
               GeoLatticeError);  // zero axis
  EXPECT_THROW(verifyNozzleClearance({V(0, 0, 0), V(0, 0, NAN)}, n, {0, 1}, cone(45)),
               GeoLatticeError);
  EXPECT_THROW(verifyNozzleClearance(p, n, {0, 1}, cone(0)),
               GeoLatticeError);  // NA outside (0, 90)
  EXPECT_THROW(verifyNozzleClearance(p, n, {0, 1}, cone(90)), GeoLatticeError);
  EXPECT_THROW(verifyNozzleClearance(p, n, {0, 1}, cone(-5)), GeoLatticeError);
  NozzleModel bad = cone(45);
  bad.length = 0;
  EXPECT_THROW(verifyNozzleClearance(p, n, {0, 1}, bad), GeoLatticeError);
  bad = cone(45);
  bad.tipFaceRadius = -0.1;
  EXPECT_THROW(verifyNozzleClearance(p, n, {0, 1}, bad), GeoLatticeError);
  EXPECT_TRUE(verifyNozzleClearance({}, {}, {}, cone(45)).collisionFree);  // nothing printed
}

// The build plate (nozzle/BuildPlate.h): a slab under z = 0 around the part's footprint, an
// obstacle at every station like material, counted as unavoidable for the order.
TEST(CollisionVerifier, BuildPlateIsAnObstacle) {
  // A 20 mm line of points 0.6 mm above the plate, printed left to right.
  auto line = [](const V& axis, double z) {
    Towers t;
    for (int i = 0; i <= 20; ++i) {
      t.points.push_back(V(i, 0, z));
      t.normals.push_back(axis);
      t.time.push_back(i);
    }
    return t;
  };
  const BuildPlate plate;  // margin 10 mm, 5 mm thick
  const NozzleModel nozzle = cone(45);
  // Vertical axis: the plate is below the tip plane, never inside the cone.
  Towers up = line(V(0, 0, 1), 0.6);
  CollisionReport r =
      verifyNozzleClearance(up.points, up.normals, up.time, nozzle, 20, nullptr, nullptr, &plate);
  EXPECT_TRUE(r.collisionFree);
  // Axis 60° from vertical (beyond 90° - NA): the cone's lower side reaches the plate 2 mm from
  // the tip (0.6 mm / tan 15°) at every station.
  const double t = 60 * M_PI / 180;
  Towers tilted = line(V(std::sin(t), 0, std::cos(t)), 0.6);
  r = verifyNozzleClearance(tilted.points, tilted.normals, tilted.time, nozzle, 20, nullptr,
                            nullptr, &plate);
  EXPECT_EQ(r.violatingStations, 21);
  EXPECT_EQ(r.plateStations, 21);
  EXPECT_FALSE(r.orderCollisionFree);  // no order to judge: the first obstacle decides
  // With an order to judge (an exemption), no order avoids the plate: unavoidable.
  CollisionExemption exemption;
  exemption.group.assign(tilted.points.size(), 0);
  exemption.unavoidable = [](int, int) {
    return false;
  };
  const CollisionReport judged = verifyNozzleClearance(tilted.points, tilted.normals, tilted.time,
                                                       nozzle, 20, &exemption, nullptr, &plate);
  EXPECT_EQ(judged.plateStations, 21);
  EXPECT_EQ(judged.unavoidableStations, 21);
  EXPECT_TRUE(judged.orderCollisionFree);
  // Either way the obstacle shown is the plate's sample nearest the tip: on its top face.
  for (const CollisionReport* report : {static_cast<const CollisionReport*>(&r), &judged}) {
    ASSERT_EQ(report->violations.size(), 20u);
    for (const CollisionViolation& v : report->violations) {
      EXPECT_EQ(v.obstacle, -1);
      EXPECT_NEAR(v.obstaclePoint.z(), 0.0, 1e-12);
    }
  }
  // 40° from vertical: the cone's lower side rises 5° above the horizon, the plate stays out.
  const double u = 40 * M_PI / 180;
  Towers mild = line(V(std::sin(u), 0, std::cos(u)), 0.6);
  EXPECT_TRUE(verifyNozzleClearance(mild.points, mild.normals, mild.time, nozzle, 20, nullptr,
                                    nullptr, &plate)
                  .collisionFree);
  // Without the plate the tilted line is free (nothing printed earlier is in the way).
  EXPECT_TRUE(
      verifyNozzleClearance(tilted.points, tilted.normals, tilted.time, nozzle).collisionFree);
  // A tip inside the plate (an air move below z = 0) collides even with the axis pointing down.
  Towers dive = line(V(0, 0, 1), 0.6);
  dive.points[10].z() = -0.3;
  dive.normals[10] = V(0, 0, -1);
  r = verifyNozzleClearance(dive.points, dive.normals, dive.time, nozzle, 20, nullptr, nullptr,
                            &plate);
  EXPECT_EQ(r.violatingStations, 1);
  EXPECT_EQ(r.violations[0].station, 10);
  EXPECT_EQ(r.plateStations, 1);
  // Bad plate parameters are named.
  BuildPlate bad;
  bad.thickness = 0;
  EXPECT_THROW(
      verifyNozzleClearance(up.points, up.normals, up.time, nozzle, 20, nullptr, nullptr, &bad),
      GeoLatticeError);
}

// With an order to judge, a station whose nozzle reaches the plate is still searched for material
// an order could have kept out (after the first plate sample the search runs on the material
// alone): such a station is avoidable, not a plate station.
TEST(CollisionVerifier, AnOrderIsJudgedPastThePlate) {
  const double t = 60 * M_PI / 180;
  const V axis(std::sin(t), 0, std::cos(t));
  Towers line;
  for (int i = 0; i <= 20; ++i) {  // every station's cone reaches the plate (see above)
    line.points.push_back(V(i, 0, 0.6));
    line.normals.push_back(axis);
    line.time.push_back(i + 1);
  }
  line.points.push_back(V(10, 0, 0.6) + 3.0 * axis);  // printed first, up station 10's axis
  line.normals.push_back(axis);
  line.time.push_back(0);
  CollisionExemption exemption;
  exemption.group.assign(line.points.size(), 0);
  exemption.group.back() = 1;
  bool ancestor = false;  // is group 1 material no order can keep out?
  exemption.unavoidable = [&](int, int obstacle) {
    return ancestor && obstacle == 1;
  };
  const BuildPlate plate;
  CollisionReport r = verifyNozzleClearance(line.points, line.normals, line.time, cone(45), 20,
                                            &exemption, nullptr, &plate);
  EXPECT_EQ(r.violatingStations, 22);
  const auto& plateIds = r.plateStationIds;
  EXPECT_EQ(std::count(plateIds.begin(), plateIds.end(), 10), 0);  // avoidable: the material
  EXPECT_LT(r.plateStations, 22);
  EXPECT_EQ(r.unavoidableStations, r.plateStations);
  EXPECT_FALSE(r.orderCollisionFree);
  ancestor = true;  // the same material, now exempt: the plate outranks it
  r = verifyNozzleClearance(line.points, line.normals, line.time, cone(45), 20, &exemption, nullptr,
                            &plate);
  EXPECT_EQ(r.violatingStations, 22);
  EXPECT_EQ(r.plateStations, 22);
  EXPECT_EQ(r.unavoidableStations, 22);
  EXPECT_TRUE(r.orderCollisionFree);
}

// Without an order to judge, a station's obstacle is the plate's or the material's, whichever
// lies nearest its tip (ties: the material), whatever the search finds first: against an all-pairs
// check over the material and the plate's samples, on stations low over the plate with axes
// tilted so that many nozzles hold both.
TEST(CollisionVerifier, ThePlateOrTheMaterialNearestTheTipIsReported) {
  std::srand(11);
  auto rnd = [] {
    return std::rand() / double(RAND_MAX);
  };
  std::vector<V> p, n;
  std::vector<int> time;
  for (int i = 0; i < 800; ++i) {
    p.push_back(V(20 * rnd(), 20 * rnd(), 0.2 + 4 * rnd()));
    const double tilt = 70 * M_PI / 180 * rnd(), turn = 2 * M_PI * rnd();
    n.push_back(
        V(std::sin(tilt) * std::cos(turn), std::sin(tilt) * std::sin(turn), std::cos(tilt)));
    time.push_back(static_cast<int>(40 * rnd()));
  }
  const NozzleModel nozzle = cone(45);
  const BuildPlate plate;
  const std::vector<V> samples = buildPlateSamples(plate, p);
  const CollisionReport r =
      verifyNozzleClearance(p, n, time, nozzle, 100000, nullptr, nullptr, &plate);
  const double c2 = 0.5;  // cos² 45°
  auto inside = [&](size_t k, const V& x) {
    const V d = x - p[k];
    const double h = d.dot(n[k]);
    return h > nozzle.tipClearance && d.norm() > nozzle.tipFaceRadius &&
           h * h > d.squaredNorm() * c2;
  };
  long long colliding = 0, onPlate = 0;
  std::vector<double> nearestD2(p.size(), -1);
  std::vector<char> plateNearest(p.size(), 0);
  for (size_t k = 0; k < p.size(); ++k) {
    double material = std::numeric_limits<double>::infinity(), fromPlate = material;
    for (size_t q = 0; q < p.size(); ++q) {
      if (time[q] < time[k] && inside(k, p[q])) {
        material = std::min(material, (p[q] - p[k]).squaredNorm());
      }
    }
    for (const V& s : samples) {
      if (inside(k, s)) {
        fromPlate = std::min(fromPlate, (s - p[k]).squaredNorm());
      }
    }
    if (std::isfinite(material) || std::isfinite(fromPlate)) {
      ++colliding;
      plateNearest[k] = fromPlate < material;
      onPlate += plateNearest[k];
      nearestD2[k] = std::min(material, fromPlate);
    }
  }
  EXPECT_EQ(r.violatingStations, colliding);
  EXPECT_EQ(r.plateStations, onPlate);
  EXPECT_GT(onPlate, 0);
  EXPECT_LT(onPlate, colliding);
  ASSERT_EQ(static_cast<long long>(r.violations.size()), colliding);
  for (const CollisionViolation& v : r.violations) {
    EXPECT_EQ(v.obstacle == -1, static_cast<bool>(plateNearest[v.station])) << v.station;
    EXPECT_NEAR((v.obstaclePoint - v.stationPoint).squaredNorm(), nearestD2[v.station], 1e-9);
  }

  // Stations left out of the search (known clear by the caller) are not searched, but are
  // still counted as stations and are still obstacles.
  std::vector<char> checked(p.size(), 1);
  EXPECT_EQ(verifyNozzleClearance(p, n, time, nozzle, 0, nullptr, nullptr, &plate, &checked)
                .violatingStations,
            colliding);
  for (int k : r.violatingStationIds) {
    checked[k] = k % 2;
  }
  const CollisionReport some =
      verifyNozzleClearance(p, n, time, nozzle, 0, nullptr, nullptr, &plate, &checked);
  EXPECT_EQ(some.stations, static_cast<long long>(p.size()));
  EXPECT_EQ(some.violatingStations,
            std::count_if(r.violatingStationIds.begin(), r.violatingStationIds.end(),
                          [](int k) { return k % 2 == 1; }));
  checked.pop_back();
  EXPECT_THROW(verifyNozzleClearance(p, n, time, nozzle, 0, nullptr, nullptr, &plate, &checked),
               GeoLatticeError);
}

// With an order to judge and the plate, each station's verdict is the first kind present of:
// material an order could have kept out (avoidable), the plate, material no order keeps out
// (exempt), and its reported obstacle is the nearest of that kind: against an all-pairs check, on
// stations low over the plate whose nozzles hold all three kinds (the past-the-plate search runs
// on a tree that skips exempt groups whole).
TEST(CollisionVerifier, AnOrderIsJudgedOverThePlateAsAnAllPairsCheckJudgesIt) {
  std::srand(13);
  auto rnd = [] {
    return std::rand() / double(RAND_MAX);
  };
  std::vector<V> p, n;
  std::vector<int> time;
  CollisionExemption exemption;
  for (int i = 0; i < 1200; ++i) {
    p.push_back(V(20 * rnd(), 20 * rnd(), 0.2 + 4 * rnd()));
    const double tilt = 75 * M_PI / 180 * rnd(), turn = 2 * M_PI * rnd();
    n.push_back(
        V(std::sin(tilt) * std::cos(turn), std::sin(tilt) * std::sin(turn), std::cos(tilt)));
    time.push_back(static_cast<int>(40 * rnd()));
    exemption.group.push_back(time.back() / 4);  // groups of print times, as sub-graphs
  }
  exemption.unavoidable = [](int station, int obstacle) {
    return obstacle < station && obstacle % 3 != 1;  // some earlier groups are not ancestors
  };
  const NozzleModel nozzle = cone(45);
  const BuildPlate plate;
  const std::vector<V> samples = buildPlateSamples(plate, p);
  const CollisionReport r =
      verifyNozzleClearance(p, n, time, nozzle, 100000, &exemption, nullptr, &plate);
  auto inside = [&](size_t k, const V& x) {
    const V d = x - p[k];
    const double h = d.dot(n[k]);
    return h > nozzle.tipClearance && d.norm() > nozzle.tipFaceRadius &&
           h * h > d.squaredNorm() * 0.5;  // cos² 45°
  };
  enum Kind { None, Avoidable, Plate, Exempt };
  std::vector<Kind> kind(p.size(), None);
  std::vector<double> nearestD2(p.size(), std::numeric_limits<double>::infinity());
  std::vector<int> nearest(p.size(), -1);
  long long count[4] = {0, 0, 0, 0};
  for (size_t k = 0; k < p.size(); ++k) {
    double d2[4] = {0, std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
    int best[4] = {-1, -1, -1, -1};
    for (size_t q = 0; q < p.size(); ++q) {
      if (time[q] < time[k] && inside(k, p[q])) {
        const Kind c =
            exemption.unavoidable(exemption.group[k], exemption.group[q]) ? Exempt : Avoidable;
        const double d = (p[q] - p[k]).squaredNorm();
        if (d < d2[c]) {
          d2[c] = d;
          best[c] = static_cast<int>(q);
        }
      }
    }
    for (const V& s : samples) {
      if (inside(k, s)) {
        d2[Plate] = std::min(d2[Plate], (s - p[k]).squaredNorm());
      }
    }
    for (const Kind c : {Avoidable, Plate, Exempt}) {
      if (std::isfinite(d2[c])) {
        kind[k] = c;
        nearestD2[k] = d2[c];
        nearest[k] = c == Plate ? -1 : best[c];
        break;
      }
    }
    ++count[kind[k]];
  }
  EXPECT_GT(count[Avoidable], 0);
  EXPECT_GT(count[Plate], 0);
  EXPECT_GT(count[Exempt], 0);
  EXPECT_EQ(r.violatingStations, count[Avoidable] + count[Plate] + count[Exempt]);
  EXPECT_EQ(r.plateStations, count[Plate]);
  EXPECT_EQ(r.unavoidableStations, count[Plate] + count[Exempt]);
  EXPECT_FALSE(r.orderCollisionFree);
  ASSERT_EQ(static_cast<long long>(r.violations.size()), r.violatingStations);
  for (const CollisionViolation& v : r.violations) {
    const int k = v.station;
    EXPECT_EQ(v.unavoidable, kind[k] != Avoidable) << k;
    EXPECT_EQ(v.obstacle, nearest[k]) << k;
    EXPECT_NEAR((v.obstaclePoint - v.stationPoint).squaredNorm(), nearestD2[k], 1e-9) << k;
  }
}
