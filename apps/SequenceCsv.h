#pragma once
/// @file SequenceCsv.h
/// @brief sequence.csv and the collision part of report.json from the sequence-stage outputs.
#include "JsonWriter.h"

#include <string>

class vtkDataObject;
class vtkPolyData;

namespace geolattice {

/// One row per printed sub-graph in order: order, subgraph, layer, start_x/y/z, end_x/y/z (mm),
/// retraction (1 if reaching it needed a retraction). Reads the field data of
/// vtkGLPrintSequencer's outputs (SequenceOrder, SequenceStart, SequenceEnd, SubgraphLayer) and
/// the Retraction cell array of its Print Order output. Written atomically; throws
/// GeoLatticeError on missing arrays or a write failure.
void writeSequenceCsv(vtkPolyData* sequencedLattice, vtkPolyData* printOrder,
                      const std::string& path);

/// Adds collision_free (strict: no earlier material inside the nozzle anywhere),
/// order_collision_free (apart from obstacles no order can avoid), violating_stations,
/// unavoidable_stations and stations from vtkGLCollisionVerifier's field data.
void reportCollisions(vtkDataObject* verifierOutput, JsonObject& section);

}  // namespace geolattice
