// Toolpath post-processing: subdivision (rotation steps, longest segment, exact extrusion) and
// the nozzle axis clearance that tilts the axis off ∇γ where it would hit earlier material.
#include "collision/CollisionVerifier.h"
#include "common/Error.h"
#include "nozzle/BuildPlate.h"
#include "nozzle/Printhead.h"
#include "toolpath/NozzleAxisClearance.h"
#include "toolpath/PathSubdivision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace geolattice;

namespace {

double degreesBetween(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / M_PI;
}

void push(Toolpath& p, const Vec3& x, const Vec3& n, MoveKind kind, double h, double e) {
  p.points.push_back(x);
  p.normals.push_back(n.normalized());
  p.kind.push_back(kind);
  p.thickness.push_back(kind == MoveKind::Air ? 0.0 : h);
  p.width.push_back(kind == MoveKind::Air ? 0.0 : 0.6);
  p.extrusion.push_back(e);
  p.feedRate.push_back(kind == MoveKind::Air ? 50.0 : 10.0);
  p.layer.push_back(kind == MoveKind::Air ? -1 : 0);
  p.subgraph.push_back(kind == MoveKind::Air ? -1 : 0);
  p.pathIndex.push_back(0);
}

/// Earlier material on a line rising at 42.3° from the axis of stations along y: inside a 45°
/// nozzle along +z at the station y = 0, outside it after a tilt of about 3°.
struct Scene {
  std::vector<Vec3> points, axes;
  std::vector<char> material;
  int station = -1;
  Scene() {
    for (double x = 3; x <= 6.01; x += 0.5) {
      points.emplace_back(x, 0, 1.1 * x);
      axes.emplace_back(0, 0, 1);
      material.push_back(1);
    }
    for (double y = -6; y <= 6.01; y += 0.5) {
      if (std::abs(y) < 1e-9)
        station = static_cast<int>(points.size());
      points.emplace_back(0, y, 0);
      axes.emplace_back(0, 0, 1);
      material.push_back(1);
    }
  }
};

NozzleModel cone45() {
  NozzleModel n;
  n.halfAngleDeg = 45;
  return n;
}

int collidingStations(const Scene& s, const std::vector<Vec3>& axes) {
  std::vector<int> time(s.points.size());
  for (size_t i = 0; i < time.size(); ++i)
    time[i] = static_cast<int>(i);
  return static_cast<int>(
      verifyNozzleClearance(s.points, axes, time, cone45(), 0, nullptr, &s.material)
          .violatingStations);
}

}  // namespace

TEST(PathSubdivision, RotationStepsLengthsAndExactExtrusion) {
  Toolpath p;
  push(p, Vec3(0, 0, 0), Vec3(0, 0, 1), MoveKind::Air, 0, 0);
  push(p, Vec3(0, 0, 0.4), Vec3(0, 0, 1), MoveKind::Print, 0.4, 0);  // arrives by air
  push(p, Vec3(3, 0, 0.4), Vec3(std::sin(0.35), 0, std::cos(0.35)), MoveKind::Print, 0.8,
       1.0);  // turns 20°
  const std::vector<Vec3> original = p.normals;
  std::vector<Vec3> reference = p.normals;
  const SubdivisionCounts c = subdivideToolpath(p, 5 * M_PI / 180, 1.0, &reference);
  // Segment 2: 3 mm and 20.05° -> max(ceil(20.05 / 5), ceil(3 / 1)) = 5 pieces; segment 1: 1 piece.
  EXPECT_EQ(c.inserted, 4);
  EXPECT_EQ(c.rotationSteps, 4);
  ASSERT_EQ(p.points.size(), 7u);
  ASSERT_EQ(reference.size(), 7u);
  EXPECT_NEAR(p.extrusion.back(), 1.0, 1e-15);
  for (size_t i = 3; i < p.points.size(); ++i) {
    EXPECT_LE(degreesBetween(p.normals[i - 1], p.normals[i]), 5.0 + 1e-9);
    EXPECT_LE((p.points[i] - p.points[i - 1]).norm(), 1.0);
    EXPECT_EQ(p.kind[i], MoveKind::Print);
    EXPECT_NEAR(degreesBetween(p.normals[i], reference[i]), 0.0, 1e-9);
    // Eq. 14 per piece: ΔE ∝ (h_a + h_b) / 2 · L with the same constant as the whole segment.
    const double piece =
        0.5 * (p.thickness[i - 1] + p.thickness[i]) * (p.points[i] - p.points[i - 1]).norm();
    const double whole = 0.5 * (0.4 + 0.8) * 3.0;
    EXPECT_NEAR((p.extrusion[i] - p.extrusion[i - 1]) / 1.0, piece / whole, 1e-12)
        << "piece ending at " << i;
  }
  EXPECT_NEAR(degreesBetween(p.normals.back(), original.back()), 0.0, 1e-12);
  // Nothing to do: no change.
  const size_t n = p.points.size();
  EXPECT_EQ(subdivideToolpath(p, 5 * M_PI / 180, 1.0).inserted, 0);
  EXPECT_EQ(p.points.size(), n);
}

