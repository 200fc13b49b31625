// vtkGLURScriptWriter: the Y part's program (reader -> ... -> planner -> writer) split into
// numbered files, each syntax-checked (balanced def/end, def names matching the file names, pose
// literals of 6 numbers with at most 6 decimals, t= and r= numbers, line length, file size);
// the whole toolpath whatever the pipeline time; stale numbered files removed; the results;
// and errors (unwritable path, NaN normals, empty toolpath, missing arrays, bad parameters,
// unreachable points and cells) with nothing written.
#include "GLTestDefaults.h"
#include "GLTestErrorObserver.h"
#include "GLTestProgress.h"
#include "GLTestYPipeline.h"
#include "GLTestFiles.h"
#include "GLTestToolpath.h"
#include "../common/URScriptSyntax.h"

#include "robot/RobotPathSolver.h"
#include "vtkGLArrayNames.h"
#include "vtkGLCurvedLayerSlicer.h"
#include "vtkGLGeodesicDistanceFields.h"
#include "vtkGLLatticeInfill.h"
#include "vtkGLMeshReader.h"
#include "vtkGLNozzle.h"
#include "vtkGLPlaceOnPlatform.h"
#include "vtkGLPrintSequencer.h"
#include "vtkGLSkeletonTree.h"
#include "vtkGLTetrahedralizeSurface.h"
#include "vtkGLToolpathPlanner.h"
#include "vtkGLURScriptWriter.h"

#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

TEST(vtkGLURScriptWriter, FileAndProgramNames) {
  EXPECT_EQ(vtkGLURScriptWriter::ProgramFileName("/a/b/part.script", 0), "/a/b/part.script");
  EXPECT_EQ(vtkGLURScriptWriter::ProgramFileName("/a/b/part.script", 1), "/a/b/part_1.script");
  EXPECT_EQ(vtkGLURScriptWriter::ProgramFileName("/a/b/part.script", 12), "/a/b/part_12.script");
  EXPECT_EQ(vtkGLURScriptWriter::ProgramFileName("part", 2), "part_2");
  EXPECT_EQ(vtkGLURScriptWriter::ProgramName("/a/b/print_part.script"), "print_part");
  EXPECT_EQ(vtkGLURScriptWriter::ProgramName("My Part-2.script"), "my_part_2");
  EXPECT_EQ(vtkGLURScriptWriter::ProgramName("3d.script"), "p_3d");
}

TEST(vtkGLURScriptWriter, DefaultsAndPrintSelf) {
  vtkNew<vtkGLURScriptWriter> w;
  EXPECT_STREQ(w->GetRobot(), "ur5");
  EXPECT_EQ(w->GetNozzleTip()[1], -400.0);  // mm, like every filter
  EXPECT_EQ(w->GetNozzleTip()[2], 350.0);
  EXPECT_EQ(w->GetNozzleAxis()[2], 1.0);
  EXPECT_EQ(w->GetPartOnFlangePosition()[2], 40.0);
  EXPECT_EQ(w->GetPartOnFlangeRotation()[2], 0.0);
  EXPECT_EQ(w->GetMaxFileBytes(), 4000000);
  EXPECT_EQ(w->GetSpeedFactor(), 0.5);
  EXPECT_EQ(w->GetMaxFilamentRate(), 5.0);
  EXPECT_EQ(w->GetMaxBlend(), 0.5);
  EXPECT_EQ(w->GetAllowUnreachable(), 0);
  EXPECT_EQ(w->GetNumberOfFilesWritten(), 0);
  EXPECT_EQ(w->GetMaxJointStep(), 20.0);
  expectPrintMentions(w, {"Robot: ur5", "MaxFileBytes: 4000000", "SpeedFactor: 0.5",
                          "AllowUnreachable: 0", "MaxJointStep: 20"});
}

