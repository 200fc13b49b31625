#include "vtkGLToolpathWriter.h"

#include "vtkGLArrayNames.h"
#include "vtkGLOutputFiles.h"
#include "vtkGLRequest.h"

#include "common/Error.h"

#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <string>

namespace gl = geolattice;

vtkGLToolpathWriter::vtkGLToolpathWriter() = default;

vtkGLToolpathWriter::~vtkGLToolpathWriter() {
  this->SetFileName(nullptr);
}

int vtkGLToolpathWriter::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

vtkTypeBool vtkGLToolpathWriter::ProcessRequest(vtkInformation* request,
                                                vtkInformationVector** inputVector,
                                                vtkInformationVector* outputVector) {
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_INFORMATION()) &&
      !gl::checkParameters(this, [&] { this->CheckParameters(); })) {
    this->SetErrorCode(vtkErrorCode::UserError);  // so that Write() returns 0
    return 0;
  }
  if (request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_UPDATE_EXTENT())) {
    gl::requestEndOfTimeRange(inputVector);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

void vtkGLToolpathWriter::CheckFileName(const char* what) {
  if (!this->FileName || !*this->FileName) {
    throw gl::GeoLatticeError(std::string(what) + ": no FileName given");
  }
}

void vtkGLToolpathWriter::CheckCollisionVerdict(vtkPolyData* toolpath, const char* what) {
  vtkFieldData* fd = toolpath ? toolpath->GetFieldData() : nullptr;
  vtkDataArray* verdict = fd ? fd->GetArray(gl::arrays::ToolpathCollisionFree) : nullptr;
  if (verdict && verdict->GetNumberOfTuples() > 0 && verdict->GetTuple1(0) != 0) {
    return;
  }
  std::string problem;
  if (!verdict) {
    problem = std::string("the toolpath carries no collision verdict (field data ") +
              gl::arrays::ToolpathCollisionFree + "; run it through GL Toolpath Planner)";
  } else {
    vtkDataArray* stations = fd->GetArray(gl::arrays::ToolpathUnclearedStations);
    problem = "the toolpath collides: the nozzle meets printed material or the build plate at " +
              std::to_string(stations ? static_cast<long long>(stations->GetTuple1(0)) : 0) +
              " stations (see GL Collision Verifier on the toolpath)";
  }
  if (!this->AllowCollisions) {
    throw gl::GeoLatticeError(std::string(what) + ": " + problem +
                              "; nothing written (AllowCollisions writes it anyway)");
  }
  vtkWarningMacro(<< what << ": " << problem << "; written anyway (AllowCollisions)");
}

void vtkGLToolpathWriter::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "AllowCollisions: " << (this->AllowCollisions ? "on" : "off") << "\n";
}