TEST(NozzleAxisClearance, TiltsTheLeastAngleAwayAndFadesAlongThePath) {
  Scene s;
  ASSERT_GT(collidingStations(s, s.axes), 0);
  std::vector<Vec3> axes = s.axes;
  AxisClearanceOptions o;
  o.blendLength = 3;
  const AxisClearanceResult r = clearNozzleAxes(s.points, axes, s.axes, s.material, cone45(), o);
  EXPECT_GT(r.collidingStations, 0);
  EXPECT_EQ(r.tiltedStations, r.collidingStations);
  EXPECT_EQ(r.unresolvedStations, 0);
  EXPECT_EQ(collidingStations(s, axes), 0);
  // The station at y = 0: obstacles at 42.27° from +z (atan(1 / 1.1)); clearing them by the
  // 0.5° margin needs 3.23°, tilting away from them (towards -x).
  const double tilt = degreesBetween(axes[s.station], Vec3(0, 0, 1));
  EXPECT_NEAR(tilt, 45.5 - std::atan(1 / 1.1) * 180 / M_PI, 0.05);
  EXPECT_LT(axes[s.station].x(), 0);
  // Fading: points farther than the blend length from every tilted station keep ∇γ; points
  // nearer than it turn, by less than the station.
  int faded = 0;
  for (size_t i = 0; i < s.points.size(); ++i) {
    if (s.points[i].x() != 0)
      continue;  // the material line, printed before the stations
    const double t = degreesBetween(axes[i], Vec3(0, 0, 1));
    EXPECT_LE(t, 15.0 + 1e-9);
    if (std::abs(s.points[i].y()) > 6 - 1e-9) {
      EXPECT_LT(t, 1e-12) << "y = " << s.points[i].y();
    }
    faded += t > 1e-9 && t < tilt - 1e-9;
  }
  EXPECT_GT(faded, 0);
}

