#include "vtkGLOverhangAnalysis.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLProgress.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "mesh/TetMeshTopology.h"
#include "overhang/OverhangAnalysis.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <string>
#include <vector>

vtkStandardNewMacro(vtkGLOverhangAnalysis);

namespace {
namespace gl = geolattice;

/// The named array of `data` with `components` components, or a GeoLatticeError naming it.
vtkDataArray* requireArray(vtkDataSetAttributes* data, const char* name, const char* kind,
                           int components, const char* what) {
  vtkDataArray* a = data->GetArray(name);
  if (!a) {
    throw gl::GeoLatticeError(std::string("missing ") + kind + " array '" + name + "' (" + what +
                              "): run GL Geodesic Distance Fields first");
  }
  if (a->GetNumberOfComponents() != components) {
    throw gl::GeoLatticeError(std::string(kind) + " array '" + name + "' has " +
                              std::to_string(a->GetNumberOfComponents()) +
                              " components, expected " + std::to_string(components));
  }
  return a;
}

}  // namespace

vtkGLOverhangAnalysis::vtkGLOverhangAnalysis() {
  this->ThresholdAngle = gl::OverhangOptions{}.thresholdDeg;  // the default lives in core
}

int vtkGLOverhangAnalysis::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

int vtkGLOverhangAnalysis::RequestInformation(vtkInformation*, vtkInformationVector**,
                                              vtkInformationVector*) {
  return gl::checkParameters(this, [&] { gl::OverhangOptions{this->ThresholdAngle}.validate(); });
}

int vtkGLOverhangAnalysis::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                       vtkInformationVector* outputVector) {
  // Collective in an MPI run: the whole tet mesh on one process (vtkGLParallel.h).
  return gl::runRequest(this, inputVector, 1, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    vtkUnstructuredGrid* input = inputs.Get<vtkUnstructuredGrid>(0);
    if (!input || input->GetNumberOfCells() == 0) {
      throw gl::GeoLatticeError("the input has no cells");
    }
    gl::OverhangOptions options;
    options.thresholdDeg = this->ThresholdAngle;
    // Array checks first: they are cheap, and name the likely mistake (input not from the GDF).
    vtkDataArray* gradient = requireArray(input->GetCellData(), gl::arrays::GammaGradient, "cell",
                                          3, "the curved-layer nozzle axis per tet");
    vtkDataArray* base = requireArray(input->GetPointData(), gl::arrays::HeatSource, "point", 1,
                                      "1 on the base vertices");

    const gl::TetMesh mesh = gl::toTetMesh(input);
    std::vector<gl::Vec3> directions(mesh.tets.size());
    for (vtkIdType t = 0; t < static_cast<vtkIdType>(directions.size()); ++t) {
      gradient->GetTuple(t, directions[t].data());
    }
    std::vector<std::uint8_t> onPlatform(mesh.points.size());
    for (vtkIdType i = 0; i < static_cast<vtkIdType>(onPlatform.size()); ++i) {
      onPlatform[i] = base->GetComponent(i, 0) != 0.0;
    }
    gl::checkAbort(this, 0.2);
    const gl::TetMeshTopology topology(mesh);
    gl::checkAbort(this, 0.5);
    const gl::OverhangResult result =
        gl::analyzeOverhang(mesh, topology, directions, onPlatform, options);
    gl::checkAbort(this, 0.7);

    // Boundary surface with its own, compact point numbering (first use order).
    const std::vector<gl::BoundaryFace>& faces = topology.boundaryFaces();
    const vtkIdType numFaces = static_cast<vtkIdType>(faces.size());
    std::vector<vtkIdType> newId(mesh.points.size(), -1);
    std::vector<vtkIdType> oldId;
    vtkNew<vtkCellArray> triangles;
    triangles->AllocateExact(numFaces, 3 * numFaces);
    for (vtkIdType f = 0; f < numFaces; ++f) {
      vtkIdType ids[3];
      for (int k = 0; k < 3; ++k) {
        const int v = faces[f].vertices[k];
        if (newId[v] < 0) {
          newId[v] = static_cast<vtkIdType>(oldId.size());
          oldId.push_back(v);
        }
        ids[k] = newId[v];
      }
      triangles->InsertNextCell(3, ids);
    }
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(oldId.size()));
    for (vtkIdType i = 0; i < static_cast<vtkIdType>(oldId.size()); ++i) {
      points->SetPoint(i, mesh.points[oldId[i]].data());
    }
    output->Initialize();
    output->SetPoints(points);
    output->SetPolys(triangles);

    vtkPointData* inPD = input->GetPointData();
    vtkPointData* outPD = output->GetPointData();
    outPD->CopyAllocate(inPD, static_cast<vtkIdType>(oldId.size()));
    for (vtkIdType i = 0; i < static_cast<vtkIdType>(oldId.size()); ++i) {
      outPD->CopyData(inPD, oldId[i], i);
    }
    gl::checkAbort(this, 0.8);
    vtkCellData* inCD = input->GetCellData();
    vtkCellData* outCD = output->GetCellData();
    outCD->CopyAllocate(inCD, numFaces);
    for (vtkIdType f = 0; f < numFaces; ++f) {
      outCD->CopyData(inCD, faces[f].tet, f);
      if (f % 65536 == 0 && this->GetAbortExecute()) {
        throw gl::RequestAborted{};
      }
    }
    outCD->AddArray(gl::doubleArray(gl::arrays::OverhangPlanar, result.planarDeg));
    outCD->AddArray(gl::doubleArray(gl::arrays::OverhangCurved, result.curvedDeg));
    vtkNew<vtkUnsignedCharArray> onBase;
    onBase->SetName(gl::arrays::OnBase);
    onBase->SetNumberOfTuples(numFaces);
    for (vtkIdType f = 0; f < numFaces; ++f) {
      onBase->SetValue(f, result.onBase[f]);
    }
    outCD->AddArray(onBase);
    outCD->SetActiveScalars(gl::arrays::OverhangCurved);

    vtkNew<vtkFieldData> fd;
    fd->DeepCopy(input->GetFieldData());
    gl::addFieldArray(fd, gl::arrays::OverhangPlanarFraction, {result.planarFraction});
    gl::addFieldArray(fd, gl::arrays::OverhangCurvedFraction, {result.curvedFraction});
    gl::addFieldArray(fd, gl::arrays::OverhangThresholdDeg, {result.thresholdDeg});
    gl::addFieldArray(fd, gl::arrays::OverhangBaseArea, {result.baseArea});
    gl::addFieldArray(fd, gl::arrays::OverhangTotalArea, {result.totalArea});
    output->SetFieldData(fd);
    this->UpdateProgress(1.0);
  });
}

void vtkGLOverhangAnalysis::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ThresholdAngle: " << this->ThresholdAngle << " deg\n";
}
