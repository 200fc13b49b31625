#include "vtkGLMeshReader.h"

#include "vtkGLMeshConversion.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "io/MeshReader.h"

#include <vtkCellArray.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellType.h>
#include <vtkCommand.h>
#include <vtkDataObject.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <utility>

vtkStandardNewMacro(vtkGLMeshReader);

namespace {
namespace gl = geolattice;
// Surfaces first, then tet meshes; kNumSurfaceExtensions splits the list.
constexpr const char* kExtensions[] = {".stl", ".obj", ".ply",  ".vtp", ".off",
                                       ".vtu", ".tet", ".node", ".ele"};
constexpr int kNumExtensions = static_cast<int>(sizeof(kExtensions) / sizeof(kExtensions[0]));
constexpr int kNumSurfaceExtensions = 5;
constexpr const char* kExtensionsString = ".stl .obj .ply .vtp .off .vtu .tet .node .ele";

/// Lower-case extension with its dot ("" if none).
std::string lowerExtension(const char* path) {
  if (!path) {
    return {};
  }
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

int extensionIndex(const char* path) {
  const std::string ext = lowerExtension(path);
  for (int i = 0; i < kNumExtensions; ++i) {
    if (ext == kExtensions[i]) {
      return i;
    }
  }
  return -1;
}

/// Collects the error and warning events of an inner reader (and of its executive) so that
/// this reader reports them once, under its own name, instead of the inner objects printing them.
class ErrorCollector : public vtkCommand {
public:
  static ErrorCollector* New() { return new ErrorCollector; }
  vtkTypeMacro(ErrorCollector, vtkCommand);

  void Execute(vtkObject*, unsigned long event, void* callData) override {
    const bool error = event == vtkCommand::ErrorEvent;
    if (!error && event != vtkCommand::WarningEvent) {
      return;
    }
    std::string& first = error ? this->FirstError : this->FirstWarning;
    this->ErrorCount += error ? 1 : 0;
    if (first.empty() && callData) {
      // "vtkSTLReader (0x...): message" -> "message"
      std::string text = static_cast<const char*>(callData);
      const size_t colon = text.find("): ");
      if (colon != std::string::npos) {
        text = text.substr(colon + 3);
      }
      while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) {
        text.pop_back();
      }
      // The executive's "Algorithm ... returned failure for request: <info dump>" says nothing
      // the reader's own message or warning does not say better.
      if (text.rfind("Algorithm ", 0) != 0 || text.find("returned failure") == std::string::npos) {
        first = text;
      }
    }
  }

  /// Observe errors and warnings of `object`; returns the two observer tags.
  std::pair<unsigned long, unsigned long> Watch(vtkObject* object) {
    return {object->AddObserver(vtkCommand::ErrorEvent, this),
            object->AddObserver(vtkCommand::WarningEvent, this)};
  }

  int ErrorCount = 0;
  std::string FirstError;
  std::string FirstWarning;
};

/// Runs a VTK algorithm, turning any error it reports into a GeoLatticeError. Errors are seen
/// through ErrorEvents (only emitted while vtkObject::GlobalWarningDisplay is on), the error
/// code, and for the XML readers their parser's errors. Warnings of a failing reader (e.g.
/// "Could not open PLY file") go into the error message; the first warning of a successful
/// one is passed on as a warning of `reporter` (this reader). The algorithm's progress is
/// forwarded as [lo, hi] of the reporter's, and the reporter's abort flag to the algorithm.
void runChecked(vtkAlgorithm* algorithm, const std::string& path, vtkAlgorithm* reporter, double lo,
                double hi) {
  vtkNew<ErrorCollector> errors;
  const auto tags = errors->Watch(algorithm);
  const auto executiveTags = errors->Watch(algorithm->GetExecutive());
  if (auto* xml = vtkXMLReader::SafeDownCast(algorithm)) {
    xml->SetReaderErrorObserver(errors);
    xml->SetParserErrorObserver(errors);
  }
  struct Forward {
    vtkAlgorithm* Reporter;
    double Lo, Hi;
  } forward{reporter, lo, hi};
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&forward);
  progress->SetCallback([](vtkObject* caller, unsigned long, void* client, void* call) {
    const Forward& f = *static_cast<Forward*>(client);
    const double p = call ? *static_cast<double*>(call) : 0.0;
    if (!f.Reporter->GetAbortExecute())  // after an abort, nothing more to report
    {
      f.Reporter->UpdateProgress(f.Lo + (f.Hi - f.Lo) * std::clamp(p, 0.0, 1.0));
    }
    if (f.Reporter->GetAbortExecute()) {
      static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    }
  });
  const unsigned long progressTag = algorithm->AddObserver(vtkCommand::ProgressEvent, progress);
  algorithm->Update();
  algorithm->RemoveObserver(progressTag);
  algorithm->RemoveObserver(tags.first);
  algorithm->RemoveObserver(tags.second);
  algorithm->GetExecutive()->RemoveObserver(executiveTags.first);
  algorithm->GetExecutive()->RemoveObserver(executiveTags.second);
  if (auto* xml = vtkXMLReader::SafeDownCast(algorithm)) {
    xml->SetReaderErrorObserver(nullptr);
    xml->SetParserErrorObserver(nullptr);
  }
  if (reporter->GetAbortExecute()) {
    throw geolattice::GeoLatticeError(
        "reading aborted");  // the inner reader may have stopped early
  }
  if (errors->ErrorCount > 0 || algorithm->GetErrorCode() != vtkErrorCode::NoError) {
    std::string reason = errors->FirstError;
    if (!errors->FirstWarning.empty()) {
      reason += (reason.empty() ? "" : " (") + errors->FirstWarning + (reason.empty() ? "" : ")");
    }
    if (reason.empty()) {
      reason = vtkErrorCode::GetStringFromErrorCode(algorithm->GetErrorCode());
    }
    throw geolattice::GeoLatticeError(std::string(algorithm->GetClassName()) + " cannot read " +
                                      path + ": " + reason);
  }
  if (!errors->FirstWarning.empty()) {
    vtkWarningWithObjectMacro(reporter, << algorithm->GetClassName() << " reading " << path << ": "
                                        << errors->FirstWarning);
  }
}

