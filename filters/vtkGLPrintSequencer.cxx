#include "vtkGLPrintSequencer.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLProgress.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "lattice/LatticeInfill.h"
#include "nozzle/NozzleModel.h"
#include "sequence/PotentialCollisions.h"
#include "sequence/PrintMaterial.h"
#include "sequence/PrintSequencer.h"
#include "sequence/SubgraphSplitting.h"
#include "skeleton/SkeletonTree.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
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
#include <string>

vtkStandardNewMacro(vtkGLPrintSequencer);

namespace {
namespace gl = geolattice;

static_assert(static_cast<int>(gl::SequenceStrategy::LayerPriority) == vtkGLPrintSequencer::LPT &&
                  static_cast<int>(gl::SequenceStrategy::DepthPriority) ==
                      vtkGLPrintSequencer::DPT &&
                  static_cast<int>(gl::SequenceStrategy::Greedy) == vtkGLPrintSequencer::A4 &&
                  static_cast<int>(gl::SequenceStrategy::Rollout) == vtkGLPrintSequencer::BEST,
              "vtkGLPrintSequencer::Strategies must match core/sequence/PrintSequencer.h");

/// Position of sub-graph `value` in the order, -1 when it is no sub-graph.
int positionOf(double value, const std::vector<int>& printIndex) {
  if (!std::isfinite(value) || value < 0 || value >= static_cast<double>(printIndex.size())) {
    return -1;
  }
  return printIndex[static_cast<size_t>(value)];
}

/// The field data shared by the three outputs.
void addSequenceFieldData(const gl::SkeletonTree& tree, const gl::PieceSequence& pieces,
                          double nozzleAngle, vtkFieldData* fd) {
  const gl::PrintSequence& seq = pieces.sequence;
  const gl::PotentialCollisions& pcg = pieces.pcg;
  gl::addFieldText(fd, gl::arrays::SequenceStrategy, gl::sequenceStrategyName(seq.strategy));
  gl::addFieldArray(fd, gl::arrays::SequenceRetractions, {static_cast<double>(seq.retractions)});
  gl::addFieldArray(fd, gl::arrays::SequenceAirLength, {seq.airLength});
  gl::addFieldArray(fd, gl::arrays::SequenceForcedSteps, {static_cast<double>(seq.forcedSteps)});
  gl::addFieldArray(fd, gl::arrays::SequenceSeconds, {seq.seconds});
  gl::addFieldArray(fd, gl::arrays::SequencePcgPairs, {static_cast<double>(pcg.pairs)});
  gl::addFieldArray(fd, gl::arrays::SequencePcgSeconds, {pcg.seconds});
  gl::addFieldArray(fd, gl::arrays::SequenceUnavoidablePairs,
                    {static_cast<double>(seq.unavoidablePairs)});
  gl::addFieldArray(fd, gl::arrays::NozzleAngleDeg, {nozzleAngle});
  std::vector<double> order, pieceOrder(seq.order.begin(), seq.order.end()), start, end;
  for (int p : seq.order) {
    order.push_back(pieces.pieceSubgraph[p]);
  }
  for (size_t k = 0; k < seq.order.size(); ++k) {
    start.insert(start.end(), seq.start[k].data(), seq.start[k].data() + 3);
    end.insert(end.end(), seq.end[k].data(), seq.end[k].data() + 3);
  }
  gl::addFieldArray(fd, gl::arrays::SequenceOrder, order);
  gl::addFieldArray(fd, gl::arrays::SequencePieces, {static_cast<double>(seq.order.size())});
  gl::addFieldArray(fd, gl::arrays::SequenceSplitSubgraphs,
                    {static_cast<double>(pieces.splitSubgraphs)});
  gl::addFieldArray(fd, gl::arrays::SequenceForcedStepsBefore,
                    {static_cast<double>(pieces.forcedStepsBefore)});
  if (pieces.splitSubgraphs > 0) {
    gl::addFieldArray(fd, gl::arrays::SequencePieceOrder, pieceOrder);
  }
  gl::addFieldArray(fd, gl::arrays::SequenceStart, start, 3);
  gl::addFieldArray(fd, gl::arrays::SequenceEnd, end, 3);
  std::vector<double> edges;
  for (const auto& e : tree.edges) {
    edges.push_back(e[0]);
    edges.push_back(e[1]);
  }
  gl::addFieldArray(fd, gl::arrays::SkeletonEdges, edges, 2);
}

/// Output 0: the lattice with PrintOrder per cell (its piece's position: the piece of its first
/// edge) and per point (the earliest of its edges' pieces), and PieceId per cell when sub-graphs
/// were split. Without split sub-graphs, pieces are sub-graphs.
void sequencedLattice(vtkPolyData* input, const gl::LatticeGraph& graph,
                      const gl::PieceSequence& pieces, vtkPolyData* out) {
  const gl::PrintSequence& seq = pieces.sequence;
  out->ShallowCopy(input);
  const vtkIdType C = input->GetNumberOfCells();
  auto cellOrder = gl::intArray(gl::arrays::PrintOrder, C);
  auto cellPiece = gl::intArray(gl::arrays::PieceId, C);
  vtkDataArray* cellSubgraph = input->GetCellData()->GetArray(gl::arrays::SubgraphId);
  for (vtkIdType c = 0; c < C; ++c) {  // every cell by its sub-graph; lines below by their piece
    const int position = positionOf(cellSubgraph->GetComponent(c, 0), seq.printIndex);
    cellOrder->SetValue(c, position);
    cellPiece->SetValue(c, position >= 0 ? seq.order[position] : -1);
  }
  const vtkIdType V = input->GetNumberOfPoints();
  auto pointOrder = gl::intArray(gl::arrays::PrintOrder, V);
  for (vtkIdType v = 0; v < V; ++v) {
    const int s = graph.vertexSubgraph[v];
    pointOrder->SetValue(v, s >= 0 ? seq.printIndex[s] : -1);
  }
  // Line cells in the order toLatticeGraph read them: n - 1 edges per cell.
  size_t edge = 0;
  std::vector<int> earliest(static_cast<size_t>(V), std::numeric_limits<int>::max());
  gl::forEachLine(input, [&](vtkIdType cell, vtkIdType n, const vtkIdType*) {
    const int piece = pieces.edgePiece[edge];
    cellPiece->SetValue(cell, piece);
    cellOrder->SetValue(cell, seq.printIndex[piece]);
    for (vtkIdType k = 0; k + 1 < n; ++k, ++edge) {
      for (const int v : graph.edges[edge]) {
        earliest[v] = std::min(earliest[v], seq.printIndex[pieces.edgePiece[edge]]);
      }
    }
  });
  for (vtkIdType v = 0; v < V; ++v) {
    if (earliest[v] != std::numeric_limits<int>::max()) {
      pointOrder->SetValue(v, earliest[v]);
    }
  }
  out->GetCellData()->AddArray(cellOrder);
  out->GetPointData()->AddArray(pointOrder);
  if (pieces.splitSubgraphs > 0) {
    out->GetCellData()->AddArray(cellPiece);
  }
}

/// Output 1: the skeleton (of the sub-graphs) with PrintOrder per node: the position of its
/// first piece.
void sequencedSkeleton(vtkPolyData* input, const gl::PieceSequence& pieces, int subgraphs,
                       vtkPolyData* out) {
  out->ShallowCopy(input);
  std::vector<int> first(static_cast<size_t>(subgraphs), std::numeric_limits<int>::max());
  for (size_t p = 0; p < pieces.pieceSubgraph.size(); ++p) {
    int& f = first[pieces.pieceSubgraph[p]];
    f = std::min(f, pieces.sequence.printIndex[p]);
  }
  vtkDataArray* nodeId = input->GetPointData()->GetArray(gl::arrays::NodeId);
  const vtkIdType N = input->GetNumberOfPoints();
  auto order = gl::intArray(gl::arrays::PrintOrder, N);
  for (vtkIdType p = 0; p < N; ++p) {
    order->SetValue(
        p, positionOf(nodeId ? nodeId->GetComponent(p, 0) : static_cast<double>(p), first));
  }
  out->GetPointData()->AddArray(order);
}

/// Output 2: the order as a polyline through the start points, one line cell per transition.
void printOrderPolyline(const gl::PieceSequence& pieces, vtkPolyData* out) {
  const gl::SkeletonTree& tree = pieces.tree;
  const gl::PrintSequence& seq = pieces.sequence;
  const vtkIdType K = static_cast<vtkIdType>(seq.order.size());
  auto position = gl::intArray(gl::arrays::PrintOrder, K);
  auto subgraph = gl::intArray(gl::arrays::SubgraphId, K);
  auto piece = gl::intArray(gl::arrays::PieceId, K);
  for (vtkIdType k = 0; k < K; ++k) {
    position->SetValue(k, static_cast<int>(k));
    subgraph->SetValue(k, pieces.pieceSubgraph[seq.order[k]]);
    piece->SetValue(k, seq.order[k]);
  }
  out->SetPoints(gl::pointsOf(seq.start));
  const vtkIdType T = std::max<vtkIdType>(K - 1, 0);
  vtkNew<vtkCellArray> lines;
  lines->AllocateExact(T, 2 * T);
  auto from = gl::intArray(gl::arrays::PrintOrder, T);
  auto retraction = gl::intArray(gl::arrays::Retraction, T);
  for (vtkIdType k = 0; k < T; ++k) {
    const vtkIdType ids[2] = {k, k + 1};
    lines->InsertNextCell(2, ids);
    from->SetValue(k, static_cast<int>(k));
    const std::vector<int>& upper = tree.nodes[seq.order[k]].upper;
    retraction->SetValue(k,
                         std::binary_search(upper.begin(), upper.end(), seq.order[k + 1]) ? 0 : 1);
  }
  out->SetLines(lines);
  out->GetPointData()->AddArray(position);
  out->GetPointData()->AddArray(subgraph);
  out->GetPointData()->AddArray(piece);
  out->GetPointData()->SetActiveScalars(gl::arrays::PrintOrder);
  out->GetCellData()->AddArray(from);
  out->GetCellData()->AddArray(retraction);
  out->GetCellData()->SetActiveScalars(gl::arrays::Retraction);
}
/// The core options of the filter's parameters (checked by RequestInformation).
gl::SequenceOptions sequenceOptions(vtkGLPrintSequencer* f) {
  gl::SequenceOptions o = f->GetOptions();
  // Both clamped by their setters.
  o.strategy = static_cast<gl::SequenceStrategy>(
      f->GetStrategyOverride() >= 0 ? f->GetStrategyOverride() : f->GetStrategy());
  return o;
}

}  // namespace

