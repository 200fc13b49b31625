// The safety gate of the program writers (vtkGLToolpathWriter): a toolpath that collides, or
// that carries no collision verdict, is refused with an error and nothing is written, unless
// AllowCollisions is on; then the program is written and a warning says so.
#include "GLTestErrorObserver.h"
#include "GLTestFiles.h"
#include "GLTestToolpath.h"

#include "vtkGLGCodeWriter.h"
#include "vtkGLURScriptWriter.h"
#include "vtkGLWaypointCsvWriter.h"

#include <gtest/gtest.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <filesystem>
#include <string>

namespace {

struct WriterCase {
  const char* name;
  vtkSmartPointer<vtkGLToolpathWriter> (*make)();
  const char* file;
};

template <class W>
vtkSmartPointer<vtkGLToolpathWriter> make() {
  return vtkSmartPointer<W>::New();
}

const WriterCase kWriters[] = {{"URScript", make<vtkGLURScriptWriter>, "p.script"},
                               {"G-code", make<vtkGLGCodeWriter>, "p.gcode"},
                               {"waypoints", make<vtkGLWaypointCsvWriter>, "p.csv"}};

}  // namespace

TEST(vtkGLToolpathWriter, RefusesACollidingToolpathUnlessAllowed) {
  const std::filesystem::path dir = glFreshDirectory("toolpath-writer-gate");
  for (const WriterCase& c : kWriters) {
    SCOPED_TRACE(c.name);
    const std::string path = (dir / c.file).string();
    for (int verdict : {0, -1}) {  // colliding, and no verdict at all
      vtkSmartPointer<vtkGLToolpathWriter> w = c.make();
      vtkNew<GLTestErrorObserver> errors;
      errors->Observe(w);
      w->SetInputData(makeTestToolpath(2, 20.0, verdict));
      w->SetFileName(path.c_str());
      EXPECT_EQ(w->Write(), 0);
      EXPECT_EQ(errors->GetErrorCount(), 1);
      EXPECT_NE(
          errors->Errors().find(verdict == 0 ? "the toolpath collides" : "no collision verdict"),
          std::string::npos)
          << errors->Errors();
      EXPECT_NE(errors->Errors().find("nothing written"), std::string::npos);
      EXPECT_FALSE(std::filesystem::exists(path));
    }
    vtkSmartPointer<vtkGLToolpathWriter> w = c.make();
    vtkNew<GLTestErrorObserver> errors;
    errors->Observe(w);
    w->SetInputData(makeTestToolpath(2, 20.0, 0));
    w->SetFileName(path.c_str());
    w->AllowCollisionsOn();
    EXPECT_EQ(w->Write(), 1) << errors->Errors();
    EXPECT_FALSE(errors->HasError()) << errors->Errors();
    EXPECT_NE(errors->Warnings().find("written anyway (AllowCollisions)"), std::string::npos);
    EXPECT_TRUE(std::filesystem::exists(path));
  }
  std::filesystem::remove_all(dir);
}
