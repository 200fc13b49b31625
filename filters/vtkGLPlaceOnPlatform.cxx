#include "vtkGLPlaceOnPlatform.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "common/WorkLimit.h"
#include "mesh/HoleFilling.h"
#include "mesh/ShellNesting.h"
#include "mesh/SurfaceRepair.h"
#include "mesh/SurfaceWrap.h"
#include "placement/PlaceOnPlatform.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>
#include <vtkPoints.h>

#include <algorithm>
#include <cmath>
#include <string>

vtkStandardNewMacro(vtkGLPlaceOnPlatform);

namespace gl = geolattice;

void vtkGLPlaceOnPlatform::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scale: " << this->Options.scale << "\n";
  os << indent << "FitSize: " << this->Options.fitSize << " mm\n";
  os << indent << "CenterXY: " << (this->Options.centerXY ? "on" : "off") << "\n";
  os << indent << "FillHoles: " << (this->Options.fillHoles ? "on" : "off") << "\n";
  os << indent << "FillCavities: " << (this->Options.fillCavities ? "on" : "off") << "\n";
  os << indent << "Wrap: " << this->Options.wrap << " mm\n";
}

vtkGLPlaceOnPlatform::vtkGLPlaceOnPlatform() = default;

int vtkGLPlaceOnPlatform::ExecuteInformation(vtkInformation*, vtkInformationVector**,
                                             vtkInformationVector*) {
  return gl::checkParameters(this, [&] { this->Options.validate(); });
}

int vtkGLPlaceOnPlatform::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                      vtkInformationVector* outputVector) {
  // Collective in an MPI run: the whole model on one process (vtkGLParallel.h), because the
  // placement depends on the bounds of all points.
  return gl::runRequest(this, inputVector, 1, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkPointSet* input = inputs.Get<vtkPointSet>(0);
    vtkPointSet* output = vtkPointSet::GetData(outputVector, 0);
    if (!input || !output) {
      throw gl::GeoLatticeError("input and output must be vtkPointSet");
    }
    const gl::PlacementOptions options = this->Options;
    options.validate();
    // The holes closed first: their patches belong to the part that is placed (and wrapped: a
    // hole wider than the wrap's resolution lets the wrap inside, around the sheet). Then the
    // wrap, which replaces the surface; then the cavities filled, on the welded surface
    // (shells are told apart by shared edges).
    vtkNew<vtkPolyData> closed;
    gl::SurfaceWrapResult wrapped;
    gl::HoleFillingResult filled;
    gl::CavityFilling solid;
    vtkPolyData* surfaceInput = vtkPolyData::SafeDownCast(input);
    if ((options.wrap > 0 || options.fillHoles || options.fillCavities) && surfaceInput &&
        surfaceInput->GetNumberOfPolys() > 0) {
      gl::TriangleSurface surface = gl::toTriangleSurface(surfaceInput);
      if (options.fillHoles) {
        filled = gl::fillHoles(surface);
      }
      if (options.wrap > 0) {
        // Wrap is in mm of the placed part: in the input's units through the placement's scale.
        double b[6];
        surfaceInput->GetPoints()->GetBounds(b);
        const double s =
            gl::placeOnPlatform(gl::Vec3(b[0], b[2], b[4]), gl::Vec3(b[1], b[3], b[5]), options)
                .scale;
        wrapped = gl::wrapSurface(surface, options.wrap / s, gl::kDefaultMaxElements, s);
      }
      if (options.fillCavities) {
        gl::repairSurface(surface);
        solid = gl::fillCavities(surface);
      }
      if (wrapped.triangles > 0 || filled.holes > 0 || solid.cavities > 0) {
        gl::fromTriangleSurface(surface, closed);
        closed->GetFieldData()->PassData(input->GetFieldData());
        input = closed;
      }
    }
    vtkPoints* inPoints = input->GetPoints();
    const vtkIdType n = inPoints ? inPoints->GetNumberOfPoints() : 0;
    if (n == 0) {
      throw gl::GeoLatticeError("empty input: no points to place");
    }
    // Bounds of all points (vtkPolyData::GetBounds would skip points no cell uses).
    double b[6];
    inPoints->GetBounds(b);
    const gl::Placement placement =
        gl::placeOnPlatform(gl::Vec3(b[0], b[2], b[4]), gl::Vec3(b[1], b[3], b[5]), options);
    const double s = placement.scale;
    const gl::Vec3& t = placement.translation;

    // Double output points: the placed coordinates (e.g. min z = 0, the FitSize side) are
    // exact to double rounding even when the input is single precision.
    vtkNew<vtkPoints> outPoints;
    outPoints->SetDataTypeToDouble();
    outPoints->SetNumberOfPoints(n);
    const vtkIdType progressStep = std::max<vtkIdType>(1, n / 20);
    for (vtkIdType i = 0; i < n; ++i) {
      if (i % progressStep == 0) {
        gl::checkAbort(this, static_cast<double>(i) / static_cast<double>(n));
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
    gl::addFieldArray(output->GetFieldData(), gl::arrays::PlacementScale, {s});
    gl::addFieldArray(output->GetFieldData(), gl::arrays::PlacementTranslation,
                      {t.x(), t.y(), t.z()});
    if (options.fillHoles) {
      gl::addFieldArray(output->GetFieldData(), gl::arrays::FilledHoles,
                        {static_cast<double>(filled.holes)});
      gl::addFieldArray(output->GetFieldData(), gl::arrays::FilledHoleTriangles,
                        {static_cast<double>(filled.addedTriangles)});
    } else {  // not this placement's (e.g. a part saved from an earlier run)
      output->GetFieldData()->RemoveArray(gl::arrays::FilledHoles);
      output->GetFieldData()->RemoveArray(gl::arrays::FilledHoleTriangles);
    }
    if (options.wrap > 0) {
      gl::addFieldArray(output->GetFieldData(), gl::arrays::WrapTriangles,
                        {static_cast<double>(wrapped.triangles)});
    } else {
      output->GetFieldData()->RemoveArray(gl::arrays::WrapTriangles);
    }
    if (options.fillCavities) {
      gl::addFieldArray(output->GetFieldData(), gl::arrays::FilledCavities,
                        {static_cast<double>(solid.cavities)});
    } else {
      output->GetFieldData()->RemoveArray(gl::arrays::FilledCavities);
    }
    this->UpdateProgress(1.0);
  });
}
