// Overhang angles under planar and curved-layer slicing (paper Section 2.2, Figs. 7-8):
// exact angles on boxes and a T made of voxels, the base exclusion, the threshold, bad input,
// and the pipeline surface -> TetGen -> GDF -> overhang on the Y and the tree (testdata copies of
// core/mesh/BranchingShapes) and the bunny.
#include "overhang/OverhangAnalysis.h"

#include "common/Error.h"
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "io/MeshReader.h"
#include "mesh/AnalyticShapes.h"
#include "mesh/TetMeshTopology.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include "../common/ErrorOf.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

using namespace geolattice;

namespace {

const std::string kData = GEOLATTICE_TESTDATA;

std::vector<std::uint8_t> flagsBelow(const TetMesh& mesh, double z) {
  std::vector<std::uint8_t> flags(mesh.points.size(), 0);
  for (size_t i = 0; i < mesh.points.size(); ++i) {
    flags[i] = mesh.points[i].z() <= z;
  }
  return flags;
}

std::vector<std::uint8_t> flagsOf(const TetMesh& mesh, const std::vector<int>& ids) {
  std::vector<std::uint8_t> flags(mesh.points.size(), 0);
  for (int i : ids) {
    flags[i] = 1;
  }
  return flags;
}

/// T / mushroom: stem 10 x 10 x 20 mm on the platform, cap 30 x 30 x 10 mm on top, 2 mm voxels.
/// Its cap has 30^2 - 10^2 = 800 mm^2 of underside facing straight down.
TetMesh mushroom() {
  return voxelTetMesh(Vec3(30, 30, 30), 15, 15, 15, [](const Vec3& c) {
    return c.z() > 20.0 || (c.x() > 10.0 && c.x() < 20.0 && c.y() > 10.0 && c.y() < 20.0);
  });
}

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "message: " << (text)

/// Tet mesh of a closed surface + GDF from the lowest vertices + overhang analysis.
struct PipelineResult {
  int tets = 0;
  OverhangResult overhang;
};

PipelineResult runPipeline(const TriangleSurface& surface, double edgeLength,
                           double baseTolerance) {
  TetrahedralizeOptions options;
  options.targetEdgeLength = edgeLength;
  const TetMesh mesh = tetrahedralizeSurface(surface, options).mesh;
  const std::vector<int> sources = sourcesNearLowestZ(mesh, baseTolerance);
  const GeodesicFields fields = computeGeodesicDistanceFields(mesh, sources);
  const TetMeshTopology topology(mesh);
  PipelineResult r;
  r.tets = static_cast<int>(mesh.tets.size());
  r.overhang = analyzeOverhang(mesh, topology, fields.gammaDirection, flagsOf(mesh, sources));
  return r;
}

}  // namespace

TEST(OverhangAnalysis, AngleOfANormal) {
  const Vec3 up(0, 0, 1);
  EXPECT_EQ(overhangAngleDeg(up, Vec3(0, 0, 3)), 0.0);
  EXPECT_EQ(overhangAngleDeg(up, Vec3(0, 0, -0.5)), 180.0);
  EXPECT_NEAR(overhangAngleDeg(up, Vec3(2, 0, 0)), 90.0, 1e-12);
  EXPECT_NEAR(overhangAngleDeg(up, Vec3(1, 0, -1)), 135.0, 1e-12);
  EXPECT_NEAR(overhangAngleDeg(Vec3(1, 0, 0), Vec3(-1, 0, -1)), 135.0, 1e-12);
  // Rounding beyond |cos| = 1 is clamped.
  EXPECT_EQ(overhangAngleDeg(Vec3(0, 0, 1.0 + 1e-15), Vec3(0, 0, 1)), 0.0);
}

