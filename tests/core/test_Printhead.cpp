// The printhead mesh as the nozzle volume (core/nozzle/Printhead.h): the swept profile against
// analytic solids and against CGAL's inside test of the mesh itself at random turns about the
// axis, the bounds used by the spatial indices, the verifier and the potential collisions with a
// printhead against brute force, and every refusal of a bad printhead mesh.
#include "collision/CollisionVerifier.h"
#include "collision/TimedPointTree.h"
#include "common/Error.h"
#include "io/MeshReader.h"
#include "mesh/AnalyticShapes.h"
#include "nozzle/NozzleModel.h"
#include "nozzle/Printhead.h"
#include "sequence/PotentialCollisions.h"
#include "sequence/PrintMaterial.h"

#include "../common/ErrorOf.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

using namespace geolattice;

namespace {

/// An axis-aligned box [lo, hi] as 12 outward triangles.
TriangleSurface box(const Vec3& lo, const Vec3& hi) {
  TriangleSurface s;
  for (int k = 0; k < 8; ++k) {
    s.points.push_back(
        Vec3(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z()));
  }
  s.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return s;
}

/// A slim printhead: face r 0.5, 40° tip cone to r 2, barrel to z 8, wider barrel r 3 to z 30,
/// heater r 10 to 40, heat sink r 11 to 70.
TriangleSurface slimHead(int n = 96) {
  const double coneTop = 1.5 / std::tan(40 * M_PI / 180);
  return revolvedSurface({{0, 0},
                          {0.5, 0},
                          {2, coneTop},
                          {2, 8},
                          {3, 8},
                          {3, 30},
                          {10, 30},
                          {10, 40},
                          {11, 40},
                          {11, 70},
                          {0, 70}},
                         n);
}

/// The nozzle model of the slim printhead of slimHead(48).
NozzleModel slimPrintheadModel() {
  NozzleModel model;
  model.printhead = std::make_shared<const Printhead>(slimHead(48), "slim");
  return model;
}

/// The analytic radius of slimHead's round solid at height h (the largest at a step).
double slimRadius(double h) {
  const double coneTop = 1.5 / std::tan(40 * M_PI / 180);
  if (h < 0 || h > 70)
    return 0;
  if (h <= coneTop)
    return 0.5 + h * std::tan(40 * M_PI / 180);
  if (h < 8)
    return 2;
  if (h < 30)
    return 3;
  if (h < 40)
    return 10;
  return 11;
}

}  // namespace

TEST(Printhead, ProfileMatchesTheAnalyticSolidOfRevolution) {
  const Printhead head(slimHead(), "slim");
  EXPECT_NEAR(head.height(), 70, 1e-12);
  EXPECT_NEAR(head.maxRadius(), 11, 1e-9);
  EXPECT_NEAR(head.faceRadius(), 0.5 + head.binHeight() * std::tan(40 * M_PI / 180), 1e-9);
  EXPECT_NEAR(head.reach(), std::hypot(70, 11), 0.02);
  // Away from the steps the tabulated radius is the circle's (vertices on it), within the slope
  // of the tip cone over one bin.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> height(0, 70);
  const double slack = head.binHeight() * std::tan(40 * M_PI / 180) + 1e-9;
  for (int i = 0; i < 20000; ++i) {
    const double h = height(rng);
    if (std::abs(h - 8) < 0.02 || std::abs(h - 30) < 0.02 || std::abs(h - 40) < 0.02) {
      continue;  // a step inside the bin: the larger radius counts (conservative)
    }
    EXPECT_GE(head.radiusAt(h), slimRadius(h) - 1e-9) << h;
    EXPECT_LE(head.radiusAt(h), slimRadius(h) + slack) << h;
  }
  EXPECT_EQ(head.radiusAt(-0.1), 0);
  EXPECT_EQ(head.radiusAt(70.1), 0);
  // The range maximum is the maximum of the lookups.
  for (int i = 0; i < 2000; ++i) {
    double a = height(rng), b = height(rng);
    if (a > b)
      std::swap(a, b);
    double m = 0;
    for (double h = a; h <= b; h += head.binHeight())
      m = std::max(m, head.radiusAt(h));
    m = std::max(m, head.radiusAt(b));
    EXPECT_NEAR(head.maxRadiusBetween(a, b), m, 1e-12) << a << " " << b;
  }
}