vtkGLPrintSequencer::vtkGLPrintSequencer() {
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(3);
  this->SampleSpacing = gl::MaterialSampling{}.spacing;
  this->NumberOfThreads = gl::PotentialCollisionOptions{}.threads;
  this->MaximumElements = gl::PotentialCollisionOptions{}.maxPairs;
  this->SplitRounds = gl::SplitOptions{}.maxRounds;
}

int vtkGLPrintSequencer::RequestInformation(vtkInformation* request, vtkInformationVector** inputs,
                                            vtkInformationVector* outputs) {
  return this->Superclass::RequestInformation(request, inputs, outputs) &&
         gl::checkParameters(this, [&] {
           sequenceOptions(this).validate();
           gl::SplitOptions split;
           split.maxRounds = this->SplitRounds;
           split.validate();
           if (!(this->SampleSpacing > 0) || !std::isfinite(this->SampleSpacing)) {
             throw gl::GeoLatticeError("print sequencer: the sample spacing must be > 0 mm (got " +
                                       std::to_string(this->SampleSpacing) + ")");
           }
           if (this->NumberOfThreads < 0) {
             throw gl::GeoLatticeError("print sequencer: the thread count must be >= 0 (got " +
                                       std::to_string(this->NumberOfThreads) + ")");
           }
         });
}

