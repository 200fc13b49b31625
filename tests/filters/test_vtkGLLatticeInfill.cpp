// vtkGLLatticeInfill: arrays and counts against the core graph on the analytic box layers, the
// GDF -> slicer -> lattice pipeline, the graded lattice, and bad input.
#include "GLTestErrorObserver.h"
#include "GLTestProgress.h"

#include "lattice/LatticeInfill.h"
#include "mesh/AnalyticShapes.h"
#include "slicer/CurvedLayerSlicer.h"
#include "vtkGLArrayNames.h"
#include "vtkGLCurvedLayerSlicer.h"
#include "vtkGLGeodesicDistanceFields.h"
#include "vtkGLLatticeInfill.h"
#include "vtkGLMeshConversion.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace arrays = geolattice::arrays;
namespace kind = geolattice::latticekind;
using geolattice::Vec3;

namespace {

/// The box 40 x 40 x 60 (2 mm tets) with γ = z, α = 40 - y, β = 40 - x, sliced at z = 1, 3, .., 59.
geolattice::CurvedLayers analyticBoxLayers() {
  const geolattice::TetMesh mesh = geolattice::boxTetMesh(Vec3(40, 40, 60), 20, 20, 30);
  Eigen::VectorXd gamma(mesh.points.size()), alpha(mesh.points.size()), beta(mesh.points.size());
  for (size_t v = 0; v < mesh.points.size(); ++v) {
    gamma[v] = mesh.points[v].z();
    alpha[v] = 40 - mesh.points[v].y();
    beta[v] = 40 - mesh.points[v].x();
  }
  geolattice::SlicerOptions o;
  o.interval = 2.0;
  o.firstLayerOffset = 1.0;
  return geolattice::sliceCurvedLayers(mesh, gamma, alpha, beta,
                                       geolattice::vertexGradientDirections(mesh, gamma), o);
}

/// The layers as the slicer filter writes them (optionally without some arrays).
vtkSmartPointer<vtkPolyData> toPolyData(const geolattice::CurvedLayers& c, bool withNormals = true,
                                        bool withGamma = true) {
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> gamma, alpha, beta, normals;
  vtkNew<vtkIdTypeArray> edge;
  gamma->SetName(arrays::Gamma);
  alpha->SetName(arrays::Alpha);
  beta->SetName(arrays::Beta);
  normals->SetName(arrays::Normals);
  normals->SetNumberOfComponents(3);
  edge->SetName(arrays::SourceEdge);
  edge->SetNumberOfComponents(2);
  for (size_t p = 0; p < c.points.size(); ++p) {
    points->InsertNextPoint(c.points[p].data());
    gamma->InsertNextValue(c.layerValues[c.pointLayer[p]]);
    alpha->InsertNextValue(c.alpha[p]);
    beta->InsertNextValue(c.beta[p]);
    normals->InsertNextTuple(c.normals[p].data());
    const vtkIdType e[2] = {c.sourceEdge[p][0], c.sourceEdge[p][1]};
    edge->InsertNextTypedTuple(e);
  }
  pd->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIntArray> layerId;
  layerId->SetName(arrays::LayerId);
  for (size_t t = 0; t < c.triangles.size(); ++t) {
    const vtkIdType ids[3] = {c.triangles[t][0], c.triangles[t][1], c.triangles[t][2]};
    polys->InsertNextCell(3, ids);
    layerId->InsertNextValue(c.layerIndex[c.triangleLayer[t]]);
  }
  pd->SetPolys(polys);
  pd->GetCellData()->AddArray(layerId);
  if (withGamma) {
    pd->GetPointData()->AddArray(gamma);
  }
  pd->GetPointData()->AddArray(alpha);
  pd->GetPointData()->AddArray(beta);
  if (withNormals) {
    pd->GetPointData()->SetNormals(normals);
  }
  pd->GetPointData()->AddArray(edge);
  return pd;
}

double field(vtkPolyData* pd, const char* name) {
  vtkDataArray* a = pd->GetFieldData()->GetArray(name);
  return a ? a->GetTuple1(0) : std::nan("");
}

}  // namespace