TEST(NozzleAxisClearance, AWideLimitStillGivesTheLeastTilt) {
  // Material on both sides of the station (the Scene's line and its mirror at -x): every tilt
  // towards x pushes the nozzle into the other line, the least clearing tilt is along the path
  // (y), acos(cos 45.5° / (1.1 / sqrt(2.21))) = 18.7°. With a 60° limit the axis must still
  // tilt by about that much, not wherever the projection off one line and then the other ends.
  Scene s;
  std::vector<Vec3> points = s.points, axes = s.axes;
  std::vector<char> material = s.material;
  for (double x = 3; x <= 6.01; x += 0.5) {
    points.insert(points.begin(), Vec3(-x, 0, 1.1 * x));
    axes.insert(axes.begin(), Vec3(0, 0, 1));
    material.insert(material.begin(), 1);
  }
  const int station = s.station + 7;
  ASSERT_EQ(points[station], Vec3(0, 0, 0));
  const double least =
      std::acos(std::cos(45.5 * M_PI / 180) / (1.1 / std::sqrt(2.21))) * 180 / M_PI;
  for (double limit : {30.0, 60.0}) {
    std::vector<Vec3> tilted = axes;
    AxisClearanceOptions o;
    o.maxTiltDeg = limit;
    o.blendLength = 0;
    const AxisClearanceResult r = clearNozzleAxes(points, tilted, axes, material, cone45(), o);
    EXPECT_EQ(r.unresolvedStations, 0) << limit;
    const double tilt = degreesBetween(tilted[station], Vec3(0, 0, 1));
    EXPECT_GE(tilt, least - 0.5) << limit;
    EXPECT_LE(tilt, least + 1.0) << limit;  // the rings' 0.5° steps
  }
}

TEST(NozzleAxisClearance, AFadeThatWouldPushAPointIntoMaterialIsNotTakenWhenAsked) {
  // The Scene's stations near y = 0 tilt towards -x, and their tilts fade along the path. Earlier
  // material on the -x side of the path near y = -3.5, just outside the 45° cone of the untilted
  // axis there (45.4°, 3 mm away): the fade turns the points there towards it and, unchecked,
  // into it.
  Scene s;
  std::vector<Vec3> points = s.points, axes = s.axes;
  std::vector<char> material = s.material;
  const double a = 45.4 * M_PI / 180;
  for (double y : {-3.6, -3.5, -3.4}) {
    points.insert(points.begin(), Vec3(-3 * std::sin(a), y, 3 * std::cos(a)));
    axes.insert(axes.begin(), Vec3(0, 0, 1));
    material.insert(material.begin(), 1);
  }
  std::vector<int> time(points.size());
  for (size_t i = 0; i < time.size(); ++i)
    time[i] = static_cast<int>(i);
  auto colliding = [&](const std::vector<Vec3>& n) {
    return verifyNozzleClearance(points, n, time, cone45(), 0, nullptr, &material)
        .violatingStations;
  };
  // Only the Scene's stations collide as they are (the new material is outside every cone).
  const size_t before = colliding(axes);
  ASSERT_EQ(before, static_cast<size_t>(collidingStations(s, s.axes)));
  AxisClearanceOptions o;
  o.blendLength = 3;
  std::vector<Vec3> unchecked = axes;
  const AxisClearanceResult free = clearNozzleAxes(points, unchecked, axes, material, cone45(), o);
  EXPECT_EQ(static_cast<size_t>(free.tiltedStations), before);
  EXPECT_EQ(free.keptPoints, 0);
  EXPECT_GT(colliding(unchecked), 0u);  // points near y = -3.5 faded into the material
  o.fadeOnlyWhereClear = true;
  std::vector<Vec3> checked = axes;
  const AxisClearanceResult settled = clearNozzleAxes(points, checked, axes, material, cone45(), o);
  EXPECT_EQ(static_cast<size_t>(settled.tiltedStations), before);
  EXPECT_GT(settled.keptPoints, 0);
  EXPECT_GT(settled.blendedPoints, 0);  // the fades that stay clear are still taken
  EXPECT_EQ(colliding(checked), 0u);
}

