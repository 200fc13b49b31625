#include "vtkGLSurfaceCheck.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "mesh/SurfaceCheck.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <string>

vtkStandardNewMacro(vtkGLSurfaceCheck);

namespace gl = geolattice;

void vtkGLSurfaceCheck::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
}

int vtkGLSurfaceCheck::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                   vtkInformationVector* outputVector) {
  // Collective in an MPI run: the whole surface on one process (vtkGLParallel.h).
  return gl::runRequest(this, inputVector, 1, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkPolyData* input = inputs.Get<vtkPolyData>(0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    if (!input) {
      throw gl::GeoLatticeError("input must be a vtkPolyData surface");
    }
    const gl::TriangleSurface surface = gl::toTriangleSurface(input);
    const gl::SurfaceCheckReport r = gl::checkSurface(surface);
    std::string verdict = "closed manifold";
    try {
      gl::requireClosedManifold(surface);
    } catch (const gl::GeoLatticeError& e) {
      verdict = e.what();
    }
    output->SetPoints(input->GetPoints());
    vtkNew<vtkCellArray> lines;
    vtkNew<vtkIntArray> kind;
    kind->SetName(gl::arrays::DefectKind);
    for (const gl::SurfaceDefectEdge& e : r.defectEdges) {
      lines->InsertNextCell({static_cast<vtkIdType>(e.lo), static_cast<vtkIdType>(e.hi)});
      kind->InsertNextValue(e.kind);
    }
    output->SetLines(lines);
    output->GetCellData()->AddArray(kind);
    vtkFieldData* fd = output->GetFieldData();
    const bool closed = verdict == "closed manifold";
    gl::addFieldArray(fd, gl::arrays::SurfaceClosed, {closed ? 1.0 : 0.0});
    gl::addFieldArray(fd, gl::arrays::BoundaryEdges, {static_cast<double>(r.boundaryEdges)});
    gl::addFieldArray(fd, gl::arrays::NonManifoldEdges, {static_cast<double>(r.nonManifoldEdges)});
    gl::addFieldArray(fd, gl::arrays::InconsistentEdges,
                      {static_cast<double>(r.inconsistentEdges)});
    gl::addFieldArray(fd, gl::arrays::DegenerateTriangles,
                      {static_cast<double>(r.degenerateTriangles)});
    gl::addFieldArray(fd, gl::arrays::SignedVolume, {r.signedVolume});
    gl::addFieldText(fd, gl::arrays::SurfaceVerdict, verdict);
    this->UpdateProgress(1.0);
  });
}
