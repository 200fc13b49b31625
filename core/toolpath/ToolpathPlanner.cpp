#include "toolpath/ToolpathPlanner.h"

#include "common/Error.h"
#include "common/Progress.h"
#include "toolpath/AirMoveRealignment.h"
#include "toolpath/EulerTour.h"
#include "toolpath/EulerianTrimming.h"
#include "toolpath/PathSubdivision.h"
#include "toolpath/SafeBoxAirMove.h"
#include "toolpath/SupportPerimeter.h"
#include "toolpath/TourWays.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <sstream>

namespace geolattice {

void ToolpathOptions::validate() const {
  auto positive = [](double v, const char* what) {
    if (!(v > 0) || !std::isfinite(v)) {
      std::ostringstream s;
      s << "toolpath: " << what << " must be > 0 (got " << v << ")";
      throw GeoLatticeError(s.str());
    }
  };
  positive(this->pathWidth, "path width");
  positive(this->filamentRadius, "filament radius");
  positive(this->printFeedRate, "print feed rate");
  positive(this->airFeedRate, "air feed rate");
  positive(this->thicknessCap, "thickness cap lambda");
  positive(this->maxTurnDeg, "maximum turn angle");
  positive(this->lift, "lift");
  if (!(this->maxSegmentLength >= 0) || !std::isfinite(this->maxSegmentLength)) {
    throw GeoLatticeError("toolpath: the longest segment must be >= 0 mm (0 = no subdivision)");
  }
  this->nozzle.validate();
  this->plate.validate();
  this->clearance.validate();
  if (!(this->toothLength >= 0) || !std::isfinite(this->toothLength)) {
    throw GeoLatticeError("toolpath: tooth length must be >= 0 mm (0 = twice the path width)");
  }
  if (!(this->flowCorrection > 0 && this->flowCorrection <= 1)) {
    throw GeoLatticeError("toolpath: flow correction mu must be in (0, 1]");
  }
  if (!(this->safeMargin >= 0) || !(this->retraction >= 0)) {
    throw GeoLatticeError("toolpath: safe margin and retraction must be >= 0");
  }
  requireValidWorkLimit(this->maxElements, "the toolpath size limit");
}

namespace {

class PathBuilder {
public:
  PathBuilder(Toolpath& path, const ToolpathOptions& o) : p_(path), o_(o) {}

  bool empty() const { return p_.points.empty(); }
  const Vec3& position() const { return p_.points.back(); }
  const Vec3& axis() const { return p_.normals.back(); }

  /// Appends a point reached by a move of `kind` (rotation steps come later, PathSubdivision.h).
  void add(const Vec3& x, const Vec3& n, MoveKind kind, double h, int layer, int subgraph, int tour,
           bool extrude = true) {
    push(x, n, kind, h, layer, subgraph, tour, extrude);
  }

  void retract(double amount) { e_ -= amount; }
  void prime(double amount) { e_ += amount; }

private:
  void push(const Vec3& x, const Vec3& n, MoveKind kind, double h, int layer, int subgraph,
            int tour, bool extrude) {
    const bool print = kind != MoveKind::Air;
    const double w = print && extrude ? o_.pathWidth : 0.0;
    if (!empty()) {
      const double len = (x - position()).norm();
      if (print) {
        // Arriving by air, the segment starts at this tour's first vertex: use h at both ends.
        const double h0 = p_.kind.back() == MoveKind::Air ? h : p_.thickness.back();
        const double hm = 0.5 * (h + h0);
        const double volume = o_.flowCorrection * w * hm * len;  // Eq. 14: μ w h L
        const double de = volume / (M_PI * o_.filamentRadius * o_.filamentRadius);
        e_ += de;
        p_.filamentLength += de;
        p_.depositedVolume += volume;
        (kind == MoveKind::Print ? p_.printLength : p_.perimeterLength) += len;
      } else {
        p_.airLength += len;
      }
    }
    p_.points.push_back(x);
    p_.normals.push_back(n);
    p_.kind.push_back(kind);
    p_.thickness.push_back(print ? h : 0.0);
    p_.width.push_back(w);
    p_.extrusion.push_back(e_);
    p_.feedRate.push_back(print ? o_.printFeedRate : o_.airFeedRate);
    p_.layer.push_back(print ? layer : -1);
    p_.subgraph.push_back(print ? subgraph : -1);
    p_.pathIndex.push_back(tour);
  }