TEST(NozzleAxisClearance, ALaterPassReusesTheSearchesOfStationsWithTheSameEarlierMaterial) {
  // The toolpath planner's attempts differ only in air moves (not material): a second pass on
  // the path with air points inserted takes the first pass's searches and gives the axes a pass
  // without the memo gives; a change of earlier material makes it search again.
  const Scene s;
  AxisClearanceOptions o;
  o.blendLength = 2;
  AxisSearchMemo memo;
  std::vector<Vec3> axes = s.axes;
  const AxisClearanceResult first =
      clearNozzleAxes(s.points, axes, s.axes, s.material, cone45(), o, nullptr, nullptr, &memo);
  ASSERT_GT(first.tiltedStations, 0);
  EXPECT_EQ(memo.reused, 0);
  EXPECT_EQ(memo.found.size(), static_cast<size_t>(first.collidingStations));

  Scene t = s;  // an air move over the line before the stations (never an obstacle itself)
  const auto at = static_cast<long>(s.station - 4);
  for (int j = 0; j < 3; ++j) {
    t.points.insert(t.points.begin() + at + j, Vec3(-2.0, -2.0 + j, 8.0));
    t.axes.insert(t.axes.begin() + at + j, Vec3(0, 0, 1));
    t.material.insert(t.material.begin() + at + j, 0);
  }
  std::vector<Vec3> fresh = t.axes, reused = t.axes;
  const AxisClearanceResult without =
      clearNozzleAxes(t.points, fresh, t.axes, t.material, cone45(), o);
  const AxisClearanceResult with =
      clearNozzleAxes(t.points, reused, t.axes, t.material, cone45(), o, nullptr, nullptr, &memo);
  EXPECT_EQ(memo.reused, first.collidingStations);  // every material station's search
  EXPECT_EQ(with.collidingStations, without.collidingStations);
  EXPECT_EQ(with.tiltedStations, without.tiltedStations);
  EXPECT_EQ(reused, fresh);

  // The first material point moved: no station's earlier material is the memo's any more.
  t.points[0].z() += 0.25;
  std::vector<Vec3> moved = t.axes, movedFresh = t.axes;
  const long long before = memo.reused;
  clearNozzleAxes(t.points, moved, t.axes, t.material, cone45(), o, nullptr, nullptr, &memo);
  EXPECT_EQ(memo.reused, before);
  clearNozzleAxes(t.points, movedFresh, t.axes, t.material, cone45(), o);
  EXPECT_EQ(moved, movedFresh);
}

TEST(NozzleAxisClearance, AStationKnownClearIsCheckedAgainstTheInsertedPoints) {
  // A later round after points were inserted: a station found clear with an unchanged axis is
  // checked against the inserted material only; an inserted point right above a clear station
  // must still be found, and the pass must give what a full pass gives.
  const Scene s;
  AxisClearanceOptions o;
  o.blendLength = 1;
  KnownClear known{std::vector<char>(s.points.size(), 0), std::vector<char>(s.points.size(), 0)};
  std::vector<Vec3> axes = s.axes;
  const AxisClearanceResult first = clearNozzleAxes(s.points, axes, s.axes, s.material, cone45(), o,
                                                    nullptr, nullptr, nullptr, &known);
  ASSERT_GT(first.tiltedStations, 0);
  const int station = s.station + 8;  // y = 4: clear, far from the tilted ones
  ASSERT_TRUE(known.clear[station]);

  Scene t = s;
  std::vector<Vec3> reference = s.axes;
  const long at = 7;  // after the material line, before every station
  t.points.insert(t.points.begin() + at, Vec3(0, 4, 2));
  t.material.insert(t.material.begin() + at, 1);
  axes.insert(axes.begin() + at, Vec3(0, 0, 1));
  reference.insert(reference.begin() + at, Vec3(0, 0, 1));
  known.clear.insert(known.clear.begin() + at, 0);
  known.inserted.assign(t.points.size(), 0);
  known.inserted[at] = 1;
  std::vector<Vec3> full = axes;
  AxisClearanceOptions detect = o;
  detect.maxTiltDeg = 0;
  const AxisClearanceResult partial = clearNozzleAxes(
      t.points, axes, reference, t.material, cone45(), detect, nullptr, nullptr, nullptr, &known);
  const AxisClearanceResult whole =
      clearNozzleAxes(t.points, full, reference, t.material, cone45(), detect);
  EXPECT_EQ(partial.colliding, whole.colliding);
  EXPECT_NE(std::find(partial.colliding.begin(), partial.colliding.end(), station + 1),
            partial.colliding.end());
  EXPECT_FALSE(known.clear[station + 1]);
}

