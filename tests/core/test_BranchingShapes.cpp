// Branching test parts (CGAL unions): validity, dimensions, the flat base, TetGen meshing,
// bad parameters, and the stored copies in testdata/.
#include "mesh/BranchingShapes.h"

#include "common/Error.h"
#include "io/MeshReader.h"
#include "mesh/SurfaceCheck.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>

using namespace geolattice;

namespace {

const std::string kData = GEOLATTICE_TESTDATA;
constexpr double kPi = 3.14159265358979323846;

struct Shape {
  const char* name;
  const char* file;  ///< copy in testdata/
  int branches;
  BranchingShapeParameters parameters;
  std::function<TriangleSurface(const BranchingShapeParameters&)> build;
};

std::vector<Shape> shapes() {
  return {{"Y", "y_shape.obj", 2, yShapeDefaults(),
           [](const auto& p) {
             return yShapeSurface(p);
           }},
          {"tree", "three_branch_tree.obj", 3, threeBranchTreeDefaults(), [](const auto& p) {
             return threeBranchTreeSurface(p);
           }}};
}

Vec3 branchAxis(const BranchingShapeParameters& p, int k, int branches) {
  const double lean = p.branchLeanDeg * kPi / 180.0;
  const double azimuth = (p.firstAzimuthDeg + 360.0 * k / branches) * kPi / 180.0;
  return Vec3(std::sin(lean) * std::cos(azimuth), std::sin(lean) * std::sin(azimuth),
              std::cos(lean));
}

double capsuleVolume(double radius, double length) {
  return kPi * radius * radius * length + 2.0 / 3.0 * kPi * radius * radius * radius;
}

std::string parameterText(const BranchingShapeParameters& p) {
  return "trunkRadius " + std::to_string(p.trunkRadius) + " mm, trunkHeight " +
         std::to_string(p.trunkHeight) + " mm, branchRadius " + std::to_string(p.branchRadius) +
         " mm, branchLength " + std::to_string(p.branchLength) + " mm, branchLeanDeg " +
         std::to_string(p.branchLeanDeg) + ", firstAzimuthDeg " +
         std::to_string(p.firstAzimuthDeg) + ", segments " + std::to_string(p.segments) +
         ", surfaceEdgeLength " + std::to_string(p.surfaceEdgeLength) + " mm";
}

/// Area of the triangles whose three vertices lie at z == 0, and whether each has normal -z.
double bottomArea(const TriangleSurface& s, bool& allFaceDown) {
  double area = 0.0;
  allFaceDown = true;
  for (const auto& t : s.triangles) {
    const Vec3& a = s.points[t[0]];
    const Vec3& b = s.points[t[1]];
    const Vec3& c = s.points[t[2]];
    if (a.z() == 0.0 && b.z() == 0.0 && c.z() == 0.0) {
      const Vec3 n = (b - a).cross(c - a);
      area += 0.5 * n.norm();
      allFaceDown = allFaceDown && n.z() < 0.0;
    }
  }
  return area;
}

}  // namespace