  Toolpath& p_;
  const ToolpathOptions& o_;
  double e_ = 0;
};

/// Refuses a toolpath whose station count, estimated from the lattice and the options, exceeds
/// the work limit: every edge, its subdivision by maxSegmentLength, four stations per tooth.
void requireToolpathWithinLimit(const LatticeGraph& g, const ToolpathOptions& o) {
  double length = 0, boundary = 0;
  for (size_t e = 0; e < g.edges.size(); ++e) {
    const double l = (g.points[g.edges[e][0]] - g.points[g.edges[e][1]]).norm();
    length += l;
    boundary += g.edgeKind[e] == LatticeEdgeKind::Boundary ? l : 0.0;
  }
  const double tooth = o.toothLength > 0 ? o.toothLength : 2 * o.pathWidth;
  const double stations = static_cast<double>(g.edges.size()) +
                          (o.maxSegmentLength > 0 ? length / o.maxSegmentLength : 0.0) +
                          (o.supportPerimeter ? 4 * boundary / tooth : 0.0);
  std::ostringstream because;
  because << "for " << std::llround(length) << " mm of lattice at a longest segment of "
          << o.maxSegmentLength << " mm and a tooth length of " << tooth << " mm";
  requireWithinWorkLimit(
      stations, o.maxElements, "toolpath", "stations", because.str(),
      "use a longer segment or tooth length, or raise the size limit (MaximumElements)");
}

/// Rounds of axis clearance a path gets at most.
constexpr int kClearanceRounds = 4;
/// From this round on, a fade that would push a point into material is not applied. The first
/// rounds fade freely (a neighbour pushed into material gets a tilt of its own in the next round,
/// so a region of stations turns to a common side); without the check later, fades push cleared
/// neighbours back round after round where a station sits in a groove between taller beads (spot
/// auto-oriented under the example printhead: 111 -> 18 -> 20 -> 12 -> 24 -> 11 ... colliding
/// stations over 16 rounds; with the check from round 2: 0 after 4).
constexpr int kSettlingRound = 2;

/// Rotation steps and subdivision, then rounds of axis clearance (each followed by the rotation
/// steps its tilts need) until no station collides or no tilt helps. Returns the stations left
/// colliding. With `replannable` (a station the caller can move, e.g. on a hop it can send over
/// the safe box) it returns early, the path unfinished, as soon as a round finds such stations
/// that no tilt clears: their obstacles only grow in later rounds, so they would stay, and the
/// caller plans the path again anyway.
std::vector<int> finishAxes(Toolpath& path, const ToolpathOptions& o,
                            const ProgressReporter& progress,
                            const std::function<bool(int)>& replannable = {},
                            std::vector<AxisSearchMemo>* memos = nullptr,
                            PathObstacleTrees* trees = nullptr) {
  AxisClearanceOptions clearance = o.clearance;
  clearance.shouldAbort = o.shouldAbort;
  const double maxTurn = o.maxTurnDeg * M_PI / 180.0;
  SubdivisionCounts counts = subdivideToolpath(path, maxTurn, o.maxSegmentLength);
  path.rotationSteps = counts.rotationSteps;
  path.subdivisionPoints = counts.inserted;
  std::vector<Vec3> reference = path.normals;
  auto materialOf = [&path] {
    std::vector<char> m(path.kind.size());
    for (size_t i = 0; i < m.size(); ++i) {
      m[i] = path.kind[i] != MoveKind::Air;
    }
    return m;
  };
  // The build plate under the part is an obstacle like material (nozzle/BuildPlate.h).
  std::vector<Vec3> part;
  for (size_t i = 0; i < path.points.size(); ++i) {
    if (path.kind[i] != MoveKind::Air) {
      part.push_back(path.points[i]);
    }
  }
  const std::vector<Vec3> plate = buildPlateSamples(o.plate, part);
  const std::vector<Vec3>* fixed = plate.empty() ? nullptr : &plate;
  bool checked = false;
  std::vector<int> uncleared;
  std::vector<char> unresolvable(path.points.size(), 0);  // no tilt clears them: not retried
  // Stations found clear keep that answer through the subdivision: a later round checks them
  // against the inserted points only.
  KnownClear known{std::vector<char>(path.points.size(), 0),
                   std::vector<char>(path.points.size(), 0)};
  auto subdivideKeepingFlags = [&] {
    enum : char { kUnresolvable = 1, kClear = 2, kOld = 4 };
    std::vector<char> flags(path.points.size());
    for (size_t i = 0; i < flags.size(); ++i) {
      flags[i] = static_cast<char>((unresolvable[i] ? kUnresolvable : 0) |
                                   (known.clear[i] ? kClear : 0) | kOld);
    }
    const SubdivisionCounts c = subdivideToolpath(path, maxTurn, 0.0, &reference, &flags);
    unresolvable.resize(flags.size());
    known.clear.resize(flags.size());
    known.inserted.resize(flags.size());
    for (size_t i = 0; i < flags.size(); ++i) {
      unresolvable[i] = (flags[i] & kUnresolvable) != 0;
      known.clear[i] = (flags[i] & kClear) != 0;
      known.inserted[i] = (flags[i] & kOld) == 0;
    }
    return c;
  };
  for (int round = 0; round < kClearanceRounds && o.clearance.maxTiltDeg > 0; ++round) {
    clearance.fadeOnlyWhereClear = round >= kSettlingRound;
    const AxisClearanceResult r = clearNozzleAxes(
        path.points, path.normals, reference, materialOf(), o.nozzle, clearance, fixed,
        &unresolvable, memos ? &(*memos)[static_cast<size_t>(round)] : nullptr, &known, trees);
    progress.report(static_cast<double>(round + 1) / kClearanceRounds);
    // A memo holds 48 bytes per material point to the stage's end (topopt: 17 MB a round) and
    // saves a later attempt this round's detection and searches: kept for round 0 (the whole
    // path's detection) and for rounds that searched at least 1 % of the stations.
    if (memos && round > 0 && static_cast<size_t>(r.collidingStations) * 100 < path.points.size()) {
      (*memos)[static_cast<size_t>(round)] = AxisSearchMemo{};
    }
    if (replannable) {
      std::vector<int> stuck;
      for (int i : r.colliding)
        if (unresolvable[static_cast<size_t>(i)] && replannable(i))
          stuck.push_back(i);
      if (!stuck.empty())
        return stuck;
    }
    if (round == 0) {
      path.collidingStations = r.collidingStations;
    }
    path.clearanceRounds = round + 1;
    path.tiltedStations += r.tiltedStations;
    if (r.collidingStations == 0 || r.tiltedStations == 0) {
      path.unclearedStations = r.collidingStations;
      uncleared = r.colliding;
      checked = true;
      break;
    }
    counts = subdivideKeepingFlags();
    path.rotationSteps += counts.rotationSteps;
    path.subdivisionPoints += counts.inserted;
  }
  if (!checked) {  // count what is left (or, with clearance off, what there is)
    AxisClearanceOptions detectOnly = clearance;
    detectOnly.maxTiltDeg = 0;
    const AxisClearanceResult r =
        clearNozzleAxes(path.points, path.normals, reference, materialOf(), o.nozzle, detectOnly,
                        fixed, nullptr, nullptr, &known, trees);
    path.unclearedStations = r.collidingStations;
    uncleared = r.colliding;
    if (path.clearanceRounds == 0) {
      path.collidingStations = r.collidingStations;
    }
  }
  path.axisTilt.resize(path.points.size());
  for (size_t i = 0; i < path.points.size(); ++i) {
    path.axisTilt[i] =
        std::atan2(path.normals[i].cross(reference[i]).norm(), path.normals[i].dot(reference[i])) *
        180.0 / M_PI;
    path.maxAxisTiltDeg = std::max(path.maxAxisTiltDeg, path.axisTilt[i]);
  }
  return uncleared;
}

/// What one continuous print path prints: a whole closed tour, or a run of one in a piece.
struct Walk {
  int tour = 0;
  int piece = -1;
  bool closed = true;
  std::vector<int> vertices;  ///< closed: first == last
};

/// The tours as they are, or cut into the maximal runs of consecutive edges of one piece.
std::vector<Walk> printWalks(const EulerTours& tours, const ToolpathPieces* pieces) {
  std::vector<Walk> walks;
  for (size_t t = 0; t < tours.vertices.size(); ++t) {
    const std::vector<int>& vs = tours.vertices[t];
    const std::vector<int>& es = tours.edges[t];
    const size_t n = es.size();
    auto pieceOf = [&](size_t i) {
      return pieces->edgePiece[es[i % n]];
    };
    size_t first = n;  // an edge whose predecessor is of another piece
    for (size_t i = 0; pieces && i < n && first == n; ++i) {
      if (pieceOf(i) != pieceOf(i + n - 1)) {
        first = i;
      }
    }
    if (first == n) {  // one piece (or none): the closed tour
      walks.push_back({static_cast<int>(t), pieces && n ? pieceOf(0) : -1, true, vs});
      continue;
    }
    for (size_t i = first; i < first + n;) {
      Walk run{static_cast<int>(t), pieceOf(i), false, {vs[i % n]}};
      for (; i < first + n && pieceOf(i) == run.piece; ++i) {
        run.vertices.push_back(vs[(i + 1) % n]);
      }
      walks.push_back(std::move(run));
    }
  }
  return walks;
}

/// The pieces must cover the lattice's edges, each with a piece of its own sub-graph printed
/// once, at a position whose sub-graph is that one.
void checkPieces(const LatticeGraph& g, const std::vector<int>& order, const ToolpathPieces& p) {
  const size_t P = p.pieceOrder.size();
  if (p.edgePiece.size() != g.edges.size() || order.size() != P) {
    throw GeoLatticeError(
        "toolpath: the pieces need one piece per lattice edge and one per position of the order");
  }
  std::vector<int> positionOf(P, -1);
  for (size_t i = 0; i < P; ++i) {
    const int piece = p.pieceOrder[i];
    if (piece < 0 || piece >= static_cast<int>(P) || positionOf[piece] >= 0 || order[i] < 0 ||
        order[i] >= static_cast<int>(g.subgraphs.size())) {
      throw GeoLatticeError("toolpath: the print order must list every piece exactly once");
    }
    positionOf[piece] = static_cast<int>(i);
  }
  for (size_t e = 0; e < g.edges.size(); ++e) {
    const int piece = p.edgePiece[e];
    if (g.edgeSubgraph[e] >= 0 && (piece < 0 || piece >= static_cast<int>(P) ||
                                   order[positionOf[piece]] != g.edgeSubgraph[e])) {
      throw GeoLatticeError("toolpath: lattice edge " + std::to_string(e) + " is in piece " +
                            std::to_string(piece) + ", which is not a piece of its sub-graph " +
                            std::to_string(g.edgeSubgraph[e]));
    }
  }
}

}  // namespace

Toolpath planToolpath(const LatticeGraph& input, const SkeletonTree& tree,
                      const std::vector<int>& order, const ToolpathOptions& o,
                      const ToolpathPieces* pieces) {
  const auto t0 = std::chrono::steady_clock::now();
  o.validate();
  const int K = static_cast<int>(input.subgraphs.size());
  if (K == 0) {
    throw GeoLatticeError("toolpath: the lattice has no sub-graph");
  }
  if (static_cast<int>(tree.nodes.size()) != K) {
    throw GeoLatticeError("toolpath: the skeleton does not match the lattice's sub-graphs");
  }
  if (input.normals.size() != input.points.size()) {
    throw GeoLatticeError("toolpath: the lattice has no nozzle direction (Normals) per vertex");
  }
  if (pieces) {
    checkPieces(input, order, *pieces);
  } else {
    std::vector<char> seen(K, 0);
    if (static_cast<int>(order.size()) != K) {
      throw GeoLatticeError("toolpath: the print order must list every sub-graph exactly once");
    }
    for (int k : order) {
      if (k < 0 || k >= K || seen[k]) {
        throw GeoLatticeError("toolpath: the print order must list every sub-graph exactly once");
      }
      seen[k] = 1;
    }
  }
  for (size_t v = 0; v < input.normals.size(); ++v) {
    if (input.vertexSubgraph[v] >= 0 && !(input.normals[v].norm() > 0)) {
      std::ostringstream s;
      s << "toolpath: lattice vertex " << v << " has a zero normal (missing nozzle direction)";
      throw GeoLatticeError(s.str());
    }
  }

  requireToolpathWithinLimit(input, o);
  const ProgressReporter progress(o.progress, o.shouldAbort, "toolpath planning");

  Toolpath path;
  Eigen::AlignedBox3d all;
  for (const Vec3& x : input.points) {
    all.extend(x);
  }
  ToolpathPieces contractedPieces;  // the pieces on the contracted edges
  if (pieces) {
    contractedPieces = *pieces;
  }
  // Contraction edits the edge arrays: the lattice is copied only when it has edges to contract
  // (rarely; the copy of a 75k-tet part's lattice is ~25 MB of fresh memory).
  const double contractBelow = 1e-9 * std::max(1.0, all.diagonal().norm());
  std::optional<LatticeGraph> contracted;
  if (countShortEdges(input, contractBelow) > 0) {
    contracted.emplace(input);
    path.contractedEdges = contractShortEdges(*contracted, contractBelow,
                                              pieces ? &contractedPieces.edgePiece : nullptr);
  }
  const LatticeGraph& g = contracted ? *contracted : input;
  const TrimResult trim = trimToEulerian(g);
  const EulerTours tours = nonCrossingEulerTours(g, trim.kept);
  path.crossings = countTourCrossovers(g, tours);
  path.trimmedEdges = trim.trimmedEdges;
  path.trimmedLength = trim.trimmedLength;
  path.splitSubgraphs = trim.splitSubgraphs;
  path.thicknessStats = computeLayerThickness(g, tree, o.thicknessCap);
  PerimeterResult perimeters;
  if (o.supportPerimeter) {
    perimeters = supportPerimeters(g, trim.kept, o.pathWidth,
                                   o.toothLength > 0 ? o.toothLength : 2 * o.pathWidth);
  }
  path.perimeterLoops = static_cast<int>(perimeters.loops.size());
  path.perimeterTeeth = perimeters.teeth;
  std::vector<std::vector<int>> loopsAt(g.points.size());  // anchor vertex -> perimeter loops
  for (size_t i = 0; i < perimeters.loops.size(); ++i) {
    loopsAt[perimeters.loops[i].anchorVertex].push_back(static_cast<int>(i));
  }
  const std::vector<double>& h = path.thicknessStats.thickness;

  // What each position of the order prints: its sub-graph's tours, or the runs of them in its
  // piece.
  const std::vector<Walk> walks = printWalks(tours, pieces ? &contractedPieces : nullptr);
  std::vector<std::vector<int>> walksAt(order.size());
  {
    std::vector<std::vector<int>> walksOf(pieces ? pieces->pieceOrder.size() : K);
    std::vector<int> positionOfPiece;
    if (pieces) {
      positionOfPiece.assign(pieces->pieceOrder.size(), 0);
      for (size_t i = 0; i < pieces->pieceOrder.size(); ++i) {
        positionOfPiece[pieces->pieceOrder[i]] = static_cast<int>(i);
      }
    }
    for (size_t w = 0; w < walks.size(); ++w) {
      const int at = pieces ? positionOfPiece[walks[w].piece] : -1;
      if (pieces) {
        walksAt[at].push_back(static_cast<int>(w));
      } else {
        walksOf[tours.subgraph[walks[w].tour]].push_back(static_cast<int>(w));
      }
    }
    if (!pieces) {
      for (size_t i = 0; i < order.size(); ++i) {
        walksAt[i] = walksOf[order[i]];
      }
    }
  }

  // Built once; if stations of a hop (the short lift onto an upper node) still collide after
  // the axis clearance, the hop passed too close to a curved layer: those transitions go over
  // the safe box instead and the path is built again.
  const Toolpath base = path;
  const std::vector<std::vector<int>> loopsAtStart = loopsAt;
  std::vector<char> overTheBox(walks.size(), 0);  // per walk: its arrival goes over the box
  std::vector<char> hopped(walks.size(), 0);      // per walk: it was reached by a hop
  std::vector<int> walkOfTour;                    // the walk printed as each tour
  std::vector<int> wayOf(walks.size(), 0);        // how each walk is printed (TourWay)
  int replannedHops = 0;
  // The attempts differ only in air moves (not material): each clearance round of a later
  // attempt reuses the same round's detection and least-tilt searches of the earlier one where
  // the material before a station is still the same (AxisSearchMemo).
  std::vector<AxisSearchMemo> memos(kClearanceRounds);
  // Their material is also the same up to inserted points: every pass keeps the obstacles'
  // kd-trees of the first where it can (PathObstacleTrees).
  PathObstacleTrees trees;
  std::vector<int> uncleared;
  auto buildPath = [&] {
    path = base;
    loopsAt = loopsAtStart;
    walkOfTour.clear();
    std::fill(hopped.begin(), hopped.end(), 0);
    PathBuilder b(path, o);
    Eigen::AlignedBox3d printed;  // everything printed so far
    int previous = -1, tourIndex = 0;
    Vec3 nearTo = Vec3::Zero();  // where the next walk starts nearest to
    for (size_t position = 0; position < order.size(); ++position) {
      const int k = order[position];
      std::vector<int> remaining = walksAt[position];
      while (!remaining.empty()) {
        // The walk with the vertex nearest to the nozzle (a closed tour: any vertex; an open
        // run: either end); start there.
        size_t bestWalk = 0, bestAt = 0;
        double bestDistance = std::numeric_limits<double>::infinity();
        for (size_t r = 0; r < remaining.size(); ++r) {
          const Walk& walk = walks[remaining[r]];
          const size_t last = walk.vertices.size() - 1;
          for (size_t i = 0; i < last || (!walk.closed && i == last); ++i) {
            if (!walk.closed && i != 0 && i != last) {
              continue;
            }
            const double d = b.empty() ? static_cast<double>(i)
                                       : (g.points[walk.vertices[i]] - nearTo).squaredNorm();
            if (d < bestDistance) {
              bestDistance = d;
              bestWalk = r;
              bestAt = i;
            }
          }
        }
        const int w = remaining[bestWalk];
        const Walk& walk = walks[w];
        walkOfTour.push_back(w);
        remaining.erase(remaining.begin() + static_cast<long>(bestWalk));
        const std::vector<int>& vs = walk.vertices;
        const size_t n = vs.size() - 1;  // closed: vs[n] == vs[0]; open: n edges
        const TourWay way = tourWay(wayOf[w]);
        // The next walk starts nearest to where this one ends printed the usual way, so that the
        // way of one tour leaves the others' as they are (TourWays.h).
        nearTo = g.points[walk.closed ? vs[bestAt] : (bestAt == 0 ? vs[n] : vs[0])];
        if (walk.closed && way.fromHalfway) {
          bestAt = (bestAt + n / 2) % n;
        }
        // The j-th vertex after the start: around a closed tour (either way), or along (or back
        // along) a run.
        auto vertexAfter = [&](size_t j) {
          if (walk.closed) {
            return vs[(way.backwards ? bestAt + n - j % n : bestAt + j) % n];
          }
          return bestAt == 0 ? vs[j] : vs[n - j];
        };
        const int start = vs[bestAt];
        const Vec3 startAxis = g.normals[start].normalized();
        if (!b.empty()) {
          b.retract(o.retraction);
          const bool upper =
              previous >= 0 && std::binary_search(tree.nodes[previous].upper.begin(),
                                                  tree.nodes[previous].upper.end(), k);
          std::vector<AirWaypoint> air;
          // A hop lifts along the axes: where they point down near the plate that would go
          // into it (the build plate is an obstacle), so such a transition goes over the box.
          const bool liftAbovePlate =
              !o.plate.enabled || ((b.position() + o.lift * b.axis()).z() >= 0 &&
                                   (g.points[start] + o.lift * startAxis).z() >= 0);
          if (upper && !overTheBox[w] && liftAbovePlate) {
            hopped[w] = 1;
            air = liftAirMove(b.position(), b.axis(), g.points[start], startAxis, o.lift);
          } else {
            Eigen::AlignedBox3d box = printed;
            box.extend(b.position());
            box.extend(g.points[start]);
            box.min().array() -= o.safeMargin;
            box.max().array() += o.safeMargin;
            air = safeBoxAirMove(b.position(), b.axis(), g.points[start], startAxis, box);
          }
          for (size_t i = 0; i + 1 < air.size(); ++i) {
            b.add(air[i].point, air[i].axis, MoveKind::Air, 0.0, -1, -1, tourIndex);
          }
          // Prime during the approach, so E at the tour's start already holds it and every print
          // segment's ΔE is its deposited filament only.
          b.prime(o.retraction);
          b.add(air.back().point, air.back().axis, MoveKind::Air, 0.0, -1, -1, tourIndex);
          ++path.retractions;
        }
        const int layer = g.subgraphs[k].layer;
        if (b.empty()) {  // the very first point: the nozzle starts there
          b.add(g.points[start], startAxis, MoveKind::Air, 0.0, -1, -1, tourIndex);
        }
        // Perimeter loops anchored at v: out along the connector, around, back without extrusion.
        auto splicePerimeters = [&](int v) {
          for (int li : loopsAt[v]) {
            const PerimeterLoop& loop = perimeters.loops[li];
            for (size_t q = 0; q < loop.points.size(); ++q) {
              b.add(loop.points[q], loop.normals[q], MoveKind::Perimeter, h[loop.nearVertex[q]],
                    layer, k, tourIndex);
              printed.extend(loop.points[q]);
            }
            b.add(g.points[v], g.normals[v].normalized(), MoveKind::Perimeter, h[v], layer, k,
                  tourIndex, false);
          }
          loopsAt[v].clear();
        };
        splicePerimeters(start);
        for (size_t j = 1; j <= n; ++j) {
          const int v = vertexAfter(j);
          b.add(g.points[v], g.normals[v].normalized(), MoveKind::Print, h[v], layer, k, tourIndex);
          printed.extend(g.points[v]);
          splicePerimeters(v);
        }
        printed.extend(g.points[start]);
        ++tourIndex;
      }
      previous = k;
    }
    path.tours = tourIndex;
  };
  for (int attempt = 0;; ++attempt) {
    buildPath();
    // Attempt 0 is the usual run; a replanned attempt only moves some hops over the box.
    const ProgressReporter attemptProgress = progress.part(
        attempt == 0 ? 0.0 : 0.85 + 0.05 * attempt, attempt == 0 ? 0.9 : 0.9 + 0.05 * attempt);
    attemptProgress.part(0, 0.3).report(1.0);
    auto replannable = [&](int i) {
      const int tour = path.pathIndex[i];
      if (path.kind[i] != MoveKind::Air || tour < 0 ||
          tour >= static_cast<int>(walkOfTour.size())) {
        return false;
      }
      const int w = walkOfTour[tour];
      return hopped[w] && !overTheBox[w];
    };
    constexpr int kLastAttempt = 2;
    uncleared = finishAxes(path, o, attemptProgress.part(0.3, 1.0),
                           attempt < kLastAttempt ? std::function<bool(int)>(replannable) : nullptr,
                           &memos, &trees);
    int replan = 0;
    for (int i : uncleared) {
      if (replannable(i)) {
        overTheBox[walkOfTour[path.pathIndex[i]]] = 1;
        ++replan;
      }
    }
    replannedHops += replan;
    if (replan == 0 || attempt == kLastAttempt) {
      break;
    }
  }
  // Air moves with colliding stations laid again along the cleared axes.
  auto realign = [&](std::vector<int> stations) {
    return o.alignTransitions && !stations.empty() ? realignCollidingAirMoves(path, stations, o)
                                                   : stations;
  };
  uncleared = realign(std::move(uncleared));
  if (o.retryTourWays && !uncleared.empty()) {
    std::vector<char> closed(walks.size());
    for (size_t w = 0; w < walks.size(); ++w) {
      closed[w] = walks[w].closed;
    }
    const TourWayRetry retry = retryTourWays(path, uncleared, walkOfTour, wayOf, closed, [&] {
      buildPath();
      return realign(finishAxes(path, o, progress.part(1.0, 1.0), nullptr, &memos, &trees));
    });
    path.reorderedTours = retry.reorderedTours;
    path.unclearedBeforeReorder = retry.before;
  }
  path.replannedHops = replannedHops;
  path.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return path;
}

}  // namespace geolattice