/// Throws if a cell refers to a point that does not exist. VTK readers do not all check this
/// (vtkOBJReader keeps "f 1 2 3 9" of a 3-vertex file as a polygon with point id 8), and the
/// filters downstream would read out of bounds.
void checkPointIds(vtkCellArray* cells, vtkIdType numPoints, const char* cellName,
                   const std::string& path) {
  if (!cells) {
    return;
  }
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  vtkIdType cell = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k < n; ++k) {
      if (ids[k] < 0 || ids[k] >= numPoints) {
        throw geolattice::GeoLatticeError("index out of range: " + std::string(cellName) + " " +
                                          std::to_string(cell) + " of " + path + " uses point " +
                                          std::to_string(ids[k]) + " (0-based), but there are " +
                                          std::to_string(numPoints) + " points");
      }
    }
  }
}

/// A binary STL is an 80-byte header, a 4-byte triangle count n and 50 bytes per triangle: the
/// count must match the file size before anything is allocated (a garbage file would otherwise
/// ask for billions of triangles). A file that starts with "solid" and does not match is ASCII.
void checkBinaryStl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char head[84] = {};
  in.read(head, sizeof head);
  const std::streamsize got = in.gcount();
  in.clear();  // a file shorter than the header left eof and fail set: tellg() would say -1
  in.seekg(0, std::ios::end);
  const auto size = static_cast<unsigned long long>(in.tellg());
  const bool solid = got >= 5 && std::string(head, 5) == "solid";
  if (got < 84) {
    if (!solid) {
      throw geolattice::GeoLatticeError("not an STL file: " + path + " has " +
                                        std::to_string(size) +
                                        " bytes, less than a binary STL header (84 bytes)");
    }
    return;
  }
  std::uint32_t n = 0;
  std::memcpy(&n, head + 80, 4);  // little endian, as the format says (and this machine is)
  const unsigned long long expected = 84ull + 50ull * n;
  if (expected == size) {
    return;  // a consistent binary STL (even if its header happens to start with "solid")
  }
  if (solid) {
    return;  // ASCII
  }
  throw geolattice::GeoLatticeError("not a valid binary STL: " + path + " says " +
                                    std::to_string(n) + " triangles (" + std::to_string(expected) +
                                    " bytes) but has " + std::to_string(size) +
                                    " bytes (truncated, or not an STL file)");
}

