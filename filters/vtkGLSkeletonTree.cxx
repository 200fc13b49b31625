#include "vtkGLSkeletonTree.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLProgress.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "lattice/LatticeInfill.h"
#include "skeleton/SkeletonTree.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
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
#include <vtkUnstructuredGrid.h>

#include <chrono>
#include <string>

vtkStandardNewMacro(vtkGLSkeletonTree);

namespace {
namespace gl = geolattice;

void buildOutput(const gl::SkeletonTree& tree, double seconds, vtkPolyData* out) {
  const vtkIdType N = static_cast<vtkIdType>(tree.nodes.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(N);
  auto nodeId = gl::intArray(gl::arrays::NodeId, N);
  auto layerId = gl::intArray(gl::arrays::LayerId, N);
  auto subgraphId = gl::intArray(gl::arrays::SubgraphId, N);
  auto lowerCount = gl::intArray(gl::arrays::LowerCount, N);
  auto upperCount = gl::intArray(gl::arrays::UpperCount, N);
  vtkNew<vtkDoubleArray> gamma, length;
  gamma->SetName(gl::arrays::Gamma);
  gamma->SetNumberOfTuples(N);
  length->SetName(gl::arrays::SubgraphLength);
  length->SetNumberOfTuples(N);
  for (vtkIdType i = 0; i < N; ++i) {
    const gl::SkeletonNode& n = tree.nodes[i];
    points->SetPoint(i, n.centroid.data());
    nodeId->SetValue(i, static_cast<int>(i));
    layerId->SetValue(i, n.layer);
    subgraphId->SetValue(i, static_cast<int>(i));
    lowerCount->SetValue(i, static_cast<int>(n.lower.size()));
    upperCount->SetValue(i, static_cast<int>(n.upper.size()));
    gamma->SetValue(i, tree.layerValues[n.layer]);
    length->SetValue(i, n.length);
  }
  out->SetPoints(points);
  vtkNew<vtkCellArray> lines;
  const vtkIdType E = static_cast<vtkIdType>(tree.edges.size());
  lines->AllocateExact(E, 2 * E);
  for (const auto& e : tree.edges) {
    const vtkIdType ids[2] = {e[0], e[1]};
    lines->InsertNextCell(2, ids);
  }
  out->SetLines(lines);
  vtkPointData* pd = out->GetPointData();
  pd->AddArray(nodeId);
  pd->AddArray(layerId);
  pd->AddArray(subgraphId);
  pd->AddArray(gamma);
  pd->AddArray(length);
  pd->AddArray(lowerCount);
  pd->AddArray(upperCount);
  pd->SetActiveScalars(gl::arrays::LayerId);

  vtkFieldData* fd = out->GetFieldData();
  gl::addFieldArray(fd, gl::arrays::SkeletonRoots, {static_cast<double>(tree.roots)});
  gl::addFieldArray(fd, gl::arrays::SkeletonFloatingNodes,
                    {static_cast<double>(tree.floatingNodes)});
  gl::addFieldArray(fd, gl::arrays::SkeletonMergeNodes, {static_cast<double>(tree.mergeNodes)});
  gl::addFieldArray(fd, gl::arrays::SkeletonSplitNodes, {static_cast<double>(tree.splitNodes)});
  gl::addFieldArray(fd, gl::arrays::SkeletonSeconds, {seconds});
  gl::addFieldArray(fd, gl::arrays::LayerValues, tree.layerValues);
}
}  // namespace

vtkGLSkeletonTree::vtkGLSkeletonTree() {
  this->SetNumberOfInputPorts(2);
}

int vtkGLSkeletonTree::FillInputPortInformation(int port, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(),
            port == 0 ? "vtkPolyData" : "vtkUnstructuredGrid");
  return 1;
}

int vtkGLSkeletonTree::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                   vtkInformationVector* outputVector) {
  // Collective in an MPI run: the lattice and the tet mesh on one process (vtkGLParallel.h).
  return gl::runRequest(this, inputVector, 2, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    vtkPolyData* lattice = inputs.Get<vtkPolyData>(0);
    vtkUnstructuredGrid* grid = inputs.Get<vtkUnstructuredGrid>(1);
    const auto t0 = std::chrono::steady_clock::now();
    const gl::LatticeGraph graph = gl::toLatticeGraph(lattice);
    if (!grid) {
      throw gl::GeoLatticeError(
          "no tet mesh on input port 1 (connect the output of GL Geodesic Distance Fields)");
    }
    const gl::TetMesh mesh = gl::toTetMesh(grid);
    vtkDataArray* gammaArray = grid->GetPointData()->GetArray(gl::arrays::Gamma);
    if (!gammaArray) {
      throw gl::GeoLatticeError(
          "the tet mesh has no point array 'Gamma' (apply GL Geodesic Distance Fields first)");
    }
    Eigen::VectorXd gamma(gammaArray->GetNumberOfTuples());
    for (vtkIdType i = 0; i < gammaArray->GetNumberOfTuples(); ++i) {
      gamma[i] = gammaArray->GetComponent(i, 0);
    }
    gl::checkAbort(this, 0.2);
    gl::SkeletonTreeOptions options;
    options.progress = gl::progressRange(this, 0.2, 0.95);
    options.shouldAbort = gl::abortFlag(this);
    const gl::SkeletonTree tree = gl::buildSkeletonTree(mesh, gamma, graph, options);
    gl::checkAbort(this, 0.95);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    buildOutput(tree, seconds, output);
    this->UpdateProgress(1.0);
  });
}

void vtkGLSkeletonTree::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
}
