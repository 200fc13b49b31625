#include "vtkGLMeshConversion.h"

#include "common/Error.h"

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <string>

namespace geolattice {

namespace {
std::vector<Vec3> readPoints(vtkPoints* points) {
  std::vector<Vec3> out;
  if (!points) {
    return out;
  }
  out.resize(points->GetNumberOfPoints());
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
    double p[3];
    points->GetPoint(i, p);
    out[i] = Vec3(p[0], p[1], p[2]);
  }
  return out;
}

vtkNew<vtkPoints> writePoints(const std::vector<Vec3>& points) {
  vtkNew<vtkPoints> out;
  out->SetDataTypeToDouble();
  out->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  for (size_t i = 0; i < points.size(); ++i) {
    out->SetPoint(static_cast<vtkIdType>(i), points[i].data());
  }
  return out;
}
} // namespace

TriangleSurface toTriangleSurface(vtkPolyData* poly) {
  if (!poly || poly->GetNumberOfPolys() == 0) {
    throw GeoLatticeError("empty surface: the input has no polygons");
  }
  TriangleSurface surface;
  surface.points = readPoints(poly->GetPoints());
  vtkCellArray* polys = poly->GetPolys();
  surface.triangles.reserve(polys->GetNumberOfCells());
  vtkNew<vtkIdList> ids;
  for (polys->InitTraversal(); polys->GetNextCell(ids);) {
    if (ids->GetNumberOfIds() != 3) {
      throw GeoLatticeError("surface has a polygon with " + std::to_string(ids->GetNumberOfIds()) +
                            " vertices; only triangles are accepted (apply a Triangulate filter)");
    }
    surface.triangles.push_back({static_cast<int>(ids->GetId(0)), static_cast<int>(ids->GetId(1)),
                                 static_cast<int>(ids->GetId(2))});
  }
  return surface;
}

TetMesh toTetMesh(vtkUnstructuredGrid* grid) {
  if (!grid || grid->GetNumberOfCells() == 0 || grid->GetNumberOfPoints() == 0) {
    throw GeoLatticeError("empty mesh: the input grid has no cells");
  }
  TetMesh mesh;
  mesh.points = readPoints(grid->GetPoints());
  mesh.tets.resize(grid->GetNumberOfCells());
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    if (grid->GetCellType(c) != VTK_TETRA) {
      throw GeoLatticeError("cell " + std::to_string(c) + " is not a linear tetrahedron (VTK type " +
                            std::to_string(grid->GetCellType(c)) + ")");
    }
    grid->GetCellPoints(c, ids);
    for (int k = 0; k < 4; ++k) {
      mesh.tets[c][k] = static_cast<int>(ids->GetId(k));
    }
  }
  return mesh;
}

void fromTetMesh(const TetMesh& mesh, vtkUnstructuredGrid* grid) {
  grid->Initialize();
  grid->SetPoints(writePoints(mesh.points));
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(static_cast<vtkIdType>(mesh.tets.size()), 4 * static_cast<vtkIdType>(mesh.tets.size()));
  for (const auto& t : mesh.tets) {
    const vtkIdType ids[4] = {t[0], t[1], t[2], t[3]};
    cells->InsertNextCell(4, ids);
  }
  grid->SetCells(VTK_TETRA, cells);
}

void fromTriangleSurface(const TriangleSurface& surface, vtkPolyData* poly) {
  poly->Initialize();
  poly->SetPoints(writePoints(surface.points));
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(static_cast<vtkIdType>(surface.triangles.size()),
                       3 * static_cast<vtkIdType>(surface.triangles.size()));
  for (const auto& t : surface.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    cells->InsertNextCell(3, ids);
  }
  poly->SetPolys(cells);
}

vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, const std::vector<double>& values, int components) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / components));
  std::copy(values.begin(), values.end(), a->GetPointer(0));
  return a;
}

void addFieldArray(vtkFieldData* fd, const char* name, const std::vector<double>& values, int components) {
  fd->AddArray(doubleArray(name, values, components));
}

} // namespace geolattice