TEST(vtkGLURScriptWriter, SmallToolpathInOneFile) {
  const fs::path dir = glFreshDirectory("urscript-small");
  vtkNew<vtkGLURScriptWriter> w;
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(w);
  auto path = makeTestToolpath();
  w->SetInputData(path);
  const std::string file = (dir / "small.script").string();
  w->SetFileName(file.c_str());
  w->SetRobot("ur5e");
  ASSERT_EQ(w->Write(), 1) << errors->Errors();
  EXPECT_FALSE(errors->HasError()) << errors->Errors();
  ASSERT_EQ(w->GetNumberOfFilesWritten(), 1);
  EXPECT_EQ(w->GetFileWritten(0), file);
  EXPECT_EQ(w->GetFileWritten(1), "");
  EXPECT_EQ(glListDirectory(dir), std::vector<std::string>{"small.script"});
  EXPECT_EQ(w->GetNumberOfWaypoints(), path->GetNumberOfPoints());
  EXPECT_EQ(w->GetNumberOfMoves(), path->GetNumberOfPoints() - 1);
  EXPECT_EQ(w->GetUnreachableCount(), 0);
  EXPECT_EQ(w->GetUnreachablePoint(0), -1);
  EXPECT_GE(w->GetIKBranch(), 0);
  EXPECT_GT(w->GetDuration(), 0.0);
  const std::string text = glReadFile(file);
  EXPECT_EQ(checkURScriptSyntax(text, "small", 1000), static_cast<size_t>(w->GetNumberOfMoves()));
  EXPECT_NE(text.find("set_tcp(p[0, 0, 0.04, 0, 0, 0])"), std::string::npos);
  EXPECT_NE(text.find("set_standard_analog_out(0, "), std::string::npos);
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------------------------
// The Y part: reader -> place -> tets -> GDF -> slicer -> lattice -> skeleton -> sequencer ->
// planner -> URScript writer (coarse, like the toolpath filter test).

class BranchingYProgram : public GLTestYSuite<BranchingYProgram> {
public:
  static vtkAlgorithm* Stage(GLTestYPipeline& y) { return y.planner; }
};

TEST_F(BranchingYProgram, SplitProgramPassesTheSyntaxCheck) {
  ASSERT_FALSE(p->errors->HasError()) << p->errors->Errors();
  const vtkIdType N = p->planner->GetOutput()->GetNumberOfPoints();
  ASSERT_GT(N, 1000);
  const fs::path dir = glFreshDirectory("urscript-y");

  vtkNew<vtkGLURScriptWriter> w;
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(w);
  w->SetInputConnection(p->planner->GetOutputPort());
  const std::string file = (dir / "y_part.script").string();
  w->SetFileName(file.c_str());
  w->SetMaxFileBytes(100000);  // force several files
  ASSERT_EQ(w->Write(), 1) << errors->Errors();
  EXPECT_FALSE(errors->HasError()) << errors->Errors();
  EXPECT_EQ(w->GetNumberOfWaypoints(), N);
  EXPECT_EQ(w->GetNumberOfMoves(), N - 1);
  EXPECT_EQ(w->GetUnreachableCount(), 0);
  const int files = w->GetNumberOfFilesWritten();
  std::printf(
      "[urscript writer] Y: %lld waypoints, %d files (<= 100 kB), max joint step %.2f deg, max "
      "joint speed "
      "%.1f deg/s, min singularity shoulder %.3f m elbow %.3f wrist %.3f, duration %.0f s, "
      "unreachable %lld, "
      "IK branch %d, longest line %lld\n",
      static_cast<long long>(N), files, w->GetMaxJointStepDeg(), w->GetMaxJointSpeedDegS(),
      w->GetMinShoulderSingularity(), w->GetMinElbowSingularity(), w->GetMinWristSingularity(),
      w->GetDuration(), static_cast<long long>(w->GetUnreachableCount()), w->GetIKBranch(),
      static_cast<long long>(w->GetMaxLineLength()));
  ASSERT_GT(files, 1);
  EXPECT_LE(w->GetMaxJointSpeedDegS(), 0.5 * 180.0 + 1e-6);  // SpeedFactor of the 180 deg/s limits
  EXPECT_GT(w->GetMaxJointStepDeg(), 0.0);
  EXPECT_LT(w->GetMaxJointStepDeg(), 90.0);
  EXPECT_GT(w->GetMinWristSingularity(), 0.0);
  EXPECT_LE(w->GetMaxLineLength(), 200);

  std::vector<std::string> expected;
  size_t movels = 0;
  for (int k = 0; k < files; ++k) {
    const std::string name = k == 0 ? "y_part.script" : "y_part_" + std::to_string(k) + ".script";
    EXPECT_EQ(w->GetFileWritten(k), (dir / name).string());
    expected.push_back(name);
    const std::string text = glReadFile(w->GetFileWritten(k));
    EXPECT_LE(text.size(), 100000u) << name;
    movels += checkURScriptSyntax(text, k == 0 ? "y_part" : "y_part_" + std::to_string(k),
                                  static_cast<size_t>(w->GetMaxLineLength()));
    // Every file sets the TCP and the analog output, and starts from a joint position.
    EXPECT_NE(text.find("  set_tcp(p[0, 0, 0.04, 0, 0, 0])\n"), std::string::npos) << name;
    EXPECT_NE(text.find("  movej(["), std::string::npos) << name;
  }
  EXPECT_EQ(movels, static_cast<size_t>(N - 1));
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(glListDirectory(dir), expected) << "no temporary or other files";

  // A larger limit: fewer files; the numbered files of the longer program are removed. A file
  // of another name pattern stays.
  std::ofstream(dir / "y_part_notes.txt") << "keep\n";
  w->SetMaxFileBytes(4000000);
  ASSERT_EQ(w->Write(), 1) << errors->Errors();
  EXPECT_EQ(w->GetNumberOfFilesWritten(), 1);
  EXPECT_EQ(glListDirectory(dir), (std::vector<std::string>{"y_part.script", "y_part_notes.txt"}));
  EXPECT_EQ(checkURScriptSyntax(glReadFile(file), "y_part", 1000), static_cast<size_t>(N - 1));

  // A joint step bound the path cannot keep (below the Y's largest step even after refinement):
  // an error naming the points (a step above the bound, or points the plan that follows the
  // bound leaves out of reach: the forearm at the nozzle), the earlier program stays as it was.
  const std::string before = glReadFile(file);
  w->SetMaxJointStep(0.5);
  EXPECT_EQ(w->Write(), 0);
  const std::string error = errors->Errors();
  EXPECT_TRUE((error.find("jumps by") != std::string::npos &&
               error.find("at toolpath point") != std::string::npos) ||
              error.find("toolpath points are unreachable") != std::string::npos)
      << error;
  EXPECT_EQ(glReadFile(file), before);
  EXPECT_EQ(glListDirectory(dir), (std::vector<std::string>{"y_part.script", "y_part_notes.txt"}));
  errors->Clear();
  w->SetMaxJointStep(0);
  EXPECT_EQ(w->Write(), 0);
  EXPECT_NE(errors->Errors().find("MaxJointStep must be in (0, 30]"), std::string::npos)
      << errors->Errors();
  errors->Clear();
  w->SetMaxJointStep(20);

  // A cell that does not reach: an error, the earlier program stays as it was.
  w->SetNozzleTip(5000.0, 0.0, 0.0);
  EXPECT_EQ(w->Write(), 0);
  EXPECT_NE(errors->Errors().find("unreachable cell set-up"), std::string::npos)
      << errors->Errors();
  EXPECT_EQ(w->GetNumberOfFilesWritten(), 0);
  EXPECT_EQ(glReadFile(file), before);
  EXPECT_EQ(glListDirectory(dir), (std::vector<std::string>{"y_part.script", "y_part_notes.txt"}));
  fs::remove_all(dir);
}

TEST_F(BranchingYProgram, Ur5eAndAnotherCell) {
  ASSERT_FALSE(p->errors->HasError()) << p->errors->Errors();
  const fs::path dir = glFreshDirectory("urscript-y-ur5e");
  vtkNew<vtkGLURScriptWriter> w;
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(w);
  w->SetInputConnection(p->planner->GetOutputPort());
  w->SetFileName((dir / "ur5e.script").string().c_str());
  w->SetRobot("ur5e");
  w->SetNozzleTip(100, -450, 350);
  w->SetPartOnFlangePosition(0, 0, 50);
  w->SetPartOnFlangeRotation(0, 0, 0.3 * 180.0 / M_PI);  // 0.3 rad in the program
  w->SetSpeedFactor(0.3);
  ASSERT_EQ(w->Write(), 1) << errors->Errors();
  EXPECT_EQ(w->GetUnreachableCount(), 0);
  EXPECT_LE(w->GetMaxJointSpeedDegS(), 0.3 * 180.0 + 1e-6);
  const std::string text = glReadFile(w->GetFileWritten(0));
  EXPECT_NE(text.find("set_tcp(p[0, 0, 0.05, 0, 0, 0.3])"), std::string::npos);
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------------------------
// Errors: reported, Write() returns 0, no file (nor temporary file) left.

namespace {
struct ErrorCase {
  vtkNew<vtkGLURScriptWriter> writer;
  vtkNew<GLTestErrorObserver> errors;
  fs::path dir;
  explicit ErrorCase(const std::string& name, vtkPolyData* input)
      : dir(glFreshDirectory("urscript-" + name)) {
    errors->Observe(writer);
    writer->SetInputData(input);
    writer->SetFileName((dir / "part.script").string().c_str());
  }
  ~ErrorCase() { fs::remove_all(dir); }
  void expectError(const std::string& text) {
    EXPECT_EQ(writer->Write(), 0) << text;
    EXPECT_TRUE(errors->HasError()) << text;
    EXPECT_NE(errors->Errors().find(text), std::string::npos) << errors->Errors();
    EXPECT_EQ(writer->GetNumberOfFilesWritten(), 0);
    EXPECT_TRUE(glListDirectory(dir).empty()) << "files left behind for: " << text;
  }
};
}  // namespace

TEST(vtkGLURScriptWriter, BadInputIsReported) {
  {
    auto path = makeTestToolpath();
    path->GetPointData()
        ->GetArray(geolattice::arrays::NozzleAxis)
        ->SetTuple3(7, std::nan(""), 0, 1);
    ErrorCase c("nan", path);
    c.expectError("toolpath point 7 has a NaN or zero nozzle axis");
    EXPECT_EQ(c.writer->GetErrorCode(), vtkErrorCode::UserError);
  }
  {
    auto path = makeTestToolpath();
    path->GetPointData()->GetArray(geolattice::arrays::NozzleAxis)->SetTuple3(3, 0, 0, 0);
    ErrorCase c("zero", path);
    c.expectError("toolpath point 3 has a NaN or zero nozzle axis");
  }
  {
    vtkNew<vtkPolyData> empty;
    ErrorCase c("empty", empty);
    c.expectError("empty toolpath");
  }
  {
    auto path = makeTestToolpath();
    path->GetPointData()->RemoveArray(geolattice::arrays::Extrusion);
    ErrorCase c("noextrusion", path);
    c.expectError("the toolpath has no point array Extrusion");
  }
  {
    auto path = makeTestToolpath();
    path->GetPointData()->GetArray(geolattice::arrays::MoveKind)->SetTuple1(4, 7);
    ErrorCase c("kind", path);
    c.expectError("toolpath point 4 has MoveKind 7");
  }
  {
    ErrorCase c("robot", makeTestToolpath());
    c.writer->SetRobot("ur6");
    c.expectError("unknown robot 'ur6'");
  }
  {
    ErrorCase c("axis", makeTestToolpath());
    c.writer->SetNozzleAxis(0, 0, 0);
    c.expectError("the nozzle axis must be a finite, non-zero vector");
  }
  {
    ErrorCase c("speed", makeTestToolpath());
    c.writer->SetSpeedFactor(0);
    c.expectError("the speed factor must be in (0, 1]");
  }
  {
    ErrorCase c("bytes", makeTestToolpath());
    c.writer->SetMaxFileBytes(100);
    c.expectError("the maximum file size must be >= 10000 bytes");
  }
  {
    ErrorCase c("rate", makeTestToolpath());
    c.writer->SetMaxFilamentRate(-1);
    c.expectError("the maximum filament rate must be > 0");
  }
  {
    ErrorCase c("blend", makeTestToolpath());
    c.writer->SetMaxBlend(-0.1);
    c.expectError("the maximum blend radius must be >= 0");
  }
  {
    ErrorCase c("cell", makeTestToolpath());
    c.writer->SetNozzleTip(5000, 0, 0);
    c.expectError("unreachable cell set-up");
  }
  {
    // Metres typed where millimetres are asked: named, not a silent cell inside the base.
    ErrorCase c("metres", makeTestToolpath());
    c.writer->SetNozzleTip(0, -0.4, 0.3);
    c.expectError("the cell is in millimetres");
  }
  {
    ErrorCase c("nofile", makeTestToolpath());
    c.writer->SetFileName(nullptr);
    c.expectError("no FileName given");
  }
  {
    // Unwritable: a directory that does not exist.
    ErrorCase c("unwritable", makeTestToolpath());
    const std::string missing = (c.dir / "no-such-dir" / "part.script").string();
    c.writer->SetFileName(missing.c_str());
    c.expectError("cannot create " + missing);
    EXPECT_EQ(c.writer->GetErrorCode(), vtkErrorCode::CannotOpenFileError);
  }
}

namespace {
/// A closed octagonal prism OBJ (mm): circumradius `radius` about the z axis, from z = 0 (the
/// tip's plane, the origin at the centre of that face) to `height`.
std::string prismObj(double radius, double height) {
  std::ostringstream obj;
  for (double z : {0.0, height}) {
    for (int k = 0; k < 8; ++k) {
      obj << "v " << radius * std::cos(k * M_PI / 4) << " " << radius * std::sin(k * M_PI / 4)
          << " " << z << "\n";
    }
  }
  obj << "v 0 0 0\nv 0 0 " << height << "\n";  // 17, 18: the faces' centres
  for (int k = 0; k < 8; ++k) {
    const int a = 1 + k, b = 1 + (k + 1) % 8;
    obj << "f " << a << " " << b << " " << b + 8 << "\nf " << a << " " << b + 8 << " " << a + 8
        << "\nf 17 " << b << " " << a << "\nf 18 " << a + 8 << " " << b + 8 << "\n";
  }
  return obj.str();
}
}  // namespace

// The printhead sets how far the arm keeps off the nozzle's axis: PrintheadRadius (default 28
// mm = core's kPrintheadRadius), or the largest radius of the PrintheadFile of a nozzle given
// with SetNozzle; the arm's surfaces keep 7 mm more (kLinkNozzleMargin).
TEST(vtkGLURScriptWriter, ThePrintheadSetsHowFarTheArmKeepsOffTheNozzle) {
  const fs::path dir = glFreshDirectory("urscript-printhead");
  auto path = makeTestToolpath();
  vtkNew<vtkGLURScriptWriter> w;
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(w);
  w->SetInputData(path);
  w->SetFileName((dir / "part.script").string().c_str());
  EXPECT_EQ(w->GetPrintheadRadius(), 1000 * geolattice::kPrintheadRadius);
  ASSERT_EQ(w->Write(), 1) << errors->Errors();
  EXPECT_EQ(w->GetPrintheadRadiusUsed(), 28.0);
  EXPECT_GE(w->GetMinLinkNozzleDistance(), 35.0 - 1e-9);
  // A printhead of 60 mm radius from the nozzle's file: kept 67 mm off (the default's program
  // comes nearer, so this one is planned anew).
  EXPECT_LT(w->GetMinLinkNozzleDistance(), 67.0);
  const std::string file = (dir / "fat.obj").string();
  {
    std::ofstream out(file);
    out << prismObj(60, 100);
  }
  vtkNew<vtkGLNozzle> nozzle;
  nozzle->SetPrintheadFile(file.c_str());
  w->SetNozzle(nozzle);
  ASSERT_EQ(w->Write(), 1) << errors->Errors();
  EXPECT_NEAR(w->GetPrintheadRadiusUsed(), 60.0, 1e-9);
  EXPECT_GE(w->GetMinLinkNozzleDistance(), 67.0 - 1e-9);
  // Without the file the property counts again; a radius out of (0, 1000) mm is refused.
  nozzle->SetPrintheadFile(nullptr);
  w->SetPrintheadRadius(0);
  EXPECT_EQ(w->Write(), 0);
  EXPECT_NE(errors->Errors().find("PrintheadRadius must be in (0, 1000) mm"), std::string::npos)
      << errors->Errors();
  fs::remove_all(dir);
}

TEST(vtkGLURScriptWriter, UnreachablePointsAreReportedNotSkipped) {
  // 2000 points: the solver's coarse samples are every 4th point, so a single far point (3 m
  // away, beyond the UR5's 0.85 m reach) between two samples is unreachable while the rest of
  // the path is reachable.
  auto path = vtkSmartPointer<vtkPolyData>::New();
  {
    auto base = makeTestToolpath(1, 0.0);
    const vtkIdType n = 2000;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkPointData* from = base->GetPointData();
    vtkPointData* to = path->GetPointData();
    to->CopyAllocate(from, n);
    for (vtkIdType i = 0; i < n; ++i) {
      const vtkIdType j = 1 + i % (base->GetNumberOfPoints() - 1);
      double x[3];
      base->GetPoint(j, x);
      if (i == 6 || i == 1001) {
        x[0] = 3000.0;
      }
      points->InsertNextPoint(x);
      to->CopyData(from, j, i);
    }
    path->SetPoints(points);
    setTestCollisionVerdict(path, true);
  }
  {
    ErrorCase c("unreachable", path);
    c.expectError(
        "2 of 2000 toolpath points are unreachable for the ur5 in this cell (out of "
        "reach, past a joint limit, or reached only with the arm or the part lower than "
        "20 mm above the floor it stands on, or with the arm nearer than 35 mm to the nozzle's "
        "axis or nearer than 15 mm to the part it holds; first: 6, 1001)");
    EXPECT_EQ(c.writer->GetUnreachableCount(), 2);
    EXPECT_EQ(c.writer->GetUnreachablePoint(0), 6);
    EXPECT_EQ(c.writer->GetUnreachablePoint(1), 1001);
  }
  {
    // AllowUnreachable: written, with a warning naming them.
    ErrorCase c("allowed", path);
    c.writer->AllowUnreachableOn();
    EXPECT_EQ(c.writer->Write(), 1) << c.errors->Errors();
    EXPECT_FALSE(c.errors->HasError()) << c.errors->Errors();
    EXPECT_EQ(c.errors->GetWarningCount(), 1);
    EXPECT_NE(c.errors->Warnings().find("2 of 2000 toolpath points are unreachable"),
              std::string::npos);
    EXPECT_EQ(c.writer->GetUnreachableCount(), 2);
    ASSERT_EQ(c.writer->GetNumberOfFilesWritten(), 1);
    EXPECT_EQ(checkURScriptSyntax(glReadFile(c.writer->GetFileWritten(0)), "part", 1000), 1999u);
  }
}

TEST(vtkGLURScriptWriter, SolveRobotPathWritesNothingAndKeepsTheSolution) {
  // The orientation tries ask the robot before the program is written (GLPrintPipeline::
  // RobotGate): a solve without a file name writes nothing, and the program of the same
  // toolpath and cell is then written from that solution (the solver's own time is the kept
  // one's: a second solve would take another).
  const fs::path dir = glFreshDirectory("urscript-solve");
  vtkNew<vtkGLURScriptWriter> w;
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(w);
  auto path = makeTestToolpath();
  w->SetInputData(path);
  ASSERT_EQ(w->SolveRobotPath(), 1) << errors->Errors();
  EXPECT_FALSE(errors->HasError()) << errors->Errors();
  EXPECT_EQ(w->GetNumberOfFilesWritten(), 0);
  EXPECT_EQ(w->GetUnreachableCount(), 0);
  EXPECT_GT(w->GetSolveSeconds(), 0.0);
  const double solved = w->GetSolveSeconds();
  const int branch = w->GetIKBranch();
  EXPECT_TRUE(glListDirectory(dir).empty());
  w->SetFileName((dir / "kept.script").string().c_str());
  ASSERT_EQ(w->Write(), 1) << errors->Errors();
  EXPECT_EQ(w->GetSolveSeconds(), solved);
  EXPECT_EQ(w->GetIKBranch(), branch);
  EXPECT_EQ(glListDirectory(dir), std::vector<std::string>{"kept.script"});
  // Another cell: solved again.
  w->SetNozzleTip(0, -450, 350);
  ASSERT_EQ(w->Write(), 1) << errors->Errors();
  EXPECT_NE(w->GetSolveSeconds(), solved);
  // A cell that reaches none of it: 0, nothing reported (the program's Write() reports it).
  w->SetNozzleTip(3000, 0, 350);
  EXPECT_EQ(w->SolveRobotPath(), 0);
  EXPECT_FALSE(errors->HasError()) << errors->Errors();
  EXPECT_EQ(w->GetUnreachableCount(), path->GetNumberOfPoints());
  EXPECT_EQ(w->Write(), 0);
  EXPECT_NE(errors->Errors().find("unreachable cell set-up"), std::string::npos)
      << errors->Errors();
  fs::remove_all(dir);
}

TEST(vtkGLURScriptWriter, ProgressAndAbortWriteNothing) {
  const fs::path dir = glFreshDirectory("urscript-abort");
  vtkNew<vtkGLURScriptWriter> w;
  w->SetInputData(makeTestToolpath(4));
  w->SetFileName((dir / "abort.script").string().c_str());
  w->SetRobot("ur5e");
  auto write = [&w] {
    EXPECT_EQ(w->Write(), 1);
  };
  auto nothingWritten = [&w, &dir] {
    return glListDirectory(dir).empty() && w->GetNumberOfFilesWritten() == 0;
  };
  // Toolpath read, joints solved (one core call), program written.
  glExpectProgressReport(w, 3, write);
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (double at : {0.1, 0.5, 0.9}) {
    SCOPED_TRACE(at);
    glExpectCleanAbort(w, glAbortAt(at), write, nothingWritten);
    EXPECT_EQ(glListDirectory(dir), std::vector<std::string>{"abort.script"});  // the recovery run
    fs::remove(dir / "abort.script");
  }
  fs::remove_all(dir);
}
