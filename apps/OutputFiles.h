#pragma once
/// @file OutputFiles.h
/// @brief Writing outputs so that nothing partial is ever left behind: every file is written to
/// a temporary name in the same directory and renamed over the target only when complete.
#include <functional>
#include <string>

class vtkDataObject;

namespace geolattice {

/// Creates the directory (and its parents) if needed and checks that a file can be created in
/// it. Throws GeoLatticeError naming the directory otherwise.
void prepareOutputDirectory(const std::string& dir);

/// Calls write(tmpPath) and renames tmpPath to path on success; removes tmpPath and throws
/// GeoLatticeError on failure (write returns false or throws).
void writeAtomically(const std::string& path,
                     const std::function<bool(const std::string& tmpPath)>& write);

/// VTK XML file (.vtu/.vtp by data type) in binary inline mode (appended mode is unreadable
/// by Debian 12's ParaView 5.11, see docs/design.md), LZ4-compressed: VTK's default zlib
/// (level 5) took 25-35 s of a 1M-tet run for ~400 MB of files, LZ4 about a third of that for
/// ~20% larger files (docs/scale-run.md). VTK and ParaView read both.
void writeVtkXml(vtkDataObject* data, const std::string& path);

}  // namespace geolattice
