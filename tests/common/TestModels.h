#pragma once
/// @file TestModels.h
/// @brief Where a test finds a model: the repository's testdata/ (GEOLATTICE_TESTDATA), else the
/// shared models of the development machine; "" when neither has it (the test then skips).
#include <filesystem>
#include <string>

inline std::string testModel(const std::string& name) {
  for (const std::string& dir :
       {std::string(GEOLATTICE_TESTDATA), std::string("/work/shared/testdata")}) {
    if (std::filesystem::exists(dir + "/" + name)) {
      return dir + "/" + name;
    }
  }
  return "";
}