TEST(vtkGLLatticeInfill, BoxLayersGiveTheGridWithTheDocumentedArrays) {
  const geolattice::CurvedLayers layers = analyticBoxLayers();
  vtkNew<vtkGLLatticeInfill> lattice;
  lattice->SetInputData(toPolyData(layers));
  lattice->SetAlphaPhase(1.3);
  lattice->SetBetaPhase(2.1);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(lattice);
  lattice->Update();
  ASSERT_FALSE(errors->HasError()) << errors->Errors();
  EXPECT_EQ(errors->GetWarningCount(), 0) << errors->Warnings();
  vtkPolyData* out = lattice->GetOutput();

  geolattice::LatticeOptions o;
  o.alphaPhase = 1.3;
  o.betaPhase = 2.1;
  const geolattice::LatticeGraph g = geolattice::buildLatticeGraph(layers, o);
  EXPECT_EQ(out->GetNumberOfPoints(), static_cast<vtkIdType>(g.points.size()));
  EXPECT_EQ(out->GetNumberOfLines(), static_cast<vtkIdType>(g.edges.size()));
  EXPECT_EQ(field(out, arrays::LatticeCrossings), 100.0 * 30);
  EXPECT_EQ(field(out, arrays::LatticeBoundaryHits), 40.0 * 30);
  EXPECT_EQ(field(out, arrays::LatticeSubgraphs), 30.0);
  EXPECT_EQ(field(out, arrays::LatticeVertices), static_cast<double>(out->GetNumberOfPoints()));
  EXPECT_EQ(field(out, arrays::LatticeEdges), static_cast<double>(out->GetNumberOfLines()));
  EXPECT_EQ(field(out, arrays::LatticeDroppedSubgraphs), 0.0);
  EXPECT_EQ(field(out, arrays::LatticeIrregularVertices), 0.0);
  EXPECT_GT(field(out, arrays::LatticeIsolineEdges), 0.0);
  ASSERT_NE(out->GetFieldData()->GetArray(arrays::LatticeAlphaLevels), nullptr);
  EXPECT_EQ(out->GetFieldData()->GetArray(arrays::LatticeAlphaLevels)->GetNumberOfTuples(), 10);
  EXPECT_EQ(out->GetFieldData()->GetArray(arrays::SubgraphLength)->GetNumberOfTuples(), 30);
  EXPECT_EQ(out->GetFieldData()->GetArray(arrays::SubgraphCentroid)->GetNumberOfComponents(), 3);
  EXPECT_EQ(out->GetFieldData()->GetArray(arrays::SubgraphLayer)->GetTuple1(29), 29.0);

  vtkPointData* pd = out->GetPointData();
  for (const char* name : {arrays::VertexKind, arrays::Degree, arrays::Gamma, arrays::Alpha,
                           arrays::Beta, arrays::SubgraphId}) {
    ASSERT_NE(pd->GetArray(name), nullptr) << name;
  }
  ASSERT_NE(pd->GetArray(arrays::NozzleAxis), nullptr);
  EXPECT_EQ(pd->GetNormals(), nullptr);  // not lit by the nozzle axis in ParaView
  vtkCellData* cd = out->GetCellData();
  for (const char* name :
       {arrays::EdgeKind, arrays::LayerId, arrays::SubgraphId, arrays::IsolineLevel}) {
    ASSERT_NE(cd->GetArray(name), nullptr) << name;
  }
  // Degrees recounted from the line cells; kinds against the degree rules; γ = layer z.
  std::vector<int> degree(out->GetNumberOfPoints(), 0);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c) {
    out->GetCellPoints(c, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), 2);
    ++degree[ids->GetId(0)];
    ++degree[ids->GetId(1)];
    const int k = static_cast<int>(cd->GetArray(arrays::EdgeKind)->GetTuple1(c));
    const double level = cd->GetArray(arrays::IsolineLevel)->GetTuple1(c);
    EXPECT_EQ(k == kind::EdgeBoundary, std::isnan(level));
    if (k == kind::EdgeAlpha) {
      EXPECT_NEAR(pd->GetArray(arrays::Alpha)->GetTuple1(ids->GetId(0)), level, 1e-9);
    }
  }
  int crossings = 0;
  for (vtkIdType v = 0; v < out->GetNumberOfPoints(); ++v) {
    const int k = static_cast<int>(pd->GetArray(arrays::VertexKind)->GetTuple1(v));
    ASSERT_EQ(degree[v], pd->GetArray(arrays::Degree)->GetTuple1(v));
    EXPECT_EQ(degree[v], k == kind::VertexCrossing ? 4 : k == kind::VertexBoundaryHit ? 3 : 2);
    crossings += k == kind::VertexCrossing;
    EXPECT_NEAR(pd->GetArray(arrays::Gamma)->GetTuple1(v), out->GetPoint(v)[2], 1e-9);
    EXPECT_NEAR(pd->GetArray(arrays::NozzleAxis)->GetComponent(v, 2), 1.0, 1e-9);
  }
  EXPECT_EQ(crossings, 3000);
}

