#pragma once
/// @file ToolpathPlanner.h
/// @brief The printing path of the whole part (paper Section 3.2): sub-graphs in printing
/// order, each printed as closed crossover-free Euler tours of its trimmed lattice, with the
/// local layer thickness (Eq. 15), extrusion by mass conservation (Eq. 14), the nozzle axis
/// (∇γ, with rotation steps where it turns faster than a set angle) and safe air moves
/// between sub-graphs (Fig. 18).
///
/// Steps: contract zero-length lattice edges (EulerianTrimming.h) -> trim to Eulerian ->
/// non-crossing tours -> support perimeters -> thickness per vertex -> for each sub-graph in
/// order: air move from
/// the nozzle's position (a short lift when continuing onto an upper node of the current
/// sub-graph, else the safe box around everything printed so far plus the next start, grown by
/// safeMargin), retract before and prime after it; each tour starts at its vertex nearest to the
/// nozzle. A support perimeter loop is spliced into the tour where the tour first reaches the
/// loop's anchor vertex: a connector of length w out to the perimeter, the loop, and the way
/// back without extrusion (width 0), so the sub-graph stays one continuous path. Extrusion per
/// print segment (Eq. 14): π r_m² ΔE = μ w h̄ L, with h̄ the mean
/// thickness of its ends; Extrusion holds the cumulative filament length E (mm).
/// Finally segments are subdivided (PathSubdivision.h: axis turn <= maxTurnDeg, length <=
/// maxSegmentLength) and, in up to four rounds, stations where the nozzle along ∇γ would hit
/// earlier material of the path get a small tilt (NozzleAxisClearance.h); AxisTilt records it.
/// Air moves with stations left colliding are laid again along the cleared axes
/// (AirMoveRealignment.h), and tours with stations left colliding are tried backwards and from
/// half-way round (TourWays.h).
#include "common/WorkLimit.h"
#include "lattice/LatticeInfill.h"
#include "sequence/PrintSequencer.h"
#include "nozzle/BuildPlate.h"
#include "nozzle/NozzleModel.h"
#include "skeleton/SkeletonTree.h"
#include "toolpath/LayerThickness.h"
#include "toolpath/NozzleAxisClearance.h"

#include <functional>
#include <vector>

namespace geolattice {

enum class MoveKind : int { Print = 0, Perimeter = 1, Air = 2 };

struct ToolpathOptions {
  double pathWidth = 0.6;         ///< w (mm, > 0)
  double filamentRadius = 0.875;  ///< r_m (mm, > 0): 1.75 mm filament
  double flowCorrection = 0.95;   ///< μ in (0, 1]
  double printFeedRate = 10.0;    ///< f_p (mm/s, > 0)
  double airFeedRate = 50.0;      ///< feed rate of air moves (mm/s, > 0)
  double thicknessCap = 1.5;      ///< λ of Eq. 15 (> 0)
  double maxTurnDeg = 5.0;        ///< largest axis change between consecutive points (deg, > 0)
  double safeMargin = 5.0;        ///< margin of the safe box around the in-process part (mm, >= 0)
  double lift = 2.0;              ///< lift for hops onto an upper node (mm, > 0)
  double retraction = 1.0;  ///< filament retracted before an air move and primed after (mm, >= 0)
  /// An air move with colliding stations is laid again leaving and reaching its stations along
  /// their final (cleared) axes instead of their layer normals (AirMoveRealignment.h,
  /// Toolpath::alignedTransitions). Off only to compare with the paper's air moves.
  bool alignTransitions = true;
  /// A tour with stations left colliding is printed again backwards and from half-way round,
  /// each such tour keeping the way where fewest of its stations collide (TourWays.h,
  /// Toolpath::reorderedTours). Off only to compare.
  bool retryTourWays = true;
  bool supportPerimeter = true;   ///< add the jagged support perimeter (SupportPerimeter.h)
  double toothLength = 0.0;       ///< l (mm); 0 = 2 w
  double maxSegmentLength = 1.0;  ///< longer segments are subdivided (mm, >= 0; 0 = never), so
      ///< the collision check of the path's points samples it this finely
  /// Bound against runaway work (common/WorkLimit.h): more estimated stations (the lattice's
  /// edges, its length / maxSegmentLength, four per perimeter tooth) than this is refused (> 0).
  double maxElements = kDefaultMaxElements;
  NozzleModel nozzle;  ///< the nozzle the axis clearance keeps earlier material out of
  BuildPlate plate;    ///< the build plate, an obstacle like material (enabled by default)
  AxisClearanceOptions
      clearance;  ///< tilts off ∇γ where the nozzle would collide (maxTiltDeg 0 = off)
  /// Called on the calling thread with the fraction done (the path built, each clearance
  /// round). Optional.
  std::function<void(double)> progress;
  /// Polled at the same points and during the clearance; true stops with a GeoLatticeError
  /// "... aborted". Optional.
  std::function<bool()> shouldAbort;
  /// Throws GeoLatticeError naming the first parameter out of its range (cheap: no data).
  void validate() const;
};

struct Toolpath {
  std::vector<Vec3> points;       ///< tip positions in printing order (mm)
  std::vector<Vec3> normals;      ///< unit nozzle axes
  std::vector<MoveKind> kind;     ///< kind of the move that ends at the point (first: Air)
  std::vector<double> thickness;  ///< h (mm), 0 on air moves
  std::vector<double> width;      ///< w (mm), 0 on air moves
  std::vector<double> extrusion;  ///< cumulative filament E (mm), after retraction/prime
  std::vector<double> feedRate;   ///< mm/s of the move that ends at the point
  std::vector<int> layer;         ///< lattice layer (-1 on air moves)
  std::vector<int> subgraph;      ///< sub-graph (-1 on air moves)
  std::vector<int>
      pathIndex;  ///< index of the continuous print path (tour) the point belongs to; air points carry the next one
  std::vector<double> axisTilt;  ///< angle between the nozzle axis and the layer normal ∇γ (deg)
  // Report.
  double printLength = 0;  ///< mm of lattice (MoveKind::Print)
  double perimeterLength =
      0;  ///< mm of support perimeter incl. its connectors (MoveKind::Perimeter)
  int perimeterLoops = 0;
  int perimeterTeeth = 0;
  double airLength = 0;  ///< mm
  int retractions = 0;   ///< air moves
  int tours = 0;
  int crossings = 0;        ///< self-crossings of the tours (countTourCrossovers; 0 expected)
  int splitSubgraphs = 0;   ///< sub-graphs printed as more than one tour
  int contractedEdges = 0;  ///< zero-length lattice edges contracted
  int trimmedEdges = 0;
  double trimmedLength = 0;   ///< mm of boundary left unprinted by the trimming
  int rotationSteps = 0;      ///< points inserted to limit the axis turn
  int subdivisionPoints = 0;  ///< all points inserted (axis turn and maxSegmentLength)
  int collidingStations = 0;  ///< stations with earlier material in the nozzle along ∇γ
  int tiltedStations = 0;     ///< stations cleared by tilting the axis (over all rounds)
  int unclearedStations = 0;  ///< stations still colliding after the last round
  int clearanceRounds = 0;
  int replannedHops = 0;  ///< hops onto an upper node that collided and went over the safe box
  /// air moves whose stations collided, laid again along the final axes of the stations they
  /// leave and reach (AirMoveRealignment.h); rotationSteps and subdivisionPoints stay those of
  /// the path as planned before
  int alignedTransitions = 0;
  /// tours printed from another start or the other way round because fewer of their stations
  /// collide so (TourWays.h); unclearedStations counted before that
  int reorderedTours = 0;
  int unclearedBeforeReorder = 0;
  double maxAxisTiltDeg = 0;
  double filamentLength = 0;   ///< Σ ΔE over print moves (mm)
  double depositedVolume = 0;  ///< Σ μ w h̄ L over print moves (mm³)
  LayerThicknessResult thicknessStats;
  double seconds = 0;

