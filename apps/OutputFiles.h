#pragma once
/// @file OutputFiles.h
/// @brief The CLI's output directory and its VTK XML files; every file is written all-or-nothing
/// through core/common/AtomicFile.h.
#include "common/AtomicFile.h"

#include <string>
#include <utility>
#include <vector>

class vtkDataObject;

namespace geolattice {

/// Creates the directory (and its parents) if needed and checks that a file can be created in
/// it. Throws GeoLatticeError naming the directory otherwise.
void prepareOutputDirectory(const std::string& dir);

/// VTK XML file (.vtu/.vtp by data type), written all-or-nothing (a temporary file renamed over
/// path) by filters/GLXMLFileWriter.h: binary inline mode (appended mode is unreadable by Debian
/// 12's ParaView 5.11, see docs/design.md), LZ4-compressed (VTK's default zlib, level 5, took
/// 25-35 s of a 1M-tet run for ~400 MB of files, LZ4 about a third of that for ~20% larger
/// files, docs/scale-run.md). VTK and ParaView read both.
void writeVtkXml(vtkDataObject* data, const std::string& path);

/// The files one run writes into its output directory, with the seconds each took. At the end
/// of a run (finished or failed) every GeoLattice output of an earlier run that this run did not
/// write again is moved into OUTDIR/previous/ (with the earlier report.json), replacing what an
/// older run left there: the directory itself then holds exactly this run's files, so it never
/// holds a program that does not belong to its report.json.
class OutputRecord {
public:
  explicit OutputRecord(std::string outDir) : dir_(std::move(outDir)) {}
  /// Records `path` (written now, `seconds` long); a path recorded twice keeps the later time.
  void add(const std::string& path, double seconds);
  /// Takes `path` out of the record (a file that was to be written and was not).
  void remove(const std::string& path);
  /// The recorded files, relative to the output directory, in the order first written.
  const std::vector<std::pair<std::string, double>>& files() const { return files_; }
  /// Moves the earlier run's outputs this run did not write into previous/; returns their
  /// names (relative to the output directory). Call before writing report.json.
  std::vector<std::string> retireStaleOutputs() const;

private:
  std::string dir_;
  std::vector<std::pair<std::string, double>> files_;
};

}  // namespace geolattice