TEST(OverhangAnalysis, BoxHasNoOverhangAndItsBottomIsTheBase) {
  const TetMesh mesh = boxTetMesh(Vec3(40, 40, 30), 8, 8, 6);
  const TetMeshTopology topology(mesh);
  const std::vector<Vec3> up(mesh.tets.size(), Vec3(0, 0, 1));
  const OverhangResult r = analyzeOverhang(mesh, topology, up, flagsBelow(mesh, 0.0));
  const size_t faces = topology.boundaryFaces().size();
  ASSERT_EQ(r.planarDeg.size(), faces);
  ASSERT_EQ(r.curvedDeg.size(), faces);
  ASSERT_EQ(r.onBase.size(), faces);
  ASSERT_EQ(r.area.size(), faces);
  EXPECT_NEAR(r.totalArea, 2 * 40 * 40 + 4 * 40 * 30, 1e-9);
  EXPECT_NEAR(r.baseArea, 40 * 40, 1e-9);
  EXPECT_EQ(r.planarFraction, 0.0);
  EXPECT_EQ(r.curvedFraction, 0.0);
  EXPECT_NEAR(r.maxPlanarDeg, 90.0, 1e-9);
  EXPECT_EQ(r.thresholdDeg, 135.0);
  EXPECT_EQ(r.zeroAreaFaces, 0);
  for (size_t f = 0; f < faces; ++f) {
    // Exact angles by face orientation: top 0°, walls 90°, bottom (on the base) 180°.
    const Vec3 c = (mesh.points[topology.boundaryFaces()[f].vertices[0]] +
                    mesh.points[topology.boundaryFaces()[f].vertices[1]] +
                    mesh.points[topology.boundaryFaces()[f].vertices[2]]) /
                   3.0;
    const double expected = c.z() == 30.0 ? 0.0 : c.z() == 0.0 ? 180.0 : 90.0;
    ASSERT_NEAR(r.planarDeg[f], expected, 1e-9) << "face " << f;
    ASSERT_EQ(r.curvedDeg[f], r.planarDeg[f]);
    ASSERT_EQ(r.onBase[f], c.z() == 0.0 ? 1 : 0);
  }

  // The same box through the GDF: γ grows along +z, so the curved layers are planes too.
  const std::vector<int> sources = sourcesNearLowestZ(mesh, 1e-9);
  const GeodesicFields fields = computeGeodesicDistanceFields(mesh, sources);
  const OverhangResult g =
      analyzeOverhang(mesh, topology, fields.gammaDirection, flagsOf(mesh, sources));
  EXPECT_EQ(g.planarFraction, 0.0);
  EXPECT_EQ(g.curvedFraction, 0.0);
  EXPECT_NEAR(g.baseArea, 40 * 40, 1e-9);
  EXPECT_LT(g.maxCurvedDeg, 100.0);
}

TEST(OverhangAnalysis, BaseFacesAreLeftOutOfTheFractions) {
  const TetMesh mesh = boxTetMesh(Vec3(40, 40, 30), 4, 4, 3);
  const TetMeshTopology topology(mesh);
  const std::vector<Vec3> up(mesh.tets.size(), Vec3(0, 0, 1));
  const double total = 2 * 40 * 40 + 4 * 40 * 30;
  // Without base flags the bottom (θ = 180°) is an overhang.
  const std::vector<std::uint8_t> none(mesh.points.size(), 0);
  const OverhangResult r = analyzeOverhang(mesh, topology, up, none);
  EXPECT_EQ(r.baseArea, 0.0);
  EXPECT_NEAR(r.planarFraction, 1600.0 / total, 1e-12);
  EXPECT_NEAR(r.planarOverhangArea, 1600.0, 1e-9);
  EXPECT_NEAR(r.maxPlanarDeg, 180.0, 1e-9);
  // A face needs all three vertices on the base: flagging only the bottom corners leaves the
  // bottom faces off the base.
  std::vector<std::uint8_t> corners(mesh.points.size(), 0);
  for (size_t i = 0; i < mesh.points.size(); ++i) {
    const Vec3& p = mesh.points[i];
    corners[i] = p.z() == 0.0 && (p.x() == 0.0 || p.x() == 40.0) && (p.y() == 0.0 || p.y() == 40.0);
  }
  EXPECT_EQ(analyzeOverhang(mesh, topology, up, corners).baseArea, 0.0);
  // A nozzle along -z turns the roof (the top) into the overhang of the curved fraction.
  const std::vector<Vec3> down(mesh.tets.size(), Vec3(0, 0, -1));
  const OverhangResult d = analyzeOverhang(mesh, topology, down, flagsBelow(mesh, 0.0));
  EXPECT_EQ(d.planarFraction, 0.0);
  EXPECT_NEAR(d.curvedFraction, 1600.0 / (total - 1600.0), 1e-12);
}

