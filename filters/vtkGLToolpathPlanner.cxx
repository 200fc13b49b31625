#include "vtkGLToolpathPlanner.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLProgress.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "lattice/LatticeInfill.h"
#include "skeleton/SkeletonTree.h"
#include "toolpath/ToolpathPlanner.h"

#include <vtkAbstractArray.h>
#include <vtkCellArray.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
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
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkGLToolpathPlanner);

namespace {
namespace gl = geolattice;

static_assert(static_cast<int>(gl::MoveKind::Print) == gl::movekind::Print &&
                  static_cast<int>(gl::MoveKind::Perimeter) == gl::movekind::Perimeter &&
                  static_cast<int>(gl::MoveKind::Air) == gl::movekind::Air,
              "geolattice::movekind must match core/toolpath/ToolpathPlanner.h");

/// The printing order: the field array SequenceOrder of the sequencer's outputs.
std::vector<int> printOrderOf(vtkPolyData* lattice) {
  vtkDataArray* order = lattice->GetFieldData()->GetArray(gl::arrays::SequenceOrder);
  if (!order) {
    throw gl::GeoLatticeError(std::string("the lattice has no field array ") +
                              gl::arrays::SequenceOrder +
                              " (the printing order): run GL Print Sequencer first and connect its "
                              "Sequenced Lattice output");
  }
  std::vector<int> out;
  out.reserve(static_cast<size_t>(order->GetNumberOfTuples()));
  for (vtkIdType k = 0; k < order->GetNumberOfTuples(); ++k) {
    const double v = order->GetComponent(k, 0);
    if (!std::isfinite(v) || v < 0 || v != std::floor(v) || v > 1e9) {
      throw gl::GeoLatticeError(std::string("the field array ") + gl::arrays::SequenceOrder +
                                " has the value " + std::to_string(v) + " at position " +
                                std::to_string(k) + "; sub-graph ids must be integers >= 0");
    }
    out.push_back(static_cast<int>(v));
  }
  return out;
}

/// The pieces of split sub-graphs, when the sequencer made any: the cell array PieceId (per
/// lattice edge, in the order toLatticeGraph reads the line cells) and the field array
/// SequencePieceOrder. False without them.
bool piecesOf(vtkPolyData* lattice, size_t edges, gl::ToolpathPieces& pieces) {
  vtkDataArray* piece = lattice->GetCellData()->GetArray(gl::arrays::PieceId);
  vtkDataArray* order = lattice->GetFieldData()->GetArray(gl::arrays::SequencePieceOrder);
  if (!piece || !order) {
    return false;
  }
  gl::forEachLine(lattice, [&](vtkIdType cell, vtkIdType n, const vtkIdType*) {
    const double p = piece->GetComponent(cell, 0);
    for (vtkIdType k = 0; k + 1 < n; ++k) {
      pieces.edgePiece.push_back(std::isfinite(p) ? static_cast<int>(p) : -1);
    }
  });
  for (vtkIdType k = 0; k < order->GetNumberOfTuples(); ++k) {
    pieces.pieceOrder.push_back(static_cast<int>(order->GetComponent(k, 0)));
  }
  if (pieces.edgePiece.size() != edges) {
    throw gl::GeoLatticeError("the lattice's PieceId does not match its edges");
  }
  return true;
}

/// The whole toolpath as polydata (see the class documentation).
void buildToolpath(const gl::Toolpath& path, const gl::LatticeGraph& graph, vtkPolyData* out) {
  const vtkIdType N = static_cast<vtkIdType>(path.points.size());
  auto kind = gl::intArray(gl::arrays::MoveKind, N);
  auto layer = gl::intArray(gl::arrays::LayerId, N);
  auto subgraph = gl::intArray(gl::arrays::SubgraphId, N);
  auto pathIndex = gl::intArray(gl::arrays::PathIndex, N);
  auto pointIndex = gl::intArray(gl::arrays::PointIndex, N);
  auto latticeLayerId = [&graph](int l) {
    return l >= 0 && l < static_cast<int>(graph.layerIndex.size()) ? graph.layerIndex[l] : l;
  };
  for (vtkIdType i = 0; i < N; ++i) {
    kind->SetValue(i, static_cast<int>(path.kind[i]));
    layer->SetValue(i, latticeLayerId(path.layer[i]));
    subgraph->SetValue(i, path.subgraph[i]);
    pathIndex->SetValue(i, path.pathIndex[i]);
    pointIndex->SetValue(i, static_cast<int>(i));
  }
  out->SetPoints(gl::pointsOf(path.points));
  vtkPointData* pd = out->GetPointData();
  pd->AddArray(gl::vectorArray(gl::arrays::NozzleAxis, path.normals));
  pd->AddArray(gl::doubleArray(gl::arrays::Thickness, path.thickness));
  pd->AddArray(gl::doubleArray(gl::arrays::Width, path.width));
  pd->AddArray(gl::doubleArray(gl::arrays::Extrusion, path.extrusion));
  pd->AddArray(gl::doubleArray(gl::arrays::FeedRate, path.feedRate));
  pd->AddArray(gl::doubleArray(gl::arrays::AxisTilt, path.axisTilt));
  pd->AddArray(kind);
  pd->AddArray(layer);
  pd->AddArray(subgraph);
  pd->AddArray(pathIndex);
  pd->AddArray(pointIndex);
  pd->SetActiveScalars(gl::arrays::MoveKind);

  // One polyline per run of moves (i - 1 -> i) with the same kind, path and sub-graph.
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIntArray> cellKind, cellPath, cellLayer, cellSubgraph;
  cellKind->SetName(gl::arrays::MoveKind);
  cellPath->SetName(gl::arrays::PathIndex);
  cellLayer->SetName(gl::arrays::LayerId);
  cellSubgraph->SetName(gl::arrays::SubgraphId);
  auto sameRun = [&path](vtkIdType a, vtkIdType b) {
    return path.kind[a] == path.kind[b] && path.pathIndex[a] == path.pathIndex[b] &&
           path.subgraph[a] == path.subgraph[b] && path.layer[a] == path.layer[b];
  };
  std::vector<vtkIdType> ids;
  for (vtkIdType first = 1; first < N;) {
    vtkIdType last = first;
    while (last + 1 < N && sameRun(last + 1, first)) {
      ++last;
    }
    ids.clear();
    for (vtkIdType i = first - 1; i <= last; ++i) {
      ids.push_back(i);
    }
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    cellKind->InsertNextValue(static_cast<int>(path.kind[first]));
    cellPath->InsertNextValue(path.pathIndex[first]);
    cellLayer->InsertNextValue(latticeLayerId(path.layer[first]));
    cellSubgraph->InsertNextValue(path.subgraph[first]);
    first = last + 1;
  }
  out->SetLines(lines);
  vtkCellData* cd = out->GetCellData();
  cd->AddArray(cellKind);
  cd->AddArray(cellPath);
  cd->AddArray(cellLayer);
  cd->AddArray(cellSubgraph);
  cd->SetActiveScalars(gl::arrays::MoveKind);

  vtkFieldData* fd = out->GetFieldData();
  auto count = [fd](const char* name, double value) {
    gl::addFieldArray(fd, name, {value});
  };
  count(gl::arrays::ToolpathPrintLength, path.printLength);
  count(gl::arrays::ToolpathPerimeterLength, path.perimeterLength);
  count(gl::arrays::ToolpathAirLength, path.airLength);
  count(gl::arrays::ToolpathPerimeterLoops, path.perimeterLoops);
  count(gl::arrays::ToolpathPerimeterTeeth, path.perimeterTeeth);
  count(gl::arrays::ToolpathRetractions, path.retractions);
  count(gl::arrays::ToolpathTours, path.tours);
  count(gl::arrays::ToolpathCrossings, path.crossings);
  count(gl::arrays::ToolpathSplitSubgraphs, path.splitSubgraphs);
  count(gl::arrays::ToolpathContractedEdges, path.contractedEdges);
  count(gl::arrays::ToolpathTrimmedEdges, path.trimmedEdges);
  count(gl::arrays::ToolpathTrimmedLength, path.trimmedLength);
  count(gl::arrays::ToolpathFilament, path.filamentLength);
  count(gl::arrays::ToolpathVolume, path.depositedVolume);
  const gl::LayerThicknessResult& t = path.thicknessStats;
  gl::addFieldArray(fd, gl::arrays::ToolpathThicknessDeviation, {t.deviationMin, t.deviationMax});
  std::vector<double> perLayer;
  for (const gl::LayerThicknessDeviation& d : t.perLayer) {
    perLayer.insert(perLayer.end(), {d.min, d.mean, d.max});
  }
  gl::addFieldArray(fd, gl::arrays::ToolpathThicknessDeviationPerLayer, perLayer, 3);
  count(gl::arrays::ToolpathCappedVertices, t.cappedVertices);
  count(gl::arrays::ToolpathUnsupportedVertices, t.unsupportedVertices);
  count(gl::arrays::ToolpathRotationSteps, path.rotationSteps);
  count(gl::arrays::ToolpathSubdivisionPoints, path.subdivisionPoints);
  count(gl::arrays::ToolpathCollidingStations, path.collidingStations);
  count(gl::arrays::ToolpathTiltedStations, path.tiltedStations);
  count(gl::arrays::ToolpathUnclearedStations, path.unclearedStations);
  count(gl::arrays::ToolpathCollisionFree, path.unclearedStations == 0 ? 1 : 0);
  count(gl::arrays::ToolpathMaxAxisTilt, path.maxAxisTiltDeg);
  count(gl::arrays::ToolpathReplannedHops, path.replannedHops);
  count(gl::arrays::ToolpathAlignedTransitions, path.alignedTransitions);
  count(gl::arrays::ToolpathReorderedTours, path.reorderedTours);
  count(gl::arrays::ToolpathUnclearedBeforeReorder, path.unclearedBeforeReorder);
  count(gl::arrays::ToolpathSeconds, path.seconds);
}

/// The core options of the filter's parameters (checked by RequestInformation).
gl::ToolpathOptions toolpathOptions(vtkGLToolpathPlanner* f) {
  gl::ToolpathOptions o = f->GetOptions();
  o.filamentRadius = 0.5 * f->GetFilamentDiameter();
  o.nozzle = gl::nozzleModel(f->GetNozzle());
  o.plate = gl::buildPlate(f->GetNozzle());
  return o;
}

}  // namespace

