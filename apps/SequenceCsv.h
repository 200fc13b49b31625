#pragma once
/// @file SequenceCsv.h
/// @brief sequence.csv from the sequence-stage outputs.
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

}  // namespace geolattice
