#include "vtkGLMeshConversion.h"

#include "GLPrintheadFile.h"
#include "vtkGLNozzle.h"

#include "vtkGLArrayNames.h"

#include "common/Error.h"

#include <vtkIntArray.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCleanPolyData.h>
#include <vtkDataSetAttributes.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <limits>
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

/// Removes point normals and texture coordinates: per-corner data that point merging would
/// make wrong, and that made readers (OBJ) split vertices in the first place.
void dropCornerAttributes(vtkPolyData* poly) {
  vtkPointData* pd = poly->GetPointData();
  int indices[vtkDataSetAttributes::NUM_ATTRIBUTES];
  pd->GetAttributeIndices(indices);
  int normals = indices[vtkDataSetAttributes::NORMALS];
  int tcoords = indices[vtkDataSetAttributes::TCOORDS];
  // Remove the higher index first so the other index stays valid.
  if (normals < tcoords) {
    std::swap(normals, tcoords);
  }
  for (int index : {normals, tcoords}) {
    if (index >= 0) {
      pd->RemoveArray(index);
    }
  }
}

}  // namespace

vtkSmartPointer<vtkAlgorithm> newSurfaceCleaner(vtkPolyData* surface) {
  vtkNew<vtkPolyData> raw;
  raw->ShallowCopy(surface);
  dropCornerAttributes(raw);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(raw);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  // Exact merging (tolerance 0); polygons that collapse are dropped, not turned into lines.
  auto clean = vtkSmartPointer<vtkCleanPolyData>::New();
  clean->SetInputConnection(triangles->GetOutputPort());
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  clean->ConvertPolysToLinesOff();
  clean->ConvertLinesToPointsOff();
  clean->ConvertStripsToPolysOff();
  return clean;
}

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
      throw GeoLatticeError("cell " + std::to_string(c) +
                            " is not a linear tetrahedron (VTK type " +
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
  grid->SetPoints(pointsOf(mesh.points));
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(static_cast<vtkIdType>(mesh.tets.size()),
                       4 * static_cast<vtkIdType>(mesh.tets.size()));
  for (const auto& t : mesh.tets) {
    const vtkIdType ids[4] = {t[0], t[1], t[2], t[3]};
    cells->InsertNextCell(4, ids);
  }
  grid->SetCells(VTK_TETRA, cells);
}

void fromTriangleSurface(const TriangleSurface& surface, vtkPolyData* poly) {
  poly->Initialize();
  poly->SetPoints(pointsOf(surface.points));
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(static_cast<vtkIdType>(surface.triangles.size()),
                       3 * static_cast<vtkIdType>(surface.triangles.size()));
  for (const auto& t : surface.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    cells->InsertNextCell(3, ids);
  }
  poly->SetPolys(cells);
}

namespace {
/// An integer-valued array entry: throws unless it is finite and integral.
int integerValue(vtkDataArray* a, vtkIdType tuple, const char* what) {
  const double v = a->GetComponent(tuple, 0);
  if (!std::isfinite(v) || v != std::floor(v) || std::abs(v) > 1e9) {
    throw GeoLatticeError(std::string(what) + " " + std::to_string(tuple) + " has " + a->GetName() +
                          " " + std::to_string(v) + ", which is not an integer");
  }
  return static_cast<int>(v);
}

/// True if values is non-decreasing; then offset gets #groups + 1 entries.
bool groupOffsets(const std::vector<int>& values, int groups, std::vector<int>& offset) {
  offset.assign(groups + 1, 0);
  for (size_t i = 0; i < values.size(); ++i) {
    if (i > 0 && values[i] < values[i - 1]) {
      offset.clear();
      return false;
    }
    ++offset[values[i] + 1];
  }
  for (int l = 0; l < groups; ++l) {
    offset[l + 1] += offset[l];
  }
  return true;
}
}  // namespace

vtkDataArray* nozzleAxisOf(vtkPointData* pd) {
  for (vtkDataArray* a :
       {pd->GetArray(arrays::NozzleAxis), pd->GetArray(arrays::Normals), pd->GetNormals()}) {
    if (a && a->GetNumberOfComponents() == 3) {
      return a;
    }
  }
  return nullptr;
}

