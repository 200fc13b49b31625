#include "vtkGLWaypointCsvWriter.h"

#include "vtkGLMeshConversion.h"
#include "vtkGLOutputFiles.h"
#include "vtkGLParallel.h"
#include "vtkGLProgress.h"

#include "common/Error.h"
#include "program/FiveAxisGCode.h"

#include <vtkErrorCode.h>
#include <vtkInformation.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

vtkStandardNewMacro(vtkGLWaypointCsvWriter);

namespace gl = geolattice;

vtkGLWaypointCsvWriter::vtkGLWaypointCsvWriter() = default;

vtkGLWaypointCsvWriter::~vtkGLWaypointCsvWriter() {
  this->SetFileName(nullptr);
}

int vtkGLWaypointCsvWriter::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

vtkTypeBool vtkGLWaypointCsvWriter::ProcessRequest(vtkInformation* request,
                                                   vtkInformationVector** inputVector,
                                                   vtkInformationVector* outputVector) {
  if (request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_UPDATE_EXTENT())) {
    gl::requestEndOfTimeRange(inputVector);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

void vtkGLWaypointCsvWriter::WriteData() {
  this->NumberOfRows = 0;
  // In an MPI run one process writes: the one with the toolpath (vtkGLParallel.h).
  const gl::ParallelInputs inputs(this);
  if (!inputs.Computes()) {
    return;  // another process writes the waypoints
  }
  try {
    if (!this->FileName || !*this->FileName) {
      throw gl::GeoLatticeError("waypoint CSV writer: no FileName given");
    }
    const gl::ToolpathArrays path = gl::toToolpathArrays(inputs.Get<vtkPolyData>(0));
    if (gl::progressAborts(this, 0.2)) {
      return;
    }
    gl::AtomicFileSet files;
    gl::writeWaypointCsv(path.points, path.normals, path.extrusion, path.kind, path.layer,
                         files.open(this->FileName));
    if (gl::progressAborts(this, 0.9)) {
      return;  // the temporary file goes with `files`: nothing written
    }
    files.commit();
    this->NumberOfRows = static_cast<vtkIdType>(path.points.size());
  } catch (const gl::FileWriteError& e) {
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    vtkErrorMacro(<< e.what());
  } catch (const std::exception& e) {
    if (this->GetAbortExecute()) {
      return;  // an abort is not an error: nothing written, no message
    }
    this->SetErrorCode(vtkErrorCode::UserError);
    vtkErrorMacro(<< e.what());
  }
}

void vtkGLWaypointCsvWriter::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "NumberOfRows: " << this->NumberOfRows << "\n";
}
