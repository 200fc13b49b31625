// vtkGLSkeletonTree: the chain of a box's layers with the documented arrays (GDF -> slicer ->
// lattice -> skeleton), the lattice and skeleton conversions of vtkGLMeshConversion.h, and bad input.
#include "GLTestArrays.h"
#include "GLTestErrorObserver.h"
#include "GLTestProgress.h"

#include "mesh/AnalyticShapes.h"
#include "vtkGLArrayNames.h"
#include "vtkGLCurvedLayerSlicer.h"
#include "vtkGLGeodesicDistanceFields.h"
#include "vtkGLLatticeInfill.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLSkeletonTree.h"

#include "common/Error.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

namespace arrays = geolattice::arrays;
namespace gl = geolattice;
using geolattice::Vec3;

namespace {

/// GDF -> slicer -> lattice on the 20 x 20 x 15 box (2 mm tets): 13 layers z = 0.5 .. 12.5, one
/// 5 x 5 grid per layer; then the skeleton.
struct BoxPipeline {
  vtkSmartPointer<vtkUnstructuredGrid> grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkGLGeodesicDistanceFields> gdf;
  vtkNew<vtkGLCurvedLayerSlicer> slicer;
  vtkNew<vtkGLLatticeInfill> lattice;
  vtkNew<vtkGLSkeletonTree> skeleton;
  vtkNew<GLTestErrorObserver> errors;
  BoxPipeline() {
    gl::fromTetMesh(gl::boxTetMesh(Vec3(20, 20, 15), 10, 10, 8), grid);
    gdf->SetInputData(grid);
    slicer->SetInputConnection(gdf->GetOutputPort());
    slicer->SetLayerInterval(1.0);
    slicer->SetFirstLayerOffset(0.5);
    slicer->SetLastLayer(12);
    lattice->SetInputConnection(slicer->GetOutputPort(0));
    lattice->SetAlphaPhase(2.0);
    lattice->SetBetaPhase(2.0);
    skeleton->SetInputConnection(0, lattice->GetOutputPort());
    skeleton->SetInputConnection(1, gdf->GetOutputPort());
    errors->Observe(lattice);
    errors->Observe(skeleton);
  }
};

void expectError(vtkPolyData* lattice, vtkUnstructuredGrid* grid, const std::string& text) {
  vtkNew<vtkGLSkeletonTree> skeleton;
  skeleton->SetInputData(0, lattice);
  skeleton->SetInputData(1, grid);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(skeleton);
  skeleton->Update();
  EXPECT_TRUE(errors->HasError()) << text;
  EXPECT_NE(errors->Errors().find(text), std::string::npos) << errors->Errors();
  EXPECT_EQ(skeleton->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(skeleton->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(skeleton->GetOutput()->GetFieldData()->GetArray(arrays::SkeletonRoots), nullptr);
}

std::string conversionError(const std::function<void()>& f) {
  try {
    f();
  } catch (const gl::GeoLatticeError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(vtkGLSkeletonTree, BoxLayersGiveAChainWithTheDocumentedArrays) {
  BoxPipeline p;
  p.skeleton->Update();
  ASSERT_FALSE(p.errors->HasError()) << p.errors->Errors();
  vtkPolyData* lattice = p.lattice->GetOutput();
  vtkPolyData* out = p.skeleton->GetOutput();
  vtkDataArray* slicerValues =
      p.slicer->GetOutput(0)->GetFieldData()->GetArray(arrays::LayerValues);
  const int L = static_cast<int>(slicerValues->GetNumberOfTuples());
  ASSERT_EQ(L, 13);
  ASSERT_EQ(out->GetNumberOfPoints(), L);
  ASSERT_EQ(out->GetNumberOfCells(), L - 1);
  EXPECT_EQ(fieldValue(out, arrays::SkeletonRoots), 1.0);
  EXPECT_EQ(fieldValue(out, arrays::SkeletonFloatingNodes), 0.0);
  EXPECT_EQ(fieldValue(out, arrays::SkeletonMergeNodes), 0.0);
  EXPECT_EQ(fieldValue(out, arrays::SkeletonSplitNodes), 0.0);
  EXPECT_GE(fieldValue(out, arrays::SkeletonSeconds), 0.0);
  ASSERT_EQ(out->GetFieldData()->GetArray(arrays::LayerValues)->GetNumberOfTuples(), L);

  vtkPointData* pd = out->GetPointData();
  for (const char* name : {arrays::NodeId, arrays::LayerId, arrays::SubgraphId, arrays::Gamma,
                           arrays::SubgraphLength, arrays::LowerCount, arrays::UpperCount}) {
    ASSERT_NE(pd->GetArray(name), nullptr) << name;
  }
  for (vtkIdType i = 0; i < L; ++i) {
    EXPECT_EQ(pd->GetArray(arrays::NodeId)->GetTuple1(i), i);
    EXPECT_EQ(pd->GetArray(arrays::SubgraphId)->GetTuple1(i), i);
    EXPECT_EQ(pd->GetArray(arrays::LayerId)->GetTuple1(i), i);
    EXPECT_EQ(pd->GetArray(arrays::LowerCount)->GetTuple1(i), i > 0 ? 1 : 0);
    EXPECT_EQ(pd->GetArray(arrays::UpperCount)->GetTuple1(i), i + 1 < L ? 1 : 0);
    const double phi = fieldValue(p.slicer->GetOutput(0), arrays::LayerValues, static_cast<int>(i));
    EXPECT_NEAR(pd->GetArray(arrays::Gamma)->GetTuple1(i), phi, 1e-9);
    EXPECT_NEAR(fieldValue(out, arrays::LayerValues, static_cast<int>(i)), phi, 1e-9);
    EXPECT_NEAR(pd->GetArray(arrays::SubgraphLength)->GetTuple1(i),
                fieldValue(lattice, arrays::SubgraphLength, static_cast<int>(i)), 1e-9);
    double x[3];
    out->GetPoint(i, x);
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(x[j], fieldValue(lattice, arrays::SubgraphCentroid, 3 * static_cast<int>(i) + j),
                  1e-9);
    }
    EXPECT_NEAR(x[0], 10.0, 0.5);
    EXPECT_NEAR(x[1], 10.0, 0.5);
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c) {
    out->GetCellPoints(c, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), 2);
    EXPECT_EQ(ids->GetId(0), c);  // (lower, upper)
    EXPECT_EQ(ids->GetId(1), c + 1);
  }
}

TEST(vtkGLSkeletonTree, ConversionsRestoreTheLatticeAndTheTree) {
  BoxPipeline p;
  p.skeleton->Update();
  ASSERT_FALSE(p.errors->HasError()) << p.errors->Errors();
  vtkPolyData* lattice = p.lattice->GetOutput();
  const gl::LatticeGraph g = gl::toLatticeGraph(lattice);
  const int L = 13;
  EXPECT_EQ(g.points.size(), static_cast<size_t>(lattice->GetNumberOfPoints()));
  EXPECT_EQ(g.edges.size(), static_cast<size_t>(lattice->GetNumberOfLines()));
  ASSERT_EQ(g.layerValues.size(), static_cast<size_t>(L));
  ASSERT_EQ(g.subgraphs.size(), static_cast<size_t>(L));
  ASSERT_EQ(g.layerVertexOffset.size(), static_cast<size_t>(L + 1));  // grouped by layer
  EXPECT_EQ(g.layerSubgraphOffset.back(), L);
  for (int l = 0; l < L; ++l) {
    EXPECT_EQ(g.layerIndex[l], l);
    EXPECT_NEAR(g.layerValues[l], 0.5 + l, 0.05);
    const gl::LatticeSubgraph& s = g.subgraphs[l];
    EXPECT_EQ(s.layer, l);
    EXPECT_EQ(s.indexInLayer, 0);
    EXPECT_NEAR(s.length, fieldValue(lattice, arrays::SubgraphLength, l), 1e-9);
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(s.centroid[j], fieldValue(lattice, arrays::SubgraphCentroid, 3 * l + j), 1e-9);
    }
  }
  for (size_t v = 0; v < g.points.size(); ++v) {
    EXPECT_EQ(g.vertexSubgraph[v],
              lattice->GetPointData()->GetArray(arrays::SubgraphId)->GetTuple1(v));
    EXPECT_NEAR(g.normals[v].norm(), 1.0, 1e-9);
  }
  const gl::SkeletonTree tree = gl::toSkeletonTree(p.skeleton->GetOutput());
  ASSERT_EQ(tree.nodes.size(), static_cast<size_t>(L));
  EXPECT_EQ(tree.edges.size(), static_cast<size_t>(L - 1));
  EXPECT_EQ(tree.roots, 1);
  EXPECT_EQ(tree.layerValues.size(), static_cast<size_t>(L));
  for (int i = 0; i + 1 < L; ++i) {
    EXPECT_EQ(tree.nodes[i].upper, std::vector<int>{i + 1});
    EXPECT_EQ(tree.nodes[i + 1].lower, std::vector<int>{i});
  }

  // A polyline of 3 points is two edges; the reversed cell (upper, lower) of a skeleton is turned.
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  for (int k = 0; k < 3; ++k) {
    points->InsertNextPoint(k, 0, 1);
  }
  poly->SetPoints(points);
  vtkNew<vtkCellArray> lines;
  const vtkIdType ids[3] = {0, 1, 2};
  lines->InsertNextCell(3, ids);
  poly->SetLines(lines);
  vtkNew<vtkDoubleArray> normals, gamma;
  normals->SetName(arrays::NozzleAxis);
  normals->SetNumberOfComponents(3);
  gamma->SetName(arrays::Gamma);
  for (int k = 0; k < 3; ++k) {
    normals->InsertNextTuple3(0, 0, 2);  // normalised on conversion
    gamma->InsertNextValue(1.0);
  }
  poly->GetPointData()->AddArray(normals);
  poly->GetPointData()->AddArray(gamma);
  vtkNew<vtkIntArray> subgraph, layer;
  subgraph->SetName(arrays::SubgraphId);
  subgraph->InsertNextValue(0);
  layer->SetName(arrays::LayerId);
  layer->InsertNextValue(7);
  poly->GetCellData()->AddArray(subgraph);
  poly->GetCellData()->AddArray(layer);
  const gl::LatticeGraph line = gl::toLatticeGraph(poly);
  ASSERT_EQ(line.edges.size(), 2u);
  EXPECT_EQ(line.edges[1], (std::array<int, 2>{1, 2}));
  EXPECT_EQ(line.layerIndex, std::vector<int>{7});
  EXPECT_EQ(line.layerValues, std::vector<double>{1.0});
  EXPECT_DOUBLE_EQ(line.subgraphs[0].length, 2.0);
  EXPECT_NEAR((line.subgraphs[0].centroid - Vec3(1, 0, 1)).norm(), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(line.normals[2].z(), 1.0);

  vtkNew<vtkPolyData> reversed;
  reversed->ShallowCopy(p.skeleton->GetOutput());
  vtkNew<vtkCellArray> flipped;
  for (int i = 0; i + 1 < L; ++i) {
    const vtkIdType e[2] = {i + 1, i};
    flipped->InsertNextCell(2, e);
  }
  reversed->SetLines(flipped);
  EXPECT_EQ(gl::toSkeletonTree(reversed).edges, tree.edges);

  // Conversion errors name the problem.
  poly->GetPointData()->RemoveArray(arrays::Gamma);
  EXPECT_NE(
      conversionError([&] { gl::toLatticeGraph(poly); }).find("lattice has no Gamma point array"),
      std::string::npos);
  poly->GetPointData()->AddArray(gamma);
  subgraph->SetValue(0, 1);
  EXPECT_NE(
      conversionError([&] { gl::toLatticeGraph(poly); }).find("no line cell has SubgraphId 0"),
      std::string::npos);
  subgraph->SetValue(0, -1);
  EXPECT_NE(conversionError([&] { gl::toLatticeGraph(poly); }).find("sub-graph ids must be 0..K-1"),
            std::string::npos);
  vtkNew<vtkPolyData> badSkeleton;
  badSkeleton->DeepCopy(p.skeleton->GetOutput());
  badSkeleton->GetPointData()->GetArray(arrays::NodeId)->SetTuple1(3, 2);
  EXPECT_NE(
      conversionError([&] { gl::toSkeletonTree(badSkeleton); }).find("NodeId is not a permutation"),
      std::string::npos);
}

TEST(vtkGLSkeletonTree, BadInputIsReported) {
  BoxPipeline p;
  p.skeleton->Update();
  ASSERT_FALSE(p.errors->HasError()) << p.errors->Errors();
  auto lattice = vtkSmartPointer<vtkPolyData>::New();
  lattice->DeepCopy(p.lattice->GetOutput());
  auto fields = vtkSmartPointer<vtkUnstructuredGrid>::New();
  fields->DeepCopy(p.gdf->GetOutput());

  auto noGamma = vtkSmartPointer<vtkUnstructuredGrid>::New();
  noGamma->DeepCopy(fields);
  noGamma->GetPointData()->RemoveArray(arrays::Gamma);
  expectError(lattice, noGamma, "the tet mesh has no point array 'Gamma'");

  vtkNew<vtkPolyData> empty;
  expectError(empty, fields, "empty lattice");

  auto noSubgraph = vtkSmartPointer<vtkPolyData>::New();
  noSubgraph->DeepCopy(lattice);
  noSubgraph->GetCellData()->RemoveArray(arrays::SubgraphId);
  expectError(noSubgraph, fields, "lattice has no SubgraphId cell array");

  auto noNormals = vtkSmartPointer<vtkPolyData>::New();
  noNormals->DeepCopy(lattice);
  noNormals->GetPointData()->RemoveArray(arrays::NozzleAxis);
  expectError(noNormals, fields, "lattice has no NozzleAxis point array");

  // A lattice layer outside the tet mesh's γ range: no tet contains its sub-graph.
  auto lifted = vtkSmartPointer<vtkPolyData>::New();
  lifted->DeepCopy(lattice);
  vtkDataArray* gamma = lifted->GetPointData()->GetArray(arrays::Gamma);
  for (vtkIdType v = 0; v < gamma->GetNumberOfTuples(); ++v) {
    gamma->SetTuple1(v, gamma->GetTuple1(v) + 100.0);
  }
  vtkNew<vtkGLSkeletonTree> skeleton;
  skeleton->SetInputData(0, lifted);
  skeleton->SetInputData(1, fields);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(skeleton);
  skeleton->Update();
  EXPECT_TRUE(errors->HasError());
  EXPECT_EQ(skeleton->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(vtkGLSkeletonTree, ProgressAndAbort) {
  BoxPipeline p;
  p.lattice->Update();
  p.gdf->Update();
  ASSERT_FALSE(p.errors->HasError()) << p.errors->Errors();
  glExpectProgressReport(p.skeleton, 10);
  glExpectCleanAbort(p.skeleton, glAbortAt(0.5));
  glExpectCleanAbort(p.skeleton, glAbortAt(0.8));
}
