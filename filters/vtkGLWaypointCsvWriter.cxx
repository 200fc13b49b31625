#include "vtkGLWaypointCsvWriter.h"

#include "vtkGLMeshConversion.h"
#include "vtkGLOutputFiles.h"
#include "vtkGLParallel.h"
#include "vtkGLProgress.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "program/WaypointCsvWriter.h"

#include <vtkErrorCode.h>
#include <vtkInformation.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

vtkStandardNewMacro(vtkGLWaypointCsvWriter);

namespace gl = geolattice;

vtkGLWaypointCsvWriter::vtkGLWaypointCsvWriter() = default;

vtkGLWaypointCsvWriter::~vtkGLWaypointCsvWriter() {}

void vtkGLWaypointCsvWriter::WriteData() {
  this->NumberOfRows = 0;
  // In an MPI run one process writes: the one with the toolpath (vtkGLParallel.h).
  const gl::ParallelInputs inputs(this);
  if (!inputs.Computes()) {
    return;  // another process writes the waypoints
  }
  this->SetErrorCode(gl::runWrite(
      this,
      [&] {
        this->CheckFileName("waypoint CSV writer");
        const gl::ToolpathArrays path = gl::toToolpathArrays(inputs.Get<vtkPolyData>(0));
        this->CheckCollisionVerdict(inputs.Get<vtkPolyData>(0), "waypoint CSV writer");
        gl::checkAbort(this, 0.2);
        gl::AtomicFileSet files;
        gl::writeWaypointCsv(path.points, path.normals, path.extrusion, path.kind, path.layer,
                             files.open(this->FileName));
        gl::checkAbort(this, 0.9);
        files.commit();
        this->NumberOfRows = static_cast<vtkIdType>(path.points.size());
      },
      [this] { this->NumberOfRows = 0; }, [this] { this->NumberOfRows = 0; }));
}

void vtkGLWaypointCsvWriter::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfRows: " << this->NumberOfRows << "\n";
}
