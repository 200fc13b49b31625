#include "vtkGLMeshReader.h"

#include "vtkGLMeshConversion.h"

#include "common/Error.h"
#include "io/MeshFileIO.h"

#include <vtkCellType.h>
#include <vtkCleanPolyData.h>
#include <vtkCommand.h>
#include <vtkDataObject.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkObjectFactory.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <system_error>

vtkStandardNewMacro(vtkGLMeshReader);

namespace
{
// Surfaces first, then tet meshes; kNumSurfaceExtensions splits the list.
constexpr const char* kExtensions[] = { ".stl", ".obj", ".ply", ".vtp", ".off", ".vtu", ".tet",
  ".node", ".ele" };
constexpr int kNumExtensions = static_cast<int>(sizeof(kExtensions) / sizeof(kExtensions[0]));
constexpr int kNumSurfaceExtensions = 5;
constexpr const char* kExtensionsString = ".stl .obj .ply .vtp .off .vtu .tet .node .ele";

/// Lower-case extension with its dot ("" if none).
std::string lowerExtension(const char* path)
{
  if (!path)
  {
    return {};
  }
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

int extensionIndex(const char* path)
{
  const std::string ext = lowerExtension(path);
  for (int i = 0; i < kNumExtensions; ++i)
  {
    if (ext == kExtensions[i])
    {
      return i;
    }
  }
  return -1;
}

/// Collects the ErrorEvents of an inner reader (and of its executive) so that this reader
/// reports them once, under its own name, instead of the inner objects printing them.
class ErrorCollector : public vtkCommand
{
public:
  static ErrorCollector* New() { return new ErrorCollector; }
  vtkTypeMacro(ErrorCollector, vtkCommand);

  void Execute(vtkObject*, unsigned long event, void* callData) override
  {
    if (event != vtkCommand::ErrorEvent)
    {
      return;
    }
    ++this->Count;
    if (this->First.empty() && callData)
    {
      // "vtkSTLReader (0x...): message" -> "message"
      std::string text = static_cast<const char*>(callData);
      const size_t colon = text.find("): ");
      if (colon != std::string::npos)
      {
        text = text.substr(colon + 3);
      }
      while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
      {
        text.pop_back();
      }
      this->First = text;
    }
  }

  int Count = 0;
  std::string First;
};

/// Runs a VTK algorithm, turning any error it reports into a GeoLatticeError.
/// Errors are seen through ErrorEvents (when warnings are displayed) and the error code.
void runChecked(vtkAlgorithm* algorithm, const std::string& path)
{
  vtkNew<ErrorCollector> errors;
  const unsigned long tag1 = algorithm->AddObserver(vtkCommand::ErrorEvent, errors);
  const unsigned long tag2 = algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  algorithm->Update();
  algorithm->RemoveObserver(tag1);
  algorithm->GetExecutive()->RemoveObserver(tag2);
  if (errors->Count > 0 || algorithm->GetErrorCode() != vtkErrorCode::NoError)
  {
    std::string reason = errors->First;
    if (reason.empty())
    {
      reason = vtkErrorCode::GetStringFromErrorCode(algorithm->GetErrorCode());
    }
    throw geolattice::GeoLatticeError(std::string(algorithm->GetClassName()) + " cannot read " +
      path + ": " + reason);
  }
}

/// Removes point normals and texture coordinates: per-corner data that point merging would
/// make wrong, and that made readers (OBJ) split vertices in the first place.
void dropCornerAttributes(vtkPolyData* poly)
{
  vtkPointData* pd = poly->GetPointData();
  int indices[vtkDataSetAttributes::NUM_ATTRIBUTES];
  pd->GetAttributeIndices(indices);
  int normals = indices[vtkDataSetAttributes::NORMALS];
  int tcoords = indices[vtkDataSetAttributes::TCOORDS];
  // Remove the higher index first so the other index stays valid.
  if (normals < tcoords)
  {
    std::swap(normals, tcoords);
  }
  for (int index : { normals, tcoords })
  {
    if (index >= 0)
    {
      pd->RemoveArray(index);
    }
  }
}

/// Surface formats -> triangles only, coincident points merged.
void readSurface(const std::string& path, const std::string& ext, vtkPolyData* output)
{
  vtkNew<vtkPolyData> raw;
  if (ext == ".off")
  {
    geolattice::fromTriangleSurface(geolattice::readOff(path), raw);
  }
  else
  {
    vtkSmartPointer<vtkAlgorithm> reader;
    if (ext == ".stl")
    {
      auto stl = vtkSmartPointer<vtkSTLReader>::New();
      stl->SetFileName(path.c_str());
      stl->MergingOn();
      stl->ScalarTagsOff();
      reader = stl;
    }
    else if (ext == ".obj")
    {
      auto obj = vtkSmartPointer<vtkOBJReader>::New();
      obj->SetFileName(path.c_str());
      reader = obj;
    }
    else if (ext == ".ply")
    {
      auto ply = vtkSmartPointer<vtkPLYReader>::New();
      ply->SetFileName(path.c_str());
      reader = ply;
    }
    else
    {
      auto vtp = vtkSmartPointer<vtkXMLPolyDataReader>::New();
      vtp->SetFileName(path.c_str());
      reader = vtp;
    }
    runChecked(reader, path);
    vtkPolyData* read = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
    if (!read)
    {
      throw geolattice::GeoLatticeError(
        std::string(reader->GetClassName()) + " gave no polydata for " + path);
    }
    raw->ShallowCopy(read);
  }
  dropCornerAttributes(raw);

  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(raw);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  // Exact merging (tolerance 0); polygons that collapse are dropped, not turned into lines.
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(triangles->GetOutputPort());
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  clean->ConvertPolysToLinesOff();
  clean->ConvertLinesToPointsOff();
  clean->ConvertStripsToPolysOff();
  runChecked(clean, path);
  vtkPolyData* cleaned = clean->GetOutput();
  if (cleaned->GetNumberOfPolys() == 0)
  {
    throw geolattice::GeoLatticeError("empty mesh: " + path + " has no triangles");
  }
  output->ShallowCopy(cleaned);
}

/// Tet formats -> VTK_TETRA cells only.
void readTetMesh(const std::string& path, const std::string& ext, vtkUnstructuredGrid* output)
{
  if (ext == ".tet")
  {
    geolattice::fromTetMesh(geolattice::readTetFile(path), output);
    return;
  }
  if (ext == ".node" || ext == ".ele")
  {
    geolattice::fromTetMesh(geolattice::readTetGenMesh(path), output);
    return;
  }
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  runChecked(reader, path);
  vtkUnstructuredGrid* grid = reader->GetOutput();
  if (grid->GetNumberOfCells() == 0 || grid->GetNumberOfPoints() == 0)
  {
    throw geolattice::GeoLatticeError("empty mesh: " + path + " has " +
      std::to_string(grid->GetNumberOfPoints()) + " points and " +
      std::to_string(grid->GetNumberOfCells()) + " cells");
  }
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    if (grid->GetCellType(c) != VTK_TETRA)
    {
      throw geolattice::GeoLatticeError("cell " + std::to_string(c) + " of " + path +
        " is not a linear tetrahedron (VTK cell type " + std::to_string(grid->GetCellType(c)) +
        "); only tet meshes are accepted");
    }
  }
  output->ShallowCopy(grid);
}
} // namespace

