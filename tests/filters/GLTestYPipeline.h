#pragma once
/// @file GLTestYPipeline.h
/// @brief The coarse branching-Y pipeline shared by the end-to-end filter tests: reader -> place
/// -> tets (2 mm) -> GDF -> slicer (1 mm layers, first at 0.5 mm) -> lattice (4 mm) -> skeleton ->
/// sequencer (NA 45°) -> toolpath planner (skeleton tree as its second input), every stage watched
/// by one error observer. Construction only wires the filters; tests update what they need.
#include "GLTestErrorObserver.h"

#include "vtkGLCurvedLayerSlicer.h"
#include "vtkGLGeodesicDistanceFields.h"
#include "vtkGLLatticeInfill.h"
#include "vtkGLMeshReader.h"
#include "vtkGLPlaceOnPlatform.h"
#include "vtkGLPrintSequencer.h"
#include "vtkGLSkeletonTree.h"
#include "vtkGLTetrahedralizeSurface.h"
#include "vtkGLToolpathPlanner.h"

#include <vtkNew.h>

#include <initializer_list>
#include <string>

struct GLTestYPipeline {
  vtkNew<vtkGLMeshReader> reader;
  vtkNew<vtkGLPlaceOnPlatform> place;
  vtkNew<vtkGLTetrahedralizeSurface> tets;
  vtkNew<vtkGLGeodesicDistanceFields> gdf;
  vtkNew<vtkGLCurvedLayerSlicer> slicer;
  vtkNew<vtkGLLatticeInfill> lattice;
  vtkNew<vtkGLSkeletonTree> skeleton;
  vtkNew<vtkGLPrintSequencer> sequencer;
  vtkNew<vtkGLToolpathPlanner> planner;
  vtkNew<GLTestErrorObserver> errors;

  GLTestYPipeline() {
    reader->SetFileName((std::string(GEOLATTICE_TESTDATA) + "/y_shape.obj").c_str());
    place->SetInputConnection(reader->GetOutputPort());
    tets->SetInputConnection(place->GetOutputPort());
    tets->SetTargetEdgeLength(2.0);  // coarse
    gdf->SetInputConnection(tets->GetOutputPort());
    slicer->SetInputConnection(gdf->GetOutputPort());
    slicer->SetLayerInterval(1.0);
    slicer->SetFirstLayerOffset(0.5);
    lattice->SetInputConnection(slicer->GetOutputPort(0));
    lattice->SetAlphaWidth(4.0);
    lattice->SetBetaWidth(4.0);
    skeleton->SetInputConnection(0, lattice->GetOutputPort());
    skeleton->SetInputConnection(1, gdf->GetOutputPort());
    sequencer->SetInputConnection(0, lattice->GetOutputPort());
    sequencer->SetInputConnection(1, skeleton->GetOutputPort());
    sequencer->GetNozzle()->SetNozzleAngle(45.0);
    planner->SetInputConnection(0, sequencer->GetOutputPort(0));
    planner->SetInputConnection(1, skeleton->GetOutputPort());  // the skeleton tree itself
    for (vtkAlgorithm* a : std::initializer_list<vtkAlgorithm*>{
             reader, place, tets, gdf, slicer, lattice, skeleton, sequencer, planner}) {
      errors->Observe(a);
    }
  }
};