TEST(Printhead, ContainsEveryPointOfTheMeshAtEveryTurnAboutTheAxis) {
  // CGAL's inside test of the mesh, turned about the axis, never finds a point the swept test
  // misses, and the swept test is tight: what it holds, some turn of the mesh holds.
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  // A round nozzle, and a box off the axis (its bottom face holds the tip at the origin).
  const TriangleSurface round =
      revolvedSurface({{0, 0}, {0.5, 0}, {1.5, 1.2}, {1.5, 10}, {0, 10}}, 64);
  const TriangleSurface offAxis = box(Vec3(-3, -2, 0), Vec3(7, 3, 4));
  for (const TriangleSurface* solid : {&round, &offAxis}) {
    const TriangleSurface& mesh = *solid;
    const Printhead head(mesh, "test");
    Mesh cgal;
    std::vector<Mesh::Vertex_index> v;
    for (const Vec3& p : mesh.points)
      v.push_back(cgal.add_vertex(K::Point_3(p.x(), p.y(), p.z())));
    for (const auto& t : mesh.triangles)
      cgal.add_face(v[t[0]], v[t[1]], v[t[2]]);
    const CGAL::Side_of_triangle_mesh<Mesh, K> inside(cgal);
    NozzleModel model;
    model.printhead = std::make_shared<const Printhead>(head);
    model.tipClearance = 0;
    model.tipFaceRadius = 0;
    model.faceContact = 0;
    const NozzleVolume volume(model);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    int insideMesh = 0, insideSwept = 0;
    for (int i = 0; i < 40000; ++i) {
      const Vec3 x(8 * u(rng), 8 * u(rng), head.height() * 0.5 * (u(rng) + 1));
      const double turn = M_PI * u(rng);
      // x in the frame of the printhead turned by `turn` about z
      const Vec3 local(std::cos(turn) * x.x() + std::sin(turn) * x.y(),
                       -std::sin(turn) * x.x() + std::cos(turn) * x.y(), x.z());
      if (inside(K::Point_3(local.x(), local.y(), local.z())) == CGAL::ON_BOUNDED_SIDE) {
        ++insideMesh;
        EXPECT_TRUE(volume.contains(Vec3::Zero(), Vec3::UnitZ(), x)) << x.transpose();
      }
      // Tight: a point well inside the swept solid is inside the mesh at some turn (both
      // solids hold the axis, so every circle up to the largest radius meets their sections).
      const double r = std::hypot(x.x(), x.y());
      if (volume.contains(Vec3::Zero(), Vec3::UnitZ(), x) && r < head.radiusAt(x.z()) - 0.05 &&
          x.z() > 0.05 && x.z() < head.height() - 0.05) {
        ++insideSwept;
        bool some = false;
        for (int a = 0; a < 720 && !some; ++a) {
          const double t = M_PI * a / 360;
          some =
              inside(K::Point_3(r * std::cos(t), r * std::sin(t), x.z())) == CGAL::ON_BOUNDED_SIDE;
        }
        EXPECT_TRUE(some) << x.transpose();
      }
    }
    EXPECT_GT(insideMesh, 100);
  }
}