  /// Reserves room for n points in every per-point array but axisTilt.
  void reservePoints(size_t n) {
    points.reserve(n);
    normals.reserve(n);
    kind.reserve(n);
    thickness.reserve(n);
    width.reserve(n);
    extrusion.reserve(n);
    feedRate.reserve(n);
    layer.reserve(n);
    subgraph.reserve(n);
    pathIndex.reserve(n);
  }
  /// Appends point i of `from` to every per-point array but axisTilt.
  void appendPointOf(const Toolpath& from, size_t i) {
    points.push_back(from.points[i]);
    normals.push_back(from.normals[i]);
    kind.push_back(from.kind[i]);
    thickness.push_back(from.thickness[i]);
    width.push_back(from.width[i]);
    extrusion.push_back(from.extrusion[i]);
    feedRate.push_back(from.feedRate[i]);
    layer.push_back(from.layer[i]);
    subgraph.push_back(from.subgraph[i]);
    pathIndex.push_back(from.pathIndex[i]);
  }
  /// Swaps every per-point array but axisTilt with other's (the report fields stay).
  void swapPoints(Toolpath& other) {
    points.swap(other.points);
    normals.swap(other.normals);
    kind.swap(other.kind);
    thickness.swap(other.thickness);
    width.swap(other.width);
    extrusion.swap(other.extrusion);
    feedRate.swap(other.feedRate);
    layer.swap(other.layer);
    subgraph.swap(other.subgraph);
    pathIndex.swap(other.pathIndex);
  }
};

/// Pieces of split sub-graphs in the printing order (sequence/SubgraphSplitting.h): a piece is
/// printed as the runs of its sub-graph's Euler tours that lie in it (open paths that end at the
/// cut vertices), at its own place in the order.
struct ToolpathPieces {
  std::vector<int> edgePiece;   ///< per lattice edge: its piece
  std::vector<int> pieceOrder;  ///< per position of the order: the piece printed there
};

/// Plans the path. lattice: from buildLatticeGraph or the VTK conversion (points, normals,
/// edges, edgeKind, edgeSubgraph, vertexSubgraph, subgraphs, layerValues); tree: its skeleton;
/// order: sub-graph ids in printing order (a permutation, e.g. PrintSequence::order; with
/// pieces, the sub-graph of the piece at each position, each sub-graph once per piece). Throws
/// GeoLatticeError for bad options, mismatched inputs, an order that is not a permutation (of
/// the pieces, with pieces), a piece whose edges are not of its sub-graph, or what trimming and
/// tours reject (odd vertices left, missing normals).
Toolpath planToolpath(const LatticeGraph& lattice, const SkeletonTree& tree,
                      const std::vector<int>& order, const ToolpathOptions& options = {},
                      const ToolpathPieces* pieces = nullptr);

}  // namespace geolattice
