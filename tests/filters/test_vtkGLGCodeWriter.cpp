// vtkGLGCodeWriter: every move line turns the toolpath's nozzle axis onto +Z and puts the point
// at Pivot + R (p + PartOffset) (A-C and B-C), header and footer, the results, and errors (tilt
// limits, NaN normals, empty toolpath, unwritable path) with nothing written.
#include "GLTestDefaults.h"
#include "GLTestErrorObserver.h"
#include "GLTestProgress.h"
#include "GLTestFiles.h"
#include "GLTestToolpath.h"

#include "vtkGLArrayNames.h"
#include "vtkGLGCodeWriter.h"

#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

/// The letter -> value words of a G-code line ("G1 X1 Y2 ..." -> {G:1, X:1, Y:2, ...}).
std::map<char, double> words(const std::string& line) {
  std::map<char, double> out;
  std::istringstream in(line.substr(0, line.find_first_of(";(")));
  std::string w;
  while (in >> w) {
    out[w[0]] = std::stod(w.substr(1));
  }
  return out;
}

/// Checks every move line against the toolpath: R n = +Z and X Y Z = pivot + R (p + offset)
/// (machine coordinates, `cam`) or p + offset (part coordinates, the controller's kinematics),
/// R = R_tilt(A or B) R_z(C); print moves carry the extrusion word `e` (E or the extruder axis).
/// Returns the number of move lines.
size_t checkMoves(const std::string& text, vtkPolyData* path, bool bc, const Eigen::Vector3d& pivot,
                  const Eigen::Vector3d& offset, bool cam = true, char e = 'E') {
  std::istringstream in(text);
  std::string line;
  vtkIdType i = 0;
  vtkDataArray* normals = path->GetPointData()->GetArray(geolattice::arrays::NozzleAxis);
  while (std::getline(in, line)) {
    if (line.rfind("G0 X", 0) != 0 && line.rfind("G1 X", 0) != 0) {
      continue;
    }
    EXPECT_LT(i, path->GetNumberOfPoints());
    if (i >= path->GetNumberOfPoints()) {
      break;
    }
    auto w = words(line);
    EXPECT_EQ(w.count(bc ? 'B' : 'A'), 1u) << line;
    EXPECT_EQ(w.count(bc ? 'A' : 'B'), 0u) << line;
    const double tilt = (bc ? w['B'] : w['A']) * M_PI / 180.0;
    const Eigen::Matrix3d r =
        Eigen::AngleAxisd(tilt, bc ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX())
            .toRotationMatrix() *
        Eigen::AngleAxisd(w['C'] * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    double n[3], p[3];
    normals->GetTuple(i, n);
    path->GetPoint(i, p);
    const Eigen::Vector3d axis = r * Eigen::Vector3d(n[0], n[1], n[2]).normalized();
    EXPECT_NEAR(axis.z(), 1.0, 1e-5) << line;
    const Eigen::Vector3d x =
        cam ? Eigen::Vector3d(pivot + r * (Eigen::Vector3d(p[0], p[1], p[2]) + offset))
            : Eigen::Vector3d(Eigen::Vector3d(p[0], p[1], p[2]) + offset);
    EXPECT_NEAR(w['X'], x.x(), 1e-4) << line;
    EXPECT_NEAR(w['Y'], x.y(), 1e-4) << line;
    EXPECT_NEAR(w['Z'], x.z(), 1e-4) << line;
    const bool air = path->GetPointData()->GetArray(geolattice::arrays::MoveKind)->GetTuple1(i) ==
                     geolattice::movekind::Air;
    EXPECT_EQ(line.rfind(air || i == 0 ? "G0 " : "G1 ", 0), 0u) << line;
    EXPECT_EQ(w.count(e), air || i == 0 ? 0u : 1u) << line;
    ++i;
  }
  EXPECT_EQ(i, path->GetNumberOfPoints());
  return static_cast<size_t>(i);
}

}  // namespace

TEST(vtkGLGCodeWriter, DefaultsAndPrintSelf) {
  vtkNew<vtkGLGCodeWriter> w;
  EXPECT_EQ(w->GetKinematics(), vtkGLGCodeWriter::AC);
  EXPECT_EQ(w->GetTiltLimits()[0], -120.0);
  EXPECT_EQ(w->GetTiltLimits()[1], 120.0);
  EXPECT_EQ(w->GetPivot()[0], 0.0);
  EXPECT_EQ(w->GetPartOffset()[2], 0.0);
  w->SetKinematicsToBC();
  EXPECT_EQ(w->GetKinematics(), vtkGLGCodeWriter::BC);
  expectPrintMentions(w, {"Kinematics: 1 (B-C)", "TiltLimits: -120 120"});
}

