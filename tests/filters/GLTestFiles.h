#ifndef GLTestFiles_h
#define GLTestFiles_h
/**
 * @file GLTestFiles.h
 * @brief Test helpers for the writers: a fresh temporary directory, its sorted listing (to see
 * that no temporary or partial file is left) and a file's text.
 */
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

/// A fresh empty directory under the system's temporary directory.
inline std::filesystem::path glFreshDirectory(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("geolattice-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The file names in dir, sorted.
inline std::vector<std::string> glListDirectory(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    names.push_back(e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

inline std::string glReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

#endif
