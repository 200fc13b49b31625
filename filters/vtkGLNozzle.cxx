#include "vtkGLNozzle.h"

#include "nozzle/NozzleModel.h"

#include <vtkObjectFactory.h>

#include <cmath>

vtkStandardNewMacro(vtkGLNozzle);

vtkGLNozzle::vtkGLNozzle() {
  const geolattice::NozzleModel defaults;  // the one place the defaults live
  this->NozzleAngle = defaults.halfAngleDeg;
  this->NozzleLength = std::isfinite(defaults.length) ? defaults.length : 0.0;
  this->HolderRadius = defaults.holderRadius;
  this->TipClearance = defaults.tipClearance;
  this->TipFaceRadius = defaults.tipFaceRadius;
}

void vtkGLNozzle::CopyParameters(vtkGLNozzle* other) {
  if (!other) {
    return;
  }
  this->SetNozzleAngle(other->NozzleAngle);
  this->SetNozzleLength(other->NozzleLength);
  this->SetHolderRadius(other->HolderRadius);
  this->SetTipClearance(other->TipClearance);
  this->SetTipFaceRadius(other->TipFaceRadius);
}

void vtkGLNozzle::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NozzleAngle: " << this->NozzleAngle << " deg\n";
  os << indent << "NozzleLength: " << this->NozzleLength << " mm\n";
  os << indent << "HolderRadius: " << this->HolderRadius << " mm\n";
  os << indent << "TipClearance: " << this->TipClearance << " mm\n";
  os << indent << "TipFaceRadius: " << this->TipFaceRadius << " mm\n";
}
