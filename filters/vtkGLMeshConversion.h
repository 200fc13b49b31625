#ifndef vtkGLMeshConversion_h
#define vtkGLMeshConversion_h
/**
 * @file vtkGLMeshConversion.h
 * @brief Conversions between VTK data sets and the plain core/ containers.
 * Each function throws geolattice::GeoLatticeError with a message that names the problem
 * (e.g. a non-tetrahedral cell) so that filters can report it with vtkErrorMacro.
 */
#include "lattice/LatticeInfill.h"
#include "mesh/SurfaceRepair.h"
#include "mesh/TetMesh.h"
#include "nozzle/BuildPlate.h"
#include "nozzle/NozzleModel.h"
#include "skeleton/SkeletonTree.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <vector>

class vtkAlgorithm;
class vtkDataArray;
class vtkDoubleArray;
class vtkIntArray;
class vtkGLNozzle;
class vtkFieldData;
class vtkPointData;
class vtkPolyData;
class vtkUnstructuredGrid;
class vtkPoints;

namespace geolattice {

/// Calls f(cell, n, ids) for every cell of `cells`, `cell` being its id in the data set: the
/// cells before them (e.g. a polydata's vertex cells before its lines) number from 0, so
/// `firstCell` is their count.
template <class F>
void forEachCell(vtkCellArray* cells, vtkIdType firstCell, F&& f) {
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell()) {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    f(firstCell + it->GetCurrentCellId(), n, ids);
  }
}

/// forEachCell over the line cells of `poly` (their ids follow its vertex cells).
template <class F>
void forEachLine(vtkPolyData* poly, F&& f) {
  forEachCell(poly->GetLines(), poly->GetNumberOfVerts(), f);
}

/// Triangle surface from polydata: polygons must all be triangles (run vtkTriangleFilter first
/// for quads); vertices/lines are ignored. Throws on an empty surface or non-triangles.
TriangleSurface toTriangleSurface(vtkPolyData* poly);
/// The surface cleaning of GL Mesh Reader, for a surface from any reader: point normals and
/// texture coordinates dropped (per-corner data, for which readers such as OBJ split vertices),
/// polygons triangulated (vertices and lines dropped), coincident points merged exactly and the
/// points numbered by first use in the triangles. The returned filter (input: a shallow copy of
/// `surface`) is not run yet. The stages downstream depend on the point order, so a part
/// opened with ParaView's own reader gives the command line's numbers only after this.
vtkSmartPointer<vtkAlgorithm> newSurfaceCleaner(vtkPolyData* surface);
/// Tet mesh from an unstructured grid of VTK_TETRA cells only. Throws otherwise.
TetMesh toTetMesh(vtkUnstructuredGrid* grid);
/// Points + VTK_TETRA cells, no arrays.
void fromTetMesh(const TetMesh& mesh, vtkUnstructuredGrid* grid);
/// Points + triangle polys, no arrays.
void fromTriangleSurface(const TriangleSurface& surface, vtkPolyData* poly);

/// The lattice graph as the sequencing code needs it, rebuilt from the output of
/// vtkGLLatticeInfill: points; normals (point array NozzleAxis, 3 components); one edge per line
/// cell (a polyline of n points gives n - 1 edges, vertex and polygon cells are ignored) with
/// edgeSubgraph from cell array SubgraphId; layers = the distinct cell LayerId values sorted
/// ascending, mapped to 0..L-1 (layerIndex holds the LayerId values, layerValues the mean point
/// Gamma of each layer); vertexLayer and vertexSubgraph from the edges (a point without edges:
/// its point SubgraphId, if any, else -1 and the layer with the nearest Gamma); subgraphs
/// (id = SubgraphId, which must be 0..K-1 without gaps, each on one layer; indexInLayer by id
/// within the layer; length, length-weighted centroid, vertex and edge counts); degree; the
/// layer offsets when points, edges and sub-graph ids are grouped by layer as the lattice filter
/// writes them (else they are left empty); edgeKind from the cell array EdgeKind and vertexKind
/// from the point array VertexKind when present (values checked; else left empty: the toolpath
/// needs edgeKind, the sequencing does not). α, β and levels are not restored. Throws
/// GeoLatticeError naming the problem ("lattice has no SubgraphId cell array", ...).
LatticeGraph toLatticeGraph(vtkPolyData* lattice);

