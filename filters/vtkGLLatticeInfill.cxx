#include "vtkGLLatticeInfill.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLProgress.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "lattice/LatticeInfill.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

vtkStandardNewMacro(vtkGLLatticeInfill);

namespace {
namespace gl = geolattice;

static_assert(
    static_cast<int>(gl::LatticeVertexKind::IsolinePoint) == gl::latticekind::VertexIsolinePoint &&
        static_cast<int>(gl::LatticeVertexKind::Crossing) == gl::latticekind::VertexCrossing &&
        static_cast<int>(gl::LatticeVertexKind::BoundaryHit) ==
            gl::latticekind::VertexBoundaryHit &&
        static_cast<int>(gl::LatticeVertexKind::Boundary) == gl::latticekind::VertexBoundary &&
        static_cast<int>(gl::LatticeEdgeKind::Alpha) == gl::latticekind::EdgeAlpha &&
        static_cast<int>(gl::LatticeEdgeKind::Beta) == gl::latticekind::EdgeBeta &&
        static_cast<int>(gl::LatticeEdgeKind::Boundary) == gl::latticekind::EdgeBoundary,
    "vtkGLArrayNames.h latticekind values must match core/lattice/LatticeInfill.h");

vtkDataArray* requireArray(vtkDataSetAttributes* data, const char* name, const char* where) {
  vtkDataArray* a = data->GetArray(name);
  if (!a) {
    throw gl::GeoLatticeError(std::string("input has no ") + where + " array '" + name +
                              "' (apply GL Curved Layer Slicer first)");
  }
  return a;
}

/// The layers of the input polydata as core CurvedLayers: triangles grouped by LayerId, points
/// copied per layer (a point shared by two layers becomes two layer points). inputPoint maps
/// each layer point back to its input point id.
gl::CurvedLayers toCurvedLayers(vtkPolyData* input, std::vector<vtkIdType>& inputPoint,
                                bool& hasGamma) {
  if (!input || input->GetNumberOfPolys() == 0) {
    throw gl::GeoLatticeError("input has no layer triangles (apply GL Curved Layer Slicer first)");
  }
  vtkPointData* pd = input->GetPointData();
  vtkDataArray* alpha = requireArray(pd, gl::arrays::Alpha, "point");
  vtkDataArray* beta = requireArray(pd, gl::arrays::Beta, "point");
  vtkDataArray* layerId = requireArray(input->GetCellData(), gl::arrays::LayerId, "cell");
  vtkDataArray* gamma = pd->GetArray(gl::arrays::Gamma);
  vtkDataArray* normals = pd->GetNormals() ? pd->GetNormals() : pd->GetArray(gl::arrays::Normals);
  if (normals && normals->GetNumberOfComponents() != 3) {
    normals = nullptr;
  }
  vtkDataArray* sourceEdge = pd->GetArray(gl::arrays::SourceEdge);
  if (sourceEdge && sourceEdge->GetNumberOfComponents() != 2) {
    sourceEdge = nullptr;
  }
  hasGamma = gamma != nullptr;

  // Triangles with their layer id (cell ids of polys follow the verts and lines).
  const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  struct Tri {
    int layer;
    vtkIdType ids[3];
  };
  std::vector<Tri> tris;
  tris.reserve(input->GetNumberOfPolys());
  gl::forEachCell(
      input->GetPolys(), firstPoly, [&](vtkIdType cell, vtkIdType n, const vtkIdType* ids) {
        if (n != 3) {
          throw gl::GeoLatticeError("cell " + std::to_string(cell) + " has " + std::to_string(n) +
                                    " points: the layers must be triangles (apply Triangulate)");
        }
        const double id = layerId->GetComponent(cell, 0);
        if (!std::isfinite(id)) {
          throw gl::GeoLatticeError("cell " + std::to_string(cell) + " has a non-finite LayerId");
        }
        tris.push_back({static_cast<int>(id), {ids[0], ids[1], ids[2]}});
      });
  std::stable_sort(tris.begin(), tris.end(),
                   [](const Tri& a, const Tri& b) { return a.layer < b.layer; });

  gl::CurvedLayers c;
  c.layerPointOffset.push_back(0);
  c.layerTriangleOffset.push_back(0);
  std::vector<int> local(input->GetNumberOfPoints(), -1);
  std::vector<vtkIdType> touched;
  for (size_t i = 0; i < tris.size();) {
    const int layer = tris[i].layer;
    const int l = static_cast<int>(c.layerValues.size());
    double gammaSum = 0;
    touched.clear();
    for (; i < tris.size() && tris[i].layer == layer; ++i) {
      std::array<int, 3> f;
      for (int k = 0; k < 3; ++k) {
        const vtkIdType p = tris[i].ids[k];
        if (local[p] < 0) {
          local[p] = static_cast<int>(c.points.size());
          touched.push_back(p);
          inputPoint.push_back(p);
          double x[3];
          input->GetPoint(p, x);
          c.points.emplace_back(x[0], x[1], x[2]);
          c.alpha.push_back(alpha->GetComponent(p, 0));
          c.beta.push_back(beta->GetComponent(p, 0));
          c.normals.push_back(normals ? gl::Vec3(normals->GetComponent(p, 0),
                                                 normals->GetComponent(p, 1),
                                                 normals->GetComponent(p, 2))
                                      : gl::Vec3::Zero());
          if (sourceEdge) {
            c.sourceEdge.push_back({static_cast<int>(sourceEdge->GetComponent(p, 0)),
                                    static_cast<int>(sourceEdge->GetComponent(p, 1))});
          }
          c.pointLayer.push_back(l);
          gammaSum += gamma ? gamma->GetComponent(p, 0) : 0.0;
        }
        f[k] = local[p];
      }
      c.triangles.push_back(f);
      c.triangleLayer.push_back(l);
    }
    for (vtkIdType p : touched) {
      local[p] = -1;
    }
    c.layerIndex.push_back(layer);
    c.layerValues.push_back(gamma ? gammaSum / static_cast<double>(touched.size())
                                  : std::numeric_limits<double>::quiet_NaN());
    c.layerPointOffset.push_back(static_cast<int>(c.points.size()));
    c.layerTriangleOffset.push_back(static_cast<int>(c.triangles.size()));
  }
  if (!normals) {
    // Area-weighted normals of the triangles (their orientation is the slicer's +∇γ).
    for (const auto& f : c.triangles) {
      const gl::Vec3 n = (c.points[f[1]] - c.points[f[0]]).cross(c.points[f[2]] - c.points[f[0]]);
      for (int v : f) {
        c.normals[v] += n;
      }
    }
    for (gl::Vec3& n : c.normals) {
      const double len = n.norm();
      n = len > 0 ? gl::Vec3(n / len) : gl::Vec3::Zero();
    }
  }
  return c;
}

void addCount(vtkFieldData* fd, const char* name, double value) {
  gl::addFieldArray(fd, name, {value});
}

void buildOutput(const gl::LatticeGraph& g, bool hasGamma, vtkPolyData* out) {
  const vtkIdType V = static_cast<vtkIdType>(g.points.size());
  const vtkIdType E = static_cast<vtkIdType>(g.edges.size());
  auto kind = gl::intArray(gl::arrays::VertexKind, V);
  auto degree = gl::intArray(gl::arrays::Degree, V);
  auto vertexSubgraph = gl::intArray(gl::arrays::SubgraphId, V);
  for (vtkIdType v = 0; v < V; ++v) {
    kind->SetValue(v, static_cast<int>(g.vertexKind[v]));
    degree->SetValue(v, g.degree[v]);
    vertexSubgraph->SetValue(v, g.vertexSubgraph[v]);
  }
  out->SetPoints(gl::pointsOf(g.points));
  vtkNew<vtkCellArray> lines;
  lines->AllocateExact(E, 2 * E);
  auto edgeKind = gl::intArray(gl::arrays::EdgeKind, E);
  auto layerId = gl::intArray(gl::arrays::LayerId, E);
  auto edgeSubgraph = gl::intArray(gl::arrays::SubgraphId, E);
  vtkNew<vtkDoubleArray> level;
  level->SetName(gl::arrays::IsolineLevel);
  level->SetNumberOfTuples(E);
  for (vtkIdType e = 0; e < E; ++e) {
    const vtkIdType ids[2] = {g.edges[e][0], g.edges[e][1]};
    lines->InsertNextCell(2, ids);
    edgeKind->SetValue(e, static_cast<int>(g.edgeKind[e]));
    layerId->SetValue(e, g.layerIndex[g.edgeLayer[e]]);
    edgeSubgraph->SetValue(e, g.edgeSubgraph[e]);
    const gl::LatticeEdgeKind k = g.edgeKind[e];
    level->SetValue(e, k == gl::LatticeEdgeKind::Alpha  ? g.alphaLevels[g.edgeLevel[e]]
                       : k == gl::LatticeEdgeKind::Beta ? g.betaLevels[g.edgeLevel[e]]
                                                        : std::numeric_limits<double>::quiet_NaN());
  }
  out->SetLines(lines);
  vtkPointData* pd = out->GetPointData();
  pd->AddArray(kind);
  pd->AddArray(degree);
  pd->AddArray(gl::vectorArray(gl::arrays::NozzleAxis, g.normals));
  if (hasGamma) {
    pd->AddArray(gl::doubleArray(gl::arrays::Gamma, g.gamma));
  }
  pd->AddArray(gl::doubleArray(gl::arrays::Alpha, g.alpha));
  pd->AddArray(gl::doubleArray(gl::arrays::Beta, g.beta));
  pd->AddArray(vertexSubgraph);
  pd->SetActiveScalars(gl::arrays::VertexKind);
  vtkCellData* cd = out->GetCellData();
  cd->AddArray(edgeKind);
  cd->AddArray(layerId);
  cd->AddArray(edgeSubgraph);
  cd->AddArray(level);
  cd->SetActiveScalars(gl::arrays::EdgeKind);

  vtkFieldData* fd = out->GetFieldData();
  addCount(fd, gl::arrays::LatticeVertices, static_cast<double>(V));
  addCount(fd, gl::arrays::LatticeEdges, static_cast<double>(E));
  addCount(fd, gl::arrays::LatticeSubgraphs, static_cast<double>(g.subgraphs.size()));
  addCount(fd, gl::arrays::LatticeCrossings, g.stats.crossings);
  addCount(fd, gl::arrays::LatticeBoundaryHits, g.stats.boundaryHits);
  addCount(fd, gl::arrays::LatticeIsolineEdges, g.stats.isolineEdges);
  addCount(fd, gl::arrays::LatticeDroppedSubgraphs, g.stats.droppedSubgraphs);
  addCount(fd, gl::arrays::LatticeIrregularVertices, g.stats.irregularVertices);
  gl::addFieldArray(fd, gl::arrays::LatticeAlphaLevels, g.alphaLevels);
  gl::addFieldArray(fd, gl::arrays::LatticeBetaLevels, g.betaLevels);
  std::vector<double> subLayer, subLength, subCentroid;
  for (const gl::LatticeSubgraph& s : g.subgraphs) {
    subLayer.push_back(g.layerIndex[s.layer]);
    subLength.push_back(s.length);
    subCentroid.insert(subCentroid.end(), s.centroid.data(), s.centroid.data() + 3);
  }
  gl::addFieldArray(fd, gl::arrays::SubgraphLayer, subLayer);
  gl::addFieldArray(fd, gl::arrays::SubgraphLength, subLength);
  gl::addFieldArray(fd, gl::arrays::SubgraphCentroid, subCentroid, 3);
}
}  // namespace