TEST(vtkGLLatticeInfill, PipelineFromTheTetGridThroughTheSlicer) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  geolattice::fromTetMesh(geolattice::boxTetMesh(Vec3(20, 20, 15), 10, 10, 8), grid);
  vtkNew<vtkGLGeodesicDistanceFields> gdf;
  gdf->SetInputData(grid);
  vtkNew<vtkGLCurvedLayerSlicer> slicer;
  slicer->SetInputConnection(gdf->GetOutputPort());
  slicer->SetLayerInterval(1.0);
  slicer->SetFirstLayerOffset(0.5);
  slicer->SetLastLayer(12);  // z <= 12.5: clear of the top face, where the last layer is partial
  vtkNew<vtkGLLatticeInfill> lattice;
  lattice->SetInputConnection(slicer->GetOutputPort(0));
  lattice->SetAlphaPhase(2.0);
  lattice->SetBetaPhase(2.0);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(lattice);
  lattice->Update();
  ASSERT_FALSE(errors->HasError()) << errors->Errors();
  vtkPolyData* out = lattice->GetOutput();
  const double layers =
      slicer->GetOutput(0)->GetFieldData()->GetArray(arrays::LayerValues)->GetNumberOfTuples();
  // α, β ≈ 20 - y, 20 - x: levels 2, 6, .., 18 -> 5 x 5 crossings on every layer.
  EXPECT_EQ(field(out, arrays::LatticeCrossings), 25 * layers);
  EXPECT_EQ(field(out, arrays::LatticeSubgraphs), layers);
  EXPECT_EQ(field(out, arrays::LatticeIrregularVertices), 0.0);
  double range[2];
  out->GetCellData()->GetArray(arrays::LayerId)->GetRange(range);
  EXPECT_EQ(range[0], 0.0);
  EXPECT_EQ(range[1], layers - 1);
  std::printf(
      "[lattice filter] GDF box 20x20x15: %g layers, %lld vertices, %lld edges, %g crossings\n",
      layers, static_cast<long long>(out->GetNumberOfPoints()),
      static_cast<long long>(out->GetNumberOfLines()), field(out, arrays::LatticeCrossings));
}

