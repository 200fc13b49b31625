#include "vtkGLCurvedLayerSlicer.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLProgress.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "slicer/CurvedLayerSlicer.h"
#include "slicer/LayerStatistics.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>

vtkStandardNewMacro(vtkGLCurvedLayerSlicer);

namespace {
namespace gl = geolattice;

Eigen::VectorXd requirePointArray(vtkUnstructuredGrid* grid, const char* name) {
  vtkDataArray* a = grid->GetPointData()->GetArray(name);
  if (!a) {
    throw gl::GeoLatticeError(std::string("input has no point array '") + name +
                              "' (apply GL Geodesic Distance Fields first)");
  }
  Eigen::VectorXd v(a->GetNumberOfTuples());
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) {
    v[i] = a->GetComponent(i, 0);
  }
  return v;
}

/// Polydata of the extracted layers [l0, l1) of `layers` (points and triangles are grouped by
/// layer, so a layer range is a contiguous range of both).
void buildPolyData(const gl::CurvedLayers& layers, const std::vector<int>& triangleComponent,
                   int l0, int l1, vtkPolyData* out) {
  out->Initialize();
  if (l0 >= l1) {
    return;
  }
  const int p0 = layers.layerPointOffset[l0], p1 = layers.layerPointOffset[l1];
  const int t0 = layers.layerTriangleOffset[l0], t1 = layers.layerTriangleOffset[l1];
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(p1 - p0);
  vtkNew<vtkDoubleArray> gamma, alpha, beta, normals, edgeT;
  vtkNew<vtkIdTypeArray> edge;
  gamma->SetName(gl::arrays::Gamma);
  alpha->SetName(gl::arrays::Alpha);
  beta->SetName(gl::arrays::Beta);
  normals->SetName(gl::arrays::Normals);
  normals->SetNumberOfComponents(3);
  edge->SetName(gl::arrays::SourceEdge);
  edge->SetNumberOfComponents(2);
  edgeT->SetName(gl::arrays::EdgeParameter);
  for (vtkDataArray* a :
       std::initializer_list<vtkDataArray*>{gamma, alpha, beta, normals, edge, edgeT}) {
    a->SetNumberOfTuples(p1 - p0);
  }
  for (int p = p0; p < p1; ++p) {
    const vtkIdType k = p - p0;
    points->SetPoint(k, layers.points[p].data());
    gamma->SetValue(k, layers.layerValues[layers.pointLayer[p]]);
    alpha->SetValue(k, layers.alpha[p]);
    beta->SetValue(k, layers.beta[p]);
    normals->SetTypedTuple(k, layers.normals[p].data());
    edge->SetTypedComponent(k, 0, layers.sourceEdge[p][0]);
    edge->SetTypedComponent(k, 1, layers.sourceEdge[p][1]);
    edgeT->SetValue(k, layers.edgeParameter[p]);
  }
  out->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(t1 - t0, 3 * (t1 - t0));
  vtkNew<vtkIntArray> layerId, component;
  layerId->SetName(gl::arrays::LayerId);
  component->SetName(gl::arrays::LayerComponent);
  layerId->SetNumberOfTuples(t1 - t0);
  component->SetNumberOfTuples(t1 - t0);
  for (int t = t0; t < t1; ++t) {
    const auto& f = layers.triangles[t];
    const vtkIdType ids[3] = {f[0] - p0, f[1] - p0, f[2] - p0};
    polys->InsertNextCell(3, ids);
    layerId->SetValue(t - t0, layers.layerIndex[layers.triangleLayer[t]]);
    component->SetValue(t - t0, triangleComponent[t]);
  }
  out->SetPolys(polys);
  vtkPointData* pd = out->GetPointData();
  pd->AddArray(gamma);
  pd->AddArray(alpha);
  pd->AddArray(beta);
  pd->SetNormals(normals);
  pd->AddArray(edge);
  pd->AddArray(edgeT);
  pd->SetActiveScalars(gl::arrays::Gamma);
  out->GetCellData()->AddArray(layerId);
  out->GetCellData()->AddArray(component);
}

}  // namespace

vtkGLCurvedLayerSlicer::vtkGLCurvedLayerSlicer() {
  this->SetNumberOfOutputPorts(2);
}

int vtkGLCurvedLayerSlicer::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