vtkGLLatticeInfill::vtkGLLatticeInfill() = default;

int vtkGLLatticeInfill::RequestInformation(vtkInformation*, vtkInformationVector**,
                                           vtkInformationVector*) {
  return gl::checkParameters(this, [&] { this->Options.validate(); });
}

int vtkGLLatticeInfill::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                    vtkInformationVector* outputVector) {
  // Collective in an MPI run: all the layers on one process (vtkGLParallel.h).
  return gl::runRequest(this, inputVector, 1, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    vtkPolyData* input = inputs.Get<vtkPolyData>(0);
    std::vector<vtkIdType> inputPoint;
    bool hasGamma = false;
    const gl::CurvedLayers layers = toCurvedLayers(input, inputPoint, hasGamma);

    gl::LatticeOptions options = this->Options;
    // Graded lattice: the width scale array, if one is selected.
    std::string scaleName;
    vtkInformation* arrayInfo = this->GetInputArrayInformation(0);
    if (arrayInfo && arrayInfo->Has(vtkDataObject::FIELD_NAME())) {
      scaleName = arrayInfo->Get(vtkDataObject::FIELD_NAME());
    }
    if (!scaleName.empty() && scaleName != "None") {
      vtkDataArray* scale = input->GetPointData()->GetArray(scaleName.c_str());
      if (!scale) {
        throw gl::GeoLatticeError("the width scale array '" + scaleName +
                                  "' is not a point array of the input");
      }
      options.widthScale.resize(inputPoint.size());
      for (size_t p = 0; p < inputPoint.size(); ++p) {
        options.widthScale[p] = scale->GetComponent(inputPoint[p], 0);
      }
    }
    options.progress = gl::progressRange(this, 0.1, 0.9);
    options.shouldAbort = gl::abortFlag(this);
    gl::checkAbort(this, 0.1);

    const gl::LatticeGraph graph = gl::buildLatticeGraph(layers, options);
    gl::checkAbort(this, 0.9);
    buildOutput(graph, hasGamma, output);
    if (graph.stats.isolineEdges == 0) {
      const auto [aLo, aHi] = std::minmax_element(layers.alpha.begin(), layers.alpha.end());
      const auto [bLo, bHi] = std::minmax_element(layers.beta.begin(), layers.beta.end());
      vtkWarningMacro(<< "empty lattice: no α- or β-isoline crosses the layers (α range [" << *aLo
                      << ", " << *aHi << "] mm, AlphaWidth " << this->Options.alphaWidth
                      << " mm; β range [" << *bLo << ", " << *bHi << "] mm, BetaWidth "
                      << this->Options.betaWidth
                      << " mm); only the layer boundaries are output (LatticeIsolineEdges = 0)");
    }
    this->UpdateProgress(1.0);
  });
}

void vtkGLLatticeInfill::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AlphaWidth: " << this->Options.alphaWidth << " mm\n";
  os << indent << "BetaWidth: " << this->Options.betaWidth << " mm\n";
  os << indent << "AlphaPhase: " << this->Options.alphaPhase << " mm\n";
  os << indent << "BetaPhase: " << this->Options.betaPhase << " mm\n";
  os << indent << "MinimumSubgraphLength: " << this->Options.minimumSubgraphLength << " mm\n";
  os << indent << "MaximumElements: " << this->Options.maxElements << "\n";
  os << indent << "MergeQuadDiagonalPoints: " << this->Options.mergeQuadDiagonalPoints << "\n";
  os << indent << "NumberOfThreads: " << this->Options.threads << "\n";
}
