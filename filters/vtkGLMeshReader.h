/**
 * @class   vtkGLMeshReader
 * @brief   Reads a model as a triangle surface or a tet mesh, chosen by the file extension.
 *
 * The entry point of the pipeline: a printed part comes in as a closed triangle surface (to be
 * tetrahedralized) or as a ready tet mesh.
 *
 * Inputs:  none (0 input ports).
 * Output:  port 0, its type decided in RequestDataObject from the extension (case-insensitive):
 *   - `.stl` (vtkSTLReader, points merged), `.ply` (vtkPLYReader), `.vtp`
 *     (vtkXMLPolyDataReader), `.obj` (core readObj: `v` and `f` statements, texture and normal
 *     references ignored) and `.off` (core readOff) -> vtkPolyData of triangles only.
 *     Polygons are triangulated, vertices/lines dropped, coincident points merged
 *     (vtkCleanPolyData, exact), so a triangle soup (STL) or a PLY whose vertices were split
 *     by texture coordinates becomes one connected surface. Point normals and texture
 *     coordinates are dropped (they are per-corner data that merging would make wrong); other
 *     point and cell arrays of a `.vtp`/`.ply` are kept.
 *   - `.vtu` (vtkXMLUnstructuredGridReader, arrays kept), `.tet` (core readTetFile),
 *     `.node`/`.ele` (core readTetGenMesh; either file of the pair) -> vtkUnstructuredGrid of
 *     VTK_TETRA cells only.
 * Coordinates are passed through unchanged (no unit conversion; see vtkGLPlaceOnPlatform).
 *
 * Parameters: FileName (path, no default).
 *
 * Errors (vtkErrorMacro, empty output, RequestData returns 0 so that Update() reports the
 * failure): no file name, missing file ("file not found: <path>"), unknown extension
 * (the message lists the supported ones), an empty mesh, a non-tetrahedral cell in a `.vtu`,
 * a parse error of the core readers (file and line), a VTK reader reporting an error.
 */
#ifndef vtkGLMeshReader_h
#define vtkGLMeshReader_h

#include "GeoLatticeFiltersModule.h"
#include "vtkDataObjectAlgorithm.h"
#include "vtkWrappingHints.h"

class vtkPolyData;

#include <string>

class GEOLATTICEFILTERS_EXPORT vtkGLMeshReader : public vtkDataObjectAlgorithm {
public:
  static vtkGLMeshReader* New();
  vtkTypeMacro(vtkGLMeshReader, vtkDataObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Path of the model file (no default). The extension chooses the format and output type.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  /// 1 if the path has a supported extension and names an existing regular file (used by
  /// ParaView's reader factory), else 0.
  static int CanReadFile(const char* path);

  /// True if the extension of `path` gives a tet mesh (.vtu, .tet, .node, .ele), false for a
  /// surface or an unsupported extension.
  static bool IsTetMeshFile(const char* path);

  /// True if the extension of `path` (case-insensitive) is one of the supported ones.
  static bool IsSupportedFile(const char* path);

  ///@{
  /// The supported extensions with their dot, lower case: ".stl", ".obj", ... (surfaces first,
  /// then tet meshes). GetSupportedExtensionsString() gives them space-separated, for messages
  /// and the CLI's help.
  static int GetNumberOfSupportedExtensions();
  static const char* GetSupportedExtension(int i);
  static const char* GetSupportedExtensionsString();
  ///@}

  /// Reads a surface file (a supported surface extension) into `output` as triangles with
  /// coincident points merged, as RequestData does; `reporter` receives the inner readers'
  /// progress and warnings. Throws geolattice::GeoLatticeError naming the file and the problem
  /// (used for files that are not the model, e.g. a printhead mesh).
  VTK_WRAPEXCLUDE static void ReadSurfaceFile(const std::string& path, vtkPolyData* output,
                                              vtkAlgorithm* reporter);

protected:
  vtkGLMeshReader();
  ~vtkGLMeshReader() override;

  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;

private:
  vtkGLMeshReader(const vtkGLMeshReader&) = delete;
  void operator=(const vtkGLMeshReader&) = delete;
};

#endif
