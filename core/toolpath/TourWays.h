#pragma once
/// @file TourWays.h
/// @brief Tours printed from another start or the other way round where their stations still
/// collide after the axis clearance (a toolpath planner step, ToolpathPlanner.h).
///
/// A closed tour starts at its vertex nearest to the nozzle and runs one way round. On a curved
/// layer the tour comes back next to beads it laid shortly before; where the layer folds (two
/// fronts meeting in a V, the top of a loop, a pipe's end) such a bead stands higher than the
/// tip, and the nozzle or the printhead's flank reaches it whatever tilt the clearance allows (a
/// generated 90° pipe elbow: ten support-perimeter stations of its last layer; topopt under the
/// example printhead: the face's rim on a neighbouring bead 0.30-0.37 mm above the tip). Which
/// of two such beads is there first is the tour's order: each tour with a colliding station is
/// printed again backwards, and from half-way round either way, and keeps the way with the
/// fewest of its stations colliding (material stations; an air move depends on the tours at
/// both ends). All such tours try the same way in one planning pass: a tour's way does not
/// change what the others see (they start where they would have; a later tour sees the same
/// material in another order). The path is kept only where fewer of its stations collide in
/// all; material and its amount are unchanged. Open runs of a split sub-graph are left as they
/// are (their ends are where the pieces meet).
///
/// The three other ways are those that helped most of eight (four starts, two directions) tried
/// on 27 runs (generated parts, bundled models as placed, with the cone and the example
/// printhead): of the 289 tours another way helped, backwards helped 108, from half-way 60 and
/// half-way backwards 25, each way from a quarter or three quarters round 12 to 35.
///
/// Cost: nothing where no station collides, or where more than kMaxRetriedFraction of the
/// stations do: that placement is far from printable (of the 27 runs, the path that came out
/// clear had 0.02 % of its stations colliding, the elbow's 10 of 46,541), and each pass
/// searches them all again (the bunny as placed under the example printhead, 0.4 %: 12 s
/// instead of 2 for 1,061 -> 808). Otherwise at most four more planning passes
/// (ToolpathPlanner's subdivision and clearance rounds, which reuse the earlier passes'
/// detection where the material before a station is unchanged): a trial pass per way until
/// every retried tour is clear, and one with the ways chosen, unless they are all one trial's
/// (one tour retried, or every tour best the same way): then that trial's path is kept.
#include "toolpath/ToolpathPlanner.h"

#include <functional>
#include <vector>

namespace geolattice {

/// How a closed tour is printed: starting at its vertex nearest to the nozzle or at the vertex
/// half-way round from it, forwards or backwards.
struct TourWay {
  bool fromHalfway = false;
  bool backwards = false;
};

/// The ways tried, in order (0: the planner's usual way).
constexpr int kTourWays = 4;

/// Way `index` of kTourWays: 0 forwards from the nearest vertex, 1 backwards, 2 forwards from
/// half-way round, 3 backwards from there.
TourWay tourWay(int index);

/// Above this fraction of colliding stations (one in a thousand) no other way is tried.
constexpr double kMaxRetriedFraction = 0.001;

/// What retryTourWays did (Toolpath::reorderedTours, unclearedBeforeReorder).
struct TourWayRetry {
  int retriedTours = 0;    ///< tours with a colliding station that were tried in other ways
  int reorderedTours = 0;  ///< of those, printed another way in the path kept (0: path unchanged)
  int before = 0;          ///< stations colliding before
  int after = 0;           ///< stations colliding in the path kept
  int passes = 0;          ///< planning passes run
};

/// Tries the other ways of the closed tours (walks) that hold a material station of `uncleared`
/// (the stations left colliding, indices into `path`). walkOfTour maps each tour of the path
/// (Toolpath::pathIndex) to its walk; closed[w] says whether walk w is a closed tour; wayOf[w]
/// is the way walk w is printed (all 0 on entry). plan() builds the path again with the current
/// wayOf (writing path and walkOfTour) and returns its stations left colliding. On return path,
/// uncleared, walkOfTour and wayOf are those of the path kept.
TourWayRetry retryTourWays(Toolpath& path, std::vector<int>& uncleared,
                           std::vector<int>& walkOfTour, std::vector<int>& wayOf,
                           const std::vector<char>& closed,
                           const std::function<std::vector<int>()>& plan);

}  // namespace geolattice