LatticeGraph toLatticeGraph(vtkPolyData* lattice) {
  if (!lattice || lattice->GetNumberOfLines() == 0 || lattice->GetNumberOfPoints() == 0) {
    throw GeoLatticeError(
        "empty lattice: the input has no line cells (apply GL Lattice Infill first)");
  }
  vtkPointData* pd = lattice->GetPointData();
  vtkCellData* cd = lattice->GetCellData();
  vtkDataArray* cellSubgraph = cd->GetArray(arrays::SubgraphId);
  if (!cellSubgraph) {
    throw GeoLatticeError("lattice has no SubgraphId cell array (apply GL Lattice Infill first)");
  }
  vtkDataArray* cellLayer = cd->GetArray(arrays::LayerId);
  if (!cellLayer) {
    throw GeoLatticeError("lattice has no LayerId cell array (apply GL Lattice Infill first)");
  }
  vtkDataArray* normals = nozzleAxisOf(pd);
  if (!normals) {
    throw GeoLatticeError(std::string("lattice has no ") + arrays::NozzleAxis +
                          " point array with 3 components (the nozzle directions)");
  }
  vtkDataArray* gamma = pd->GetArray(arrays::Gamma);
  if (!gamma) {
    throw GeoLatticeError(
        "lattice has no Gamma point array (the layer values; slice with GL Curved Layer Slicer, "
        "which writes Gamma, before GL Lattice Infill)");
  }
  vtkDataArray* pointSubgraph = pd->GetArray(arrays::SubgraphId);
  vtkDataArray* cellKind = cd->GetArray(arrays::EdgeKind);     // optional
  vtkDataArray* pointKind = pd->GetArray(arrays::VertexKind);  // optional

  LatticeGraph g;
  const vtkIdType V = lattice->GetNumberOfPoints();
  g.points = readPoints(lattice->GetPoints());
  g.normals.resize(V);
  g.gamma.resize(V);
  if (pointKind) {
    g.vertexKind.resize(V);
  }
  for (vtkIdType v = 0; v < V; ++v) {
    if (pointKind) {
      const int kind = integerValue(pointKind, v, "lattice point");
      if (kind < latticekind::VertexIsolinePoint || kind > latticekind::VertexBoundary) {
        throw GeoLatticeError("lattice point " + std::to_string(v) + " has VertexKind " +
                              std::to_string(kind) + "; vertex kinds are 0..3");
      }
      g.vertexKind[v] = static_cast<LatticeVertexKind>(kind);
    }
    Vec3 n(normals->GetComponent(v, 0), normals->GetComponent(v, 1), normals->GetComponent(v, 2));
    const double len = n.norm();
    g.normals[v] = len > 0 && std::isfinite(len) ? Vec3(n / len) : n;
    g.gamma[v] = gamma->GetComponent(v, 0);
  }

  // Edges: line cells, polylines split.
  std::vector<int> rawLayer;  // LayerId value per edge
  forEachLine(lattice, [&](vtkIdType cell, vtkIdType n, const vtkIdType* ids) {
    if (n < 2) {
      throw GeoLatticeError("lattice line cell " + std::to_string(cell) + " has " +
                            std::to_string(n) + " point(s); a line needs at least 2");
    }
    const int s = integerValue(cellSubgraph, cell, "lattice line cell");
    if (s < 0) {
      throw GeoLatticeError("lattice line cell " + std::to_string(cell) + " has SubgraphId " +
                            std::to_string(s) + "; sub-graph ids must be 0..K-1");
    }
    const int layer = integerValue(cellLayer, cell, "lattice line cell");
    const int kind = cellKind ? integerValue(cellKind, cell, "lattice line cell") : 0;
    if (kind < latticekind::EdgeAlpha || kind > latticekind::EdgeBoundary) {
      throw GeoLatticeError("lattice line cell " + std::to_string(cell) + " has EdgeKind " +
                            std::to_string(kind) +
                            "; edge kinds are 0 (alpha), 1 (beta) and 2 (boundary)");
    }
    for (vtkIdType k = 0; k + 1 < n; ++k) {
      g.edges.push_back({static_cast<int>(ids[k]), static_cast<int>(ids[k + 1])});
      g.edgeSubgraph.push_back(s);
      rawLayer.push_back(layer);
      if (cellKind) {
        g.edgeKind.push_back(static_cast<LatticeEdgeKind>(kind));
      }
    }
  });

  // Layers: the distinct LayerId values, ascending.
  g.layerIndex = rawLayer;
  std::sort(g.layerIndex.begin(), g.layerIndex.end());
  g.layerIndex.erase(std::unique(g.layerIndex.begin(), g.layerIndex.end()), g.layerIndex.end());
  const int L = static_cast<int>(g.layerIndex.size());
  g.edgeLayer.resize(g.edges.size());
  for (size_t e = 0; e < g.edges.size(); ++e) {
    const auto l = std::lower_bound(g.layerIndex.begin(), g.layerIndex.end(), rawLayer[e]);
    g.edgeLayer[e] = static_cast<int>(l - g.layerIndex.begin());
  }

  // Sub-graphs: ids 0..K-1, each on one layer.
  const int K = *std::max_element(g.edgeSubgraph.begin(), g.edgeSubgraph.end()) + 1;
  g.subgraphs.resize(K);
  std::vector<int> subgraphLayer(K, -1);
  std::vector<double> centroidWeight(K, 0.0);
  for (size_t e = 0; e < g.edges.size(); ++e) {
    const int s = g.edgeSubgraph[e];
    if (subgraphLayer[s] < 0) {
      subgraphLayer[s] = g.edgeLayer[e];
    } else if (subgraphLayer[s] != g.edgeLayer[e]) {
      throw GeoLatticeError("sub-graph " + std::to_string(s) +
                            " has line cells on two layers (LayerId " +
                            std::to_string(g.layerIndex[subgraphLayer[s]]) + " and " +
                            std::to_string(g.layerIndex[g.edgeLayer[e]]) + ")");
    }
    LatticeSubgraph& sub = g.subgraphs[s];
    const Vec3& a = g.points[g.edges[e][0]];
    const Vec3& b = g.points[g.edges[e][1]];
    const double len = (b - a).norm();
    ++sub.edgeCount;
    sub.length += len;
    sub.centroid += len * 0.5 * (a + b);
    centroidWeight[s] += len;
  }
  for (int s = 0; s < K; ++s) {
    if (subgraphLayer[s] < 0) {
      throw GeoLatticeError(
          "sub-graph ids must be 0..K-1 without gaps: no line cell has SubgraphId " +
          std::to_string(s) + " (largest id " + std::to_string(K - 1) + ")");
    }
  }

  // Vertices: sub-graph and layer from their edges.
  g.vertexSubgraph.assign(V, -1);
  g.vertexLayer.assign(V, -1);
  g.degree.assign(V, 0);
  for (size_t e = 0; e < g.edges.size(); ++e) {
    for (int v : g.edges[e]) {
      ++g.degree[v];
      if (g.vertexSubgraph[v] < 0) {
        g.vertexSubgraph[v] = g.edgeSubgraph[e];
        g.vertexLayer[v] = g.edgeLayer[e];
      } else if (g.vertexSubgraph[v] != g.edgeSubgraph[e]) {
        throw GeoLatticeError("lattice point " + std::to_string(v) + " is shared by sub-graphs " +
                              std::to_string(g.vertexSubgraph[v]) + " and " +
                              std::to_string(g.edgeSubgraph[e]));
      }
    }
  }
  for (vtkIdType v = 0; v < V; ++v) {
    const int own = pointSubgraph ? integerValue(pointSubgraph, v, "lattice point") : -1;
    if (g.degree[v] > 0) {
      if (pointSubgraph && own != g.vertexSubgraph[v]) {
        throw GeoLatticeError("lattice point " + std::to_string(v) + " has SubgraphId " +
                              std::to_string(own) + " but its line cells belong to sub-graph " +
                              std::to_string(g.vertexSubgraph[v]));
      }
      continue;
    }
    if (own >= 0 && own < K) {  // an isolated point of a sub-graph
      g.vertexSubgraph[v] = own;
      g.vertexLayer[v] = subgraphLayer[own];
    }
  }

  // φ_i: mean point Gamma of each layer.
  g.layerValues.assign(L, 0.0);
  std::vector<int> layerCount(L, 0);
  for (vtkIdType v = 0; v < V; ++v) {
    if (g.vertexLayer[v] >= 0) {
      if (!std::isfinite(g.gamma[v])) {
        throw GeoLatticeError("lattice point " + std::to_string(v) + " has a non-finite Gamma");
      }
      g.layerValues[g.vertexLayer[v]] += g.gamma[v];
      ++layerCount[g.vertexLayer[v]];
    }
  }
  for (int l = 0; l < L; ++l) {
    g.layerValues[l] /= layerCount[l];
  }
  for (vtkIdType v = 0; v < V; ++v) {  // points without a sub-graph: the layer of the nearest φ
    if (g.vertexLayer[v] < 0) {
      int best = 0;
      for (int l = 1; l < L; ++l) {
        if (std::abs(g.layerValues[l] - g.gamma[v]) < std::abs(g.layerValues[best] - g.gamma[v])) {
          best = l;
        }
      }
      g.vertexLayer[v] = best;
    }
    if (g.vertexSubgraph[v] >= 0) {
      ++g.subgraphs[g.vertexSubgraph[v]].vertexCount;
    }
  }

  // Sub-graph records; j of G_{i,j} by id within the layer.
  std::vector<int> nextInLayer(L, 0);
  for (int s = 0; s < K; ++s) {
    LatticeSubgraph& sub = g.subgraphs[s];
    sub.id = s;
    sub.layer = subgraphLayer[s];
    sub.indexInLayer = nextInLayer[sub.layer]++;
    if (centroidWeight[s] > 0) {
      sub.centroid /= centroidWeight[s];
    } else {  // only zero-length edges: their mean point
      sub.centroid = Vec3::Zero();
      for (size_t e = 0; e < g.edges.size(); ++e) {
        if (g.edgeSubgraph[e] == s) {
          sub.centroid += g.points[g.edges[e][0]] / sub.edgeCount;
        }
      }
    }
  }

  // Layer offsets, when everything is grouped by layer (as the lattice filter writes it).
  if (!groupOffsets(g.vertexLayer, L, g.layerVertexOffset) ||
      !groupOffsets(g.edgeLayer, L, g.layerEdgeOffset) ||
      !groupOffsets(subgraphLayer, L, g.layerSubgraphOffset)) {
    g.layerVertexOffset.clear();
    g.layerEdgeOffset.clear();
    g.layerSubgraphOffset.clear();
  }
  return g;
}

