#pragma once
/// @file AtomicFile.h
/// @brief Writing files all-or-nothing, the one scheme every GeoLattice writer uses (core mesh
/// files, the VTK writers, the CLI's outputs): each file goes to a temporary name in its
/// target's directory (".NAME.tmp-PID") and is renamed onto its target only when complete, so an
/// error leaves no partial file and the earlier file of that name untouched.
#include "common/Error.h"

#include <deque>
#include <fstream>
#include <functional>
#include <string>

namespace geolattice {

/// A file could not be created or written (the writers report vtkErrorCode::CannotOpenFileError).
class FileWriteError : public GeoLatticeError {
public:
  using GeoLatticeError::GeoLatticeError;
};

/// The temporary name for path: ".NAME.tmp-PID" in the same directory.
std::string temporaryPathFor(const std::string& path);

/// Several files written together: all are renamed onto their targets only by commit().
class AtomicFileSet {
public:
  AtomicFileSet() = default;
  AtomicFileSet(const AtomicFileSet&) = delete;
  AtomicFileSet& operator=(const AtomicFileSet&) = delete;
  /// Removes the temporary files that were not committed.
  ~AtomicFileSet();

  /// Opens the temporary file for `path` (the earlier one is closed). Throws FileWriteError
  /// naming `path` if it cannot be created (missing directory, no permission).
  std::ostream& open(const std::string& path);
  /// Closes the files, checks that every write succeeded and renames them onto their targets.
  /// Throws FileWriteError naming the file otherwise (the temporary files are removed; a file
  /// renamed before the failing one stays written).
  void commit();

private:
  void closeLast();
  void removeTemporaries();
  struct Entry {
    std::string target, temporary;
    bool good = true;
  };
  std::deque<Entry> entries_;
  std::ofstream stream_;
};

/// One file written by a function that takes a file name (e.g. a VTK writer): calls
/// write(temporary) and renames the temporary file onto path when it returns true; removes it and
/// throws FileWriteError naming path when write returns false, and rethrows what write throws.
void writeAtomically(const std::string& path,
                     const std::function<bool(const std::string& temporaryPath)>& write);

}  // namespace geolattice