TEST(BranchingShapes, ClosedOutwardWithFlatBaseAndExpectedSize) {
  for (const Shape& shape : shapes()) {
    SCOPED_TRACE(shape.name);
    const BranchingShapeParameters& p = shape.parameters;
    const TriangleSurface s = shape.build(p);
    const SurfaceCheckReport report = requireClosedManifold(s);
    EXPECT_TRUE(report.isClosedManifold());
    EXPECT_EQ(report.unusedPoints, 0);

    // Volume: more than the trunk and the branch parts that overlap nothing (farther than
    // 2 * trunkRadius from the joint), less than all capsules together.
    const double trunk = capsuleVolume(p.trunkRadius, p.trunkHeight);
    const double branch = capsuleVolume(p.branchRadius, p.branchLength);
    const double freeBranches = shape.branches * kPi * p.branchRadius * p.branchRadius *
                                (p.branchLength - 2 * p.trunkRadius);
    EXPECT_GT(report.signedVolume, 0.98 * (trunk + freeBranches));
    EXPECT_LT(report.signedVolume, trunk + shape.branches * branch);

    // Flat bottom disk of radius trunkRadius at z = 0, nothing below it.
    double rimRadius = 0.0;
    double minZAboveBase = 1e9;
    for (const Vec3& q : s.points) {
      ASSERT_GE(q.z(), 0.0);
      if (q.z() == 0.0) {
        rimRadius = std::max(rimRadius, std::hypot(q.x(), q.y()));
      } else {
        minZAboveBase = std::min(minZAboveBase, q.z());
      }
    }
    EXPECT_NEAR(rimRadius, p.trunkRadius, 1e-9);
    EXPECT_GT(minZAboveBase, 0.25 * p.surfaceEdgeLength);  // the wall rises straight from the rim
    bool allFaceDown = false;
    EXPECT_NEAR(bottomArea(s, allFaceDown), kPi * p.trunkRadius * p.trunkRadius,
                0.02 * kPi * p.trunkRadius * p.trunkRadius);
    EXPECT_TRUE(allFaceDown);

    // Height and the reach of every branch tip along its horizontal direction.
    const double sag =
        0.3;  // remeshed vertices lie on the faceted caps, at most this far inside (mm)
    double maxZ = 0.0;
    for (const Vec3& q : s.points) {
      maxZ = std::max(maxZ, q.z());
    }
    const Vec3 tip = Vec3(0, 0, p.trunkHeight) + p.branchLength * branchAxis(p, 0, shape.branches);
    EXPECT_LE(maxZ, tip.z() + p.branchRadius + 1e-9);
    EXPECT_GE(maxZ, tip.z() + p.branchRadius - sag);
    for (int k = 0; k < shape.branches; ++k) {
      Vec3 horizontal = branchAxis(p, k, shape.branches);
      horizontal.z() = 0.0;
      horizontal.normalize();
      double reach = 0.0;
      for (const Vec3& q : s.points) {
        reach = std::max(reach, q.dot(horizontal));
      }
      const double expected =
          p.branchLength * std::sin(p.branchLeanDeg * kPi / 180.0) + p.branchRadius;
      EXPECT_LE(reach, expected + 1e-9) << "branch " << k;
      EXPECT_GE(reach, expected - sag) << "branch " << k;
    }
  }
}

TEST(BranchingShapes, OtherParametersGiveValidSurfaces) {
  BranchingShapeParameters p = yShapeDefaults();
  p.branchLeanDeg = 65.0;
  p.branchRadius = 0.9 * p.trunkRadius;  // largest allowed
  p.segments = 12;
  p.firstAzimuthDeg = 33.0;
  p.surfaceEdgeLength = 1.0;
  EXPECT_TRUE(checkSurface(yShapeSurface(p)).isClosedManifold());
  p = threeBranchTreeDefaults();
  p.branchLeanDeg = 10.0;  // branches nearly vertical, overlapping each other near the joint
  p.branchLength = p.trunkRadius;
  EXPECT_TRUE(checkSurface(threeBranchTreeSurface(p)).isClosedManifold());
}

TEST(BranchingShapes, TetGenMeshesThem) {
  for (const Shape& shape : shapes()) {
    SCOPED_TRACE(shape.name);
    TetrahedralizeOptions options;
    options.targetEdgeLength = 3.0;
    const TetrahedralizeResult r = tetrahedralizeSurface(shape.build(shape.parameters), options);
    EXPECT_GT(r.tetCount, 5000);
    EXPECT_EQ(r.flippedSurfaceTriangles, 0);  // the surfaces are outward already
    EXPECT_NEAR(r.meshVolume, r.enclosedVolume, 1e-5 * r.enclosedVolume);
  }
}

