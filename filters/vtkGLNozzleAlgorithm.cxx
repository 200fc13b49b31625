#include "vtkGLNozzleAlgorithm.h"

#include "vtkGLMeshConversion.h"
#include "vtkGLRequest.h"

#include <algorithm>

vtkGLNozzleAlgorithm::vtkGLNozzleAlgorithm() : Nozzle(vtkSmartPointer<vtkGLNozzle>::New()) {}

void vtkGLNozzleAlgorithm::SetNozzle(vtkGLNozzle* nozzle) {
  if (nozzle == this->Nozzle.Get() && nozzle) {
    return;
  }
  if (nozzle) {
    this->Nozzle = nozzle;
  } else {
    this->Nozzle = vtkSmartPointer<vtkGLNozzle>::New();
  }
  this->Modified();
}

vtkMTimeType vtkGLNozzleAlgorithm::GetMTime() {
  return std::max(this->Superclass::GetMTime(), this->Nozzle->GetMTime());
}

void vtkGLNozzleAlgorithm::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Nozzle:\n";
  this->Nozzle->PrintSelf(os, indent.GetNextIndent());
}

int vtkGLNozzleAlgorithm::RequestInformation(vtkInformation*, vtkInformationVector**,
                                             vtkInformationVector*) {
  return geolattice::checkParameters(this, [&] {
    geolattice::nozzleModel(this->Nozzle);  // both validate
    geolattice::buildPlate(this->Nozzle);
  });
}
