#pragma once
/// @file RobotPathSolver.h
/// @brief Joint values for every toolpath point in the robot cell (RobotCell.h), with the free
/// rotation ψ about the nozzle axis chosen along the path, not per point.
///
/// 1. Coarse pass: every stride-th point (about 500 samples). For each of the 8 IK branches,
///    dynamic programming over a grid of ψ (psiSamples values) picks the ψ sequence that
///    minimises Σ joint-space steps + singularity penalties, allowing ψ to move at most
///    maxPsiStep grid cells between samples; infeasible states (no IK, joint limits) cost ∞.
///    Joints are carried as reached along the path (turns add up, no folding modulo 2π), so a
///    path that would wind a joint past its limit is infeasible too.
///    The branch with the least cost wins.
/// 2. Fine pass: ψ is interpolated between the coarse samples, IK of the chosen branch is
///    solved at every point and unwrapped to the joint values nearest to the previous ones
///    (multiples of 2π inside the ±2π limits), so joints stay continuous. A point whose IK
///    fails is retried at nearby ψ; if that fails too it is reported in `unreachable` (never
///    skipped silently) and keeps the previous joints.
/// 3. Refinement: where a joint still steps by more than maxJointStepDeg between consecutive
///    points (ψ was only interpolated between two coarse samples, and the wrist flipped near a
///    singularity or a joint ran into its limit), the coarse interval around the step is sampled
///    64 times more densely and the plan is made again (up to `refinements` passes). Steps left
///    are listed in `largeSteps` for the caller to refuse.
/// Cost O(samples · ψ² · 8 + N) IK solutions; 1M points ≈ 1 s.
#include "robot/RobotCell.h"

#include <vector>

namespace geolattice {

struct RobotPathOptions {
  int psiSamples = 72;      ///< grid of ψ over 2π (5° steps)
  int maxPsiStep = 2;       ///< grid cells ψ may move between coarse samples
  int coarseSamples = 500;  ///< about this many coarse samples
  double singularityMargin =
      0.05;  ///< below this (|sin θ5|, |sin θ3|, shoulder distance in m) a penalty applies
  double maxJointStepDeg =
      20.0;  ///< a larger step of any joint between consecutive points triggers refinement
  int refinements = 3;  ///< passes that densify the coarse samples around such steps
};

struct RobotPath {
  std::vector<JointVector> joints;  ///< per point, continuous (unwrapped)
  std::vector<double> psi;          ///< per point (rad)
  std::vector<int> unreachable;     ///< point indices without a valid IK solution
  int branch = -1;                  ///< IK branch used (inverseKinematicsBranch)
  double maxJointStepDeg = 0;       ///< largest change of any joint between consecutive points
  int maxJointStepAt = -1;          ///< the point where it happens (the step from the point before)
  std::vector<int>
      largeSteps;         ///< points reached by a step above RobotPathOptions::maxJointStepDeg
  int coarseSamples = 0;  ///< coarse samples after refinement
  int refinements = 0;    ///< refinement passes used
  SingularityDistance minSingularity;  ///< smallest distances along the path
  double maxTipError = 0;      ///< m: |FK(q)·partOnFlange·p − nozzle tip| over reachable points
  double maxAxisErrorDeg = 0;  ///< angle between the placed axis n and the nozzle axis
  double seconds = 0;
};

/// points/normals: toolpath in part units. Throws GeoLatticeError for an empty path, NaN or
/// zero normals, a bad cell, or a cell in which no branch reaches the coarse path at all
/// ("unreachable cell set-up").
RobotPath solveRobotPath(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
                         const std::vector<Eigen::Vector3d>& normals,
                         const RobotPathOptions& options = {});

/// Largest per-joint speed ratio |Δq| / (Δt · maxSpeed) over consecutive points, with Δt from
/// segment lengths (part units · scale) and feed rates (part units/s); ≤ 1 means within limits.
/// Also returns the largest joint speed in deg/s through maxSpeedDegS.
double jointSpeedRatio(const RobotCell& cell, const RobotPath& path,
                       const std::vector<Eigen::Vector3d>& points,
                       const std::vector<double>& feedRate, double& maxSpeedDegS);

}  // namespace geolattice