SkeletonTree toSkeletonTree(vtkPolyData* skeleton) {
  if (!skeleton || skeleton->GetNumberOfPoints() == 0) {
    throw GeoLatticeError("empty skeleton: the input has no nodes (apply GL Skeleton Tree first)");
  }
  vtkPointData* pd = skeleton->GetPointData();
  vtkDataArray* layer = pd->GetArray(arrays::LayerId);
  if (!layer) {
    throw GeoLatticeError("skeleton has no LayerId point array (apply GL Skeleton Tree first)");
  }
  vtkDataArray* nodeId = pd->GetArray(arrays::NodeId);
  vtkDataArray* length = pd->GetArray(arrays::SubgraphLength);
  const vtkIdType N = skeleton->GetNumberOfPoints();
  SkeletonTree tree;
  tree.nodes.resize(N);
  std::vector<int> node(N);  // point -> node
  std::vector<char> seen(N, 0);
  for (vtkIdType p = 0; p < N; ++p) {
    const int id = nodeId ? integerValue(nodeId, p, "skeleton point") : static_cast<int>(p);
    if (id < 0 || id >= N || seen[id]) {
      throw GeoLatticeError("skeleton NodeId is not a permutation of 0.." + std::to_string(N - 1) +
                            " (point " + std::to_string(p) + " has " + std::to_string(id) + ")");
    }
    seen[id] = 1;
    node[p] = id;
    SkeletonNode& n = tree.nodes[id];
    n.layer = integerValue(layer, p, "skeleton point");
    if (n.layer < 0) {
      throw GeoLatticeError("skeleton point " + std::to_string(p) + " has LayerId " +
                            std::to_string(n.layer) + "; lattice layers are 0..L-1");
    }
    double x[3];
    skeleton->GetPoint(p, x);
    n.centroid = Vec3(x[0], x[1], x[2]);
    n.length = length ? length->GetComponent(p, 0) : 0.0;
  }
  std::vector<int> count;
  for (SkeletonNode& n : tree.nodes) {
    if (n.layer >= static_cast<int>(count.size())) {
      count.resize(n.layer + 1, 0);
    }
    n.indexInLayer = count[n.layer]++;
  }

  forEachLine(skeleton, [&](vtkIdType cell, vtkIdType n, const vtkIdType* ids) {
    if (n != 2) {
      throw GeoLatticeError("skeleton line cell " + std::to_string(cell) + " has " +
                            std::to_string(n) +
                            " points; each edge must be a 2-point line (lower, upper)");
    }
    if (ids[0] < 0 || ids[0] >= N || ids[1] < 0 || ids[1] >= N) {
      throw GeoLatticeError("skeleton line cell " + std::to_string(cell) +
                            " uses a point id out of range");
    }
    int a = node[ids[0]], b = node[ids[1]];
    if (tree.nodes[a].layer == tree.nodes[b].layer + 1) {
      std::swap(a, b);
    }
    tree.edges.push_back({a, b});
  });
  std::sort(tree.edges.begin(), tree.edges.end());
  tree.edges.erase(std::unique(tree.edges.begin(), tree.edges.end()), tree.edges.end());
  linkSkeletonEdges(tree);
  if (vtkDataArray* values = skeleton->GetFieldData()->GetArray(arrays::LayerValues)) {
    for (vtkIdType l = 0; l < values->GetNumberOfTuples(); ++l) {
      tree.layerValues.push_back(values->GetComponent(l, 0));
    }
  }
  validateSkeletonTree(tree);
  return tree;
}

