#include "vtkGLPrintSummary.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "summary/PrintSummary.h"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <cstdio>
#include <string>

vtkStandardNewMacro(vtkGLPrintSummary);

namespace gl = geolattice;

namespace {

/// A field value of `data` (0 when absent).
double fieldOf(vtkDataObject* data, const char* name, int component = 0) {
  vtkDataArray* a = data ? data->GetFieldData()->GetArray(name) : nullptr;
  return a && a->GetNumberOfTuples() > 0 ? a->GetComponent(0, component) : 0.0;
}

/// The summary's input: the planner's arrays (checked by toToolpathArrays) and SubgraphId.
gl::PrintSummaryInput summaryInput(vtkPolyData* toolpath) {
  gl::ToolpathArrays a = gl::toToolpathArrays(toolpath);
  gl::PrintSummaryInput in;
  in.points.reserve(a.points.size());
  for (const gl::Vec3& p : a.points) {
    in.points.push_back({p.x(), p.y(), p.z()});
  }
  in.feedRate = std::move(a.feedRate);
  in.moveKind = std::move(a.kind);
  in.layer = std::move(a.layer);
  vtkDataArray* subgraph = toolpath->GetPointData()->GetArray(gl::arrays::SubgraphId);
  if (!subgraph) {
    throw gl::GeoLatticeError(std::string("the toolpath has no point array ") +
                              gl::arrays::SubgraphId +
                              ": connect the output of GL Toolpath Planner");
  }
  in.subgraph.resize(in.points.size());
  for (size_t i = 0; i < in.subgraph.size(); ++i) {
    in.subgraph[i] = static_cast<int>(subgraph->GetTuple1(static_cast<vtkIdType>(i)));
  }
  in.filamentLength = a.extrusion.empty() ? 0.0 : a.extrusion.back();
  if (toolpath->GetFieldData()->GetArray(gl::arrays::ToolpathFilamentDiameter)) {
    in.filamentDiameter = fieldOf(toolpath, gl::arrays::ToolpathFilamentDiameter);
  }
  return in;
}

}  // namespace

vtkGLPrintSummary::vtkGLPrintSummary() {
  this->SetNumberOfInputPorts(2);
}

void vtkGLPrintSummary::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FilamentDensity: " << this->Options.filamentDensity << " g/cm3\n";
}

int vtkGLPrintSummary::FillInputPortInformation(int port, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1) {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkGLPrintSummary::RequestInformation(vtkInformation*, vtkInformationVector**,
                                          vtkInformationVector*) {
  return gl::checkParameters(this, [&] { this->Options.validate(); });
}

int vtkGLPrintSummary::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                   vtkInformationVector* outputVector) {
  // Collective in an MPI run: the toolpath on one process (vtkGLParallel.h).
  const int n = this->GetNumberOfInputConnections(1) > 0 ? 2 : 1;  // the verifier is optional
  return gl::runRequest(this, inputVector, n, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkPolyData* toolpath = inputs.Get<vtkPolyData>(0);
    vtkPolyData* verifier = n == 2 ? inputs.Get<vtkPolyData>(1) : nullptr;
    if (!toolpath || toolpath->GetNumberOfPoints() == 0) {
      throw gl::GeoLatticeError(
          "empty input: no toolpath to summarize (connect the output of GL Toolpath Planner)");
    }
    const gl::PrintSummary s = gl::summarizePrint(summaryInput(toolpath), this->Options);

    // The strict verdict: the independent verifier's when connected, else the planner's check.
    const bool strict = verifier && verifier->GetFieldData()->GetArray(gl::arrays::CollisionFree);
    const bool collisionFree = strict ? fieldOf(verifier, gl::arrays::CollisionFree) != 0
                                      : fieldOf(toolpath, gl::arrays::ToolpathCollisionFree) != 0;
    const double colliding = strict ? fieldOf(verifier, gl::arrays::CollisionViolatingStations)
                                    : fieldOf(toolpath, gl::arrays::ToolpathUnclearedStations);
    const double plate = strict ? fieldOf(verifier, gl::arrays::CollisionPlateStations) : 0.0;
    const double stations =
        strict ? fieldOf(verifier, gl::arrays::CollisionStations) : static_cast<double>(s.points);

    vtkNew<vtkStringArray> quantity, unit, key;
    vtkNew<vtkDoubleArray> value;
    quantity->SetName("Quantity");
    value->SetName("Value");
    unit->SetName("Unit");
    key->SetName("Key");
    auto row = [&](const char* k, const char* what, double v, const char* u) {
      key->InsertNextValue(k);
      quantity->InsertNextValue(what);
      value->InsertNextValue(v);
      unit->InsertNextValue(u);
    };
    row("layers", "Layers", s.layers, "");
    row("subgraphs", "Sub-graphs", s.subgraphs, "");
    row("points", "Toolpath points", static_cast<double>(s.points), "");
    row("tours", "Tours", fieldOf(toolpath, gl::arrays::ToolpathTours), "");
    row("retractions", "Retractions", fieldOf(toolpath, gl::arrays::ToolpathRetractions), "");
    row("print_length_mm", "Print length", s.printLength, "mm");
    row("air_length_mm", "Air length", s.airLength, "mm");
    row("print_time_min", "Estimated print time", (s.printSeconds + s.airSeconds) / 60.0, "min");
    row("filament_m", "Filament length", s.filamentLength / 1000.0, "m");
    row("filament_g", "Filament mass", s.filamentMass, "g");
    row("max_axis_tilt_deg", "Largest nozzle axis tilt",
        fieldOf(toolpath, gl::arrays::ToolpathMaxAxisTilt), "deg");
    row("collision_free", strict ? "Collision-free (strict verifier)" : "Collision-free (planner)",
        collisionFree ? 1.0 : 0.0, "");
    row("colliding_stations", "Colliding stations", colliding, "");
    row("plate_stations", "Stations in the build plate", plate, "");
    row("stations", "Stations checked", stations, "");

    vtkTable* output = vtkTable::GetData(outputVector, 0);
    output->AddColumn(quantity);
    output->AddColumn(value);
    output->AddColumn(unit);
    output->AddColumn(key);

    char verdict[256];
    if (collisionFree) {
      std::snprintf(verdict, sizeof verdict,
                    "collision-free (%.0f stations checked); %d layers, %.0f min, %.1f g", stations,
                    s.layers, (s.printSeconds + s.airSeconds) / 60.0, s.filamentMass);
    } else {
      std::snprintf(verdict, sizeof verdict,
                    "COLLIDES at %.0f of %.0f stations (%.1f %%, %.0f at the build plate): no "
                    "machine program unless collisions are allowed",
                    colliding, stations, stations > 0 ? 100.0 * colliding / stations : 0.0, plate);
    }
    gl::addFieldText(output->GetFieldData(), gl::arrays::SummaryVerdict, verdict);
    this->UpdateProgress(1.0);
  });
}
