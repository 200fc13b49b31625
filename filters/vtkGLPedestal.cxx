#include "vtkGLPedestal.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "pedestal/Pedestal.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkGLPedestal);

namespace gl = geolattice;

namespace {
/// The core options of the filter's parameters (checked by RequestInformation), or of the
/// pedestal the orientation search chose for `input` when it carries one and UseOrientation is on.
gl::PedestalOptions pedestalOptions(vtkGLPedestal* f, vtkDataObject* input = nullptr) {
  gl::PedestalOptions o = f->GetOptions();
  vtkFieldData* fd = input ? input->GetFieldData() : nullptr;
  vtkDataArray* height = fd ? fd->GetArray(gl::arrays::OrientPedestalHeight) : nullptr;
  vtkDataArray* reach = fd ? fd->GetArray(gl::arrays::OrientPedestalContactHeight) : nullptr;
  if (f->GetUseOrientation() && height && reach && height->GetNumberOfTuples() == 1 &&
      reach->GetNumberOfTuples() == 1) {
    o.height = height->GetTuple1(0);
    o.contactHeight = reach->GetTuple1(0);
  }
  if (f->GetHeightOverride() >= 0) {
    o.height = f->GetHeightOverride();
  }
  return o;
}
}  // namespace

vtkGLPedestal::vtkGLPedestal() = default;

void vtkGLPedestal::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Height: " << this->Options.height << " mm\n";
  os << indent << "ContactHeight: " << this->Options.contactHeight << " mm\n";
  os << indent << "UseOrientation: " << (this->UseOrientation ? "on" : "off") << "\n";
  os << indent << "HeightOverride: " << this->HeightOverride << " mm\n";
}

double vtkGLPedestal::HeightFor(vtkDataObject* input) {
  return pedestalOptions(this, input).height;
}

int vtkGLPedestal::RequestInformation(vtkInformation*, vtkInformationVector**,
                                      vtkInformationVector*) {
  return gl::checkParameters(this, [&] { pedestalOptions(this).validate(); });
}

int vtkGLPedestal::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                               vtkInformationVector* outputVector) {
  // Collective in an MPI run: the whole surface on one process (vtkGLParallel.h).
  return gl::runRequest(this, inputVector, 1, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkPolyData* input = inputs.Get<vtkPolyData>(0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    const gl::PedestalOptions options = pedestalOptions(this, input);
    options.validate();
    if (options.height == 0.0) {
      output->ShallowCopy(input);  // no pedestal: the part as it is
    } else {
      const gl::PedestalResult r = gl::addPedestal(gl::toTriangleSurface(input), options);
      gl::checkAbort(this, 0.8);
      gl::fromTriangleSurface(r.surface, output);
      output->GetFieldData()->PassData(input->GetFieldData());
      gl::addFieldArray(output->GetFieldData(), gl::arrays::PedestalFootprintArea,
                        {r.footprintArea});
      gl::addFieldArray(output->GetFieldData(), gl::arrays::PedestalFootprintPieces,
                        {static_cast<double>(r.footprintPieces)});
    }
    gl::addFieldArray(output->GetFieldData(), gl::arrays::PedestalHeight, {options.height});
    this->UpdateProgress(1.0);
  });
}