vtkGLToolpathPlanner::vtkGLToolpathPlanner() {
  this->SetNumberOfInputPorts(2);
  const gl::ToolpathOptions d;  // the defaults live in core
  this->FilamentDiameter = 2.0 * d.filamentRadius;
}

vtkGLToolpathPlanner::~vtkGLToolpathPlanner() = default;

int vtkGLToolpathPlanner::RequestInformation(vtkInformation* request,
                                             vtkInformationVector** inputVector,
                                             vtkInformationVector* outputVector) {
  if (!this->Superclass::RequestInformation(request, inputVector, outputVector) ||
      !gl::checkParameters(this, [&] {
        if (!(this->FilamentDiameter > 0) || !std::isfinite(this->FilamentDiameter)) {
          throw gl::GeoLatticeError("toolpath: filament diameter must be > 0 mm (got " +
                                    std::to_string(this->FilamentDiameter) + ")");
        }
        toolpathOptions(this).validate();
      })) {
    return 0;
  }
  return 1;
}

int vtkGLToolpathPlanner::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                      vtkInformationVector* outputVector) {
  // Collective in an MPI run: the lattice and the skeleton on one process (vtkGLParallel.h).
  return gl::runRequest(this, inputVector, 2, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    vtkPolyData* lattice = inputs.Get<vtkPolyData>(0);
    vtkPolyData* skeleton = inputs.Get<vtkPolyData>(1);
    const gl::LatticeGraph graph = gl::toLatticeGraph(lattice);
    if (graph.edgeKind.size() != graph.edges.size()) {
      throw gl::GeoLatticeError(std::string("the lattice has no ") + gl::arrays::EdgeKind +
                                " cell array (alpha, beta or boundary edge, written by GL "
                                "Lattice Infill; the trimming needs it)");
    }
    const std::vector<int> order = printOrderOf(lattice);
    gl::SkeletonTree tree = gl::toSkeletonTree(skeleton);
    gl::matchSkeletonToLattice(tree, graph);
    gl::checkAbort(this, 0.1);

    gl::ToolpathOptions options = toolpathOptions(this);
    options.progress = gl::progressRange(this, 0.1, 0.8);
    options.shouldAbort = gl::abortFlag(this);
    gl::ToolpathPieces pieces;
    const bool split = piecesOf(lattice, graph.edges.size(), pieces);
    const gl::Toolpath path =
        gl::planToolpath(graph, tree, order, options, split ? &pieces : nullptr);
    gl::checkAbort(this, 0.8);

    buildToolpath(path, graph, output);
    gl::addFieldArray(output->GetFieldData(), gl::arrays::ToolpathFilamentDiameter,
                      {this->FilamentDiameter});
    if (vtkDataArray* edges = lattice->GetFieldData()->GetArray(gl::arrays::SkeletonEdges)) {
      output->GetFieldData()->AddArray(edges);
    }
    this->UpdateProgress(1.0);
  });
}