/// The nozzle axis of a lattice or toolpath: point array NozzleAxis, or (files written before it
/// was renamed) Normals / the active normals; nullptr when none has 3 components.
vtkDataArray* nozzleAxisOf(vtkPointData* pd);

/// The skeleton tree from the output of vtkGLSkeletonTree: one node per point (node index =
/// point data NodeId if present, which must then be a permutation of 0..N-1, else the point
/// index) with layer = point data LayerId (lattice layer 0..L-1), length = SubgraphLength (0 if
/// absent), centroid = the point; one edge per line cell between consecutive layers (stored as
/// (lower, upper) whatever the cell's point order); layerValues from the field data LayerValues
/// (empty if absent); lower/upper lists, roots, floating (roots above the lowest layer with a
/// node), merge and split counts recomputed;
/// then validateSkeletonTree. Throws GeoLatticeError naming the problem (missing LayerId, a line
/// cell that is not a 2-point line, "cyclic or missing adjacency", ...).
SkeletonTree toSkeletonTree(vtkPolyData* skeleton);

/// Checks that `tree` (from toSkeletonTree) is the skeleton of `graph` (from toLatticeGraph): one
/// node per sub-graph, node i on the layer of sub-graph i. Fills tree.layerValues from the
/// lattice when the skeleton has none. Throws GeoLatticeError naming the mismatch.
void matchSkeletonToLattice(SkeletonTree& tree, const LatticeGraph& graph);

/// A toolpath as the program writers (core/program/) need it, per point in point order.
struct ToolpathArrays {
  std::vector<Vec3> points;       ///< mm, part (platform) frame
  std::vector<Vec3> normals;      ///< unit nozzle axes (normalized here)
  std::vector<double> extrusion;  ///< cumulative filament E (mm)
  std::vector<double> feedRate;   ///< mm/s
  std::vector<int> kind;          ///< movekind: 0 print, 1 perimeter, 2 air
  std::vector<int> layer;         ///< the lattice's LayerId, -1 on air moves
};

/// The toolpath from the output of vtkGLToolpathPlanner: its points in point order (the printing
/// order; cells are not used) with the point arrays NozzleAxis (3 components), Extrusion, FeedRate,
/// MoveKind and LayerId. Throws GeoLatticeError naming the problem: an empty toolpath, a missing
/// array or one with the wrong number of components ("run GL Toolpath Planner first"), a point
/// with a NaN coordinate or a NaN or zero nozzle axis (naming its index), non-finite extrusion, a
/// feed rate that is not finite and > 0 after the first point, a MoveKind other than 0, 1 or 2.
ToolpathArrays toToolpathArrays(vtkPolyData* toolpath);

/// The nozzle of the filters' properties (NozzleLength 0 = cone only); validated, throws
/// GeoLatticeError naming a bad parameter.
NozzleModel nozzleModel(vtkGLNozzle* nozzle);
/// The build plate of the filters' nozzle block; validated (throws naming a bad parameter).
BuildPlate buildPlate(vtkGLNozzle* nozzle);

/// Double-precision points at the given positions (mm).
vtkSmartPointer<vtkPoints> pointsOf(const std::vector<Vec3>& positions);
/// A named double array of values.size() / components tuples holding values.
vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, const std::vector<double>& values,
                                            int components = 1);
/// A named double array holding values (one component).
vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, const Eigen::VectorXd& values);
/// A named 3-component double array holding the vectors.
vtkSmartPointer<vtkDoubleArray> vectorArray(const char* name, const std::vector<Vec3>& vectors);
/// A named int array of n tuples (their values to be set).
vtkSmartPointer<vtkIntArray> intArray(const char* name, vtkIdType n);
/// Adds doubleArray(name, values, components) to the field data (replacing one of that name).
void addFieldArray(vtkFieldData* fd, const char* name, const std::vector<double>& values,
                   int components = 1);
/// Adds a one-value string array to the field data (a verdict, a mode, a reason).
void addFieldText(vtkFieldData* fd, const char* name, const std::string& text);
/// The repairs a surface got before meshing (core/mesh/SurfaceRepair.h; mergedBodies also counts
/// crossing bodies united): field data MergedBodies, DuplicateTriangles, ReorientedTriangles,
/// DegenerateTrianglesRemoved, WeldedVertices, InvertedBodies.
void addSurfaceRepairArrays(vtkFieldData* fd, const SurfaceRepairCounts& repairs);

}  // namespace geolattice
#endif
