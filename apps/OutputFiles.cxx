#include "OutputFiles.h"

#include "common/Error.h"

#include <vtkDataObject.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
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

void writeAtomically(const std::string& path,
                     const std::function<bool(const std::string&)>& write) {
  const fs::path target(path);
  const std::string tmp = (target.parent_path() / ("." + target.filename().string() + ".tmp-" +
                                                   std::to_string(::getpid())))
                              .string();
  bool ok = false;
  try {
    ok = write(tmp);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  std::error_code ec;
  if (ok) {
    fs::rename(tmp, target, ec);
  }
  if (!ok || ec) {
    fs::remove(tmp, ec);
    throw GeoLatticeError("could not write " + path);
  }
}

void writeVtkXml(vtkDataObject* data, const std::string& path) {
  writeAtomically(path, [data](const std::string& tmp) {
    if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data)) {
      vtkNew<vtkXMLUnstructuredGridWriter> writer;
      writer->SetInputData(grid);
      writer->SetDataModeToBinary();
      writer->SetCompressorTypeToLZ4();
      writer->SetFileName(tmp.c_str());
      return writer->Write() == 1;
    }
    if (auto* poly = vtkPolyData::SafeDownCast(data)) {
      vtkNew<vtkXMLPolyDataWriter> writer;
      writer->SetInputData(poly);
      writer->SetDataModeToBinary();
      writer->SetCompressorTypeToLZ4();
      writer->SetFileName(tmp.c_str());
      return writer->Write() == 1;
    }
    throw GeoLatticeError("cannot write a " + std::string(data ? data->GetClassName() : "null") +
                          " to " + tmp);
  });
}

}  // namespace geolattice
