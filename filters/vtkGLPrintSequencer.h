/**
 * @class   vtkGLPrintSequencer
 * @brief   The printing order of the lattice sub-graphs G_{i,j}: layer priority, depth
 *          priority, the paper's collision-aware greedy traversal (A4), or a rollout of it.
 *
 * Paper Section 3.1 (Criteria 1-2, Algorithms 3-4), core/sequence/PrintSequencer.h. The printed
 * material is sampled (every lattice vertex plus points every SampleSpacing mm along the edges,
 * core/sequence/PrintMaterial.h); for A4 and Best the potential collision sub-graphs (PCG: the
 * sub-graphs with material inside the nozzle volume swept over a sub-graph, which must not be
 * printed before it) are computed with the nozzle of core/nozzle/NozzleModel.h (a cone of
 * half-angle NozzleAngle about the layer normal, optionally cut at NozzleLength above which the
 * holder is a cylinder of radius HolderRadius). Strategies:
 *   - LPT (0): layer by layer, nearest next sub-graph within a layer;
 *   - DPT (1): along branches, depth first (ignores collisions);
 *   - A4 (2): candidates satisfy Criterion 1 (lower nodes printed) and Criterion 2 (in no
 *     unprinted node's PCG); an upper node of the current node first, else the nearest;
 *   - Best (3): rollout of A4 at every retraction (tries the RolloutCandidates nearest
 *     candidates, completes each with A4, keeps the cheapest by retractions × RetractionCost +
 *     air length); never worse than A4 on retractions and air length, as collision-free.
 * A PCG entry j of i where j is a skeleton ancestor of i (a wide nozzle over a curved layer
 * reaching the layer below) is a collision no order avoids, since Criterion 1 prints j first: it
 * is left out of Criterion 2 and counted in SequenceUnavoidablePairs. When no candidate satisfies
 * Criterion 2 (mutual PCGs) one is forced and counted in SequenceForcedSteps. With SplitRounds
 * > 0 (A4 and Best) sub-graphs that block each other are split along the lattice into
 * pieces that can be ordered (core/sequence/SubgraphSplitting.h): the order becomes an order of
 * pieces; the lattice gets the cell array `PieceId`, the field data `SequencePieceOrder` (per
 * position the piece; SequenceOrder gives its sub-graph), `SequencePieces`,
 * `SequenceSplitSubgraphs` and `SequenceForcedStepsBefore`, and GL Toolpath Planner prints each
 * piece as the runs of its sub-graph's tour in it.
 *
 * Input port 0: vtkPolyData, the output of vtkGLLatticeInfill (line cells with cell arrays
 *         `SubgraphId`, `LayerId`, point arrays `NozzleAxis`, `Gamma`).
 * Input port 1: vtkPolyData, the output of vtkGLSkeletonTree built from the same lattice (point
 *         data `LayerId`, optionally `NodeId`, `SubgraphLength`; line cells (lower, upper)).
 * Output port 0 (Sequenced Lattice): the lattice (shallow copy) with cell and point data
 *   `PrintOrder` (int: position of the cell's / point's sub-graph in the order, -1 for none).
 * Output port 1 (Sequenced Skeleton): the skeleton (shallow copy) with point data `PrintOrder`.
 * Output port 2 (Print Order): one point per position at the sub-graph's start point (the
 *   sample where its closed tour starts and ends), point data `PrintOrder` (position) and
 *   `SubgraphId`; one line cell per transition k -> k + 1 with cell data `PrintOrder` (k) and
 *   `Retraction` (int: 1 unless the next sub-graph is an upper node of the current one).
 * Field data on all three outputs: `SequenceStrategy` (vtkStringArray: "lpt", "dpt", "a4" or
 *   "best"), `SequenceRetractions`, `SequenceAirLength` (mm), `SequenceForcedSteps`,
 *   `SequenceSeconds`, `SequencePcgPairs`, `SequencePcgSeconds`, `SequenceUnavoidablePairs` (PCG
 *   entries that are skeleton ancestors: collisions no order avoids, left out of Criterion 2; all
 *   0 for LPT and DPT), `NozzleAngleDeg`, per position `SequenceOrder` (sub-graph id),
 *   `SequenceStart`, `SequenceEnd` (3 values, mm), and `SkeletonEdges` (2 values per skeleton
 *   edge: lower and upper sub-graph id; vtkGLCollisionVerifier uses it to tell unavoidable
 *   collisions from avoidable ones).
 * Parameters: Strategy (default 3 = Best), the nozzle (vtkGLNozzle: NozzleAngle, NozzleLength,
 *   HolderRadius, TipClearance, TipFaceRadius), SampleSpacing (mm, default 1, > 0),
 *   MaximumElements (default 40e6: more sub-graph pairs for the PCG is refused),
 *   RolloutCandidates (default 6, >= 1), RetractionCost (mm, default 20, >= 0), NumberOfThreads
 *   (PCG, default 0 = all cores), SplitRounds (default 0 = never split).
 * Errors (an empty lattice, missing arrays, a skeleton that does not match the lattice (node
 * count or layers), a skeleton edge between non-consecutive layers, NozzleAngle outside (0, 90)
 * or another bad nozzle or option) are reported with vtkErrorMacro and give empty outputs.
 */