vtkGLMeshReader::vtkGLMeshReader()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

vtkGLMeshReader::~vtkGLMeshReader()
{
  this->SetFileName(nullptr);
}

void vtkGLMeshReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}

int vtkGLMeshReader::GetNumberOfSupportedExtensions()
{
  return kNumExtensions;
}

const char* vtkGLMeshReader::GetSupportedExtension(int i)
{
  return (i >= 0 && i < kNumExtensions) ? kExtensions[i] : nullptr;
}

const char* vtkGLMeshReader::GetSupportedExtensionsString()
{
  return kExtensionsString;
}

bool vtkGLMeshReader::IsSupportedFile(const char* path)
{
  return extensionIndex(path) >= 0;
}

bool vtkGLMeshReader::IsTetMeshFile(const char* path)
{
  return extensionIndex(path) >= kNumSurfaceExtensions;
}

int vtkGLMeshReader::CanReadFile(const char* path)
{
  std::error_code ec;
  return IsSupportedFile(path) && std::filesystem::is_regular_file(path, ec) ? 1 : 0;
}

int vtkGLMeshReader::RequestDataObject(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // Unsupported or missing names get an (empty) polydata; RequestData reports the error.
  const int type = IsTetMeshFile(this->FileName) ? VTK_UNSTRUCTURED_GRID : VTK_POLY_DATA;
  return vtkDataObjectAlgorithm::SetOutputDataObject(
           type, outputVector->GetInformationObject(0), /*exact=*/true)
    ? 1
    : 0;
}

int vtkGLMeshReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  try
  {
    if (!this->FileName || this->FileName[0] == '\0')
    {
      throw geolattice::GeoLatticeError("no file name set (FileName is empty)");
    }
    const std::string path = this->FileName;
    const std::string ext = lowerExtension(this->FileName);
    if (!IsSupportedFile(this->FileName))
    {
      throw geolattice::GeoLatticeError("unsupported file extension '" + ext + "' of " + path +
        "; supported: " + kExtensionsString);
    }
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
    {
      throw geolattice::GeoLatticeError("file not found: " + path);
    }
    if (!std::filesystem::is_regular_file(path, ec))
    {
      throw geolattice::GeoLatticeError("not a regular file: " + path);
    }
    this->UpdateProgress(0.0);
    if (IsTetMeshFile(this->FileName))
    {
      vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(output);
      if (!grid)
      {
        throw geolattice::GeoLatticeError("internal error: output is not an unstructured grid");
      }
      readTetMesh(path, ext, grid);
    }
    else
    {
      vtkPolyData* poly = vtkPolyData::SafeDownCast(output);
      if (!poly)
      {
        throw geolattice::GeoLatticeError("internal error: output is not polydata");
      }
      readSurface(path, ext, poly);
    }
    this->UpdateProgress(1.0);
  }
  catch (const std::exception& e)
  {
    // GeoLatticeError from core and the conversions, or std errors (bad_alloc, filesystem).
    output->Initialize();
    vtkErrorMacro(<< e.what());
  }
  return 1;
}
