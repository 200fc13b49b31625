#ifndef GLXMLFileWriter_h
#define GLXMLFileWriter_h
/**
 * @file GLXMLFileWriter.h
 * @brief One VTK XML file (.vtu for an unstructured grid, .vtp for polydata) in binary inline
 * mode, LZ4-compressed, as VTK's own writers write it, byte for byte, but faster.
 *
 * Binary inline mode because Debian 12's ParaView 5.11 cannot read appended files
 * (docs/design.md); LZ4 because zlib took about three times as long at 1M tets
 * (docs/scale-run.md). VTK's base64 encoder hands the file stream 4 characters at a time (one
 * stream call per 3 bytes, most of a file's time); here the base64 characters go to the stream
 * in 48 KiB blocks, encoded by a table loop that writes the characters vtkBase64Utilities writes
 * (Debian's build of it makes a checked function call per character), so the file is the same
 * (test GLXMLFileWriter.SameBytesAsVtksWriter).
 */
#include "GeoLatticeFiltersModule.h"

#include <string>

class vtkDataObject;

namespace geolattice {

/// Writes data (vtkUnstructuredGrid or vtkPolyData) to file. Returns false when VTK's writer
/// reports a failure (e.g. the file cannot be opened); throws GeoLatticeError for another
/// data type. Caches one-component arrays' ranges in their information (vtkDataArray::GetRange
/// returns the same numbers). bufferedBase64 false: VTK's own encoder and ranges, the data
/// untouched (for comparison in tests).
GEOLATTICEFILTERS_EXPORT bool writeXmlDataFile(vtkDataObject* data, const std::string& file,
                                               bool bufferedBase64 = true);

}  // namespace geolattice
#endif
