#pragma once
/// @file StageReports.h
/// @brief One report.json section per stage, read from the stage's output (field data the filters
/// write). Keys keep the names earlier versions wrote, so scripts reading report.json keep working.
#include <nlohmann/json.hpp>

class vtkDataObject;
class GLPrintPipeline;

namespace geolattice {

using Json = nlohmann::ordered_json;

/// A field-data value of `data` (0 when absent): component `component` of the first tuple.
double fieldValue(vtkDataObject* data, const char* name, int component = 0);

void reportInput(vtkDataObject* placed, bool tetMesh, Json& section);
void reportMesh(vtkDataObject* tets, bool meshed, Json& section);
/// The chosen orientation: up, rotation, candidates, seconds, before / after (colliding stations
/// as placed and chosen), evaluation tets.
void reportOrientation(vtkDataObject* oriented, Json& section);
void reportPedestal(vtkDataObject* raised, Json& section);
void reportFields(vtkDataObject* fields, Json& section);
void reportLayers(GLPrintPipeline& pipeline, vtkDataObject* layers, Json& section);
void reportOverhang(vtkDataObject* surface, Json& section);
void reportLattice(GLPrintPipeline& pipeline, vtkDataObject* lattice, Json& section);
void reportSkeleton(vtkDataObject* skeleton, Json& section);
/// The sequencer's results and the nozzle; reportCollisions adds the verifier's verdict.
void reportSequence(GLPrintPipeline& pipeline, vtkDataObject* sequenced, Json& section);
/// The toolpath parameters and results (field data of vtkGLToolpathPlanner's output).
void reportToolpath(GLPrintPipeline& pipeline, vtkDataObject* toolpath, Json& section);
/// collision_free (strict), order_collision_free, stations, violating_stations,
/// unavoidable_stations, and the layer range of the violating stations when known.
void reportCollisions(vtkDataObject* verifierOutput, Json& section);
/// GL Print Summary's table as key: value (its Key and Value columns) and "verdict" (its
/// SummaryVerdict): the numbers the GUI's spreadsheet shows.
void reportSummary(vtkDataObject* summaryTable, Json& section);
/// The robot cell and URScript parameters, and the writer's results.
void reportScript(GLPrintPipeline& pipeline, Json& section);
/// The G-code writer's parameters and results (when it wrote a file).
void reportGCode(GLPrintPipeline& pipeline, Json& section);

}  // namespace geolattice
