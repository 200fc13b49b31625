#ifndef GLTestTowers_h
#define GLTestTowers_h
/**
 * @file GLTestTowers.h
 * @brief Test helper shared by the sequencer and planner tests: the "towers" lattice and
 * skeleton, made by hand as vtkGLLatticeInfill and vtkGLSkeletonTree write them.
 *
 * towerLattice: `towers` columns of unit squares (one closed loop of 4 line cells = one sub-graph
 * per tower and layer), `gap` mm between the squares' sides, layers at z = 1, 2, .., NozzleAxis
 * +z, Gamma = z, cell LayerId = firstLayerId + layer, EdgeKind boundary on every edge (no
 * isoline ends on the squares: nothing is trimmed, no support perimeter). Sub-graph id =
 * layer * towers + tower. towerSkeleton: one chain of nodes per tower, at the squares' centres.
 */
#include "GLTestArrays.h"
#include "vtkGLArrayNames.h"

#include "lattice/LatticeInfill.h"

#include <vtkCellArray.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <utility>
#include <vector>

struct TowerLayout {
  int towers = 2;
  double gap = 2.0;      ///< mm between the squares' sides
  int firstLayerId = 0;  ///< LayerId of the lowest layer
};

inline vtkSmartPointer<vtkPolyData> towerLattice(int layers, const TowerLayout& t = {}) {
  namespace arrays = geolattice::arrays;
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> normals, gamma;
  normals->SetName(arrays::NozzleAxis);
  normals->SetNumberOfComponents(3);
  gamma->SetName(arrays::Gamma);
  auto pointSubgraph = namedIntArray(arrays::SubgraphId);
  auto cellSubgraph = namedIntArray(arrays::SubgraphId);
  auto layerId = namedIntArray(arrays::LayerId);
  auto edgeKind = namedIntArray(arrays::EdgeKind);
  vtkNew<vtkCellArray> lines;
  for (int l = 0; l < layers; ++l) {
    const double z = 1.0 + l;
    for (int k = 0; k < t.towers; ++k) {
      const double x0 = k * (1.0 + t.gap);
      const int s = l * t.towers + k;
      const vtkIdType first = points->GetNumberOfPoints();
      for (const auto& [dx, dy] : {std::pair<double, double>{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
        points->InsertNextPoint(x0 + dx, dy, z);
        normals->InsertNextTuple3(0, 0, 1);
        gamma->InsertNextValue(z);
        pointSubgraph->InsertNextValue(s);
      }
      for (int e = 0; e < 4; ++e) {
        const vtkIdType ids[2] = {first + e, first + (e + 1) % 4};
        lines->InsertNextCell(2, ids);
        cellSubgraph->InsertNextValue(s);
        layerId->InsertNextValue(t.firstLayerId + l);
        edgeKind->InsertNextValue(geolattice::latticekind::EdgeBoundary);
      }
    }
  }
  pd->SetPoints(points);
  pd->SetLines(lines);
  pd->GetPointData()->AddArray(normals);
  pd->GetPointData()->AddArray(gamma);
  pd->GetPointData()->AddArray(pointSubgraph);
  pd->GetCellData()->AddArray(layerId);
  pd->GetCellData()->AddArray(cellSubgraph);
  pd->GetCellData()->AddArray(edgeKind);
  return pd;
}

/// The skeleton of towerLattice (point arrays NodeId, LayerId, SubgraphLength = 4; field data
/// LayerValues = the layers' z). `extra` adds line cells (node pairs).
inline vtkSmartPointer<vtkPolyData> towerSkeleton(
    int layers, const TowerLayout& t = {}, const std::vector<std::pair<int, int>>& extra = {}) {
  namespace arrays = geolattice::arrays;
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  auto nodeId = namedIntArray(arrays::NodeId);
  auto layerId = namedIntArray(arrays::LayerId);
  vtkNew<vtkDoubleArray> length, layerValues;
  length->SetName(arrays::SubgraphLength);
  layerValues->SetName(arrays::LayerValues);
  vtkNew<vtkCellArray> lines;
  for (int l = 0; l < layers; ++l) {
    layerValues->InsertNextValue(1.0 + l);
    for (int k = 0; k < t.towers; ++k) {
      const int s = l * t.towers + k;
      points->InsertNextPoint(k * (1.0 + t.gap) + 0.5, 0.5, 1.0 + l);
      nodeId->InsertNextValue(s);
      layerId->InsertNextValue(l);
      length->InsertNextValue(4.0);
      if (l > 0) {
        const vtkIdType ids[2] = {s - t.towers, s};
        lines->InsertNextCell(2, ids);
      }
    }
  }
  for (const auto& [a, b] : extra) {
    const vtkIdType ids[2] = {a, b};
    lines->InsertNextCell(2, ids);
  }
  pd->SetPoints(points);
  pd->SetLines(lines);
  pd->GetPointData()->AddArray(nodeId);
  pd->GetPointData()->AddArray(layerId);
  pd->GetPointData()->AddArray(length);
  pd->GetFieldData()->AddArray(layerValues);
  return pd;
}

#endif