TEST(NozzleAxisClearance, ReportsStationsNoAllowedTiltClears) {
  Scene s;
  std::vector<Vec3> axes = s.axes;
  AxisClearanceOptions o;
  o.maxTiltDeg = 2;  // 3.2° would be needed
  const AxisClearanceResult r = clearNozzleAxes(s.points, axes, s.axes, s.material, cone45(), o);
  EXPECT_GT(r.unresolvedStations, 0);
  EXPECT_NEAR(degreesBetween(axes[s.station], Vec3(0, 0, 1)), 0.0,
              2.0 + 1e-9);  // within the limit, maybe faded
  EXPECT_GT(collidingStations(s, axes), 0);
  // Off: detection only.
  axes = s.axes;
  o.maxTiltDeg = 0;
  const AxisClearanceResult off = clearNozzleAxes(s.points, axes, s.axes, s.material, cone45(), o);
  EXPECT_EQ(off.collidingStations, collidingStations(s, s.axes));
  EXPECT_EQ(off.tiltedStations, 0);
  EXPECT_EQ(axes, s.axes);
}

TEST(NozzleAxisClearance, BadInput) {
  Scene s;
  std::vector<Vec3> axes = s.axes;
  AxisClearanceOptions o;
  std::vector<Vec3> shortAxes(axes.begin(), axes.end() - 1);
  EXPECT_THROW(clearNozzleAxes(s.points, shortAxes, s.axes, s.material, cone45(), o),
               GeoLatticeError);
  o.maxTiltDeg = 70;
  EXPECT_THROW(clearNozzleAxes(s.points, axes, s.axes, s.material, cone45(), o), GeoLatticeError);
  o = AxisClearanceOptions{};
  o.blendLength = -1;
  EXPECT_THROW(clearNozzleAxes(s.points, axes, s.axes, s.material, cone45(), o), GeoLatticeError);
  NozzleModel bad = cone45();
  bad.halfAngleDeg = 95;
  EXPECT_THROW(clearNozzleAxes(s.points, axes, s.axes, s.material, bad, AxisClearanceOptions{}),
               GeoLatticeError);
}

// The build plate as a fixed obstacle: a line printed 0.6 mm above the plate with the layer normal
// 50° from vertical hits the plate with a 45° cone; the clearance tilts each axis back towards
// vertical by the least angle that clears the (finite: the footprint + 10 mm) plate.
TEST(NozzleAxisClearance, TiltsAwayFromTheBuildPlate) {
  std::vector<Vec3> points, axes, reference;
  const double t = 50 * M_PI / 180;
  for (int i = 0; i <= 20; ++i) {
    points.push_back(Vec3(i, 0, 0.6));
    axes.push_back(Vec3(0, std::sin(t), std::cos(t)));
  }
  reference = axes;
  const std::vector<char> material(points.size(), 1);
  NozzleModel nozzle;
  BuildPlate plate;
  const std::vector<Vec3> samples = buildPlateSamples(plate, points);
  AxisClearanceOptions o;
  const AxisClearanceResult r =
      clearNozzleAxes(points, axes, reference, material, nozzle, o, &samples);
  EXPECT_EQ(r.collidingStations, 21);
  EXPECT_EQ(r.tiltedStations, 21);
  for (const Vec3& a : axes) {
    const double tilt = std::acos(a.z()) * 180 / M_PI;
    EXPECT_LT(tilt, 49.0);  // turned back towards vertical ...
    EXPECT_GT(tilt, 44.0);  // ... by a few degrees only
  }
  // Checked again: nothing left.
  AxisClearanceOptions detect = o;
  detect.maxTiltDeg = 0;
  EXPECT_EQ(clearNozzleAxes(points, axes, reference, material, nozzle, detect, &samples)
                .collidingStations,
            0);
}

