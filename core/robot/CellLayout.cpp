#include "robot/CellLayout.h"

#include "common/Error.h"
#include "common/ParallelFor.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

namespace geolattice {

namespace {

/// Lower is better: unreachable points, then large steps, then the largest step.
double badness(const RobotPath& p, size_t points) {
  return 1e6 * static_cast<double>(p.unreachable.size()) / std::max<size_t>(points, 1) +
         1e3 * static_cast<double>(p.largeSteps.size()) + p.maxJointStepDeg;
}

}  // namespace

CellLayoutResult solveWithCellLayout(const RobotCell& cell,
                                     const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<Eigen::Vector3d>& normals,
                                     const RobotPathOptions& o, const CellLayoutOptions& l,
                                     const std::vector<int>& kind) {
  CellLayoutResult result;
  result.cell = cell;
  std::string unreachableCell;  // the given cell reaches no part of the path continuously
  try {
    result.path = solveRobotPath(cell, points, normals, o, kind);
  } catch (const GeoLatticeError& e) {
    if (!l.search) {
      throw;
    }
    unreachableCell = e.what();
  }
  if (unreachableCell.empty() && (result.path.works() || !l.search)) {
    return result;
  }
  // The candidates: the mounting turned about the flange z axis and moved along it.
  const double given = cell.partOnFlange.translation().z();
  struct Candidate {
    RobotCell cell;
    double rotation, offset, score = 0;
  };
  std::vector<Candidate> candidates;
  for (double offset : l.offsetSteps) {
    if (given + offset < l.minOffset - 1e-12 || given + offset > l.maxOffset + 1e-12) {
      continue;
    }
    for (double rotation : l.rotationsDeg) {
      if (rotation == 0 && offset == 0) {
        continue;  // the layout as given: solved above
      }
      Candidate c{cell, rotation, offset};
      c.cell.partOnFlange =
          Isometry(Eigen::Translation3d(0, 0, offset)) *
          Isometry(Eigen::AngleAxisd(rotation * M_PI / 180, Eigen::Vector3d::UnitZ())) *
          cell.partOnFlange;
      candidates.push_back(c);
    }
  }
  // Rank on a subsample of the path (the same solver, fewer points).
  const size_t stride = std::max<size_t>(1, points.size() / std::max<size_t>(l.rankingPoints, 1));
  std::vector<Eigen::Vector3d> sp, sn;
  for (size_t i = 0; i < points.size(); i += stride) {
    sp.push_back(points[i]);
    sn.push_back(normals[i]);
  }
  RobotPathOptions ranking = o;  // a coarser plan: it only ranks the layouts
  ranking.reconfigure = false;   // the subsample has no air moves of its own
  ranking.coarseSamples = std::min(o.coarseSamples, 150);
  ranking.psiSamples = std::max(12, o.psiSamples / 2);
  ranking.refinements = 1;
  ranking.denserPlanFactor = 1;
  ranking.explainUnreachable = false;
  ranking.threads = 1;  // the layouts are ranked in parallel
  parallelFor(candidates.size(), 0, [&](size_t i, int) {
    Candidate& c = candidates[i];
    try {
      c.score = badness(solveRobotPath(c.cell, sp, sn, ranking), sp.size());
    } catch (const GeoLatticeError&) {
      c.score = std::numeric_limits<double>::infinity();  // e.g. unreachable cell set-up
    }
  });
  result.layoutsTried = static_cast<int>(candidates.size()) + 1;
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
  for (int k = 0; k < l.fullSolves && k < static_cast<int>(candidates.size()); ++k) {
    const Candidate& c = candidates[k];
    if (!std::isfinite(c.score)) {
      break;
    }
    ++result.fullSolves;
    RobotPath path;
    try {
      RobotPathOptions other = o;  // its error is not shown
      other.explainUnreachable = false;
      path = solveRobotPath(c.cell, points, normals, other, kind);
    } catch (const GeoLatticeError&) {
      continue;
    }
    if (path.works()) {
      result.cell = c.cell;
      result.path = std::move(path);
      result.rotationDeg = c.rotation;
      result.offsetAdded = c.offset;
      result.changed = true;
      return result;
    }
  }
  if (!unreachableCell.empty()) {
    throw GeoLatticeError(unreachableCell + "; no other mounting of the part on the flange (" +
                          std::to_string(result.layoutsTried - 1) + " tried) reaches it");
  }
  return result;  // nothing works: the given layout's path, for the caller's report
}

}  // namespace geolattice
