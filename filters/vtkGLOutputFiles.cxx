#include "vtkGLOutputFiles.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkStreamingDemandDrivenPipeline.h>

namespace geolattice {

void requestEndOfTimeRange(vtkInformationVector** inputVector) {
  vtkInformation* in =
      inputVector && inputVector[0] ? inputVector[0]->GetInformationObject(0) : nullptr;
  if (!in) {
    return;
  }
  using SDDP = vtkStreamingDemandDrivenPipeline;
  const int steps = in->Has(SDDP::TIME_STEPS()) ? in->Length(SDDP::TIME_STEPS()) : 0;
  if (steps > 0) {
    in->Set(SDDP::UPDATE_TIME_STEP(), in->Get(SDDP::TIME_STEPS())[steps - 1]);
  } else if (in->Has(SDDP::TIME_RANGE()) && in->Length(SDDP::TIME_RANGE()) == 2) {
    in->Set(SDDP::UPDATE_TIME_STEP(), in->Get(SDDP::TIME_RANGE())[1]);
  }
}

}  // namespace geolattice
