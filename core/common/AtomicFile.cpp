#include "common/AtomicFile.h"

#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace geolattice {

namespace fs = std::filesystem;

std::string temporaryPathFor(const std::string& path) {
  const fs::path target(path);
  return (target.parent_path() /
          ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid())))
      .string();
}

AtomicFileSet::~AtomicFileSet() {
  removeTemporaries();
}

void AtomicFileSet::closeLast() {
  if (stream_.is_open()) {
    stream_.flush();
    entries_.back().good = static_cast<bool>(stream_);
    stream_.close();
    entries_.back().good = entries_.back().good && !stream_.fail();
  }
}

void AtomicFileSet::removeTemporaries() {
  if (stream_.is_open()) {
    stream_.close();
  }
  std::error_code ec;
  for (const Entry& e : entries_) {
    if (!e.temporary.empty()) {
      fs::remove(e.temporary, ec);
    }
  }
  entries_.clear();
}

std::ostream& AtomicFileSet::open(const std::string& path) {
  closeLast();
  if (path.empty()) {
    throw GeoLatticeError("no file name given");
  }
  Entry e;
  e.target = path;
  e.temporary = temporaryPathFor(path);
  stream_.clear();
  stream_.open(e.temporary, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!stream_) {
    stream_.clear();
    throw FileWriteError("cannot create " + path + " (missing directory or no permission)");
  }
  entries_.push_back(e);
  return stream_;
}

void AtomicFileSet::commit() {
  closeLast();
  for (const Entry& e : entries_) {
    if (!e.good) {
      const std::string target = e.target;
      removeTemporaries();
      throw FileWriteError("could not write " + target + " (disk full?)");
    }
  }
  for (Entry& e : entries_) {
    std::error_code ec;
    fs::rename(e.temporary, e.target, ec);
    if (ec) {
      const std::string target = e.target;
      removeTemporaries();
      throw FileWriteError("could not write " + target + ": " + ec.message());
    }
    e.temporary.clear();
  }
  entries_.clear();
}

void writeAtomically(const std::string& path,
                     const std::function<bool(const std::string&)>& write) {
  const std::string tmp = temporaryPathFor(path);
  bool ok = false;
  try {
    ok = write(tmp);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  std::error_code ec;
  if (ok) {
    fs::rename(tmp, path, ec);
  }
  if (!ok || ec) {
    std::string why = ec ? ": " + ec.message() : "";
    // A writer that only says it failed: name a full device, the common cause (measured before
    // the partial file is removed).
    std::error_code spaceError;
    const fs::space_info space =
        fs::space(fs::absolute(path, spaceError).parent_path(), spaceError);
    if (!ok && !spaceError && space.available < (1u << 20)) {
      why =
          ": no space left on the device (" + std::to_string(space.available / 1024) + " KiB free)";
    }
    fs::remove(tmp, ec);
    throw FileWriteError("could not write " + path + why);
  }
}

}  // namespace geolattice
