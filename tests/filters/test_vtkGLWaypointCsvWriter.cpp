// vtkGLWaypointCsvWriter: header and one row per toolpath point with its position, unit axis,
// extrusion, kind and layer; errors (NaN normals, empty toolpath, unwritable path) with nothing
// written and an earlier file untouched.
#include "GLTestErrorObserver.h"
#include "GLTestProgress.h"
#include "GLTestFiles.h"
#include "GLTestToolpath.h"

#include "vtkGLArrayNames.h"
#include "vtkGLWaypointCsvWriter.h"

#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

TEST(vtkGLWaypointCsvWriter, OneRowPerPoint) {
  const fs::path dir = glFreshDirectory("csv");
  auto path = makeTestToolpath(2, 25.0);
  // Not unit length: the rows hold the unit axis.
  path->GetPointData()->GetArray(geolattice::arrays::NozzleAxis)->SetTuple3(0, 0, 0, 3);
  vtkNew<vtkGLWaypointCsvWriter> w;
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(w);
  w->SetInputData(path);
  const std::string file = (dir / "waypoints.csv").string();
  w->SetFileName(file.c_str());
  ASSERT_EQ(w->Write(), 1) << errors->Errors();
  EXPECT_EQ(w->GetNumberOfRows(), path->GetNumberOfPoints());
  std::istringstream in(glReadFile(file));
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(line, "x,y,z,nx,ny,nz,e,kind,layer");
  vtkPointData* pd = path->GetPointData();
  vtkIdType i = 0;
  while (std::getline(in, line)) {
    ASSERT_LT(i, path->GetNumberOfPoints());
    std::vector<double> v;
    std::stringstream fields(line);
    std::string f;
    while (std::getline(fields, f, ',')) {
      v.push_back(std::stod(f));
    }
    ASSERT_EQ(v.size(), 9u) << line;
    double p[3], n[3];
    path->GetPoint(i, p);
    pd->GetArray(geolattice::arrays::NozzleAxis)->GetTuple(i, n);
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(v[k], p[k], 1e-6) << line;
      EXPECT_NEAR(v[3 + k], n[k] / len, 1e-6) << line;
    }
    EXPECT_NEAR(v[6], pd->GetArray(geolattice::arrays::Extrusion)->GetTuple1(i), 1e-6) << line;
    EXPECT_EQ(v[7], pd->GetArray(geolattice::arrays::MoveKind)->GetTuple1(i)) << line;
    EXPECT_EQ(v[8], pd->GetArray(geolattice::arrays::LayerId)->GetTuple1(i)) << line;
    ++i;
  }
  EXPECT_EQ(i, path->GetNumberOfPoints());
  EXPECT_EQ(glListDirectory(dir), std::vector<std::string>{"waypoints.csv"});
  std::ostringstream os;
  w->Print(os);
  EXPECT_NE(os.str().find("NumberOfRows: " + std::to_string(i)), std::string::npos);
  fs::remove_all(dir);
}

TEST(vtkGLWaypointCsvWriter, BadInputIsReported) {
  const fs::path dir = glFreshDirectory("csv-errors");
  const std::string file = (dir / "waypoints.csv").string();
  std::ofstream(file) << "earlier\n";
  auto expectError = [&](vtkPolyData* input, const std::string& name, const std::string& text) {
    vtkNew<vtkGLWaypointCsvWriter> w;
    vtkNew<GLTestErrorObserver> errors;
    errors->Observe(w);
    w->SetInputData(input);
    w->SetFileName(name.c_str());
    EXPECT_EQ(w->Write(), 0) << text;
    EXPECT_NE(errors->Errors().find(text), std::string::npos) << errors->Errors();
    EXPECT_EQ(w->GetNumberOfRows(), 0);
    EXPECT_EQ(glReadFile(file), "earlier\n");
    EXPECT_EQ(glListDirectory(dir), std::vector<std::string>{"waypoints.csv"}) << text;
    return w->GetErrorCode();
  };
  auto path = makeTestToolpath();
  path->GetPointData()->GetArray(geolattice::arrays::NozzleAxis)->SetTuple3(2, std::nan(""), 0, 1);
  EXPECT_EQ(expectError(path, file, "toolpath point 2 has a NaN or zero nozzle axis"),
            vtkErrorCode::UserError);
  vtkNew<vtkPolyData> empty;
  expectError(empty, file, "empty toolpath");
  auto noLayer = makeTestToolpath();
  noLayer->GetPointData()->RemoveArray(geolattice::arrays::LayerId);
  expectError(noLayer, file, "the toolpath has no point array LayerId");
  const std::string missing = (dir / "no-such-dir" / "w.csv").string();
  EXPECT_EQ(expectError(makeTestToolpath(), missing, "cannot create " + missing),
            vtkErrorCode::CannotOpenFileError);
  fs::remove_all(dir);
}

TEST(vtkGLWaypointCsvWriter, ProgressAndAbortWriteNothing) {
  const fs::path dir = glFreshDirectory("csv-abort");
  vtkNew<vtkGLWaypointCsvWriter> w;
  w->SetInputData(makeTestToolpath(4));
  w->SetFileName((dir / "abort.csv").string().c_str());
  auto write = [&w] {
    EXPECT_EQ(w->Write(), 1);
  };
  auto nothingWritten = [&w, &dir] {
    return glListDirectory(dir).empty() && w->GetNumberOfRows() == 0;
  };
  glExpectProgressReport(w, 2, write);
  fs::remove(dir / "abort.csv");
  for (double at : {0.2, 0.9}) {
    SCOPED_TRACE(at);
    glExpectCleanAbort(w, glAbortAt(at), write, nothingWritten);
    fs::remove(dir / "abort.csv");
  }
  fs::remove_all(dir);
}
