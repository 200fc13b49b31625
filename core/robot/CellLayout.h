#pragma once
/// @file CellLayout.h
/// @brief When the robot cannot follow the path as the cell is laid out (a wrist flip, a joint
/// limit, unreachable points), search the layout's free parameters before failing: how the part
/// (the platform) is mounted on the flange, i.e. its rotation about the flange's z axis and its
/// distance in front of the flange (within [minOffset, maxOffset] m). The nozzle and the robot
/// stay where they are. Each candidate layout is first ranked on a subsample of the path (every
/// stride-th point, the same solver), then the most promising ones are solved on the whole path;
/// the first without unreachable points and joint steps above the bound is taken. The layout as
/// given is always tried first, so a path that works keeps its cell.
///
/// Reported: the layout used (rotation, offset, whether it differs from the one given) and how
/// many were tried; the program's set_tcp carries the new mounting, and its header says how to
/// mount the platform.
#include "robot/RobotPathSolver.h"

#include <vector>

namespace geolattice {

struct CellLayoutOptions {
  bool search = true;  ///< false: the cell as given only
  /// Rotations of the part about the flange z axis tried (degrees, added to the given mounting).
  std::vector<double> rotationsDeg = {0, 45, 90, 135, 180, 225, 270, 315};
  /// Distances added to the given part offset along the flange z axis (m).
  std::vector<double> offsetSteps = {0.0, 0.03, 0.06};
  double minOffset = 0.02, maxOffset = 0.15;  ///< bounds of the part's distance from the flange (m)
  size_t rankingPoints = 4000;  ///< the ranking solves every stride-th point, about this many
  int fullSolves = 4;           ///< whole-path solves of the best ranked layouts (at most)
};

struct CellLayoutResult {
  RobotCell cell;          ///< the layout used
  RobotPath path;          ///< its joint path
  double rotationDeg = 0;  ///< rotation added about the flange z axis
  double offsetAdded = 0;  ///< metres added in front of the flange
  bool changed = false;    ///< not the layout as given
  int layoutsTried = 1;    ///< ranked candidates (the given one included)
  int fullSolves = 1;      ///< whole-path solves
};

/// kind: per point 0 print, 1 perimeter, 2 air, for reconfigurations (RobotPathSolver.h, step
/// 4), which are tried in a layout before the next layout is (the ranking plans without them).
/// The joint path in the cell as given if it works, else in the best layout found (see the file
/// comment); when none works, the given cell's path (its failure is then reported by the
/// caller). Throws GeoLatticeError when no layout reaches the path at all ("unreachable cell
/// set-up ...; no other mounting ... reaches it").
CellLayoutResult solveWithCellLayout(const RobotCell& cell,
                                     const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<Eigen::Vector3d>& normals,
                                     const RobotPathOptions& pathOptions,
                                     const CellLayoutOptions& layoutOptions = {},
                                     const std::vector<int>& kind = {});

}  // namespace geolattice