TEST(vtkGLGCodeWriter, MovesTurnTheAxisUpAC_BC) {
  const fs::path dir = glFreshDirectory("gcode");
  auto path = makeTestToolpath(3, 30.0);
  for (bool bc : {false, true}) {
    vtkNew<vtkGLGCodeWriter> w;
    vtkNew<GLTestErrorObserver> errors;
    errors->Observe(w);
    w->SetInputData(path);
    const std::string file = (dir / (bc ? "part.nc" : "part.gcode")).string();
    w->SetFileName(file.c_str());
    w->SetKinematics(bc ? vtkGLGCodeWriter::BC : vtkGLGCodeWriter::AC);
    w->SetPivot(100, 50, 20);
    w->SetPartOffset(1, 2, 3);
    w->SetToolCentrePoint(vtkGLGCodeWriter::CAM);  // machine coordinates
    ASSERT_EQ(w->Write(), 1) << errors->Errors();
    EXPECT_FALSE(errors->HasError()) << errors->Errors();
    EXPECT_EQ(w->GetNumberOfMoves(), path->GetNumberOfPoints());
    EXPECT_EQ(w->GetOutOfLimitsCount(), 0);
    // The axis turns by 30° at once in this toolpath: A-C tilts by 30° (C stays), B-C also turns C.
    EXPECT_GE(w->GetMaxRotaryStepDeg(), 30.0 - 1e-9);
    EXPECT_LE(w->GetMaxRotaryStepDeg(), bc ? 180.0 : 30.0 + 1e-9);
    const std::string text = glReadFile(file);
    EXPECT_NE(text.find(bc ? "B-C tilting-rotary table" : "A-C tilting-rotary table"),
              std::string::npos);
    EXPECT_NE(text.find("\nG21 G90 G93\n"), std::string::npos);
    EXPECT_EQ(text.find("M83"), std::string::npos);  // not a LinuxCNC code
    EXPECT_EQ(text.substr(text.size() - 7), "G94\nM2\n");
    checkMoves(text, path, bc, Eigen::Vector3d(100, 50, 20), Eigen::Vector3d(1, 2, 3), true, 'U');
    // The controller's kinematics (the default): part coordinates + offset.
    w->SetToolCentrePoint(vtkGLGCodeWriter::CONTROLLER);
    ASSERT_EQ(w->Write(), 1) << errors->Errors();
    checkMoves(glReadFile(file), path, bc, Eigen::Vector3d(100, 50, 20), Eigen::Vector3d(1, 2, 3),
               false, 'U');
    // RepRapFirmware: machine coordinates, relative E, M83, no G93.
    w->SetFlavor(vtkGLGCodeWriter::REPRAP);
    w->SetToolCentrePoint(vtkGLGCodeWriter::CAM);
    ASSERT_EQ(w->Write(), 1) << errors->Errors();
    const std::string rrf = glReadFile(file);
    EXPECT_NE(rrf.find("\nM83\n"), std::string::npos);
    EXPECT_EQ(rrf.find("G93"), std::string::npos);
    checkMoves(rrf, path, bc, Eigen::Vector3d(100, 50, 20), Eigen::Vector3d(1, 2, 3), true, 'E');
    // Flavor checks: RepRap needs the CAM tool centre point; the extruder is no motion axis.
    w->SetToolCentrePoint(vtkGLGCodeWriter::CONTROLLER);
    EXPECT_EQ(w->Write(), 0);
    EXPECT_NE(errors->Errors().find("reprap flavor needs"), std::string::npos) << errors->Errors();
    errors->Clear();
    w->SetFlavor(vtkGLGCodeWriter::LINUXCNC);
    w->SetExtrusionAxis("C");
    EXPECT_EQ(w->Write(), 0);
    EXPECT_NE(errors->Errors().find("extrusion axis C is a motion axis"), std::string::npos)
        << errors->Errors();
    errors->Clear();
    w->SetExtrusionAxis("U");
    w->SetFlavor(7);
    EXPECT_EQ(w->Write(), 0);
    EXPECT_NE(errors->Errors().find("Flavor must be 0 (LinuxCNC) or 1 (RepRap)"),
              std::string::npos);
    errors->Clear();
    w->SetFlavor(vtkGLGCodeWriter::LINUXCNC);
  }
  EXPECT_EQ(glListDirectory(dir), (std::vector<std::string>{"part.gcode", "part.nc"}));
  fs::remove_all(dir);
}