void vtkGLToolpathPlanner::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PathWidth: " << this->Options.pathWidth << " mm\n";
  os << indent << "FilamentDiameter: " << this->FilamentDiameter << " mm\n";
  os << indent << "FlowCorrection: " << this->Options.flowCorrection << "\n";
  os << indent << "PrintFeedRate: " << this->Options.printFeedRate << " mm/s\n";
  os << indent << "AirFeedRate: " << this->Options.airFeedRate << " mm/s\n";
  os << indent << "ThicknessCap: " << this->Options.thicknessCap << "\n";
  os << indent << "MaxTurnAngle: " << this->Options.maxTurnDeg << " deg\n";
  os << indent << "SafeMargin: " << this->Options.safeMargin << " mm\n";
  os << indent << "Lift: " << this->Options.lift << " mm\n";
  os << indent << "Retraction: " << this->Options.retraction << " mm\n";
  os << indent << "SupportPerimeter: " << this->Options.supportPerimeter << "\n";
  os << indent << "ToothLength: " << this->Options.toothLength << " mm\n";
  os << indent << "MaxSegmentLength: " << this->Options.maxSegmentLength << " mm\n";
  os << indent << "MaximumElements: " << this->Options.maxElements << "\n";
  os << indent << "MaxAxisTilt: " << this->Options.clearance.maxTiltDeg << " deg\n";
  os << indent << "TiltBlendLength: " << this->Options.clearance.blendLength << " mm\n";
}
