#include "BaseContactReport.h"

#include "StageReports.h"

#include "GLPrintPipeline.h"
#include "orient/AutoOrient.h"
#include "vtkGLArrayNames.h"
#include "vtkGLAutoOrient.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLPedestal.h"

#include <vtkPolyData.h>

#include <sstream>

namespace geolattice {

std::string reportBaseContact(GLPrintPipeline& pipeline, vtkDataObject* overhang, Json& section) {
  double area = fieldValue(overhang, arrays::OverhangBaseArea);
  if (!pipeline.GetTetMeshInput()) {
    if (auto* meshed = vtkPolyData::SafeDownCast(pipeline.Pedestal->GetOutputDataObject(0))) {
      area = baseContactArea(toTriangleSurface(meshed), Eigen::Matrix3d::Identity(),
                             OrientOptions{}.contactHeight);
    }
  }
  const double least = pipeline.Orientation->GetMinBaseArea();
  section["base_contact_mm2"] = area;
  section["small_base"] = area < least;
  if (!(area < least)) {
    return "";
  }
  std::ostringstream w;
  w << "geolattice: warning: the part touches the plate on " << area
    << " mm^2 only (less than --min-base-area " << least
    << " mm^2): it may come loose while printing; "
    << (pipeline.Orientation->GetOrient() == vtkGLAutoOrient::AUTO
            ? "a brim, glue or a clamp holds it"
            : "--orient auto looks for a side with more contact")
    << "\n";
  return w.str();
}

}  // namespace geolattice
