#include "vtkGLNozzle.h"

#include "nozzle/BuildPlate.h"
#include "nozzle/NozzleModel.h"

#include <vtkObjectFactory.h>

#include <cmath>

vtkStandardNewMacro(vtkGLNozzle);

vtkGLNozzle::vtkGLNozzle() {
  const geolattice::NozzleModel defaults;  // the one place the defaults live
  this->NozzleAngle = defaults.halfAngleDeg;
  this->NozzleLength = std::isfinite(defaults.length) ? defaults.length : 0.0;
  this->HolderRadius = defaults.holderRadius;
  this->HolderLength = std::isfinite(defaults.holderLength) ? defaults.holderLength : 0.0;
  this->TipClearance = defaults.tipClearance;
  this->TipFaceRadius = defaults.tipFaceRadius;
  this->FaceContact = defaults.faceContact;
  const geolattice::BuildPlate plate;
  this->BuildPlate = plate.enabled;
  this->PlateMargin = plate.margin;
  this->PlateThickness = plate.thickness;
}

vtkGLNozzle::~vtkGLNozzle() {
  this->SetPrintheadFile(nullptr);
}

void vtkGLNozzle::CopyParameters(vtkGLNozzle* other) {
  if (!other) {
    return;
  }
  this->SetNozzleAngle(other->NozzleAngle);
  this->SetNozzleLength(other->NozzleLength);
  this->SetHolderRadius(other->HolderRadius);
  this->SetHolderLength(other->HolderLength);
  this->SetTipClearance(other->TipClearance);
  this->SetTipFaceRadius(other->TipFaceRadius);
  this->SetFaceContact(other->FaceContact);
  this->SetBuildPlate(other->BuildPlate);
  this->SetPlateMargin(other->PlateMargin);
  this->SetPlateThickness(other->PlateThickness);
  this->SetPrintheadFile(other->PrintheadFile);
}

void vtkGLNozzle::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NozzleAngle: " << this->NozzleAngle << " deg\n";
  os << indent << "NozzleLength: " << this->NozzleLength << " mm\n";
  os << indent << "HolderRadius: " << this->HolderRadius << " mm\n";
  os << indent << "HolderLength: " << this->HolderLength << " mm\n";
  os << indent << "TipClearance: " << this->TipClearance << " mm\n";
  os << indent << "TipFaceRadius: " << this->TipFaceRadius << " mm\n";
  os << indent << "FaceContact: " << this->FaceContact << " mm\n";
  os << indent << "BuildPlate: " << (this->BuildPlate ? "on" : "off") << "\n";
  os << indent << "PlateMargin: " << this->PlateMargin << " mm\n";
  os << indent << "PlateThickness: " << this->PlateThickness << " mm\n";
  os << indent << "PrintheadFile: " << (this->PrintheadFile ? this->PrintheadFile : "(none)")
     << "\n";
}
