#include "vtkGLToolpathReplay.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLRequest.h"

#include "common/Error.h"

#include <vtkAlgorithmOutput.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

vtkStandardNewMacro(vtkGLToolpathReplay);

namespace gl = geolattice;
using SDDP = vtkStreamingDemandDrivenPipeline;

namespace {

/// The distinct LayerId values >= 0 of the cells (air moves have -1), ascending.
std::vector<double> layerSteps(vtkPolyData* path) {
  std::set<int> ids;
  if (vtkDataArray* layer = path ? path->GetCellData()->GetArray(gl::arrays::LayerId) : nullptr) {
    for (vtkIdType c = 0; c < layer->GetNumberOfTuples(); ++c) {
      const double v = layer->GetTuple1(c);
      if (v >= 0) {
        ids.insert(static_cast<int>(v));
      }
    }
  }
  return std::vector<double>(ids.begin(), ids.end());
}

/// The first n tuples of every array of `from` into `to`.
void copyPrefix(vtkFieldData* from, vtkFieldData* to, vtkIdType n) {
  for (int i = 0; i < from->GetNumberOfArrays(); ++i) {
    vtkAbstractArray* a = from->GetAbstractArray(i);
    auto copy = vtkSmartPointer<vtkAbstractArray>::Take(a->NewInstance());
    copy->SetName(a->GetName());
    copy->SetNumberOfComponents(a->GetNumberOfComponents());
    copy->InsertTuples(0, n, 0, a);
    to->AddArray(copy);
  }
}

}  // namespace

void vtkGLToolpathReplay::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "StepBy: " << this->StepBy << (this->StepBy == Layers ? " (Layers)" : " (Points)")
     << "\n";
  os << indent << "NumberOfTimeSteps: " << this->NumberOfTimeSteps << "\n";
  os << indent << "KeepUnprintedPoints: " << this->KeepUnprintedPoints << "\n";
}

int vtkGLToolpathReplay::RequestInformation(vtkInformation*, vtkInformationVector**,
                                            vtkInformationVector* outputVector) {
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  std::vector<double> steps;
  if (this->StepBy == Points) {
    const int n = this->NumberOfTimeSteps;
    for (int k = 0; k < n; ++k) {
      steps.push_back(static_cast<double>(k) / (n - 1));
    }
  } else if (vtkAlgorithmOutput* input = this->GetInputConnection(0, 0)) {
    // The layers are known only once the toolpath is planned: the upstream runs here, once (its
    // output is cached for the data pass that follows).
    input->GetProducer()->Update(input->GetIndex());
    steps = layerSteps(
        vtkPolyData::SafeDownCast(input->GetProducer()->GetOutputDataObject(input->GetIndex())));
  }
  if (steps.empty()) {
    outInfo->Remove(SDDP::TIME_STEPS());
    outInfo->Remove(SDDP::TIME_RANGE());
    return 1;
  }
  const double range[2] = {steps.front(), steps.back()};
  outInfo->Set(SDDP::TIME_STEPS(), steps.data(), static_cast<int>(steps.size()));
  outInfo->Set(SDDP::TIME_RANGE(), range, 2);
  return 1;
}

int vtkGLToolpathReplay::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                     vtkInformationVector* outputVector) {
  // Collective in an MPI run: the toolpath on one process (vtkGLParallel.h).
  return gl::runRequest(this, inputVector, 1, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkInformation* outInfo = outputVector->GetInformationObject(0);
    vtkPolyData* input = inputs.Get<vtkPolyData>(0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    if (!input || input->GetNumberOfPoints() == 0 || input->GetNumberOfLines() == 0) {
      throw gl::GeoLatticeError(
          "empty input: no toolpath to replay (connect the output of GL Toolpath Planner)");
    }
    const vtkIdType N = input->GetNumberOfPoints();
    const bool timed = outInfo->Has(SDDP::UPDATE_TIME_STEP());
    const double t =
        timed ? outInfo->Get(SDDP::UPDATE_TIME_STEP()) : std::numeric_limits<double>::infinity();
    vtkDataArray* cellLayer = input->GetCellData()->GetArray(gl::arrays::LayerId);
    if (this->StepBy == Layers && !cellLayer) {
      throw gl::GeoLatticeError(std::string("the toolpath has no ") + gl::arrays::LayerId +
                                " cell array (StepBy Layers needs it): connect the output of GL "
                                "Toolpath Planner");
    }

    // The cells printed at time t (cells are in printing order).
    vtkIdType last = -1;  // the last printed point
    const vtkIdType lastPoint =
        std::isfinite(t) ? static_cast<vtkIdType>(
                               std::llround(std::clamp(t, 0.0, 1.0) * static_cast<double>(N - 1)))
                         : N - 1;
    vtkNew<vtkCellArray> lines;
    vtkCellData* inCells = input->GetCellData();
    vtkCellData* outCells = output->GetCellData();
    outCells->CopyAllocate(inCells, input->GetNumberOfLines());
    vtkCellArray* inLines = input->GetLines();
    vtkIdType count;
    const vtkIdType* ids;
    for (vtkIdType c = 0; c < inLines->GetNumberOfCells(); ++c) {
      inLines->GetCellAtId(c, count, ids);
      if (count == 0) {
        continue;
      }
      vtkIdType kept = count;
      if (this->StepBy == Points) {
        if (ids[0] >= lastPoint) {
          break;
        }
        kept = std::min(count, lastPoint - ids[0] + 1);
      } else {
        const double layer = cellLayer->GetTuple1(c);
        if (layer < 0 || layer > t) {
          continue;
        }
      }
      outCells->CopyData(inCells, c, lines->InsertNextCell(kept, ids));
      last = std::max(last, ids[kept - 1]);
    }
    output->SetLines(lines);

    if (this->KeepUnprintedPoints || this->StepBy == Layers) {
      output->SetPoints(input->GetPoints());
      output->GetPointData()->ShallowCopy(input->GetPointData());
    } else {
      const vtkIdType n = last + 1;
      vtkNew<vtkPoints> points;
      points->SetDataType(input->GetPoints()->GetDataType());
      points->GetData()->InsertTuples(0, n, 0, input->GetPoints()->GetData());
      output->SetPoints(points);
      copyPrefix(input->GetPointData(), output->GetPointData(), n);
    }
    output->GetPointData()->SetActiveScalars(gl::arrays::MoveKind);
    outCells->SetActiveScalars(gl::arrays::MoveKind);
    output->GetFieldData()->ShallowCopy(input->GetFieldData());
    gl::addFieldArray(output->GetFieldData(), gl::arrays::ReplayLastPoint,
                      {static_cast<double>(last)});
    if (timed) {
      output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), t);
    }
    this->UpdateProgress(1.0);
  });
}