TEST(vtkGLLatticeInfill, GradedLatticeFromAPointArray) {
  const geolattice::CurvedLayers layers = analyticBoxLayers();
  auto input = toPolyData(layers);
  vtkNew<vtkDoubleArray> scale;
  scale->SetName("Scale");
  scale->SetNumberOfTuples(input->GetNumberOfPoints());
  scale->Fill(0.5);
  input->GetPointData()->AddArray(scale);
  vtkNew<vtkGLLatticeInfill> lattice;
  lattice->SetInputData(input);
  lattice->SetAlphaPhase(1.0);
  lattice->SetBetaPhase(1.0);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(lattice);
  lattice->Update();
  ASSERT_FALSE(errors->HasError());
  EXPECT_EQ(field(lattice->GetOutput(), arrays::LatticeCrossings), 100.0 * 30);  // uniform: 10 x 10
  lattice->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Scale");
  lattice->Update();
  ASSERT_FALSE(errors->HasError()) << errors->Errors();
  EXPECT_EQ(field(lattice->GetOutput(), arrays::LatticeCrossings), 400.0 * 30);  // 2 mm: 20 x 20
  lattice->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "None");
  lattice->Update();
  ASSERT_FALSE(errors->HasError());
  EXPECT_EQ(field(lattice->GetOutput(), arrays::LatticeCrossings), 100.0 * 30);
  lattice->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "NoSuchArray");
  lattice->Update();
  EXPECT_TRUE(errors->HasError());
  EXPECT_NE(errors->Errors().find("NoSuchArray"), std::string::npos) << errors->Errors();
  EXPECT_EQ(lattice->GetOutput()->GetNumberOfPoints(), 0);
  errors->Clear();
  scale->SetValue(5, -1.0);
  scale->Modified();
  lattice->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Scale");
  lattice->Update();
  EXPECT_NE(errors->Errors().find("width scale must be > 0"), std::string::npos)
      << errors->Errors();
  EXPECT_EQ(lattice->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(vtkGLLatticeInfill, WithoutNormalsAndGammaAndWithMinimumLength) {
  const geolattice::CurvedLayers layers = analyticBoxLayers();
  vtkNew<vtkGLLatticeInfill> lattice;
  lattice->SetInputData(toPolyData(layers, false, false));
  lattice->SetMinimumSubgraphLength(1e6);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(lattice);
  lattice->Update();
  ASSERT_FALSE(errors->HasError()) << errors->Errors();
  EXPECT_EQ(field(lattice->GetOutput(), arrays::LatticeDroppedSubgraphs), 30.0);
  EXPECT_EQ(lattice->GetOutput()->GetNumberOfPoints(), 0);
  lattice->SetMinimumSubgraphLength(0);
  lattice->Update();
  vtkPolyData* out = lattice->GetOutput();
  EXPECT_EQ(out->GetPointData()->GetArray(arrays::Gamma), nullptr);
  ASSERT_NE(out->GetPointData()->GetArray(arrays::NozzleAxis), nullptr);
  for (vtkIdType v = 0; v < out->GetNumberOfPoints(); ++v) {
    ASSERT_NEAR(out->GetPointData()->GetArray(arrays::NozzleAxis)->GetComponent(v, 2), 1.0,
                1e-9);  // from the triangles
  }
  EXPECT_EQ(field(out, arrays::LatticeCrossings), 81.0 * 30);
}

TEST(vtkGLLatticeInfill, WidthLargerThanThePartIsAnEmptyLatticeWithAWarning) {
  vtkNew<vtkGLLatticeInfill> lattice;
  lattice->SetInputData(toPolyData(analyticBoxLayers()));
  lattice->SetAlphaWidth(1000);
  lattice->SetBetaWidth(1000);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(lattice);
  lattice->Update();
  EXPECT_FALSE(errors->HasError()) << errors->Errors();
  EXPECT_EQ(errors->GetWarningCount(), 1);
  EXPECT_NE(errors->Warnings().find("empty lattice"), std::string::npos) << errors->Warnings();
  vtkPolyData* out = lattice->GetOutput();
  EXPECT_EQ(field(out, arrays::LatticeIsolineEdges), 0.0);
  EXPECT_EQ(field(out, arrays::LatticeCrossings), 0.0);
  EXPECT_EQ(field(out, arrays::LatticeSubgraphs), 30.0);  // the layer boundaries remain
  double range[2];
  out->GetCellData()->GetArray(arrays::EdgeKind)->GetRange(range);
  EXPECT_EQ(range[0], kind::EdgeBoundary);
}

TEST(vtkGLLatticeInfill, BadInputIsReported) {
  const geolattice::CurvedLayers layers = analyticBoxLayers();
  auto expectError = [](vtkPolyData* input, const std::string& text, double width = 4.0) {
    vtkNew<vtkGLLatticeInfill> lattice;
    lattice->SetInputData(input);
    lattice->SetAlphaWidth(width);
    vtkNew<GLTestErrorObserver> errors;
    errors->Observe(lattice);
    lattice->Update();
    EXPECT_TRUE(errors->HasError()) << text;
    EXPECT_NE(errors->Errors().find(text), std::string::npos) << errors->Errors();
    EXPECT_EQ(lattice->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(lattice->GetOutput()->GetNumberOfCells(), 0);
  };
  auto noAlpha = toPolyData(layers);
  noAlpha->GetPointData()->RemoveArray(arrays::Alpha);
  expectError(noAlpha, "no point array 'Alpha'");
  auto noBeta = toPolyData(layers);
  noBeta->GetPointData()->RemoveArray(arrays::Beta);
  expectError(noBeta, "no point array 'Beta'");
  auto noLayer = toPolyData(layers);
  noLayer->GetCellData()->RemoveArray(arrays::LayerId);
  expectError(noLayer, "no cell array 'LayerId'");
  expectError(toPolyData(layers), "lattice width must be > 0", 0.0);
  expectError(toPolyData(layers), "lattice width must be > 0", -4.0);
  vtkNew<vtkPolyData> empty;
  expectError(empty, "no layer triangles");
  // A quad among the triangles.
  auto quad = toPolyData(layers);
  const vtkIdType ids[4] = {0, 1, 2, 3};
  quad->GetPolys()->InsertNextCell(4, ids);
  vtkIntArray::SafeDownCast(quad->GetCellData()->GetArray(arrays::LayerId))->InsertNextValue(0);
  expectError(quad, "must be triangles");
}

TEST(vtkGLLatticeInfill, ProgressPerLayerAndAbort) {
  auto layers = toPolyData(analyticBoxLayers());  // 30 layers
  vtkNew<vtkGLLatticeInfill> filter;
  filter->SetInputData(layers);
  filter->SetNumberOfThreads(1);  // every layer reported by the calling thread
  glExpectProgressReport(filter, 25);
  glExpectCleanAbort(filter, glAbortAt(0.3));
  filter->SetNumberOfThreads(2);  // the other worker finishes its layer, silently
  glExpectCleanAbort(filter, glAbortAt(0.3));
}
