#ifndef vtkGLOutputFiles_h
#define vtkGLOutputFiles_h
/**
 * @file vtkGLOutputFiles.h
 * @brief Writing one or more files all-or-nothing, for the GeoLattice writers: each file goes to
 * a temporary name in its target's directory (".NAME.tmp-PID", as apps/OutputFiles.h) and all
 * are renamed onto their targets only by commit(), so an error leaves no partial file and the
 * earlier files of those names untouched.
 */
#include "common/Error.h"

#include <deque>
#include <fstream>
#include <string>

class vtkInformation;
class vtkInformationVector;

namespace geolattice {

/// A file could not be created or written (the writers report vtkErrorCode::CannotOpenFileError).
class FileWriteError : public GeoLatticeError {
public:
  using GeoLatticeError::GeoLatticeError;
};

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

/// The temporary name for path: ".NAME.tmp-PID" in the same directory.
std::string temporaryPathFor(const std::string& path);

/// For a writer's REQUEST_UPDATE_EXTENT: asks input port 0 for the end of its time range (the
/// last TIME_STEPS value, else the end of TIME_RANGE) if it has one, so a time-dependent
/// toolpath (the planner's print replay) is written whole whatever the pipeline time.
void requestEndOfTimeRange(vtkInformationVector** inputVector);

}  // namespace geolattice
#endif