/// Refuses NaN or infinite coordinates, naming the first such vertex (they would end as
/// zero-volume tets or "intersecting facets", pointing at the wrong problem).
void checkFinitePoints(vtkPointSet* data, const std::string& path) {
  vtkPoints* points = data->GetPoints();
  for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i) {
    double p[3];
    points->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      throw geolattice::GeoLatticeError("non-finite coordinates in " + path + ": vertex " +
                                        std::to_string(i) + " is (" + std::to_string(p[0]) + ", " +
                                        std::to_string(p[1]) + ", " + std::to_string(p[2]) + ")");
    }
  }
}

/// Surface formats -> triangles only, coincident points merged.
void readSurface(const std::string& path, const std::string& ext, vtkPolyData* output,
                 vtkAlgorithm* reporter) {
  vtkNew<vtkPolyData> raw;
  if (ext == ".off" || ext == ".obj") {
    // Core's readers: errors name the line; VTK's OBJ reader keeps the previous vertex for a
    // coordinate it cannot parse and reads past its arrays on a face's out-of-range texture
    // coordinate or normal index (heap corruption), where core ignores those references.
    geolattice::fromTriangleSurface(
        ext == ".off" ? geolattice::readOff(path) : geolattice::readObj(path), raw);
    checkFinitePoints(raw, path);
  } else {
    vtkSmartPointer<vtkAlgorithm> reader;
    if (ext == ".stl") {
      checkBinaryStl(path);
      auto stl = vtkSmartPointer<vtkSTLReader>::New();
      stl->SetFileName(path.c_str());
      stl->MergingOn();
      stl->ScalarTagsOff();
      reader = stl;
    } else if (ext == ".ply") {
      auto ply = vtkSmartPointer<vtkPLYReader>::New();
      ply->SetFileName(path.c_str());
      reader = ply;
    } else {
      auto vtp = vtkSmartPointer<vtkXMLPolyDataReader>::New();
      vtp->SetFileName(path.c_str());
      reader = vtp;
    }
    runChecked(reader, path, reporter, 0.02, 0.6);
    vtkPolyData* read = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
    if (!read) {
      throw geolattice::GeoLatticeError(std::string(reader->GetClassName()) +
                                        " gave no polydata for " + path);
    }
    raw->ShallowCopy(read);
    checkFinitePoints(raw, path);
    checkPointIds(raw->GetPolys(), raw->GetNumberOfPoints(), "polygon", path);
    checkPointIds(raw->GetStrips(), raw->GetNumberOfPoints(), "triangle strip", path);
  }
  gl::checkAbort(reporter, 0.6);
  vtkSmartPointer<vtkAlgorithm> clean = gl::newSurfaceCleaner(raw);
  runChecked(clean, path, reporter, 0.6, 0.95);
  vtkPolyData* cleaned = vtkPolyData::SafeDownCast(clean->GetOutputDataObject(0));
  if (cleaned->GetNumberOfPolys() == 0) {
    throw geolattice::GeoLatticeError("empty mesh: " + path + " has no triangles");
  }
  output->ShallowCopy(cleaned);
}

/// Refuses an unsupported extension (listing `supported`), a missing or irregular file.
void requireReadableFile(const std::string& path, const std::string& supported) {
  const std::string ext = lowerExtension(path.c_str());
  if (ext.empty() || (" " + supported + " ").find(" " + ext + " ") == std::string::npos) {
    throw geolattice::GeoLatticeError("unsupported file extension '" + ext + "' of " + path +
                                      "; supported: " + supported);
  }
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw geolattice::GeoLatticeError("file not found: " + path);
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw geolattice::GeoLatticeError("not a regular file: " + path);
  }
}