TEST(OverhangAnalysis, ThresholdIsStrict) {
  const TetMesh mesh = mushroom();
  const TetMeshTopology topology(mesh);
  const std::vector<Vec3> up(mesh.tets.size(), Vec3(0, 0, 1));
  const auto base = flagsBelow(mesh, 0.0);
  OverhangOptions options;
  options.thresholdDeg = 180.0;  // nothing is steeper than 180°
  EXPECT_EQ(analyzeOverhang(mesh, topology, up, base, options).planarFraction, 0.0);
  options.thresholdDeg = 179.999;
  EXPECT_GT(analyzeOverhang(mesh, topology, up, base, options).planarFraction, 0.0);
  // Walls (90°) never count, whatever the threshold in (90, 180].
  options.thresholdDeg = 90.001;
  EXPECT_NEAR(analyzeOverhang(mesh, topology, up, base, options).planarOverhangArea, 800.0, 1e-9);
}

TEST(OverhangAnalysis, MushroomCapOverhangsOnlyUnderPlanarSlicing) {
  const TetMesh mesh = mushroom();
  ASSERT_EQ(mesh.tets.size(), 6u * (5 * 5 * 10 + 15 * 15 * 5));
  const TetMeshTopology topology(mesh);
  // Planar slicing: exactly the cap's underside, 800 mm^2, out of all faces but the base.
  const double total = 4 * 10 * 20 + 30 * 30 + 800 + 4 * 30 * 10 + 100;
  const std::vector<Vec3> up(mesh.tets.size(), Vec3(0, 0, 1));
  const OverhangResult planar = analyzeOverhang(mesh, topology, up, flagsBelow(mesh, 0.0));
  EXPECT_NEAR(planar.totalArea, total, 1e-9);
  EXPECT_NEAR(planar.baseArea, 100.0, 1e-9);
  EXPECT_NEAR(planar.planarFraction, 800.0 / (total - 100.0), 1e-12);

  // Curved layers: the nozzle follows ∇γ, which turns outward into the cap.
  const std::vector<int> sources = sourcesNearLowestZ(mesh, 1e-9);
  const GeodesicFields fields = computeGeodesicDistanceFields(mesh, sources);
  const OverhangResult r =
      analyzeOverhang(mesh, topology, fields.gammaDirection, flagsOf(mesh, sources));
  EXPECT_NEAR(r.planarFraction, planar.planarFraction, 1e-12);
  std::printf("[overhang] mushroom (%zu tets): planar %.3g %%, curved %.3g %%\n", mesh.tets.size(),
              100 * r.planarFraction, 100 * r.curvedFraction);
  EXPECT_LT(r.curvedFraction, 0.25 * r.planarFraction);
}

TEST(OverhangAnalysis, BadInputIsReported) {
  const TetMesh mesh = boxTetMesh(Vec3(10, 10, 10), 2, 2, 2);
  const TetMeshTopology topology(mesh);
  std::vector<Vec3> up(mesh.tets.size(), Vec3(0, 0, 1));
  const auto base = flagsBelow(mesh, 0.0);
  for (double bad : {90.0, 80.0, 180.5, std::nan("")}) {
    OverhangOptions options;
    options.thresholdDeg = bad;
    EXPECT_CONTAINS(expectedErrorOf([&] { analyzeOverhang(mesh, topology, up, base, options); }),
                    "threshold angle must be in (90, 180] degrees");
  }
  std::vector<Vec3> shortList(up.begin(), up.end() - 1);
  EXPECT_CONTAINS(expectedErrorOf([&] { analyzeOverhang(mesh, topology, shortList, base); }),
                  std::to_string(up.size() - 1) + " nozzle directions for " +
                      std::to_string(up.size()) + " tets");
  std::vector<std::uint8_t> shortBase(base.begin(), base.end() - 1);
  EXPECT_CONTAINS(expectedErrorOf([&] { analyzeOverhang(mesh, topology, up, shortBase); }),
                  std::to_string(base.size() - 1) + " base flags for " +
                      std::to_string(base.size()) + " vertices");
  // A non-unit or non-finite direction of a boundary tet names the tet.
  const int tet = topology.boundaryFaces().front().tet;
  up[tet] = Vec3(0, 0, 2);
  EXPECT_CONTAINS(
      expectedErrorOf([&] { analyzeOverhang(mesh, topology, up, base); }),
      "nozzle direction of tet " + std::to_string(tet) + " is (0.000000, 0.000000, 2.000000)");
  up[tet] = Vec3(0, std::nan(""), 1);
  EXPECT_CONTAINS(expectedErrorOf([&] { analyzeOverhang(mesh, topology, up, base); }),
                  "nozzle direction of tet " + std::to_string(tet));
  up[tet] = Vec3(0, 0, 1.0005);  // float-precision unit vectors are accepted
  EXPECT_NO_THROW(analyzeOverhang(mesh, topology, up, base));
  up[tet] = Vec3(0, 0, 1);
  // Topology of another mesh.
  const TetMesh other = boxTetMesh(Vec3(10, 10, 10), 1, 1, 1);
  const TetMeshTopology otherTopology(other);
  EXPECT_CONTAINS(expectedErrorOf([&] { analyzeOverhang(mesh, otherTopology, up, base); }),
                  "topology of another mesh");
  // Every boundary vertex on the base: nothing left to analyse.
  const std::vector<std::uint8_t> all(mesh.points.size(), 1);
  EXPECT_CONTAINS(expectedErrorOf([&] { analyzeOverhang(mesh, topology, up, all); }),
                  "every boundary face lies on the base");
}