void matchSkeletonToLattice(SkeletonTree& tree, const LatticeGraph& graph) {
  if (tree.nodes.size() != graph.subgraphs.size()) {
    throw GeoLatticeError("the skeleton has " + std::to_string(tree.nodes.size()) +
                          " nodes but the lattice has " + std::to_string(graph.subgraphs.size()) +
                          " sub-graphs (connect the GL Skeleton Tree of this lattice)");
  }
  for (size_t i = 0; i < tree.nodes.size(); ++i) {
    if (tree.nodes[i].layer != graph.subgraphs[i].layer) {
      throw GeoLatticeError("skeleton node " + std::to_string(i) + " is on lattice layer " +
                            std::to_string(tree.nodes[i].layer) + " but sub-graph " +
                            std::to_string(i) + " of the lattice is on layer " +
                            std::to_string(graph.subgraphs[i].layer) +
                            " (connect the GL Skeleton Tree of this lattice)");
    }
  }
  if (tree.layerValues.empty()) {
    tree.layerValues = graph.layerValues;
  }
}

ToolpathArrays toToolpathArrays(vtkPolyData* toolpath) {
  const vtkIdType n = toolpath && toolpath->GetPoints() ? toolpath->GetNumberOfPoints() : 0;
  if (n == 0) {
    throw GeoLatticeError(
        "empty toolpath: the input has no points (connect the output of GL Toolpath Planner)");
  }
  vtkPointData* pd = toolpath->GetPointData();
  auto array = [pd](const char* name, int components) {
    vtkDataArray* a = pd->GetArray(name);
    if (!a) {
      throw GeoLatticeError(std::string("the toolpath has no point array ") + name +
                            ": connect the output of GL Toolpath Planner");
    }
    if (a->GetNumberOfComponents() != components) {
      throw GeoLatticeError(std::string("the toolpath's point array ") + name + " has " +
                            std::to_string(a->GetNumberOfComponents()) + " components, expected " +
                            std::to_string(components));
    }
    return a;
  };
  vtkDataArray* normals = nozzleAxisOf(pd) ? nozzleAxisOf(pd) : array(arrays::NozzleAxis, 3);
  vtkDataArray* extrusion = array(arrays::Extrusion, 1);
  vtkDataArray* feedRate = array(arrays::FeedRate, 1);
  vtkDataArray* kind = array(arrays::MoveKind, 1);
  vtkDataArray* layer = array(arrays::LayerId, 1);
  ToolpathArrays t;
  t.points = readPoints(toolpath->GetPoints());
  t.normals.resize(n);
  t.extrusion.resize(n);
  t.feedRate.resize(n);
  t.kind.resize(n);
  t.layer.resize(n);
  for (vtkIdType i = 0; i < n; ++i) {
    const std::string at = "toolpath point " + std::to_string(i);
    if (!t.points[i].allFinite()) {
      throw GeoLatticeError(at + " has a NaN or infinite coordinate");
    }
    double v[3];
    normals->GetTuple(i, v);
    const Vec3 axis(v[0], v[1], v[2]);
    const double length = axis.norm();
    if (!std::isfinite(length) || !(length > 1e-12)) {
      throw GeoLatticeError(at + " has a NaN or zero nozzle axis (" + arrays::NozzleAxis + ")");
    }
    t.normals[i] = axis / length;
    t.extrusion[i] = extrusion->GetComponent(i, 0);
    if (!std::isfinite(t.extrusion[i])) {
      throw GeoLatticeError(at + " has a non-finite " + arrays::Extrusion);
    }
    t.feedRate[i] = feedRate->GetComponent(i, 0);
    if (i > 0 && !(std::isfinite(t.feedRate[i]) && t.feedRate[i] > 0)) {
      throw GeoLatticeError(at + " has " + arrays::FeedRate + " " + std::to_string(t.feedRate[i]) +
                            "; feed rates must be > 0 mm/s");
    }
    t.kind[i] = integerValue(kind, i, "toolpath point");
    if (t.kind[i] != movekind::Print && t.kind[i] != movekind::Perimeter &&
        t.kind[i] != movekind::Air) {
      throw GeoLatticeError(at + " has " + arrays::MoveKind + " " + std::to_string(t.kind[i]) +
                            " (0 print, 1 perimeter, 2 air)");
    }
    t.layer[i] = integerValue(layer, i, "toolpath point");
  }
  return t;
}

