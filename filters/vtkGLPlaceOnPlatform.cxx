#include "vtkGLPlaceOnPlatform.h"

#include "vtkGLArrayNames.h"
#include "vtkGLParallel.h"

#include "common/Error.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>

#include <algorithm>
#include <cmath>
#include <string>

vtkStandardNewMacro(vtkGLPlaceOnPlatform);

void vtkGLPlaceOnPlatform::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scale: " << this->Scale << "\n";
  os << indent << "FitSize: " << this->FitSize << " mm\n";
  os << indent << "CenterXY: " << (this->CenterXY ? "on" : "off") << "\n";
}

int vtkGLPlaceOnPlatform::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                      vtkInformationVector* outputVector) {
  // Collective in an MPI run: the whole model on one process (vtkGLParallel.h), because the
  // placement depends on the bounds of all points.
  const geolattice::ParallelInputs inputs(inputVector, 1, outputVector);
  vtkPointSet* output = vtkPointSet::GetData(outputVector, 0);
  if (output && !inputs.Computes()) {
    output->Initialize();
    return 1;  // another process has the model
  }
  vtkPointSet* input = inputs.Get<vtkPointSet>(0);
  if (!input || !output) {
    vtkErrorMacro(<< "input and output must be vtkPointSet");
    return 1;
  }
  output->Initialize();
  try {
    // Negated comparisons also catch NaN.
    if (!(this->Scale > 0.0)) {
      throw geolattice::GeoLatticeError("Scale must be > 0, got " + std::to_string(this->Scale));
    }
    if (!(this->FitSize >= 0.0)) {
      throw geolattice::GeoLatticeError("FitSize must be >= 0 mm (0 = off), got " +
                                        std::to_string(this->FitSize));
    }
    vtkPoints* inPoints = input->GetPoints();
    const vtkIdType n = inPoints ? inPoints->GetNumberOfPoints() : 0;
    if (n == 0) {
      throw geolattice::GeoLatticeError("empty input: no points to place");
    }
    // Bounds of all points (vtkPolyData::GetBounds would skip points no cell uses).
    double b[6];
    inPoints->GetBounds(b);
    const double largestSide = std::max({b[1] - b[0], b[3] - b[2], b[5] - b[4]});
    double s = this->Scale;
    if (this->FitSize > 0.0) {
      if (!(largestSide > 0.0)) {
        throw geolattice::GeoLatticeError(
            "FitSize needs a model with extent: its bounding box is a single point");
      }
      s = this->FitSize / largestSide;
    }
    const double t[3] = {this->CenterXY ? -(s * (0.5 * (b[0] + b[1]))) : 0.0,
                         this->CenterXY ? -(s * (0.5 * (b[2] + b[3]))) : 0.0, -(s * b[4])};

    // Double output points: the placed coordinates (e.g. min z = 0, the FitSize side) are
    // exact to double rounding even when the input is single precision.
    vtkNew<vtkPoints> outPoints;
    outPoints->SetDataTypeToDouble();
    outPoints->SetNumberOfPoints(n);
    const vtkIdType progressStep = std::max<vtkIdType>(1, n / 20);
    for (vtkIdType i = 0; i < n; ++i) {
      if (i % progressStep == 0) {
        this->UpdateProgress(static_cast<double>(i) / static_cast<double>(n));
        if (this->GetAbortExecute()) {
          return 1;  // aborted by the user: empty output, not an error
        }
      }
      double p[3];
      inPoints->GetPoint(i, p);
      for (int k = 0; k < 3; ++k) {
        p[k] = s * p[k] + t[k];
      }
      outPoints->SetPoint(i, p);
    }

    output->CopyStructure(input);
    output->SetPoints(outPoints);
    output->GetPointData()->PassData(input->GetPointData());
    output->GetCellData()->PassData(input->GetCellData());
    output->GetFieldData()->PassData(input->GetFieldData());

    vtkNew<vtkDoubleArray> scaleArray;
    scaleArray->SetName(geolattice::arrays::PlacementScale);
    scaleArray->InsertNextValue(s);
    vtkNew<vtkDoubleArray> translationArray;
    translationArray->SetName(geolattice::arrays::PlacementTranslation);
    for (double v : t) {
      translationArray->InsertNextValue(v);
    }
    output->GetFieldData()->AddArray(scaleArray);
    output->GetFieldData()->AddArray(translationArray);
    this->UpdateProgress(1.0);
  } catch (const std::exception& e) {
    output->Initialize();
    if (!this->GetAbortExecute())  // an abort is not an error: empty output, no message
    {
      vtkErrorMacro(<< e.what());
    }
  }
  return 1;
}
