#include "OutputFiles.h"

#include "GLXMLFileWriter.h"
#include "common/AtomicFile.h"
#include "common/Error.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <unistd.h>

namespace geolattice {

namespace fs = std::filesystem;

void prepareOutputDirectory(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw GeoLatticeError("cannot create output directory " + dir +
                          (ec ? ": " + ec.message() : ""));
  }
  const std::string probe =
      (fs::path(dir) / (".geolattice-write-test-" + std::to_string(::getpid()))).string();
  {
    std::ofstream out(probe);
    if (!out) {
      throw GeoLatticeError("output directory is not writable: " + dir);
    }
  }
  fs::remove(probe, ec);
}

void writeVtkXml(vtkDataObject* data, const std::string& path) {
  writeAtomically(path, [data](const std::string& tmp) { return writeXmlDataFile(data, tmp); });
}

namespace {

/// Names of every file a GeoLattice run can write into its output directory (relative paths).
bool isGeoLatticeOutput(const std::string& name) {
  static const std::regex known(
      "(tets\\.vtu|fields\\.vtu|layers\\.vtp|overhang\\.vtp|lattice\\.vtp|skeleton\\.vtp|"
      "sequence\\.vtp|sequence\\.csv|collisions\\.vtp|toolpath\\.vtp|toolpath_collisions\\.vtp|"
      "toolpath\\.pvd|toolpath/step_[0-9]{4}\\.vtp|toolpath/"
      "empty\\.vtp|print_part(_[0-9]+)?\\.script|toolpath\\.gcode|"
      "toolpath\\.ngc|waypoints\\.csv|orientation\\.csv|orientation\\.vtp|placed\\.vtp)");
  return std::regex_match(name, known);
}

}  // namespace

void OutputRecord::add(const std::string& path, double seconds) {
  const std::string name = fs::path(path).lexically_relative(dir_).generic_string();
  for (auto& f : files_) {
    if (f.first == name) {
      f.second = seconds;
      return;
    }
  }
  files_.emplace_back(name, seconds);
}

void OutputRecord::remove(const std::string& path) {
  const std::string name = fs::path(path).lexically_relative(dir_).generic_string();
  files_.erase(
      std::remove_if(files_.begin(), files_.end(), [&](const auto& f) { return f.first == name; }),
      files_.end());
}

std::vector<std::string> OutputRecord::retireStaleOutputs() const {
  std::vector<std::string> stale;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir_, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    const std::string name = it->path().lexically_relative(dir_).generic_string();
    if (name.rfind("previous", 0) == 0) {
      it.disable_recursion_pending();
      continue;
    }
    if (!it->is_regular_file(ec) || !isGeoLatticeOutput(name)) {
      continue;
    }
    bool written = false;
    for (const auto& f : files_) {
      written = written || f.first == name;
    }
    if (!written) {
      stale.push_back(name);
    }
  }
  if (stale.empty()) {
    return stale;
  }
  const fs::path previous = fs::path(dir_) / "previous";
  fs::remove_all(previous, ec);
  for (const std::string& name : stale) {
    const fs::path to = previous / name;
    fs::create_directories(to.parent_path(), ec);
    fs::rename(fs::path(dir_) / name, to, ec);
  }
  const fs::path report = fs::path(dir_) / "report.json";
  if (fs::is_regular_file(report, ec)) {
    fs::copy_file(report, previous / "report.json", fs::copy_options::overwrite_existing, ec);
  }
  fs::remove(fs::path(dir_) / "toolpath", ec);  // only if empty
  return stale;
}

}  // namespace geolattice