TEST(Printhead, NeighbouringBeadsUnderTheFaceRimAreNotObstacles) {
  NozzleModel model;
  model.printhead = std::make_shared<const Printhead>(slimHead(48), "slim");
  const Vec3 tip(1, 2, 3), axis = Vec3(0.2, 0.1, 1).normalized();
  const Vec3 side = axis.unitOrthogonal();
  auto at = [&](double h, double r) {
    return Vec3(tip + h * axis + r * side);
  };
  const NozzleVolume volume(model);
  // A bead a path width (0.6 mm) away whose top is 0.2 mm higher: pressed by the face's rim.
  EXPECT_FALSE(volume.contains(tip, axis, at(0.2, 0.6)));
  EXPECT_FALSE(volume.contains(tip, axis, at(0.3, 0.79)));
  // Higher, or farther out under the tip cone: the nozzle's body.
  EXPECT_TRUE(volume.contains(tip, axis, at(0.35, 0.6)));
  EXPECT_TRUE(volume.contains(tip, axis, at(0.8, 0.9)));
  model.faceContact = 0;  // no contact zone: the rim's neighbour is inside the tip cone
  EXPECT_TRUE(NozzleVolume(model).contains(tip, axis, at(0.2, 0.6)));
  // The cone model has no face: the zone does not apply, its own exemptions decide.
  NozzleModel cone;
  cone.halfAngleDeg = 80;
  EXPECT_TRUE(NozzleVolume(cone).contains(tip, axis, at(0.2, 0.6)));
}

TEST(Printhead, TheShippedSlimPrintheadIsValid) {
  const TriangleSurface mesh = readObj(std::string(GEOLATTICE_TESTDATA) + "/printhead_slim.obj");
  const Printhead head(mesh, "printhead_slim.obj");
  EXPECT_NEAR(head.height(), 100, 1e-9);
  EXPECT_NEAR(head.maxRadius(), 20 * std::sqrt(2.0), 1e-5);
  EXPECT_NEAR(head.faceRadius(), 0.5, 0.02);  // the first bin's top: 0.5 + bin tan 40°
  EXPECT_NEAR(head.radiusAt(20), 3, 1e-5);    // the long barrel
  EXPECT_NEAR(head.radiusAt(35), 10, 1e-5);   // the heater block's circumscribed cylinder
  // The bounding cone is slim (the 40° tip cone), with its apex below the tip.
  EXPECT_LT(head.boundHalfAngleRad(), 41 * M_PI / 180);
  EXPECT_GT(head.boundApexOffset(), 0);
  for (double h = 0; h <= 100; h += 0.01) {
    EXPECT_LE(head.radiusAt(h), (h - std::fmod(h, head.binHeight()) + head.boundApexOffset()) *
                                        std::tan(head.boundHalfAngleRad()) +
                                    1e-9)
        << h;
  }
}

TEST(Printhead, BoundsNeverRejectABallThatReachesInside) {
  const NozzleModel model = slimPrintheadModel();
  for (double margin : {0.0, 2.0}) {
    const NozzleModel m = model.widened(margin);
    const NozzleVolume volume(m);
    NozzleBound bound(m, volume);
    bound.setStation(Vec3(1, 2, 3), Vec3(0.3, -0.2, 1).normalized());
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    int touching = 0;
    for (int i = 0; i < 20000; ++i) {
      const Vec3 c = Vec3(1, 2, 3) + Vec3(30 * u(rng), 30 * u(rng), 50 * u(rng) + 40);
      const double rho = 3 * (u(rng) + 1);
      bool any = false;
      for (int s = 0; s < 60 && !any; ++s) {
        const Vec3 d(u(rng), u(rng), u(rng));
        any = volume.contains(bound.tip, bound.axis, c + rho * std::abs(u(rng)) * d.normalized());
      }
      touching += any;
      if (any) {
        EXPECT_TRUE(bound.mayTouch(c, rho)) << c.transpose() << " " << rho;
      }
    }
    EXPECT_GT(touching, 500);
  }
}

