#pragma once
/// @file StraightMove.h
/// @brief The controller's straight move between two joint configurations, followed joint by
/// joint: where is the arm between two waypoints of a movel?
///
/// A UR movel moves the TCP on a straight line with its orientation slerped, and the controller
/// tracks the joints continuously (the inverse kinematics solution nearest the joints it is at).
/// Near the wrist singularity (|sin θ5| small) a small turn of the part turns joints 4 and 6 a
/// lot: the joints may change by more than the path's bound between two waypoints although
/// nothing flips. Followed in small steps (each at most half the bound, halved down to 1/4096
/// of the move where needed), such a move is continuous when it arrives at the planned joints
/// of the second waypoint; a wrist flip, a branch change through the singularity or a joint
/// sent round by its ±360° limit arrives elsewhere (or needs a jump) and is not.
///
/// The waypoints returned (`via`) are joints on the move placed so that no joint changes by
/// more than the bound from one waypoint to the next: written as movel targets of their own,
/// the program keeps the bound and the controller's timing sees the fast stretch.
#include "robot/URKinematics.h"

#include <vector>

namespace geolattice {

struct StraightMoveVia {
  std::vector<double> t;            ///< move parameter in (0, 1) of each waypoint, increasing
  std::vector<JointVector> joints;  ///< joints there
  double maxStep = 0;               ///< rad: largest joint change between consecutive waypoints
};

/// Follows the move from joints `from` to joints `to` (both of the robot, TCP = flange ·
/// partOnFlange). True when it is continuous and every tracked joint stays inside the limits;
/// then `via` holds the waypoints needed to keep every step within maxStep (rad; empty when
/// the direct step already does). False for a flip, a limit or an unreachable pose on the way.
bool followStraightMove(const RobotModel& robot, const Isometry& partOnFlange,
                        const JointVector& from, const JointVector& to, double maxStep,
                        StraightMoveVia& via);

}  // namespace geolattice
