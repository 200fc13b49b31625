#include "toolpath/AirMoveRealignment.h"

#include "nozzle/BuildPlate.h"
#include "toolpath/NozzleAxisClearance.h"
#include "toolpath/PathSubdivision.h"
#include "toolpath/SafeBoxAirMove.h"

#include <algorithm>
#include <cmath>

namespace geolattice {

namespace {

/// Air points [first, last] between two material points, and how many of them collide.
struct AirRun {
  size_t first = 0, last = 0;
  int colliding = 0;
};

/// The air move laid again for a run: its points after the leave point (which the chain starts
/// with, so that the subdivision sees the first segment).
struct Chain {
  Toolpath points;
  std::vector<int> colliding;  ///< offsets (from 1) of the new points that collide
  bool keep = false;
};

void appendPoint(Toolpath& q, const Toolpath& p, size_t i) {
  q.appendPointOf(p, i);
  q.axisTilt.push_back(i < p.axisTilt.size() ? p.axisTilt[i] : 0.0);
}

double pathLength(const std::vector<Vec3>& points, size_t from, size_t to) {
  double length = 0;
  for (size_t i = from; i <= to; ++i) {
    length += (points[i] - points[i - 1]).norm();
  }
  return length;
}

/// The maximal air runs holding a colliding station, not the path's first (nothing printed
/// before it) or a last one (nothing after).
/// `colliding` ascending.
std::vector<AirRun> collidingAirRuns(const Toolpath& path, const std::vector<int>& colliding) {
  const size_t N = path.points.size();
  auto isAir = [&path](size_t i) {
    return path.kind[i] == MoveKind::Air;
  };
  std::vector<AirRun> runs;
  for (int c : colliding) {
    const size_t i = static_cast<size_t>(c);
    if (!isAir(i)) {
      continue;
    }
    if (!runs.empty() && i >= runs.back().first && i <= runs.back().last) {
      ++runs.back().colliding;
      continue;
    }
    AirRun run{i, i, 1};
    while (run.first > 0 && isAir(run.first - 1)) {
      --run.first;
    }
    while (run.last + 1 < N && isAir(run.last + 1)) {
      ++run.last;
    }
    if (run.first > 0 && run.last + 1 < N) {
      runs.push_back(run);
    }
  }
  return runs;
}

/// The safe-box move from the run's leave point (the material point before it) to its approach
/// end (the air point at the next start vertex), subdivided as the planner subdivides (axis turn
/// and segment length). It approaches along the approach end's final axis, and leaves along the
/// leave point's final axis where that pose is clear (`leaveClear`), else along the axis the old
/// move left with: a pose moved back along its own axis holds only what the pose holds.
Toolpath relaidMove(const Toolpath& path, const AirRun& run, bool leaveClear,
                    const Eigen::AlignedBox3d& printed, const ToolpathOptions& o) {
  const size_t a = run.first - 1;
  const Vec3& from = path.points[a];
  const Vec3& to = path.points[run.last];
  const Vec3 leaveAxis = path.normals[leaveClear ? a : run.first].normalized();
  Eigen::AlignedBox3d box = printed;
  box.extend(from);
  box.extend(to);
  box.min().array() -= o.safeMargin;
  box.max().array() += o.safeMargin;
  const std::vector<AirWaypoint> air =
      safeBoxAirMove(from, leaveAxis, to, path.normals[run.last].normalized(), box);
  Toolpath chain;
  appendPoint(chain, path, a);
  for (size_t w = 0; w < air.size(); ++w) {
    // Retracted on the way, primed at the approach's end (as the planner's moves).
    appendPoint(chain, path, w + 1 < air.size() ? run.first : run.last);
    chain.points.back() = air[w].point;
    chain.normals.back() = air[w].axis;
  }
  subdivideToolpath(chain, o.maxTurnDeg * M_PI / 180.0, o.maxSegmentLength);
  chain.axisTilt.assign(chain.points.size(), 0.0);  // on their planned axes
  return chain;
}

/// The path with the runs whose chain is kept (or, with `all`, every run) replaced by their
/// chains; chainStart[r] is where chain r's first new point lies (-1 when not used).
Toolpath splice(const Toolpath& path, const std::vector<AirRun>& runs,
                const std::vector<Chain>& chains, bool all, std::vector<long>& chainStart,
                std::vector<long>* newIndexOfOld) {
  Toolpath q;
  size_t extra = 0;
  for (size_t r = 0; r < runs.size(); ++r) {
    extra += chains[r].points.points.size();
  }
  q.reservePoints(path.points.size() + extra);
  q.axisTilt.reserve(path.points.size() + extra);
  chainStart.assign(runs.size(), -1);
  if (newIndexOfOld) {
    newIndexOfOld->assign(path.points.size(), -1);
  }
  size_t next = 0;  // the first old point not yet copied or replaced
  for (size_t r = 0; r < runs.size(); ++r) {
    if (!all && !chains[r].keep) {
      continue;
    }
    for (; next < runs[r].first; ++next) {
      if (newIndexOfOld) {
        (*newIndexOfOld)[next] = static_cast<long>(q.points.size());
      }
      appendPoint(q, path, next);
    }
    chainStart[r] = static_cast<long>(q.points.size());
    const Toolpath& c = chains[r].points;
    for (size_t i = 1; i < c.points.size(); ++i) {
      appendPoint(q, c, i);
    }
    next = runs[r].last + 1;
  }
  for (; next < path.points.size(); ++next) {
    if (newIndexOfOld) {
      (*newIndexOfOld)[next] = static_cast<long>(q.points.size());
    }
    appendPoint(q, path, next);
  }
  return q;
}

/// The checked stations of q with material before them (or the plate) inside the nozzle; the
/// others are not searched (KnownClear, nothing inserted).
std::vector<int> collidingAmong(const Toolpath& q, const std::vector<char>& checked,
                                const ToolpathOptions& o) {
  std::vector<char> material(q.points.size());
  std::vector<Vec3> part;
  for (size_t i = 0; i < q.points.size(); ++i) {
    material[i] = q.kind[i] != MoveKind::Air;
    if (material[i]) {
      part.push_back(q.points[i]);
    }
  }
  const std::vector<Vec3> plate = buildPlateSamples(o.plate, part);
  KnownClear known{std::vector<char>(q.points.size(), 1), std::vector<char>(q.points.size(), 0)};
  for (size_t i = 0; i < checked.size(); ++i) {
    known.clear[i] = checked[i] ? 0 : 1;
  }
  AxisClearanceOptions detect = o.clearance;
  detect.maxTiltDeg = 0;  // detection only
  detect.shouldAbort = o.shouldAbort;
  std::vector<Vec3> axes = q.normals;
  const AxisClearanceResult r =
      clearNozzleAxes(q.points, axes, q.normals, material, o.nozzle, detect,
                      plate.empty() ? nullptr : &plate, nullptr, nullptr, &known);
  return r.colliding;
}

}  // namespace

std::vector<int> realignCollidingAirMoves(Toolpath& path, const std::vector<int>& colliding,
                                          const ToolpathOptions& o) {
  std::vector<int> sorted = colliding;
  std::sort(sorted.begin(), sorted.end());
  const std::vector<AirRun> runs = collidingAirRuns(path, sorted);
  if (runs.empty()) {
    return colliding;
  }
  // The new moves, each in the safe box of the material printed before it.
  std::vector<Chain> chains(runs.size());
  Eigen::AlignedBox3d printed;
  size_t scanned = 0;
  for (size_t r = 0; r < runs.size(); ++r) {
    for (; scanned < runs[r].first; ++scanned) {
      if (path.kind[scanned] != MoveKind::Air) {
        printed.extend(path.points[scanned]);
      }
    }
    const bool leaveClear =
        !std::binary_search(sorted.begin(), sorted.end(), static_cast<int>(runs[r].first - 1));
    chains[r].points = relaidMove(path, runs[r], leaveClear, printed, o);
  }
  // All of them checked in one pass (air points are no obstacles: one move's verdict does not
  // depend on another's).
  std::vector<long> start;
  const Toolpath trial = splice(path, runs, chains, true, start, nullptr);
  std::vector<char> checked(trial.points.size(), 0);
  for (size_t r = 0; r < runs.size(); ++r) {
    const size_t n = chains[r].points.points.size() - 1;
    std::fill_n(checked.begin() + start[r], n, 1);
  }
  std::vector<int> owner(trial.points.size(), -1);
  for (size_t r = 0; r < runs.size(); ++r) {
    std::fill_n(owner.begin() + start[r], chains[r].points.points.size() - 1, static_cast<int>(r));
  }
  for (int i : collidingAmong(trial, checked, o)) {
    const int r = owner[static_cast<size_t>(i)];
    chains[static_cast<size_t>(r)].colliding.push_back(i - static_cast<int>(start[r]));
  }
  int kept = 0;
  for (size_t r = 0; r < runs.size(); ++r) {
    chains[r].keep = static_cast<int>(chains[r].colliding.size()) < runs[r].colliding;
    kept += chains[r].keep ? 1 : 0;
  }
  if (kept == 0) {
    return colliding;
  }
  // The kept ones spliced in; the stations left colliding: the old ones outside the replaced
  // runs, and the kept moves' own.
  std::vector<long> newIndexOfOld;
  Toolpath q = splice(path, runs, chains, false, start, &newIndexOfOld);
  std::vector<int> left;
  for (int i : colliding) {
    const long at = newIndexOfOld[static_cast<size_t>(i)];
    if (at >= 0) {
      left.push_back(static_cast<int>(at));
    }
  }
  for (size_t r = 0; r < runs.size(); ++r) {
    if (!chains[r].keep) {
      continue;
    }
    path.airLength += pathLength(chains[r].points.points, 1, chains[r].points.points.size() - 1) -
                      pathLength(path.points, runs[r].first, runs[r].last);
    for (int k : chains[r].colliding) {
      left.push_back(static_cast<int>(start[r]) + k);
    }
  }
  std::sort(left.begin(), left.end());
  path.swapPoints(q);
  path.axisTilt.swap(q.axisTilt);
  path.alignedTransitions += kept;
  path.unclearedStations = static_cast<int>(left.size());
  path.maxAxisTiltDeg =
      path.axisTilt.empty() ? 0.0 : *std::max_element(path.axisTilt.begin(), path.axisTilt.end());
  return left;
}

}  // namespace geolattice