TEST(vtkGLGCodeWriter, BadInputIsReported) {
  const fs::path dir = glFreshDirectory("gcode-errors");
  const std::string file = (dir / "part.gcode").string();
  std::ofstream(file) << "earlier\n";
  auto expectError = [&](vtkPolyData* input, const std::string& text, auto&& setUp) {
    vtkNew<vtkGLGCodeWriter> w;
    vtkNew<GLTestErrorObserver> errors;
    errors->Observe(w);
    w->SetInputData(input);
    w->SetFileName(file.c_str());
    setUp(w.Get());
    EXPECT_EQ(w->Write(), 0) << text;
    EXPECT_NE(errors->Errors().find(text), std::string::npos) << errors->Errors();
    EXPECT_EQ(w->GetNumberOfMoves(), 0);
    EXPECT_EQ(glReadFile(file), "earlier\n") << "the earlier file is untouched: " << text;
    EXPECT_EQ(glListDirectory(dir), std::vector<std::string>{"part.gcode"}) << text;
    return w->GetErrorCode();
  };
  auto nothing = [](vtkGLGCodeWriter*) {
  };
  // The 20° tilt of the second half of each loop (points 22.., 63..) is outside +-10°.
  expectError(makeTestToolpath(2, 20.0),
              "40 of 83 toolpath points need a tilt outside the limits [-10, 10] degrees (first: "
              "22, 23, 24",
              [](vtkGLGCodeWriter* w) { w->SetTiltLimits(-10, 10); });
  // A tilt above the limit on one side only: the other solution is used.
  {
    vtkNew<vtkGLGCodeWriter> w;
    w->SetInputData(makeTestToolpath(2, 20.0));
    const std::string ok = (dir / "oneside.gcode").string();
    w->SetFileName(ok.c_str());
    w->SetTiltLimits(-5, 30);
    EXPECT_EQ(w->Write(), 1);
    EXPECT_GT(w->GetBranchFlips(), 0);
    fs::remove(ok);
  }
  expectError(makeTestToolpath(), "the tilt limits must be finite with min < max",
              [](vtkGLGCodeWriter* w) { w->SetTiltLimits(10, -10); });
  expectError(makeTestToolpath(), "the pivot and the part offset must be finite",
              [](vtkGLGCodeWriter* w) { w->SetPivot(std::nan(""), 0, 0); });
  {
    auto path = makeTestToolpath();
    path->GetPointData()
        ->GetArray(geolattice::arrays::NozzleAxis)
        ->SetTuple3(5, 0, std::nan(""), 1);
    EXPECT_EQ(expectError(path, "toolpath point 5 has a NaN or zero nozzle axis", nothing),
              vtkErrorCode::UserError);
  }
  {
    vtkNew<vtkPolyData> empty;
    expectError(empty, "empty toolpath", nothing);
  }
  {
    const std::string missing = (dir / "no-such-dir" / "x.gcode").string();
    EXPECT_EQ(expectError(makeTestToolpath(), "cannot create " + missing,
                          [&](vtkGLGCodeWriter* w) { w->SetFileName(missing.c_str()); }),
              vtkErrorCode::CannotOpenFileError);
  }
  fs::remove_all(dir);
}

TEST(vtkGLGCodeWriter, ProgressAndAbortWriteNothing) {
  const fs::path dir = glFreshDirectory("gcode-abort");
  vtkNew<vtkGLGCodeWriter> w;
  w->SetInputData(makeTestToolpath(4));
  w->SetFileName((dir / "abort.gcode").string().c_str());
  auto write = [&w] {
    EXPECT_EQ(w->Write(), 1);
  };
  auto nothingWritten = [&w, &dir] {
    return glListDirectory(dir).empty() && w->GetNumberOfMoves() == 0;
  };
  glExpectProgressReport(w, 3, write);
  fs::remove(dir / "abort.gcode");
  for (double at : {0.1, 0.2, 0.9}) {
    SCOPED_TRACE(at);
    glExpectCleanAbort(w, glAbortAt(at), write, nothingWritten);
    fs::remove(dir / "abort.gcode");
  }
  fs::remove_all(dir);
}