namespace {

/// j in PCG(i) iff some station of sub-graph i has a sample of j inside the printhead, as
/// planned and widened by a margin (the clear-angle test adds it as an angle); at least
/// `leastPairs` such pairs.
void expectPotentialCollisionsMatchBruteForce(const MaterialSamples& m, const NozzleModel& model,
                                              long long leastPairs) {
  const int groups = static_cast<int>(m.offset.size()) - 1;
  for (double margin : {0.0, 3.0}) {
    const NozzleModel widened = model.widened(margin);
    const NozzleVolume wide(widened);
    const PotentialCollisions pcg = computePotentialCollisions(m, widened, 2);
    long long pairs = 0;
    for (int i = 0; i < groups; ++i) {
      for (int j = 0; j < groups; ++j) {
        bool hit = false;
        for (int s = m.offset[i]; s < m.offset[i + 1] && !hit && i != j; ++s) {
          for (int q = m.offset[j]; q < m.offset[j + 1] && !hit; ++q) {
            hit = wide.contains(m.points[s], m.normals[s], m.points[q]);
          }
        }
        EXPECT_EQ(hit, std::binary_search(pcg.pcg[i].begin(), pcg.pcg[i].end(), j))
            << i << " " << j << " margin " << margin;
        pairs += hit;
      }
    }
    EXPECT_GE(pairs, leastPairs);
  }
}

}  // namespace

TEST(Printhead, VerifierAndPotentialCollisionsMatchBruteForce) {
  const NozzleModel model = slimPrintheadModel();
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> p, n;
  std::vector<int> time;
  for (int i = 0; i < 1500; ++i) {
    p.push_back(i % 3 == 2 ? Vec3(p.back() + Vec3(3 * u(rng) - 1.5, 3 * u(rng) - 1.5, 6 * u(rng)))
                           : Vec3(150 * u(rng), 150 * u(rng), 150 * u(rng)));
    n.push_back(Vec3(u(rng) - 0.5, u(rng) - 0.5, 1.0).normalized());
    time.push_back(static_cast<int>(30 * u(rng)));
  }
  const CollisionReport r = verifyNozzleClearance(p, n, time, model, 100000);
  const NozzleVolume volume(model);
  long long brute = 0;
  for (size_t k = 0; k < p.size(); ++k) {
    bool hit = false;
    for (size_t q = 0; q < p.size() && !hit; ++q) {
      hit = time[q] < time[k] && volume.contains(p[k], n[k], p[q]);
    }
    brute += hit;
  }
  EXPECT_EQ(r.violatingStations, brute);
  EXPECT_GT(brute, 20);
  EXPECT_LT(brute, static_cast<long long>(p.size()) * 3 / 4);

  // Potential collisions: every time group is a sub-graph; j in PCG(i) iff some station of i has
  // a point of j inside the printhead.
  MaterialSamples m;
  const int groups = 30;
  for (int g = 0; g < groups; ++g) {
    m.offset.push_back(static_cast<int>(m.points.size()));
    for (size_t k = 0; k < p.size(); ++k) {
      if (time[k] == g) {
        m.points.push_back(p[k]);
        m.normals.push_back(n[k]);
      }
    }
  }
  m.offset.push_back(static_cast<int>(m.points.size()));
  expectPotentialCollisionsMatchBruteForce(m, model, 1);
}

TEST(Printhead, PotentialCollisionsOfSmallSubgraphsMatchBruteForce) {
  // Sub-graphs of two samples 0.5-2 mm apart with axes up to 40° apart: each pair's verdict
  // hangs on one or two points, so a node test that rejects a ball reaching into the printhead
  // (the profile, the clear angle, the bounding cone) shows as a missing pair.
  const NozzleModel model = slimPrintheadModel();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  MaterialSamples m;
  const int groups = 250;
  for (int g = 0; g < groups; ++g) {
    m.offset.push_back(static_cast<int>(m.points.size()));
    const Vec3 at(30 * u(rng), 30 * u(rng), 30 * u(rng));
    for (int k = 0; k < 2; ++k) {
      m.points.push_back(at + (0.5 + 1.5 * u(rng)) * k * Vec3(1, u(rng), u(rng)).normalized());
      m.normals.push_back(Vec3(0.8 * u(rng) - 0.4, 0.8 * u(rng) - 0.4, 1.0).normalized());
    }
  }
  m.offset.push_back(static_cast<int>(m.points.size()));
  expectPotentialCollisionsMatchBruteForce(m, model, 100);
}

