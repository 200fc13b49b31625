// URScript programs for a real toolpath (the Y part in the UR5 cell): syntax check of every
// file (balanced def/end, valid pose literals, numbers with at most 6 decimals, line length),
// splitting at air moves, segment times within the joint speed limits.
#include "../common/CoreStages.h"
#include "common/Error.h"
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "io/MeshReader.h"
#include "common/FixedNumber.h"
#include "program/URScriptWriter.h"
#include "sequence/PrintMaterial.h"
#include "sequence/PrintSequencer.h"
#include "skeleton/SkeletonTree.h"
#include "slicer/CurvedLayerSlicer.h"
#include "tetrahedralize/TetrahedralizeSurface.h"
#include "toolpath/ToolpathPlanner.h"
#include "../common/URScriptSyntax.h"

#include <gtest/gtest.h>

#include <cstdio>

#include <regex>
#include <sstream>

using namespace geolattice;

namespace {

const Toolpath& yToolpath() {
  static const Toolpath path = [] {
    fixtures::CoreStageOptions o;
    o.edgeLength = 2.5;
    const fixtures::CoreStages stages =
        fixtures::runCoreStages(readObj(std::string(GEOLATTICE_TESTDATA) + "/y_shape.obj"), o);
    const LatticeGraph& g = stages.lattice;
    const SkeletonTree& tree = stages.tree;
    SequenceOptions so;
    so.strategy = SequenceStrategy::LayerPriority;
    const PrintSequence seq = sequencePrint(tree, sampleLatticeMaterial(g, 1.0), nullptr, so);
    return planToolpath(g, tree, seq.order, ToolpathOptions{});
  }();
  return path;
}

}  // namespace

TEST(URScriptWriter, YPartInTheUr5Cell) {
  const Toolpath& path = yToolpath();
  RobotCell cell;
  const RobotPath rp = solveRobotPath(cell, path.points, path.normals);
  ASSERT_TRUE(rp.unreachable.empty());
  std::vector<int> kind(path.kind.size());
  for (size_t i = 0; i < kind.size(); ++i)
    kind[i] = static_cast<int>(path.kind[i]);
  ProgramInput in{&path.points, &path.extrusion, &path.feedRate, &kind};
  URScriptOptions o;
  o.maxFileBytes = 200000;  // force several files
  std::vector<std::ostringstream> files(64);
  const ProgramStats stats =
      writeURScript(cell, rp, in, o, [&](size_t k) -> std::ostream& { return files.at(k); });
  std::printf(
      "[urscript] Y: %zu waypoints, %zu moves, %zu files, duration %.0f s, max joint speed %.1f "
      "deg/s, "
      "longest line %zu\n",
      path.points.size(), stats.moves, stats.files, stats.duration, stats.maxJointSpeedDegS,
      stats.maxLineLength);
  EXPECT_GT(stats.files, 1u);
  EXPECT_EQ(stats.moves, path.points.size() - 1);
  EXPECT_LE(stats.maxJointSpeedDegS, 0.5 * 180.0 + 1e-6);  // speedFactor of the 180°/s limit
  size_t movels = 0;
  for (size_t k = 0; k < stats.files; ++k) {
    const std::string text = files[k].str();
    EXPECT_LE(text.size(), o.maxFileBytes);
    checkURScriptSyntax(text, "", 1000);
    // A file other than the first starts right after an air move's first point.
    for (size_t at = text.find("movel("); at != std::string::npos; at = text.find("movel(", at + 1))
      ++movels;
  }
  EXPECT_EQ(movels, stats.moves);
}

TEST(URScriptWriter, NumbersAndBadInput) {
  EXPECT_EQ(urNumber(0.1234564), "0.123456");
  EXPECT_EQ(urNumber(-1e-9), "0");
  EXPECT_EQ(urNumber(2.0), "2");
  EXPECT_EQ(urNumber(-0.5), "-0.5");
  // Never an exponent or "-0" (common/FixedNumber.h), the same digits as printf's %.6f.
  EXPECT_EQ(urNumber(-4e-7), "0");
  EXPECT_EQ(urNumber(6e-7), "0.000001");
  EXPECT_EQ(urNumber(1e20), "100000000000000000000");
  EXPECT_EQ(urNumber(-1234.5), "-1234.5");
  EXPECT_EQ(urNumber(0.0), "0");
  EXPECT_EQ(fixedNumber(2.5, 0), "2");  // round half to even, as %.0f
  EXPECT_EQ(fixedNumber(-0.25, 1), "-0.2");
  for (const double v : {0.1, 1.0 / 3, -2.0 / 3, 123.456789, 1e-5, 9.9999995}) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6f", v);
    std::string expected = buf;
    while (expected.back() == '0') {
      expected.pop_back();
    }
    if (expected.back() == '.') {
      expected.pop_back();
    }
    EXPECT_EQ(urNumber(v), expected) << v;
  }
  RobotCell cell;
  RobotPath rp;
  std::vector<Eigen::Vector3d> pts;
  std::vector<double> e, f;
  std::vector<int> k;
  ProgramInput in{&pts, &e, &f, &k};
  std::ostringstream os;
  EXPECT_THROW(
      writeURScript(cell, rp, in, URScriptOptions{}, [&](size_t) -> std::ostream& { return os; }),
      GeoLatticeError);  // empty toolpath
}