TEST(BranchingShapes, BadParametersAreReported) {
  struct Case {
    std::function<void(BranchingShapeParameters&)> change;
    const char* message;
  };
  const std::vector<Case> cases = {
      {[](auto& p) { p.trunkRadius = 0.0; }, "trunkRadius must be positive"},
      {[](auto& p) { p.trunkRadius = std::nan(""); }, "trunkRadius must be positive"},
      {[](auto& p) { p.trunkHeight = 5.0; }, "trunkHeight (> trunkRadius) must be in"},
      {[](auto& p) { p.branchRadius = 5.5; },
       "branchRadius must be in (0, 0.9 * trunkRadius = 5.4"},
      {[](auto& p) { p.branchRadius = -1.0; }, "branchRadius must be in"},
      {[](auto& p) { p.branchLength = 5.0; }, "branchLength (>= trunkRadius) must be in"},
      {[](auto& p) { p.branchLeanDeg = 85.0; },
       "branchLeanDeg must be in [10.000000, 80.000000] degrees, got 85"},
      {[](auto& p) { p.branchLeanDeg = 5.0; }, "branchLeanDeg must be in"},
      {[](auto& p) { p.firstAzimuthDeg = INFINITY; }, "firstAzimuthDeg must be finite"},
      {[](auto& p) { p.segments = 7; }, "segments must be in [8, 256], got 7"},
      {[](auto& p) { p.segments = 257; }, "segments must be in [8, 256], got 257"},
      {[](auto& p) { p.surfaceEdgeLength = 0.05; }, "surfaceEdgeLength must be in"},
      {[](auto& p) { p.surfaceEdgeLength = 5.0; }, "surfaceEdgeLength must be in"},
  };
  for (const Case& c : cases) {
    BranchingShapeParameters p = yShapeDefaults();
    c.change(p);
    for (int which = 0; which < 2; ++which) {
      try {
        which == 0 ? yShapeSurface(p) : threeBranchTreeSurface(p);
        ADD_FAILURE() << "expected an error containing: " << c.message;
      } catch (const GeoLatticeError& e) {
        EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
      }
    }
  }
}

// testdata/y_shape.obj and testdata/three_branch_tree.obj are yShapeSurface() and
// threeBranchTreeSurface() with the default parameters. Regenerate them with
//   GEOLATTICE_WRITE_TESTDATA=1 geolattice_core_tests --gtest_filter=BranchingShapes.TestdataCopies*
// This test checks that the stored copies are what the generator makes today (the same
// counts up to 2 %, volume and extents), so a change of defaults cannot go unnoticed.
TEST(BranchingShapes, TestdataCopiesMatchTheGenerator) {
  const bool write = std::getenv("GEOLATTICE_WRITE_TESTDATA") != nullptr;
  for (const Shape& shape : shapes()) {
    SCOPED_TRACE(shape.file);
    const TriangleSurface generated = shape.build(shape.parameters);
    const std::string path = kData + "/" + shape.file;
    if (write) {
      writeObj(path, generated,
               std::string(shape.name) +
                   " test part generated by core/mesh/BranchingShapes (GeoLattice), z up, mm.\n" +
                   "Parameters: " + parameterText(shape.parameters) + ".\n" +
                   "Closed, edge-manifold, outward; flat bottom disk at z = 0.");
    }
    const TriangleSurface stored = readObj(path);
    const SurfaceCheckReport a = requireClosedManifold(stored);
    const SurfaceCheckReport b = checkSurface(generated);
    EXPECT_NEAR(static_cast<double>(a.triangleCount), b.triangleCount, 0.02 * b.triangleCount);
    EXPECT_NEAR(a.signedVolume, b.signedVolume, 1e-3 * b.signedVolume);
    EXPECT_NEAR(a.bboxDiagonal, b.bboxDiagonal, 1e-2);
    double minZ = 1e9;
    for (const Vec3& q : stored.points) {
      minZ = std::min(minZ, q.z());
    }
    EXPECT_EQ(minZ, 0.0);
  }
}
