#ifndef vtkGLMeshConversion_h
#define vtkGLMeshConversion_h
/**
 * @file vtkGLMeshConversion.h
 * @brief Conversions between VTK data sets and the plain core/ containers.
 * Each function throws geolattice::GeoLatticeError with a message that names the problem
 * (e.g. a non-tetrahedral cell) so that filters can report it with vtkErrorMacro.
 */
#include "mesh/TetMesh.h"

#include <vtkSmartPointer.h>

#include <vector>

class vtkDoubleArray;
class vtkFieldData;
class vtkPolyData;
class vtkUnstructuredGrid;
class vtkPoints;

namespace geolattice {

/// Triangle surface from polydata: polygons must all be triangles (run vtkTriangleFilter first
/// for quads); vertices/lines are ignored. Throws on an empty surface or non-triangles.
TriangleSurface toTriangleSurface(vtkPolyData* poly);
/// Tet mesh from an unstructured grid of VTK_TETRA cells only. Throws otherwise.
TetMesh toTetMesh(vtkUnstructuredGrid* grid);
/// Points + VTK_TETRA cells, no arrays.
void fromTetMesh(const TetMesh& mesh, vtkUnstructuredGrid* grid);
/// Points + triangle polys, no arrays.
void fromTriangleSurface(const TriangleSurface& surface, vtkPolyData* poly);

/// A named double array of values.size() / components tuples holding values.
vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, const std::vector<double>& values, int components = 1);
/// Adds doubleArray(name, values, components) to the field data (replacing one of that name).
void addFieldArray(vtkFieldData* fd, const char* name, const std::vector<double>& values, int components = 1);

} // namespace geolattice
#endif