int vtkGLPrintSequencer::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                     vtkInformationVector* outputVector) {
  // Collective in an MPI run: the lattice and the skeleton on one process (vtkGLParallel.h).
  return gl::runRequest(this, inputVector, 2, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkPolyData* lattice = inputs.Get<vtkPolyData>(0);
    vtkPolyData* skeleton = inputs.Get<vtkPolyData>(1);
    const gl::NozzleModel nozzle = gl::nozzleModel(this->Nozzle);
    const gl::LatticeGraph graph = gl::toLatticeGraph(lattice);
    gl::SkeletonTree tree = gl::toSkeletonTree(skeleton);
    gl::matchSkeletonToLattice(tree, graph);
    gl::checkAbort(this, 0.05);
    const gl::MaterialSamples material = gl::sampleLatticeMaterial(graph, this->SampleSpacing);
    gl::checkAbort(this, 0.1);

    gl::SequenceOptions options = sequenceOptions(this);
    const bool needPcg = options.strategy == gl::SequenceStrategy::Greedy ||
                         options.strategy == gl::SequenceStrategy::Rollout;
    options.progress = gl::progressRange(this, needPcg ? 0.6 : 0.1, 0.95);
    options.shouldAbort = gl::abortFlag(this);
    // The pieces: the sub-graphs themselves unless A4/Best split some (SubgraphSplitting.h).
    gl::PieceSequence pieces;
    if (needPcg) {
      gl::PotentialCollisionOptions pcgOptions;
      pcgOptions.threads = this->NumberOfThreads;
      pcgOptions.maxPairs = this->MaximumElements;
      pcgOptions.progress = gl::progressRange(this, 0.1, 0.6);
      pcgOptions.shouldAbort = gl::abortFlag(this);
      gl::SplitOptions split;
      split.maxRounds = this->SplitRounds;
      pieces =
          gl::sequencePieces(graph, tree, this->SampleSpacing, nozzle, pcgOptions, options, split);
    } else {
      pieces.edgePiece = graph.edgeSubgraph;
      for (size_t k = 0; k < tree.nodes.size(); ++k) {
        pieces.pieceSubgraph.push_back(static_cast<int>(k));
      }
      pieces.tree = tree;
      pieces.sequence = gl::sequencePrint(tree, material, nullptr, options);
      pieces.forcedStepsBefore = pieces.sequence.forcedSteps;
    }
    gl::checkAbort(this, 0.95);

    vtkPolyData* outputs[3];
    for (int port = 0; port < 3; ++port) {
      outputs[port] = vtkPolyData::GetData(outputVector, port);
    }
    sequencedLattice(lattice, graph, pieces, outputs[0]);
    sequencedSkeleton(skeleton, pieces, static_cast<int>(tree.nodes.size()), outputs[1]);
    printOrderPolyline(pieces, outputs[2]);
    for (vtkPolyData* out : outputs) {
      addSequenceFieldData(tree, pieces, nozzle.halfAngleDeg, out->GetFieldData());
    }
    this->UpdateProgress(1.0);
  });
}

void vtkGLPrintSequencer::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Strategy: " << this->GetStrategy() << "\n";
  os << indent << "StrategyOverride: " << this->StrategyOverride << "\n";
  os << indent << "SampleSpacing: " << this->SampleSpacing << " mm\n";
  os << indent << "MaximumElements: " << this->MaximumElements << "\n";
  os << indent << "RolloutCandidates: " << this->Options.rolloutCandidates << "\n";
  os << indent << "RetractionCost: " << this->Options.retractionCost << " mm\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "SplitRounds: " << this->SplitRounds << "\n";
}
