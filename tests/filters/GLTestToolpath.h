#ifndef GLTestToolpath_h
#define GLTestToolpath_h
/**
 * @file GLTestToolpath.h
 * @brief Test helper: a small hand-made toolpath with the point arrays of vtkGLToolpathPlanner's
 * output (NozzleAxis, Extrusion, FeedRate, MoveKind, LayerId), for the program writers' tests.
 *
 * `loops` square loops of 10 mm side, one per layer at z = 1, 2, …, each printed from an air
 * move onto its first corner (10 points per side); normals tilted by `tiltDeg` about +x on the
 * second half of every loop; extrusion grows 0.05 mm per print point; feed rate 10 mm/s (print)
 * and 50 mm/s (air); LayerId = the loop, -1 on air points.
 */
#include "vtkGLArrayNames.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkFieldData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <vector>

/// Gives a hand-made toolpath the planner's collision verdict (field data ToolpathCollisionFree
/// and, when colliding, 7 ToolpathUnclearedStations), which the program writers check.
inline void setTestCollisionVerdict(vtkPolyData* toolpath, bool collisionFree) {
  namespace arrays = geolattice::arrays;
  vtkNew<vtkIntArray> verdict, stations;
  verdict->SetName(arrays::ToolpathCollisionFree);
  verdict->InsertNextValue(collisionFree ? 1 : 0);
  stations->SetName(arrays::ToolpathUnclearedStations);
  stations->InsertNextValue(collisionFree ? 0 : 7);
  toolpath->GetFieldData()->AddArray(verdict);
  toolpath->GetFieldData()->AddArray(stations);
}

/// A small planned-looking toolpath: `loops` square loops 1 mm apart, the last two sides tilted
/// by tiltDeg, air moves between them; field data ToolpathCollisionFree = `collisionFree` (the
/// planner's verdict the writers check; -1 leaves it out).
inline vtkSmartPointer<vtkPolyData> makeTestToolpath(int loops = 2, double tiltDeg = 20.0,
                                                     int collisionFree = 1) {
  namespace arrays = geolattice::arrays;
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> normals, extrusion, feed;
  normals->SetName(arrays::NozzleAxis);
  normals->SetNumberOfComponents(3);
  extrusion->SetName(arrays::Extrusion);
  feed->SetName(arrays::FeedRate);
  vtkNew<vtkIntArray> kind, layer;
  kind->SetName(arrays::MoveKind);
  layer->SetName(arrays::LayerId);
  const double t = tiltDeg * M_PI / 180.0;
  double e = 0;
  auto add = [&](double x, double y, double z, bool tilted, int k, int l) {
    points->InsertNextPoint(x, y, z);
    normals->InsertNextTuple3(0, tilted ? -std::sin(t) : 0.0, tilted ? std::cos(t) : 1.0);
    if (k != geolattice::movekind::Air && points->GetNumberOfPoints() > 1) {
      e += 0.05;
    }
    extrusion->InsertNextValue(e);
    feed->InsertNextValue(k == geolattice::movekind::Air ? 50.0 : 10.0);
    kind->InsertNextValue(k);
    layer->InsertNextValue(k == geolattice::movekind::Air ? -1 : l);
  };
  add(0, 0, 5, false, geolattice::movekind::Air, -1);  // the start
  for (int l = 0; l < loops; ++l) {
    const double z = 1.0 + l;
    add(0, 0, z, false, geolattice::movekind::Air, l);
    const double corners[5][2] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}};
    for (int side = 0; side < 4; ++side) {
      for (int k = 1; k <= 10; ++k) {
        const double s = k / 10.0;
        const double x = corners[side][0] + s * (corners[side + 1][0] - corners[side][0]);
        const double y = corners[side][1] + s * (corners[side + 1][1] - corners[side][1]);
        add(x, y, z, side >= 2, geolattice::movekind::Print, l);
      }
    }
  }
  vtkNew<vtkCellArray> lines;
  std::vector<vtkIdType> ids(static_cast<size_t>(points->GetNumberOfPoints()));
  for (size_t i = 0; i < ids.size(); ++i) {
    ids[i] = static_cast<vtkIdType>(i);
  }
  lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  pd->SetPoints(points);
  pd->SetLines(lines);
  pd->GetPointData()->AddArray(normals);
  pd->GetPointData()->AddArray(extrusion);
  pd->GetPointData()->AddArray(feed);
  pd->GetPointData()->AddArray(kind);
  pd->GetPointData()->AddArray(layer);
  if (collisionFree >= 0) {
    setTestCollisionVerdict(pd, collisionFree != 0);
  }
  return pd;
}

#endif