int vtkGLCurvedLayerSlicer::RequestInformation(vtkInformation*, vtkInformationVector**,
                                               vtkInformationVector*) {
  return gl::checkParameters(this, [&] { this->Options.validate(); });
}

int vtkGLCurvedLayerSlicer::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                        vtkInformationVector* outputVector) {
  // Collective in an MPI run: the whole tet mesh on one process (vtkGLParallel.h).
  return gl::runRequest(this, inputVector, 1, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkPolyData* all = vtkPolyData::GetData(outputVector, 0);
    vtkPolyData* selected = vtkPolyData::GetData(outputVector, 1);
    vtkUnstructuredGrid* input = inputs.Get<vtkUnstructuredGrid>(0);
    const gl::TetMesh mesh = gl::toTetMesh(input);
    const Eigen::VectorXd gamma = requirePointArray(input, gl::arrays::Gamma);
    const Eigen::VectorXd alpha = requirePointArray(input, gl::arrays::Alpha);
    const Eigen::VectorXd beta = requirePointArray(input, gl::arrays::Beta);
    gl::checkAbort(this, 0.05);
    const std::vector<gl::Vec3> normals = gl::vertexGradientDirections(mesh, gamma);
    gl::checkAbort(this, 0.1);
    gl::SlicerOptions options = this->Options;
    options.progress = gl::progressRange(this, 0.1, 0.6);
    options.shouldAbort = gl::abortFlag(this);
    const gl::CurvedLayers layers =
        gl::sliceCurvedLayers(mesh, gamma, alpha, beta, normals, options);
    gl::checkAbort(this, 0.6);
    const int L = static_cast<int>(layers.layerValues.size());
    std::vector<int> triangleComponent(layers.triangles.size());
    std::vector<double> componentCount(L);
    std::vector<int> local;
    const int stride = std::max(1, L / 16);
    for (int l = 0; l < L; ++l) {
      if (l % stride == 0) {
        gl::checkAbort(this, 0.6 + 0.15 * l / L);
      }
      componentCount[l] = gl::layerComponents(layers, l, local);
      std::copy(local.begin(), local.end(),
                triangleComponent.begin() + layers.layerTriangleOffset[l]);
    }
    gl::checkAbort(this, 0.75);
    buildPolyData(layers, triangleComponent, 0, L, all);
    const int s = this->SelectedLayer - layers.layerIndex.front();
    buildPolyData(layers, triangleComponent, std::max(0, s), s >= 0 && s < L ? s + 1 : 0, selected);
    gl::checkAbort(this, 0.85);

    vtkNew<vtkFieldData> fd;
    gl::addFieldArray(fd, gl::arrays::LayerValues, layers.layerValues);
    gl::addFieldArray(fd, gl::arrays::LayerComponents, componentCount);
    if (this->ComputeStatistics) {
      const auto stats = gl::computeLayerStatistics(layers, 0, gl::progressRange(this, 0.85, 0.95),
                                                    gl::abortFlag(this));
      std::vector<double> area(L), smin(L), smean(L), smax(L);
      for (int l = 0; l < L; ++l) {
        area[l] = stats[l].area;
        smin[l] = stats[l].spacingMin;
        smean[l] = stats[l].spacingMean;
        smax[l] = stats[l].spacingMax;
      }
      gl::addFieldArray(fd, gl::arrays::LayerArea, area);
      gl::addFieldArray(fd, gl::arrays::LayerSpacingMin, smin);
      gl::addFieldArray(fd, gl::arrays::LayerSpacingMean, smean);
      gl::addFieldArray(fd, gl::arrays::LayerSpacingMax, smax);
      gl::checkAbort(this, 0.95);
    }
    all->SetFieldData(fd);
    selected->GetFieldData()->PassData(fd);
    this->UpdateProgress(1.0);
  });
}

void vtkGLCurvedLayerSlicer::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LayerInterval: " << this->Options.interval << " mm\n";
  os << indent << "FirstLayerOffset: " << this->Options.firstLayerOffset << " mm\n";
  os << indent << "FirstLayer: " << this->Options.firstLayer << "\n";
  os << indent << "LastLayer: " << this->Options.lastLayer << "\n";
  os << indent << "MaximumElements: " << this->Options.maxElements << "\n";
  os << indent << "SelectedLayer: " << this->SelectedLayer << "\n";
  os << indent << "ComputeStatistics: " << this->ComputeStatistics << "\n";
}
