// The orientation search (core/orient/AutoOrient.h) on a part built so that one orientation is
// printable: a flat-topped mushroom (a 20 mm stem under a 50 mm wide, 4 mm thick flange). Stem
// down, the flange overhangs 15 mm: its curved layers lean out sideways and the nozzle meets the
// build plate. Flange down, it lies flat and the stem grows straight up: no collision.
#include "common/Error.h"
#include "common/ParallelFor.h"
#include "io/MeshReader.h"
#include "mesh/AnalyticShapes.h"
#include "orient/AutoOrient.h"
#include "pedestal/Pedestal.h"
#include "../common/ErrorOf.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace geolattice;

namespace {

TriangleSurface flatMushroom() {
  return revolvedSurface({{0, 0}, {10, 0}, {10, 26}, {25, 26}, {25, 30}, {0, 30}}, 48);
}

/// A ball of radius R centred at z = R, its bottom cut flat at height `cut` (0: no cut, a ball).
TriangleSurface cutBall(double R, double cut, int rings, int segments) {
  std::vector<std::pair<double, double>> profile = {{0, cut}};
  const double start = std::acos(1 - cut / R);  // polar angle from the bottom pole
  for (int i = 0; i <= rings; ++i) {
    const double a = start + (M_PI - start) * i / rings;
    if (i == 0 && cut == 0) {
      continue;
    }
    profile.emplace_back(R * std::sin(a), R - R * std::cos(a));
  }
  profile.back().first = 0;
  return revolvedSurface(profile, segments);
}

OrientOptions fewCandidates(int sphere) {
  OrientOptions o;
  o.sphereCandidates = sphere;
  o.hullCandidates = 0;
  o.evaluationTets = 4000;
  return o;
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
  const std::string m = expectedErrorOf([&] { searchOrientation(flatMushroom(), o); });
  EXPECT_NE(m.find("no orientation has a base contact area of 100000 mm^2"), std::string::npos)
      << m;
  EXPECT_NE(m.find("the largest is"), std::string::npos) << m;
  OrientOptions bad;
  bad.minBaseArea = -1;
  EXPECT_THROW(searchOrientation(flatMushroom(), bad), GeoLatticeError);
}

TEST(AutoOrient, WhenEveryOrientationFailsAStageTheMessageSaysWhichNotTheArea) {
  // A ball floating in the closed cavity of a box: no side puts it on the base, whatever the
  // contact area (900 mm^2 here). The message gives the stage's reason.
  TriangleSurface part = boxSurface(Vec3(30, 30, 30), 5.0);
  auto append = [&part](TriangleSurface s, const Vec3& shift, bool inward) {
    const int offset = static_cast<int>(part.points.size());
    for (const Vec3& p : s.points) {
      part.points.push_back(p + shift);
    }
    for (auto t : s.triangles) {
      if (inward) {
        std::swap(t[1], t[2]);
      }
      part.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
  };
  append(boxSurface(Vec3(20, 20, 20), 5.0), Vec3(5, 5, 5), true);
  append(sphereSurface(Vec3::Zero(), 4.0, 2), Vec3(15, 15, 15), false);
  OrientOptions o;
  o.sphereCandidates = 12;
  o.hullCandidates = 4;
  const std::string m = expectedErrorOf([&] { searchOrientation(part, o); });
  EXPECT_NE(m.find("every orientation with a base contact area of at least 10 mm^2 failed a "
                   "stage"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("does not touch the base"), std::string::npos) << m;
  EXPECT_EQ(m.find("no orientation has a base contact area"), std::string::npos) << m;
}

TEST(AutoOrient, ASideWithoutAPrintLayerIsNotChosen) {
  // A 0.4 mm plate: lying flat it has nothing to collide but no layer either (the first one is
  // at 0.6 mm); it is printed standing on an edge.
  const TriangleSurface plate = boxSurface(Vec3(30, 30, 0.4), 2.0);
  OrientOptions o;
  o.sphereCandidates = 12;
  o.hullCandidates = 6;
  const OrientResult r = searchOrientation(plate, o);
  const OrientCandidate& best = r.candidates[r.best];
  EXPECT_TRUE(best.feasible);
  EXPECT_LT(std::abs(best.down.z()), 0.5) << best.down.transpose();
  int flat = 0;
  for (const OrientCandidate& c : r.candidates) {
    if (std::abs(c.down.z()) > 0.99 && c.pedestal == 0) {
      ++flat;
      EXPECT_FALSE(c.feasible);
      EXPECT_NE(c.error.find("no layer"), std::string::npos) << c.error;
    }
  }
  EXPECT_GT(flat, 0);
}

TEST(AutoOrient, APartWithNoFlatSideStandsOnAPedestal) {
  // A ball touches the plate on a small cap: 0.3 mm deep it is 2 pi R 0.3 = 28 mm^2, below the
  // 50 asked for; a pedestal reaching 1 mm into it stands it on 2 pi R 1 = 94 mm^2.
  const TriangleSurface ball = cutBall(15, 0, 24, 32);
  OrientOptions o = fewCandidates(6);
  o.minBaseArea = 50;
  o.pedestal = PedestalChoice::Never;
  EXPECT_THROW(searchOrientation(ball, o), GeoLatticeError);
  o.pedestal = PedestalChoice::WhenItHelps;
  const OrientResult r = searchOrientation(ball, o);
  const OrientCandidate& best = r.candidates[r.best];
  EXPECT_TRUE(best.feasible);
  EXPECT_EQ(best.pedestal, o.pedestalHeight);
  EXPECT_GE(best.baseArea, o.minBaseArea);  // the faces within 1 mm (as tessellated)
  EXPECT_GT(best.baseArea, 1.5 * r.candidates[0].baseArea);
  EXPECT_NEAR(best.height, 30 + o.pedestalHeight, 0.5);
  EXPECT_FALSE(r.candidates[0].feasible);  // the ball as placed, on the plate
  // The side's base area is the cross-section of the column built under it.
  PedestalOptions column;
  column.height = best.pedestal;
  column.contactHeight = o.pedestalContactHeight;
  const PedestalResult built = addPedestal(orientSurface(ball, best.rotation), column);
  EXPECT_NEAR(best.baseArea, built.footprintArea, 1e-6 * built.footprintArea);
}

TEST(AutoOrient, ThePlateInTheNozzlesWayIsLiftedOnAPedestal) {
  // A ball on a small flat (r 4 mm): the first layers curl around the flat's rim a millimetre
  // above the plate, where the nozzle meets it. Only the placement is a candidate.
  const TriangleSurface blob = cutBall(15, 15 - std::sqrt(15.0 * 15.0 - 16.0), 24, 32);
  OrientOptions o = fewCandidates(0);
  o.pedestal = PedestalChoice::Never;
  o.maxTiltDeg = 0;  // a toolpath that never tilts: a 30° tilt lifts these off the plate (below)
  // The flat alone is the base: the coarse ball's first ring of facets round it lies within the
  // flat band (0.6 mm, within 10° of level) and would start the layers on the plate too.
  o.baseFlatBand = 0;
  const OrientResult onPlate = searchOrientation(blob, o);
  ASSERT_EQ(onPlate.candidates.size(), 1u);
  const OrientCandidate& keep = onPlate.candidates[0];
  EXPECT_GT(keep.plateStations, 0);
  EXPECT_EQ(keep.pedestal, 0);
  o.pedestal = PedestalChoice::WhenItHelps;
  const OrientResult r = searchOrientation(blob, o);
  ASSERT_EQ(r.candidates.size(), 2u);  // the placement on the plate and on a pedestal
  const OrientCandidate& best = r.candidates[r.best];
  EXPECT_EQ(best.pedestal, o.pedestalHeight);
  EXPECT_LT(best.collidingStations, r.candidates[0].collidingStations);
  EXPECT_EQ(best.plateStations, 0);
  o.pedestal = PedestalChoice::Always;  // every candidate on one: the placement only
  const OrientResult always = searchOrientation(blob, o);
  ASSERT_EQ(always.candidates.size(), 1u);
  EXPECT_EQ(always.candidates[0].pedestal, o.pedestalHeight);
  // The toolpath's default tilt lifts the nozzle off the plate there: the placement stays on
  // the plate (its pedestal is tried too, and needs no tilt, but costs a column).
  o.pedestal = PedestalChoice::WhenItHelps;
  o.maxTiltDeg = OrientOptions{}.maxTiltDeg;
  const OrientResult tilted = searchOrientation(blob, o);
  ASSERT_EQ(tilted.candidates.size(), 2u);
  const OrientCandidate& placement = tilted.candidates[tilted.best];
  EXPECT_EQ(placement.pedestal, 0);
  EXPECT_EQ(placement.plateStations, 0);
  EXPECT_EQ(placement.tiltClearedPlateStations, keep.plateStations);
}

TEST(AutoOrient, PlateStationsTheToolpathsTiltLiftsOffThePlateAreNotCounted) {
  // A bowl widening 60° off the vertical from a 10 mm foot: along its wall the layer normal
  // leans 60° out, so a 45° cone on it reaches below its tip, into the plate; a 30° tilt
  // towards +z stands the cone's lowest line level. Only the placement is a candidate.
  const double widen = std::tan(60 * M_PI / 180);
  const TriangleSurface bowl = revolvedSurface(
      {{0, 0}, {10, 0}, {10 + 12 * widen, 12}, {10 + 12 * widen - 2, 14}, {0, 14}}, 48);
  OrientOptions o = fewCandidates(0);
  o.pedestal = PedestalChoice::Never;
  o.maxTiltDeg = 0;
  const OrientCandidate untilted = searchOrientation(bowl, o).candidates[0];
  EXPECT_GT(untilted.plateStations, 20);
  o.maxTiltDeg = OrientOptions{}.maxTiltDeg;
  const OrientCandidate tilted = searchOrientation(bowl, o).candidates[0];
  EXPECT_EQ(tilted.stations, untilted.stations);
  EXPECT_LT(tilted.plateStations, untilted.plateStations / 3);  // the lowest 1 mm stay counted
  EXPECT_EQ(untilted.collidingStations - tilted.collidingStations,
            untilted.plateStations - tilted.plateStations);
  EXPECT_EQ(tilted.tiltClearedPlateStations, untilted.plateStations - tilted.plateStations);
  EXPECT_EQ(untilted.tiltClearedPlateStations, 0);
  o.maxTiltDeg = 61;
  EXPECT_THROW(searchOrientation(bowl, o), GeoLatticeError);
}

TEST(AutoOrient, TheBestCoarseCandidatesAndThePlacementAreScoredAtThePrintsResolution) {
  OrientOptions o = fewCandidates(16);
  o.refineCandidates = 2;
  const OrientResult r = searchOrientation(flatMushroom(), o);
  int refined = 0;
  for (const OrientCandidate& c : r.candidates) {
    refined += c.refined;
    if (!c.refined) {
      EXPECT_EQ(c.coarseCollidingStations, c.collidingStations);
    }
  }
  EXPECT_EQ(refined, r.refined);
  EXPECT_GE(r.refined, 2);
  EXPECT_LE(r.refined, 3);  // the two best and the placement, when it is not one of them
  EXPECT_TRUE(r.candidates[0].refined);
  const OrientCandidate& best = r.candidates[r.best];
  EXPECT_TRUE(best.refined);
  // At 0.6 mm layers and a 4 mm lattice there are more stations than at 1.5 mm and 8 mm.
  EXPECT_GT(best.stations, 0);
  EXPECT_GT(best.layers, 30 / o.layerInterval);
  for (const OrientCandidate& c : r.candidates) {
    if (c.refined) {
      EXPECT_LE(best.collidingStations, c.collidingStations);
    }
  }
  o.refineCandidates = -1;
  EXPECT_THROW(searchOrientation(flatMushroom(), o), GeoLatticeError);
}

TEST(AutoOrient, BaseContactArea) {
  const TriangleSurface s = flatMushroom();
  // Stem down: the 10 mm disc; flange down: the 25 mm disc; on its side: one facet of the
  // 48-sided rim and of the stem, a small fraction.
  EXPECT_NEAR(baseContactArea(s, Eigen::Matrix3d::Identity(), 0.3), M_PI * 100, 0.05 * M_PI * 100);
  EXPECT_NEAR(baseContactArea(s, rotationTakingDownToMinusZ(Vec3::UnitZ()), 0.3), M_PI * 625,
              0.05 * M_PI * 625);
  EXPECT_LT(baseContactArea(s, rotationTakingDownToMinusZ(Vec3::UnitX()), 0.3), 0.05 * M_PI * 625);
  // Every triangle turned inward (a common export error): the same contact, not 0.
  TriangleSurface inward = s;
  for (auto& t : inward.triangles) {
    std::swap(t[1], t[2]);
  }
  EXPECT_DOUBLE_EQ(baseContactArea(inward, Eigen::Matrix3d::Identity(), 0.3),
                   baseContactArea(s, Eigen::Matrix3d::Identity(), 0.3));
  EXPECT_DOUBLE_EQ(baseContactArea(inward, rotationTakingDownToMinusZ(Vec3::UnitZ()), 0.3),
                   baseContactArea(s, rotationTakingDownToMinusZ(Vec3::UnitZ()), 0.3));
}

TEST(AutoOrient, AThinBowlIsScoredOnACoarseMesh) {
  // A hemispherical bowl, 2.5 mm wall: the count of its coarse mesh follows the surface's
  // triangles, not the volume (the 2.5 mm bowl generated by marching cubes: 146k tets for 15k).
  // Its second meshing coarsens the simplified surface (the input again, at twice TetGen's
  // volume-bound edge, left the count as it was). At 1 mm no surface helps: TetGen's quality
  // bound alone makes tets about as small as the wall.
  const double R = 25, wall = 2.5;
  std::vector<std::pair<double, double>> profile;
  const int rings = 40;
  for (int i = 0; i <= rings; ++i) {  // outside, from the bottom pole up to the rim
    const double a = 0.5 * M_PI * i / rings;
    profile.emplace_back(R * std::sin(a), R - R * std::cos(a));
  }
  for (int i = rings; i >= 0; --i) {  // inside, from the rim down to the inner pole
    const double a = 0.5 * M_PI * i / rings;
    profile.emplace_back((R - wall) * std::sin(a), R - (R - wall) * std::cos(a));
  }
  profile.back().first = 0;
  OrientOptions o = fewCandidates(4);
  o.evaluationTets = 1000;
  const OrientResult r = searchOrientation(revolvedSurface(profile, 96), o);
  EXPECT_LE(r.evaluationTets, 3 * o.evaluationTets);  // 4,078 before, 2,380 now
  EXPECT_GE(4 * r.evaluationTets, o.evaluationTets);
}

TEST(AutoOrient, TurningUpsideDownIsARotationWithoutScale) {
  // The gear's chosen down direction: within 5e-12 of +z, just above Eigen's own threshold for
  // opposite vectors; its quaternion came out 1e-5 off unit length and the part 2e-5 taller.
  for (const Vec3& down : {Vec3(-3.06469036272112e-06, -2.9548685596932395e-07, 1.0),
                           Vec3(1e-7, 0, 1), Vec3(0, 0, 1), Vec3(0.3, -0.2, 0.9), Vec3(1, 0, 0)}) {
    const Eigen::Matrix3d R = rotationTakingDownToMinusZ(down);
    EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 1e-14) << down.transpose();
    EXPECT_NEAR(R.determinant(), 1.0, 1e-14);
    EXPECT_LT((R * down.normalized() + Vec3::UnitZ()).norm(), 1e-8) << down.transpose();
  }
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

TEST(ParallelFor, ProgressCountsEveryItemWhenTheCallerWakesLate) {
  // The calling thread is held up in its first callback while the workers finish the rest: it
  // still reports 2, 3, ..., n after it (callers report at counts of their choosing, e.g. each
  // 64th, and must not miss one; under load this made the progress of the potential-collision
  // search skip most of its reports).
  std::vector<size_t> counts;
  parallelFor(
      200, 2, [](size_t, int) {},
      [&](size_t done) {
        if (counts.empty()) {
          std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        counts.push_back(done);
      });
  std::vector<size_t> expected(200);
  std::iota(expected.begin(), expected.end(), size_t{1});
  EXPECT_EQ(counts, expected);
}

TEST(AutoOrient, HullCandidatesDoNotDependOnThePointOrder) {
  // The hull's facets merged within 2° are grouped greedily; the grouping must follow the facets,
  // not the order CGAL's hull lists them in (that followed the allocator: the 80 mm bunny gave
  // another direction with malloc on huge pages). Here: the bunny's points in a shuffled order.
  const TriangleSurface bunny = readObj(std::string(GEOLATTICE_TESTDATA) + "/bunny.obj");
  TriangleSurface shuffled = bunny;
  std::vector<int> relabel(bunny.points.size());
  std::iota(relabel.begin(), relabel.end(), 0);
  std::shuffle(relabel.begin(), relabel.end(), std::mt19937(3));
  for (size_t v = 0; v < bunny.points.size(); ++v) {
    shuffled.points[static_cast<size_t>(relabel[v])] = bunny.points[v];
  }
  for (auto& t : shuffled.triangles) {
    for (int& v : t) {
      v = relabel[static_cast<size_t>(v)];
    }
  }
  const std::vector<Vec3> a = hullFacetNormals(bunny, 24);
  const std::vector<Vec3> b = hullFacetNormals(shuffled, 24);
  ASSERT_EQ(a.size(), 24u);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i], b[i]) << "normal " << i;
    EXPECT_NEAR(a[i].norm(), 1.0, 1e-12);
  }
}

TEST(AutoOrient, ALargePartIsScoredAtAResolutionItsSizeScales) {
  // An evaluation's stations grow as volume / (layer interval x lattice width): the bunny at
  // 300 mm had 3.0M stations per refined candidate and a 251 s search. Above
  // kFullResolutionVolume both (and the material samples' spacing) are scaled by
  // sqrt(volume / kFullResolutionVolume), so a part four times as large as one of that volume is
  // scored with no more stations than that one (measured: 0.62x; 4x at the given resolution).
  EXPECT_EQ(evaluationScale(0.5 * kFullResolutionVolume), 1.0);
  EXPECT_DOUBLE_EQ(evaluationScale(4 * kFullResolutionVolume), 2.0);
  const TriangleSurface mushroom = flatMushroom();  // 16,022 mm³
  auto scaled = [&](double volume) {
    TriangleSurface s = mushroom;
    const double k = std::cbrt(volume / 16022.0);
    for (Vec3& p : s.points) {
      p *= k;
    }
    return s;
  };
  OrientOptions o = fewCandidates(0);  // the placement alone, coarse only
  o.refineCandidates = 0;
  o.pedestal = PedestalChoice::Never;
  const OrientResult reference = searchOrientation(scaled(kFullResolutionVolume), o);
  const OrientResult large = searchOrientation(scaled(4 * kFullResolutionVolume), o);
  EXPECT_NEAR(reference.evaluationScale, 1.0, 0.05);
  EXPECT_NEAR(large.evaluationScale, 2.0, 0.1);
  const double ratio = static_cast<double>(large.candidates[0].stations) /
                       static_cast<double>(reference.candidates[0].stations);
  std::printf("[ mushroom at 1x and 4x %.0f mm³ ] stations %lld and %lld, scale %.2f and %.2f\n",
              kFullResolutionVolume, reference.candidates[0].stations, large.candidates[0].stations,
              reference.evaluationScale, large.evaluationScale);
  EXPECT_GT(ratio, 0.3);
  EXPECT_LT(ratio, 1.2);
}

TEST(AutoOrient, ASideTallerThanTheCellPrintsRanksAfterTheSidesThatFit) {
  // A round post (r 6 mm) 60 mm tall: standing on its flat end it needs no pedestal, lying it
  // does (a round side has no contact), so without a limit it stands. 60 mm is more than the
  // cell holds (maxHeight 40): the chosen side lies down (at most 40 mm tall with its pedestal).
  const TriangleSurface post = revolvedSurface({{0, 0}, {6, 0}, {6, 60}, {0, 60}}, 32);
  OrientOptions o;
  o.sphereCandidates = 12;
  o.hullCandidates = 6;
  o.maxHeight = 40;
  const OrientResult r = searchOrientation(post, o);
  const OrientCandidate& best = r.candidates[r.best];
  EXPECT_TRUE(best.feasible);
  EXPECT_TRUE(best.fitsHeight);
  EXPECT_LE(best.height, 40.0) << best.down.transpose();
  int tall = 0;
  for (const OrientCandidate& c : r.candidates) {
    EXPECT_EQ(c.fitsHeight, c.height <= 40.0);
    tall += c.fitsHeight ? 0 : 1;
    if (c.feasible && !c.fitsHeight && c.refined == best.refined &&
        c.collidingStations >= best.collidingStations) {
      EXPECT_GT(c.rank, best.rank);
    }
  }
  EXPECT_GT(tall, 0);
  o.maxHeight = 0;  // no limit: the post stands
  const OrientResult free = searchOrientation(post, o);
  EXPECT_GT(free.candidates[free.best].height, 40.0);
  o.maxHeight = -1;
  EXPECT_THROW(searchOrientation(post, o), GeoLatticeError);
}
