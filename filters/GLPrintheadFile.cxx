#include "GLPrintheadFile.h"

#include "vtkGLMeshConversion.h"
#include "vtkGLMeshReader.h"

#include "common/Error.h"

#include <vtkNew.h>
#include <vtkPolyData.h>

#include <filesystem>
#include <map>
#include <mutex>
#include <tuple>

namespace geolattice {

std::shared_ptr<const Printhead> readPrintheadFile(const std::string& path) {
  using Version = std::tuple<std::string, std::uintmax_t, std::filesystem::file_time_type>;
  static std::mutex mutex;
  static std::map<Version, std::shared_ptr<const Printhead>> cache;

  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  const auto time = std::filesystem::last_write_time(path, ec);
  const Version version{path, ec ? 0 : size, ec ? std::filesystem::file_time_type{} : time};
  {
    const std::lock_guard<std::mutex> lock(mutex);
    const auto it = cache.find(version);
    if (!ec && it != cache.end()) {
      return it->second;
    }
  }
  vtkNew<vtkGLMeshReader> reporter;  // receives the inner readers' progress and warnings
  vtkNew<vtkPolyData> poly;
  try {
    vtkGLMeshReader::ReadSurfaceFile(path, poly, reporter);
  } catch (const GeoLatticeError& e) {
    throw GeoLatticeError(std::string("printhead file: ") + e.what());
  }
  auto printhead = std::make_shared<const Printhead>(toTriangleSurface(poly), path);
  const std::lock_guard<std::mutex> lock(mutex);
  if (cache.size() > 16) {
    cache.clear();  // a few printheads per session; never grows without bound
  }
  cache[version] = printhead;
  return printhead;
}

}  // namespace geolattice