/// Tet formats -> VTK_TETRA cells only.
void readTetMesh(const std::string& path, const std::string& ext, vtkUnstructuredGrid* output,
                 vtkAlgorithm* reporter) {
  if (ext == ".tet" || ext == ".node" || ext == ".ele") {
    const geolattice::TetMesh mesh =
        ext == ".tet" ? geolattice::readTetFile(path) : geolattice::readTetGenMesh(path);
    gl::checkAbort(reporter, 0.8);
    geolattice::fromTetMesh(mesh, output);
    checkFinitePoints(output, path);
    return;
  }
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  runChecked(reader, path, reporter, 0.02, 0.8);
  gl::checkAbort(reporter, 0.8);
  vtkUnstructuredGrid* grid = reader->GetOutput();
  if (grid->GetNumberOfCells() == 0 || grid->GetNumberOfPoints() == 0) {
    throw geolattice::GeoLatticeError("empty mesh: " + path + " has " +
                                      std::to_string(grid->GetNumberOfPoints()) + " points and " +
                                      std::to_string(grid->GetNumberOfCells()) + " cells");
  }
  checkPointIds(grid->GetCells(), grid->GetNumberOfPoints(), "cell", path);
  checkFinitePoints(grid, path);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    if (grid->GetCellType(c) != VTK_TETRA) {
      throw geolattice::GeoLatticeError("cell " + std::to_string(c) + " of " + path +
                                        " is not a linear tetrahedron (VTK cell type " +
                                        std::to_string(grid->GetCellType(c)) +
                                        "); only tet meshes are accepted");
    }
  }
  output->ShallowCopy(grid);
}
}  // namespace

vtkGLMeshReader::vtkGLMeshReader() {
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

vtkGLMeshReader::~vtkGLMeshReader() {
  this->SetFileName(nullptr);
}

void vtkGLMeshReader::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}

void vtkGLMeshReader::ReadSurfaceFile(const std::string& path, vtkPolyData* output,
                                      vtkAlgorithm* reporter) {
  std::string surfaces;
  for (int i = 0; i < kNumSurfaceExtensions; ++i) {
    surfaces += std::string(i ? " " : "") + kExtensions[i];
  }
  requireReadableFile(path, surfaces);
  readSurface(path, lowerExtension(path.c_str()), output, reporter);
}

int vtkGLMeshReader::GetNumberOfSupportedExtensions() {
  return kNumExtensions;
}

const char* vtkGLMeshReader::GetSupportedExtension(int i) {
  return (i >= 0 && i < kNumExtensions) ? kExtensions[i] : nullptr;
}

const char* vtkGLMeshReader::GetSupportedExtensionsString() {
  return kExtensionsString;
}

bool vtkGLMeshReader::IsSupportedFile(const char* path) {
  return extensionIndex(path) >= 0;
}

bool vtkGLMeshReader::IsTetMeshFile(const char* path) {
  return extensionIndex(path) >= kNumSurfaceExtensions;
}

int vtkGLMeshReader::CanReadFile(const char* path) {
  std::error_code ec;
  return IsSupportedFile(path) && std::filesystem::is_regular_file(path, ec) ? 1 : 0;
}

int vtkGLMeshReader::RequestDataObject(vtkInformation*, vtkInformationVector**,
                                       vtkInformationVector* outputVector) {
  // Unsupported or missing names get an (empty) polydata; RequestData reports the error.
  const int type = IsTetMeshFile(this->FileName) ? VTK_UNSTRUCTURED_GRID : VTK_POLY_DATA;
  return vtkDataObjectAlgorithm::SetOutputDataObject(type, outputVector->GetInformationObject(0),
                                                     /*exact=*/true)
             ? 1
             : 0;
}

int vtkGLMeshReader::RequestData(vtkInformation*, vtkInformationVector**,
                                 vtkInformationVector* outputVector) {
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  return gl::runRequest(this, outputVector, [&] {
    if (!this->FileName || this->FileName[0] == '\0') {
      throw geolattice::GeoLatticeError("no file name set (FileName is empty)");
    }
    const std::string path = this->FileName;
    const std::string ext = lowerExtension(this->FileName);
    requireReadableFile(path, kExtensionsString);
    gl::checkAbort(this, 0.01);
    if (IsTetMeshFile(this->FileName)) {
      vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(output);
      if (!grid) {
        throw geolattice::GeoLatticeError("internal error: output is not an unstructured grid");
      }
      readTetMesh(path, ext, grid, this);
    } else {
      vtkPolyData* poly = vtkPolyData::SafeDownCast(output);
      if (!poly) {
        throw geolattice::GeoLatticeError("internal error: output is not polydata");
      }
      readSurface(path, ext, poly, this);
    }
    this->UpdateProgress(1.0);
  });
}
