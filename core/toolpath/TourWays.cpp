#include "toolpath/TourWays.h"

#include "common/Error.h"

#include <string>
#include <utility>

namespace geolattice {

TourWay tourWay(int index) {
  if (index < 0 || index >= kTourWays) {
    throw GeoLatticeError("toolpath: tour way " + std::to_string(index) + " is not in [0, 4)");
  }
  return TourWay{index >= 2, index % 2 == 1};
}

namespace {

/// Colliding material stations per walk (a station of tour t counts for walkOfTour[t]). Air
/// stations are left out: an air move depends on the walks at both of its ends.
std::vector<int> collidingPerWalk(const Toolpath& path, const std::vector<int>& stations,
                                  const std::vector<int>& walkOfTour, size_t walks) {
  std::vector<int> count(walks, 0);
  for (int i : stations) {
    const int tour = path.pathIndex[static_cast<size_t>(i)];
    if (path.kind[static_cast<size_t>(i)] != MoveKind::Air && tour >= 0 &&
        tour < static_cast<int>(walkOfTour.size())) {
      ++count[static_cast<size_t>(walkOfTour[static_cast<size_t>(tour)])];
    }
  }
  return count;
}

}  // namespace

TourWayRetry retryTourWays(Toolpath& path, std::vector<int>& uncleared,
                           std::vector<int>& walkOfTour, std::vector<int>& wayOf,
                           const std::vector<char>& closed,
                           const std::function<std::vector<int>()>& plan) {
  TourWayRetry r;
  r.before = r.after = static_cast<int>(uncleared.size());
  if (static_cast<double>(uncleared.size()) >
      kMaxRetriedFraction * static_cast<double>(path.points.size())) {
    return r;
  }
  const size_t W = closed.size();
  std::vector<int> best = collidingPerWalk(path, uncleared, walkOfTour, W);
  std::vector<int> retried;
  for (size_t w = 0; w < W; ++w) {
    if (best[w] > 0 && closed[w]) {
      retried.push_back(static_cast<int>(w));
    }
  }
  r.retriedTours = static_cast<int>(retried.size());
  if (retried.empty()) {
    return r;
  }
  Toolpath kept = std::move(path);
  std::vector<int> keptUncleared = uncleared, keptWalkOfTour = walkOfTour;
  const std::vector<int> keptWays = wayOf;
  std::vector<int> chosen = wayOf;
  bool changed = false;
  // The trial with the fewest colliding stations, kept: where every tour's way chosen is that
  // trial's (one tour retried, or all best the same way), it is the path, with no pass more.
  struct Trial {
    Toolpath path;
    std::vector<int> uncleared, walkOfTour, ways;
  } bestTrial;
  bestTrial.uncleared = keptUncleared;
  // Every retried tour tries the same way in one pass: tours on different layers hardly meet,
  // and a pass is the cost (the whole path's subdivision and clearance).
  for (int way = 1; way < kTourWays && !retried.empty(); ++way) {
    wayOf = chosen;
    for (int w : retried) {
      wayOf[static_cast<size_t>(w)] = way;
    }
    const std::vector<int> trial = plan();
    ++r.passes;
    const std::vector<int> count = collidingPerWalk(path, trial, walkOfTour, W);
    std::vector<int> still;
    for (int w : retried) {
      const size_t u = static_cast<size_t>(w);
      if (count[u] < best[u]) {
        best[u] = count[u];
        chosen[u] = way;
        changed = true;
      }
      if (best[u] > 0) {
        still.push_back(w);
      }
    }
    retried.swap(still);
    if (trial.size() < bestTrial.uncleared.size()) {
      bestTrial = Trial{path, trial, walkOfTour, wayOf};
    }
  }
  if (changed) {
    wayOf = chosen;
    std::vector<int> result;
    if (chosen == bestTrial.ways) {
      path = std::move(bestTrial.path);
      walkOfTour = std::move(bestTrial.walkOfTour);
      result = std::move(bestTrial.uncleared);
    } else {
      result = plan();
      ++r.passes;
    }
    if (result.size() < keptUncleared.size()) {
      uncleared = std::move(result);
      r.after = static_cast<int>(uncleared.size());
      for (size_t w = 0; w < W; ++w) {
        r.reorderedTours += wayOf[w] != keptWays[w];
      }
      return r;
    }
  }
  path = std::move(kept);
  uncleared = std::move(keptUncleared);
  walkOfTour = std::move(keptWalkOfTour);
  wayOf = keptWays;
  return r;
}

}  // namespace geolattice
