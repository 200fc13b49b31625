#pragma once
/// @file GLTestYPipeline.h
/// @brief The coarse branching-Y pipeline shared by the end-to-end filter tests: GLPrintPipeline
/// (the CLI's pipeline) on testdata/y_shape.obj with tets of 2 mm, 1 mm layers (first at 0.5 mm)
/// and a 4 mm lattice, every stage watched by one error observer. Construction only wires the
/// filters; tests update what they need.
#include "GLTestErrorObserver.h"

#include "GLPrintPipeline.h"
#include "vtkGLCurvedLayerSlicer.h"
#include "vtkGLGeodesicDistanceFields.h"
#include "vtkGLLatticeInfill.h"
#include "vtkGLMeshReader.h"
#include "vtkGLPlaceOnPlatform.h"
#include "vtkGLPrintSequencer.h"
#include "vtkGLSkeletonTree.h"
#include "vtkGLTetrahedralizeSurface.h"
#include "vtkGLToolpathPlanner.h"

#include <gtest/gtest.h>
#include <vtkNew.h>

#include <initializer_list>
#include <memory>
#include <string>

struct GLTestYPipeline {
  GLPrintPipeline pipeline;  ///< the CLI's pipeline, wired once (filters/GLPrintPipeline.h)
  vtkGLMeshReader* reader = pipeline.Reader;
  vtkGLPlaceOnPlatform* place = pipeline.Placement;
  vtkGLTetrahedralizeSurface* tets = pipeline.Tetrahedralize;
  vtkGLGeodesicDistanceFields* gdf = pipeline.GeodesicFields;
  vtkGLCurvedLayerSlicer* slicer = pipeline.Slicer;
  vtkGLLatticeInfill* lattice = pipeline.LatticeInfill;
  vtkGLSkeletonTree* skeleton = pipeline.SkeletonTree;
  vtkGLPrintSequencer* sequencer = pipeline.Sequencer;
  vtkGLToolpathPlanner* planner = pipeline.Planner;
  vtkNew<GLTestErrorObserver> errors;

  GLTestYPipeline() {
    reader->SetFileName((std::string(GEOLATTICE_TESTDATA) + "/y_shape.obj").c_str());
    tets->SetTargetEdgeLength(2.0);  // coarse
    slicer->SetLayerInterval(1.0);
    slicer->SetFirstLayerOffset(0.5);
    lattice->SetAlphaWidth(4.0);
    lattice->SetBetaWidth(4.0);
    for (vtkAlgorithm* a : std::initializer_list<vtkAlgorithm*>{
             reader, place, tets, gdf, slicer, lattice, skeleton, sequencer, planner}) {
      errors->Observe(a);
    }
  }
};

/// A test suite on one GLTestYPipeline built once for the suite and updated up to the stage
/// `Suite::Stage(y)` names (CRTP: `class S : public GLTestYSuite<S>` with a static Stage()).
template <class Suite>
class GLTestYSuite : public ::testing::Test {
protected:
  using Pipeline = GLTestYPipeline;
  static inline std::unique_ptr<Pipeline> p;

  static void SetUpTestSuite() {
    p = std::make_unique<Pipeline>();
    Suite::Stage(*p)->Update();
  }
  static void TearDownTestSuite() { p.reset(); }
};