TEST(Printhead, TheClearAnglesCosineIsTheCosineOfTheClearAngle) {
  const auto head = std::make_shared<const Printhead>(slimHead(48), "slim");
  NozzleModel model;
  model.printhead = head;
  for (double margin : {0.0, 3.0, 60.0}) {
    const NozzleVolume volume(model.widened(margin));
    for (double rho0 : {0.0, 0.3, 1.0, 5.0, 20.0, 47.0}) {
      for (double width : {0.0, 0.5, 4.0, 30.0}) {
        const double angle = volume.maxClearAngleBetween(rho0, rho0 + width);
        EXPECT_NEAR(volume.cosMaxClearAngleBetween(rho0, rho0 + width),
                    angle >= M_PI ? -1.0 : std::cos(angle), 1e-12)
            << rho0 << " " << width << " margin " << margin;
      }
    }
  }
  EXPECT_EQ(head->cosMaxClearAngleBetween(5.0, 1.0), 1.0);  // an empty range: no angle
}

TEST(Printhead, BadMeshesAreRefusedWithTheReason) {
  const TriangleSurface good = slimHead(24);
  ASSERT_NO_THROW(Printhead(good, "good"));

  TriangleSurface open = good;
  open.triangles.pop_back();
  EXPECT_NE(errorOf([&] { Printhead(open, "open.stl"); }).find("printhead open.stl: "),
            std::string::npos);
  EXPECT_NE(errorOf([&] { Printhead(open, "open.stl"); }).find("closed"), std::string::npos);

  TriangleSurface nonManifold = good;  // a fin: a third triangle on an existing edge
  nonManifold.points.push_back(Vec3(20, 0, 35));
  nonManifold.triangles.push_back({nonManifold.triangles[30][0], nonManifold.triangles[30][1],
                                   static_cast<int>(nonManifold.points.size()) - 1});
  EXPECT_NE(errorOf([&] { Printhead(nonManifold, "fin"); }).find("manifold"), std::string::npos);

  TriangleSurface lifted = good;
  for (Vec3& q : lifted.points)
    q.z() += 5;
  EXPECT_NE(errorOf([&] { Printhead(lifted, "lifted"); }).find("lowest point is at z = 5"),
            std::string::npos);

  TriangleSurface aside = good;
  for (Vec3& q : aside.points)
    q.x() += 10;
  EXPECT_NE(errorOf([&] { Printhead(aside, "aside"); }).find("the origin is"), std::string::npos);

  TriangleSurface metres = good;
  for (Vec3& q : metres.points)
    q *= 0.001;
  EXPECT_NE(errorOf([&] { Printhead(metres, "m"); }).find("metres"), std::string::npos);

  // Two overlapping boxes in one mesh: closed and manifold, but self-intersecting.
  TriangleSurface twoBoxes = box(Vec3(-1, -1, 0), Vec3(1, 1, 10));
  const TriangleSurface other = box(Vec3(-3, -0.5, 4), Vec3(3, 0.5, 6));
  const int o = static_cast<int>(twoBoxes.points.size());
  twoBoxes.points.insert(twoBoxes.points.end(), other.points.begin(), other.points.end());
  for (auto t : other.triangles)
    twoBoxes.triangles.push_back({t[0] + o, t[1] + o, t[2] + o});
  EXPECT_NE(errorOf([&] { Printhead(twoBoxes, "boxes"); }).find("intersects itself"),
            std::string::npos);
}