NozzleModel nozzleModel(vtkGLNozzle* n) {
  NozzleModel nozzle;
  nozzle.halfAngleDeg = n->GetNozzleAngle();
  nozzle.length =
      n->GetNozzleLength() == 0 ? std::numeric_limits<double>::infinity() : n->GetNozzleLength();
  nozzle.holderRadius = n->GetHolderRadius();
  nozzle.holderLength =
      n->GetHolderLength() == 0 ? std::numeric_limits<double>::infinity() : n->GetHolderLength();
  nozzle.tipClearance = n->GetTipClearance();
  nozzle.tipFaceRadius = n->GetTipFaceRadius();
  nozzle.faceContact = n->GetFaceContact();
  if (n->GetPrintheadFile() && n->GetPrintheadFile()[0] != '\0') {
    nozzle.printhead = readPrintheadFile(n->GetPrintheadFile());
  }
  nozzle.validate();
  return nozzle;
}

BuildPlate buildPlate(vtkGLNozzle* n) {
  BuildPlate plate;
  plate.enabled = n->GetBuildPlate() != 0;
  plate.margin = n->GetPlateMargin();
  plate.thickness = n->GetPlateThickness();
  plate.validate();
  return plate;
}

vtkSmartPointer<vtkIntArray> intArray(const char* name, vtkIdType n) {
  auto a = vtkSmartPointer<vtkIntArray>::New();
  a->SetName(name);
  a->SetNumberOfTuples(n);
  return a;
}

vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, const std::vector<double>& values,
                                            int components) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / components));
  std::copy(values.begin(), values.end(), a->GetPointer(0));
  return a;
}

vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, const Eigen::VectorXd& values) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  std::copy(values.data(), values.data() + values.size(), a->GetPointer(0));
  return a;
}

vtkSmartPointer<vtkDoubleArray> vectorArray(const char* name, const std::vector<Vec3>& vectors) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(static_cast<vtkIdType>(vectors.size()));
  for (size_t i = 0; i < vectors.size(); ++i) {
    a->SetTypedTuple(static_cast<vtkIdType>(i), vectors[i].data());
  }
  return a;
}

vtkSmartPointer<vtkPoints> pointsOf(const std::vector<Vec3>& positions) {
  auto out = vtkSmartPointer<vtkPoints>::New();
  out->SetDataTypeToDouble();
  out->SetNumberOfPoints(static_cast<vtkIdType>(positions.size()));
  for (size_t i = 0; i < positions.size(); ++i) {
    out->SetPoint(static_cast<vtkIdType>(i), positions[i].data());
  }
  return out;
}

void addFieldArray(vtkFieldData* fd, const char* name, const std::vector<double>& values,
                   int components) {
  fd->AddArray(doubleArray(name, values, components));
}

void addFieldText(vtkFieldData* fd, const char* name, const std::string& text) {
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->InsertNextValue(text);
  fd->AddArray(array);
}

void addSurfaceRepairArrays(vtkFieldData* fd, const SurfaceRepairCounts& repairs) {
  addFieldArray(fd, arrays::MergedBodies, {static_cast<double>(repairs.mergedBodies)});
  addFieldArray(fd, arrays::DuplicateTriangles, {static_cast<double>(repairs.duplicateTriangles)});
  addFieldArray(fd, arrays::ReorientedTriangles,
                {static_cast<double>(repairs.reorientedTriangles)});
  addFieldArray(fd, arrays::DegenerateTrianglesRemoved,
                {static_cast<double>(repairs.degenerateTriangles)});
  addFieldArray(fd, arrays::WeldedVertices, {static_cast<double>(repairs.weldedVertices)});
  addFieldArray(fd, arrays::InvertedBodies, {static_cast<double>(repairs.invertedBodies)});
}

}  // namespace geolattice