// The numbers of the closing note: curved layers (nozzle along ∇γ) against planar
// slicing, threshold 135°, on the Y model, the three-branch tree and the bunny.
TEST(OverhangAnalysis, CurvedLayersRemoveMostOverhangOfTheYModel) {
  // The stored copy (generated by yShapeSurface(), see testdata/README.md), so that the
  // reported numbers do not depend on how CGAL's output varies between builds.
  const PipelineResult r = runPipeline(readObj(kData + "/y_shape.obj"), 2.0, 1e-6);
  std::printf(
      "[overhang] Y model (%d tets): planar %.3g %%, curved %.3g %% (area > 135 deg, of %.0f mm^2 "
      "off the base); "
      "max angle planar %.1f, curved %.1f deg\n",
      r.tets, 100 * r.overhang.planarFraction, 100 * r.overhang.curvedFraction,
      r.overhang.totalArea - r.overhang.baseArea, r.overhang.maxPlanarDeg, r.overhang.maxCurvedDeg);
  EXPECT_GT(r.tets, 20000);
  EXPECT_LT(r.tets, 80000);
  // Base: the trunk's bottom disk (radius 6 mm, a polygon after remeshing).
  EXPECT_NEAR(r.overhang.baseArea, 3.14159265 * 36.0, 0.02 * 3.14159265 * 36.0);
  EXPECT_GT(r.overhang.planarFraction, 0.03);  // branch undersides lean 50° + round tips
  EXPECT_GT(r.overhang.maxPlanarDeg, 138.0);   // 90° + lean on the lowest line of a branch
  EXPECT_LT(r.overhang.curvedFraction, 0.1 * r.overhang.planarFraction);
}

TEST(OverhangAnalysis, CurvedLayersRemoveMostOverhangOfTheTree) {
  const PipelineResult r = runPipeline(readObj(kData + "/three_branch_tree.obj"), 2.5, 1e-6);
  std::printf("[overhang] three-branch tree (%d tets): planar %.3g %%, curved %.3g %%\n", r.tets,
              100 * r.overhang.planarFraction, 100 * r.overhang.curvedFraction);
  EXPECT_LT(r.tets, 80000);
  EXPECT_GT(r.overhang.planarFraction, 0.03);
  EXPECT_LT(r.overhang.curvedFraction, 0.1 * r.overhang.planarFraction);
}

TEST(OverhangAnalysis, CurvedLayersRemoveMostOverhangOfTheBunny) {
  TriangleSurface bunny = readObj(kData + "/bunny.obj");
  // Scale to 80 mm tall and put it on the platform; the base is the vertices within 0.5 mm
  // of the lowest one (the bunny's bottom is not flat).
  double zMin = 1e300;
  double zMax = -1e300;
  for (const Vec3& p : bunny.points) {
    zMin = std::min(zMin, p.z());
    zMax = std::max(zMax, p.z());
  }
  const double scale = 80.0 / (zMax - zMin);
  for (Vec3& p : bunny.points) {
    p = scale * (p - Vec3(0, 0, zMin));
  }
  const PipelineResult r = runPipeline(bunny, 6.0, 0.5);
  std::printf("[overhang] bunny 80 mm (%d tets): planar %.3g %%, curved %.3g %%\n", r.tets,
              100 * r.overhang.planarFraction, 100 * r.overhang.curvedFraction);
  EXPECT_LT(r.tets, 80000);
  EXPECT_GT(r.overhang.baseArea, 0.0);
  EXPECT_GT(r.overhang.planarFraction, 0.08);  // chin, belly, ears, tail
  EXPECT_LT(r.overhang.curvedFraction, 0.1 * r.overhang.planarFraction);
}
