#include "vtkGLParallel.h"

#include <vtkAppendFilter.h>
#include <vtkAppendPolyData.h>
#include <vtkCellData.h>
#include <vtkCleanPolyData.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkDataSetAttributes.h>
#include <vtkFieldData.h>
#include <vtkAlgorithm.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkUnstructuredGrid.h>

namespace geolattice {

namespace {

/// A shallow copy of `piece` without its ghost cells and ghost arrays (null for unsupported
/// types).
vtkSmartPointer<vtkDataSet> withoutGhosts(vtkDataObject* piece) {
  vtkSmartPointer<vtkDataSet> copy;
  if (auto* poly = vtkPolyData::SafeDownCast(piece)) {
    auto p = vtkSmartPointer<vtkPolyData>::New();
    p->ShallowCopy(poly);
    p->RemoveGhostCells();
    copy = p;
  } else if (auto* grid = vtkUnstructuredGrid::SafeDownCast(piece)) {
    auto g = vtkSmartPointer<vtkUnstructuredGrid>::New();
    g->ShallowCopy(grid);
    g->RemoveGhostCells();
    copy = g;
  }
  if (copy) {
    copy->GetPointData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
    copy->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  }
  return copy;
}

/// The parts gathered on rank 0 as one data set: polydata appended and cleaned (exact point
/// merging, no cell conversions), unstructured grids appended with exact point merging (by
/// global point ids where they exist). The field data is that of the first part.
vtkSmartPointer<vtkDataObject> merge(const std::vector<vtkSmartPointer<vtkDataObject>>& pieces) {
  std::vector<vtkSmartPointer<vtkDataSet>> parts;
  for (const auto& piece : pieces) {
    if (hasData(piece)) {
      if (auto part = withoutGhosts(piece)) {
        parts.push_back(part);
      }
    }
  }
  if (parts.empty()) {
    return nullptr;
  }
  vtkSmartPointer<vtkDataSet> merged;
  if (vtkPolyData::SafeDownCast(parts.front())) {
    vtkNew<vtkAppendPolyData> append;
    for (const auto& part : parts) {
      if (vtkPolyData::SafeDownCast(part)) {
        append->AddInputData(vtkPolyData::SafeDownCast(part));
      }
    }
    vtkNew<vtkCleanPolyData> clean;
    clean->SetInputConnection(append->GetOutputPort());
    clean->PointMergingOn();
    clean->ToleranceIsAbsoluteOn();
    clean->SetAbsoluteTolerance(0.0);
    clean->ConvertLinesToPointsOff();
    clean->ConvertPolysToLinesOff();
    clean->ConvertStripsToPolysOff();
    clean->Update();
    merged = clean->GetOutput();
  } else {
    vtkNew<vtkAppendFilter> append;
    append->MergePointsOn();
    append->ToleranceIsAbsoluteOn();
    append->SetTolerance(0.0);
    for (const auto& part : parts) {
      if (vtkUnstructuredGrid::SafeDownCast(part)) {
        append->AddInputData(part);
      }
    }
    append->Update();
    merged = append->GetOutput();
  }
  vtkNew<vtkFieldData> fd;
  fd->ShallowCopy(parts.front()->GetFieldData());
  merged->SetFieldData(fd);
  return merged;
}

}  // namespace

bool hasData(vtkDataObject* data) {
  if (auto* ds = vtkDataSet::SafeDownCast(data)) {
    return ds->GetNumberOfPoints() > 0 || ds->GetNumberOfCells() > 0;
  }
  return data != nullptr;
}

namespace {
int requestedPieces(vtkInformation* info) {
  return info && info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
             ? info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
             : 1;
}
}  // namespace

ParallelInputs::ParallelInputs(vtkInformationVector** inputVector, int ports,
                               vtkInformationVector* outputVector) {
  std::vector<vtkDataObject*> local(ports, nullptr);
  for (int port = 0; port < ports; ++port) {
    local[port] = inputVector[port]->GetNumberOfInformationObjects() > 0
                      ? vtkDataObject::GetData(inputVector[port], 0)
                      : nullptr;
  }
  this->Distribute(local, requestedPieces(outputVector->GetInformationObject(0)), /*writer=*/false);
}

ParallelInputs::ParallelInputs(vtkAlgorithm* writer) {
  vtkInformation* info =
      writer->GetNumberOfInputConnections(0) > 0 ? writer->GetInputInformation(0, 0) : nullptr;
  this->Distribute({writer->GetInputDataObject(0, 0)}, requestedPieces(info), /*writer=*/true);
}

void ParallelInputs::Distribute(const std::vector<vtkDataObject*>& local, int pieces, bool writer) {
  this->Inputs.assign(local.begin(), local.end());
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int processes = controller ? controller->GetNumberOfProcesses() : 1;
  if (processes <= 1) {
    return;
  }
  const int rank = controller->GetLocalProcessId();
  if (pieces != processes) {
    // Every process was asked for the whole data (or a streamed piece): no collective call.
    // Filters compute on their own input; one writer is enough.
    this->ComputesHere = !writer || rank == 0;
    if (!this->ComputesHere) {
      this->Inputs.assign(local.size(), nullptr);
    }
    return;
  }
  const int ports = static_cast<int>(local.size());
  // Which process has data on which port.
  std::vector<int> mine(ports), all(static_cast<size_t>(ports) * processes);
  for (int port = 0; port < ports; ++port) {
    mine[port] = hasData(local[port]) ? 1 : 0;
  }
  if (ports > 0) {
    controller->AllGather(mine.data(), all.data(), ports);
  }
  int holders = 0, holder = 0;
  for (int r = processes - 1; r >= 0; --r) {
    for (int port = 0; port < ports; ++port) {
      if (all[static_cast<size_t>(r) * ports + port]) {
        ++holders;
        holder = r;
        break;
      }
    }
  }
  if (holders <= 1) {
    // All the data on one process (or none anywhere: rank 0 reports the empty input).
    this->ComputesHere = rank == holder;
  } else {
    this->ComputesHere = rank == 0;
    this->WasGathered = true;
    for (int port = 0; port < ports; ++port) {
      std::vector<vtkSmartPointer<vtkDataObject>> pieces;
      controller->Gather(mine[port] ? local[port] : nullptr, pieces, 0);
      if (rank == 0) {
        vtkSmartPointer<vtkDataObject> merged = merge(pieces);
        if (merged) {
          this->Inputs[port] = merged;
        }
      }
    }
  }
  if (!this->ComputesHere) {
    for (auto& input : this->Inputs) {
      input = nullptr;
    }
  }
}

}  // namespace geolattice
