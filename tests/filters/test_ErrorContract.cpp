// VTK's error contract, for every GeoLattice filter: on a failure RequestData reports the problem
// with vtkErrorMacro and returns 0, so Update() returns false and the filters downstream do not
// run (no cascade of "empty input" errors); a writer's Write() returns 0.
#include "GLTestErrorObserver.h"
#include "GLTestToolpath.h"

#include "vtkGLCollisionVerifier.h"
#include "vtkGLCurvedLayerSlicer.h"
#include "vtkGLGCodeWriter.h"
#include "vtkGLGeodesicDistanceFields.h"
#include "vtkGLLatticeInfill.h"
#include "vtkGLMeshReader.h"
#include "vtkGLOverhangAnalysis.h"
#include "vtkGLPedestal.h"
#include "vtkGLToolpathReplay.h"
#include "vtkGLPrintPart.h"
#include "vtkGLPrintSummary.h"
#include "vtkGLPlaceOnPlatform.h"
#include "vtkGLPrintSequencer.h"
#include "vtkGLSkeletonTree.h"
#include "vtkGLSurfaceCheck.h"
#include "vtkGLTetrahedralizeSurface.h"
#include "vtkGLToolpathPlanner.h"
#include "vtkGLURScriptWriter.h"
#include "vtkGLWaypointCsvWriter.h"

#include <gtest/gtest.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <functional>
#include <string>

namespace {

/// Connects an empty input of the type the filter takes to every input port.
template <class F>
vtkSmartPointer<vtkAlgorithm> withEmptyInputs(bool tetMesh0, bool tetMesh1 = false) {
  auto f = vtkSmartPointer<F>::New();
  for (int port = 0; port < f->GetNumberOfInputPorts(); ++port) {
    if ((port == 0 && tetMesh0) || (port == 1 && tetMesh1)) {
      f->SetInputDataObject(port, vtkSmartPointer<vtkUnstructuredGrid>::New());
    } else {
      f->SetInputDataObject(port, vtkSmartPointer<vtkPolyData>::New());
    }
  }
  return f;
}

struct FilterCase {
  const char* name;
  std::function<vtkSmartPointer<vtkAlgorithm>()> make;
};

}  // namespace

TEST(ErrorContract, EveryFilterReturnsFalseOnFailure) {
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);  // the executive's failure dump
  const FilterCase cases[] = {
      {"GL Mesh Reader",
       [] {
         auto r = vtkSmartPointer<vtkGLMeshReader>::New();
         r->SetFileName("/nonexistent/part.stl");
         return vtkSmartPointer<vtkAlgorithm>(r);
       }},
      {"GL Place On Platform",
       [] {
         return withEmptyInputs<vtkGLPlaceOnPlatform>(false);
       }},
      {"GL Pedestal",
       [] {
         auto f = withEmptyInputs<vtkGLPedestal>(false);
         vtkGLPedestal::SafeDownCast(f)->SetHeight(5);
         return f;
       }},
      {"GL Print Part",
       [] {
         return withEmptyInputs<vtkGLPrintPart>(false);
       }},
      {"GL Print Summary",
       [] {
         auto f = vtkSmartPointer<vtkGLPrintSummary>::New();
         f->SetInputDataObject(0, vtkSmartPointer<vtkPolyData>::New());
         return vtkSmartPointer<vtkAlgorithm>(f);
       }},
      {"GL Toolpath Replay",
       [] {
         return withEmptyInputs<vtkGLToolpathReplay>(false);
       }},
      {"GL Surface Check",
       [] {
         return withEmptyInputs<vtkGLSurfaceCheck>(false);
       }},
      {"GL Tetrahedralize Surface",
       [] {
         return withEmptyInputs<vtkGLTetrahedralizeSurface>(false);
       }},
      {"GL Geodesic Distance Fields",
       [] {
         return withEmptyInputs<vtkGLGeodesicDistanceFields>(true);
       }},
      {"GL Curved Layer Slicer",
       [] {
         return withEmptyInputs<vtkGLCurvedLayerSlicer>(true);
       }},
      {"GL Overhang Analysis",
       [] {
         return withEmptyInputs<vtkGLOverhangAnalysis>(true);
       }},
      {"GL Lattice Infill",
       [] {
         return withEmptyInputs<vtkGLLatticeInfill>(false);
       }},
      {"GL Skeleton Tree",
       [] {
         return withEmptyInputs<vtkGLSkeletonTree>(false, true);
       }},
      {"GL Print Sequencer",
       [] {
         return withEmptyInputs<vtkGLPrintSequencer>(false);
       }},
      {"GL Collision Verifier",
       [] {
         return withEmptyInputs<vtkGLCollisionVerifier>(false);
       }},
      {"GL Toolpath Planner",
       [] {
         return withEmptyInputs<vtkGLToolpathPlanner>(false);
       }},
  };
  for (const FilterCase& c : cases) {
    SCOPED_TRACE(c.name);
    vtkSmartPointer<vtkAlgorithm> filter = c.make();
    vtkNew<GLTestErrorObserver> errors;
    errors->Observe(filter);
    EXPECT_FALSE(filter->Update(0, nullptr));
    EXPECT_EQ(errors->GetErrorCount(), 1) << errors->Errors();
  }
  // A failing upstream filter stops the pipeline: the downstream filter reports nothing.
  vtkNew<vtkGLMeshReader> reader;
  reader->SetFileName("/nonexistent/part.stl");
  vtkNew<vtkGLPlaceOnPlatform> place;
  place->SetInputConnection(reader->GetOutputPort());
  vtkNew<GLTestErrorObserver> upstream, downstream;
  upstream->Observe(reader);
  downstream->Observe(place);
  EXPECT_FALSE(place->Update(0, nullptr));
  EXPECT_EQ(upstream->GetErrorCount(), 1);
  EXPECT_EQ(downstream->GetErrorCount(), 0) << downstream->Errors();
}

TEST(ErrorContract, EveryWriterReturnsZeroOnFailure) {
  vtkSmartPointer<vtkGLToolpathWriter> writers[] = {vtkSmartPointer<vtkGLURScriptWriter>::New(),
                                                    vtkSmartPointer<vtkGLGCodeWriter>::New(),
                                                    vtkSmartPointer<vtkGLWaypointCsvWriter>::New()};
  for (vtkGLToolpathWriter* w : writers) {
    SCOPED_TRACE(w->GetClassName());
    vtkNew<GLTestErrorObserver> errors;
    errors->Observe(w);
    w->SetInputData(makeTestToolpath());
    w->SetFileName("/nonexistent-dir/program.out");
    EXPECT_EQ(w->Write(), 0);
    EXPECT_EQ(errors->GetErrorCount(), 1) << errors->Errors();
  }
}