TEST(NozzleAxisClearance, EveryTiltedStationIsClearOfEveryNozzleShape) {
  // A random path with random axes; for a cone, a cone with a holder wider than the cone (its
  // angle atan(R / L) above NA) and a printhead mesh, every station the clearance tilted has no
  // earlier material inside the nozzle at its new axis (brute force), and the clearance finds
  // some stations to tilt and some it cannot clear.
  std::srand(17);
  auto rnd = [] {
    return std::rand() / double(RAND_MAX);
  };
  std::vector<Vec3> points, reference;
  for (int i = 0; i < 900; ++i) {
    points.push_back(i % 3 ? Vec3(points.back() + Vec3(rnd() - 0.5, rnd() - 0.5, 0.6 * rnd()))
                           : Vec3(30 * rnd(), 30 * rnd(), 20 * rnd()));
    reference.push_back(Vec3(0.4 * (rnd() - 0.5), 0.4 * (rnd() - 0.5), 1).normalized());
  }
  const std::vector<char> material(points.size(), 1);
  NozzleModel holder;
  holder.halfAngleDeg = 15;
  holder.length = 3;
  holder.holderRadius = 4;  // atan(4 / 3) = 53° > 15°
  holder.holderLength = 10;
  NozzleModel head;
  TriangleSurface mesh;  // a stepped body of revolution: r 0.5 -> 1.5 at z 1, r 5 from z 6 to 12
  {
    const std::vector<std::pair<double, double>> profile = {{0, 0}, {0.5, 0}, {1.5, 1}, {1.5, 6},
                                                            {5, 6}, {5, 12},  {0, 12}};
    const int n = 32;
    mesh.points.push_back(Vec3(0, 0, 0));
    for (size_t i = 1; i + 1 < profile.size(); ++i) {
      for (int j = 0; j < n; ++j) {
        mesh.points.push_back(Vec3(profile[i].first * std::cos(2 * M_PI * j / n),
                                   profile[i].first * std::sin(2 * M_PI * j / n),
                                   profile[i].second));
      }
    }
    mesh.points.push_back(Vec3(0, 0, 12));
    const int rings = static_cast<int>(profile.size()) - 2, top = 1 + rings * n;
    for (int j = 0; j < n; ++j) {
      const int jn = (j + 1) % n;
      mesh.triangles.push_back({0, 1 + jn, 1 + j});
      for (int i = 0; i + 1 < rings; ++i) {
        mesh.triangles.push_back({1 + i * n + j, 1 + i * n + jn, 1 + (i + 1) * n + jn});
        mesh.triangles.push_back({1 + i * n + j, 1 + (i + 1) * n + jn, 1 + (i + 1) * n + j});
      }
      mesh.triangles.push_back({1 + (rings - 1) * n + j, 1 + (rings - 1) * n + jn, top});
    }
  }
  head.printhead = std::make_shared<const Printhead>(mesh, "stepped");
  for (const NozzleModel& nozzle : {cone45(), holder, head}) {
    std::vector<Vec3> axes = reference;
    AxisClearanceOptions o;
    o.blendLength = 0;  // only the stations move
    const AxisClearanceResult r = clearNozzleAxes(points, axes, reference, material, nozzle, o);
    EXPECT_GT(r.tiltedStations, 0);
    EXPECT_GT(r.unresolvedStations, 0);
    const NozzleVolume volume(nozzle);
    int checked = 0;
    for (int k : r.colliding) {
      if ((axes[k] - reference[k]).norm() < 1e-12) {
        continue;  // not tilted (unresolved)
      }
      ++checked;
      for (int q = 0; q < k; ++q) {
        EXPECT_FALSE(volume.contains(points[k], axes[k], points[q])) << k << " " << q;
      }
    }
    EXPECT_EQ(checked, r.tiltedStations);
  }
}