#ifndef vtkGLPrintSequencer_h
#define vtkGLPrintSequencer_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLOptionMacros.h"
#include "vtkGLNozzleAlgorithm.h"

#include "sequence/PrintSequencer.h"  // SequenceOptions: the parameters and their defaults

class GEOLATTICEFILTERS_EXPORT vtkGLPrintSequencer : public vtkGLNozzleAlgorithm {
public:
  static vtkGLPrintSequencer* New();
  vtkTypeMacro(vtkGLPrintSequencer, vtkGLNozzleAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Values of Strategy (= geolattice::SequenceStrategy).
  enum Strategies {
    LPT = 0,  ///< layer priority traversal
    DPT = 1,  ///< depth priority traversal
    A4 = 2,   ///< the paper's greedy traversal with PCGs (Algorithm 4)
    BEST = 3  ///< rollout of A4 at every retraction
  };

  ///@{
  /// Ordering strategy (default 3 = Best).
  vtkGLOptionEnumMacro(Strategy, strategy, LPT, BEST);
  ///@}

  ///@{
  /// The strategy used in place of Strategy (default -1 = none: Strategy is used). Not a user
  /// setting: GLPrintPipeline::ChooseOrderByToolpath sets it when, for Best, another order's
  /// toolpath collides less; `SequenceStrategy` names the strategy used.
  vtkSetClampMacro(StrategyOverride, int, -1, BEST);
  vtkGetMacro(StrategyOverride, int);
  ///@}

  ///@{
  /// Bound against runaway work (core/common/WorkLimit.h): more pairs of sub-graphs to test for
  /// potential collisions than this is refused (default 40e6, about 9000 sub-graphs).
  vtkSetClampMacro(MaximumElements, double, 1.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumElements, double);
  ///@}

  ///@{
  /// Spacing of the material samples along the lattice edges (mm, default 1, > 0).
  vtkSetMacro(SampleSpacing, double);
  vtkGetMacro(SampleSpacing, double);
  ///@}

  ///@{
  /// Best: nearest candidates tried at each retraction (default 6, >= 1).
  vtkGLOptionMacro(RolloutCandidates, int, rolloutCandidates);
  ///@}

  ///@{
  /// Best: millimetres of air move one retraction is worth (default 20, >= 0).
  vtkGLOptionMacro(RetractionCost, double, retractionCost);
  ///@}

  ///@{
  /// A4 and Best: rounds of sub-graph splitting while forced steps remain (default 0 = sub-graphs
  /// are never split, in [0, 100]). core/sequence/SubgraphSplitting.h.
  vtkSetMacro(SplitRounds, int);
  vtkGetMacro(SplitRounds, int);
  ///@}

  ///@{
  /// Worker threads of the PCG computation (default 0 = hardware concurrency).
  vtkSetClampMacro(NumberOfThreads, int, 0, 256);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /// The stage's core options as the parameters set them (C++ only: a core type).
  VTK_WRAPEXCLUDE const geolattice::SequenceOptions& GetOptions() const { return this->Options; }

protected:
  vtkGLPrintSequencer();
  ~vtkGLPrintSequencer() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  geolattice::SequenceOptions Options;  ///< the parameters, defaults from core
  int StrategyOverride = -1;
  double SampleSpacing;
  double MaximumElements;
  int NumberOfThreads;
  int SplitRounds;

private:
  vtkGLPrintSequencer(const vtkGLPrintSequencer&) = delete;
  void operator=(const vtkGLPrintSequencer&) = delete;
};

#endif
