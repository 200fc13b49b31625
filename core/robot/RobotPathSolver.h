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
///    The branches are ranked by their least cost.
/// 2. Fine pass: ψ is interpolated between the coarse samples, IK of the cheapest branch is
///    solved at every point and unwrapped to the joint values nearest to the previous ones
///    (multiples of 2π inside the ±2π limits), so joints stay continuous. A point whose IK
///    fails is retried at nearby ψ; if that fails too it is reported in `unreachable` (never
///    skipped silently) and keeps the previous joints. When this path steps too far or misses
///    points, the plans of the other branches are followed in the order of their cost, and the
///    first without either is taken (a flip between two samples often stays when they are
///    made denser, below; another branch may have none). A step above maxJointStepDeg where
///    the part itself turns by at most that much is the wrist near its singularity, not a flip,
///    when the controller's straight move between the two points is continuous
///    (StraightMove.h): it is kept, with waypoints between (`via`), not counted as large.
/// 3. Refinement: where a joint still steps by more than maxJointStepDeg between consecutive
///    points (ψ was only interpolated between two coarse samples, and the wrist flipped near a
///    singularity or a joint ran into its limit), the coarse interval around the step is sampled
///    64 times more densely and the plan is made again (at most 4 · coarseSamples new samples
///    per pass, so a bound the path cannot keep anywhere does not make every later plan
///    slower); so are points the fine pass missed between samples (the interpolated ψ puts the
///    arm where it may not be) that some state reaches. Passes go on while they make progress:
///    up to `refinements` of them, and until three in a row leave no tenth fewer unreachable
///    points and large steps than the best pass before (one pass may fix a stretch and expose
///    the next: the auto-oriented knight needed 4, a tilted-cap mushroom 7; a fixed 3 refused
///    both). Each pass plans every branch again and follows the others as in 2. Where steps
///    1–3 leave unreachable points or large steps (or find no plan), they are made again on
///    denserPlanFactor times the coarse samples (ψ moves at most maxPsiStep grid cells from one
///    sample to the next: denser, it may turn faster where the path needs it), and the path
///    with fewer of them kept. Steps left are listed in `largeSteps` for the caller to refuse.
/// 4. Reconfiguration (only when 1–3 leave unreachable points or large steps, and the point kinds
///    are given): one IK branch and a continuous ψ per stretch between changes instead of one
///    for the whole path. The plan of step 1 runs over all (branch, ψ) states at once; a step
///    no fine path can make within maxJointStepDeg costs more than a reconfiguration; between
///    two consecutive air points — the highest of every air move (where the nozzle is above the
///    in-process part) and any air step found too large — the state may change at a cost of
///    reconfigurationCost plus the joints' turns (joints 1–5, a tenth of joint 6's), and a
///    branch found flipping inside a stretch is barred there. Where a plan steps too far inside
///    a print stretch (the wrist swung round near its singularity where the part's axis sweeps
///    round, a joint wound to its limit), the next plans may change right there, at a seam (if
///    the plan has at most 100 large steps), for 4 × reconfigurationCost: the robot leaves point i in the old configuration and comes back
///    to point i in the new one (the extruder stops, retracts and primes meanwhile), then prints
///    on to i + 1; and near such a wrist step (|sin θ5| < 0.25) the plans keep ψ away from the
///    singularity (its penalty then starts at |sin θ5| = 0.25 instead of singularityMargin).
///    A joint wound to its limit (a step of more than half a turn: the path circles the part
///    the same way round, whatever the branch and ψ) is turned back a full turn at the last
///    air move before it, in the same branch at the same ψ (the Y with the nozzle at the edge
///    of the reach: wrist 3, once). Step 4 starts from the samples of the plan 1–3 kept, as
///    refined, or where 1–3 found no plan from the denser samples (the generated coil).
///    Each change becomes a reconfiguration move (Reconfiguration): the part is moved straight
///    away from the nozzle along the nozzle axis until the bounding sphere of the toolpath is
///    reconfigurationMargin (which covers the build plate) clear of the nozzle body (a segment
///    of nozzleLength from the tip) and of the floor the robot stands on (base z = 0) during
///    the whole joint move (extended in 50 mm steps up to maxRetreat), the arm moves in joint
///    space to the new configuration — straight, or where that sweeps the part into the floor
///    or the nozzle through one detour waypoint (the base, shoulder and elbow turned from the
///    move's middle) —, and the part approaches the next point (a seam's own point) along that
///    point's nozzle axis (the nozzle then moves inside its own volume at that station, which
///    the collision verifier checked). The retreat lines are solved every 5 mm (no step above
///    maxJointStepDeg) and the joint move is checked every degree; a change whose move cannot
///    be made so is excluded and the plan made again (at most 12 plans, and no more once two
///    plans in a row leave neither fewer large steps nor all at new places). The path as solved
///    by 1–3 is kept when this does not remove every unreachable point and large step.
/// The floor the robot stands on (base z = 0): in every step, a state, a point, a waypoint
/// between points (the step with it is then a large step), a retreat or a joint move with a
/// surface of the arm (ArmCapsules.h: upper arm to wrist 3) lower than floorClearance is
/// not reachable (IK branches that put the elbow under the base plane reach the same poses: the
/// bundled 30 mm cube's path was followed with it 225 mm below), nor a state, point or waypoint
/// with the part as printed so far (PartFloor.h: its box with the plate's footprint) lower than
/// that (during joint moves and retreats the part's bounding sphere is kept clear). The nozzle:
/// nor is a state, point, waypoint, retreat or joint move with the arm's surfaces (base to
/// wrist 1) nearer than linkNozzleClearance to the nozzle's axis (tip to nozzleLength). The
/// part it holds: nor is one with the arm's surfaces (base to wrist 2) nearer than
/// linkPartClearance to the part as printed so far or its plate (PartArmClearance.h). The arm
/// is its links' bodies as capsules fitted to the manufacturer's collision meshes
/// (ArmCapsules.h). Robot self-collision and other obstacles of the cell are not modelled.
/// Cost O(samples · ψ · 8) IK solutions for the plan and O(N) for each fine pass (the other
/// branches' passes stop at their first large step), in parallel over `threads` (the result
/// does not depend on them); 1M points ≈ 1 s; step 4 adds one IK per state at every air
/// move's coarse samples. Each state's links are searched for material within
/// linkPartClearance in a kd-tree of the part (O(log N) where the arm is far from it); the
/// demo bunny (255k points) solves in 6 s with it, 1 s without (docs/performance.md).
#include "robot/RobotCell.h"
#include "robot/StraightMove.h"

#include <string>
#include <vector>

namespace geolattice {

/// m: the printhead's largest distance from its axis when no printhead is given: a slim hot end
/// with its holder (testdata/printhead_slim.obj's carriage: 28.3 mm).
constexpr double kPrintheadRadius = 0.028;
/// m: the arm's surfaces keep this much more than the printhead's radius from its axis.
constexpr double kLinkNozzleMargin = 0.007;
/// m: the distance of the arm's surfaces (ArmCapsules.h: base to wrist 1) from the nozzle's
/// axis below which the arm may hit the nozzle, for the default printhead. The wrist 2 and 3
/// links behind the plate are the collision verifier's (the plate is an obstacle there).
constexpr double kLinkNozzleSafeDistance = kPrintheadRadius + kLinkNozzleMargin;

/// m: the distance of the arm's surfaces (ArmCapsules.h: base to wrist 2) from the part the
/// robot holds (PartArmClearance.h) below which the arm may hit it: the part's samples (the
/// plate's within 3.5 mm of its surface) and a margin.
constexpr double kLinkPartSafeDistance = 0.015;

/// A stretch of the nozzle's axis, `from` to `to` m above the tip, and how far from the axis the
/// arm's surfaces stay there (m): a printhead's radius over that stretch plus a margin.
struct NozzleSection {
  double from = 0, to = 0;
  double clearance = 0;
};

class Printhead;
/// The sections of a printhead's profile (nozzle/Printhead.h, mm) from its tip to its top, each
/// kept its largest radius plus `margin` (m) off: a new section starts where the radius grows
/// by more than `step` (m) over the section's first, at most `maxSections` of them (the last
/// takes the rest), so the slim part near the tip is not kept as far off as the carriage above.
std::vector<NozzleSection> nozzleSectionsFor(const Printhead& head, double margin,
                                             double step = 0.005, int maxSections = 4);

struct RobotPathOptions;
/// The height (part units) of the tallest part the cell can print standing up: the largest h
/// (in steps of `step`) such that the part's point (0, 0, h) with its layer normal along the
/// part's +z can be put at the nozzle tip, turned about the nozzle's axis in RobotPathOptions::
/// psiSamples steps, by a configuration within the joint limits whose arm keeps floorClearance
/// above the floor and the nozzle's clearance (the part's own is not checked). The top layers of
/// a taller part standing on the plate need the arm lower than that (the flange holds the plate
/// below the part): the orientation search ranks such sides last (OrientOptions::maxHeight).
/// 0 when not even the plate (h = 0) can be put there.
double tallestPart(const RobotCell& cell, const RobotPathOptions& o, double step = 2.0);

/// How far the arm keeps off the nozzle's axis, for messages: "35 mm", or with a printhead's
/// sections "10-35 mm (along the printhead's profile)".
std::string nozzleClearanceText(const RobotPathOptions& o);

struct RobotPathOptions {
  int psiSamples = 72;      ///< grid of ψ over 2π (5° steps)
  int maxPsiStep = 2;       ///< grid cells ψ may move between coarse samples
  int coarseSamples = 500;  ///< about this many coarse samples
  double singularityMargin =
      0.05;  ///< below this (|sin θ5|, |sin θ3|, shoulder distance in m) a penalty applies
  double maxJointStepDeg =
      20.0;  ///< a larger step of any joint between consecutive points triggers refinement
  int refinements = 12;  ///< at most this many passes densify the samples around such steps
  /// Steps 1–3 that leave unreachable points or large steps (or find no plan) are made again on
  /// this many times the coarse samples before step 4 (1: not).
  int denserPlanFactor = 4;
  /// When no plan reaches the path, name the clearance that stops it (the coarse plan made
  /// again without the part's, the nozzle's, or both) in the error; off for solves whose error
  /// is not shown (CellLayout's ranking and other mountings).
  bool explainUnreachable = true;
  bool reconfigure = true;  ///< step 4: allow reconfiguration moves at air moves (needs kinds)
  double reconfigurationCost = 50;  ///< rad-equivalents a change of configuration costs the plan
  double nozzleLength = 0.25;       ///< m: nozzle and holder length kept clear during a joint move
  double reconfigurationMargin = 0.02;  ///< m added to the part's bounding sphere (the plate)
  double maxRetreat = 0.4;              ///< m: the farthest the part is moved away from the nozzle
  /// m: the arm's surfaces (lowestArmSurface: upper arm to wrist 3) and the part held
  /// (PartFloor) stay this far above the floor the robot stands on (base z = 0), at every
  /// point, retreat and joint move; a point reached only lower is unreachable. Until the twelfth
  /// session 50 mm, from the joints' DH origins: the elbow's housing (62 mm radius) could touch.
  double floorClearance = 0.02;
  /// m: the arm's surfaces (ArmCapsules.h: base to wrist 1) stay this far from the nozzle's
  /// axis (tip to nozzleLength along it) at every point, waypoint, retreat and joint move; a
  /// point reached only nearer is unreachable (0: not kept, only measured in
  /// RobotPath::minLinkNozzleDistance). Before the tenth session nothing kept it: the programs
  /// of the demo bunny, the Y and the three-branch tree drove the forearm through the nozzle 10
  /// mm above the tip (docs/performance.md); until the twelfth, 60 mm from the DH lines.
  double linkNozzleClearance = kLinkNozzleSafeDistance;
  /// The nozzle's axis in sections nearer the tip, each with its own clearance (a printhead's
  /// profile: nozzleSectionsFor); linkNozzleClearance then holds above the last one, to
  /// nozzleLength (the printhead's mount). Empty: linkNozzleClearance from the tip up. Used only
  /// where linkNozzleClearance > 0.
  std::vector<NozzleSection> nozzleSections;
  /// m: the arm's surfaces (ArmCapsules.h: base to wrist 2) stay this far from the part as
  /// printed so far and its plate (PartArmClearance.h) at every point, waypoint, retreat and
  /// joint move; a point reached only nearer is unreachable (0: not kept, only measured in
  /// RobotPath::minLinkPartDistance). Before the eleventh session nothing kept it: the demo
  /// bunny's program drove the forearm through the bunny it held; until the twelfth, 60 mm from
  /// the DH lines (the upper arm's tube runs 136 mm off its line).
  double linkPartClearance = kLinkPartSafeDistance;
  int threads = 0;  ///< workers for the IK (0: every core); results do not depend on it
};

/// A change of IK branch (or of ψ) at an air move or a seam, made away from the part (module
/// comment, step 4): at the toolpath point `point` the robot arrives in the old configuration
/// (arrive), moves the part straight away from the nozzle (a linear move to retreatFrom), moves
/// in joint space to retreatTo, and approaches point + 1 in the new configuration (leave = its
/// joints); at a seam it approaches `point` again (leave = its joints in the new
/// configuration), and the segment to point + 1 is printed from there.
struct Reconfiguration {
  int point = -1;                      ///< toolpath point (an air move, or the seam's)
  bool atSeam = false;                 ///< inside a print stretch (module comment, step 4)
  int fromBranch = -1, toBranch = -1;  ///< IK branches before and after
  JointVector arrive{}, retreatFrom{}, retreatTo{}, leave{};
  /// Joint-space waypoints of the joint move from retreatFrom to retreatTo (empty: straight),
  /// where the straight one would sweep the part into the floor or the nozzle.
  std::vector<JointVector> through;
  double retreat = 0;    ///< m the part moves away from the nozzle (the larger of both ends)
  double clearance = 0;  ///< m: least distance of the part's sphere to the nozzle or floor
};

/// Waypoints the program adds on the straight move from point - 1 to point: the part turns by
/// at most the bound there, but joints 4 and 6 turn more because the wrist is near its
/// singularity (StraightMove.h); the move is continuous, and with them no joint changes by more
/// than maxJointStepDeg from one waypoint to the next.
struct WaypointsBetween {
  int point = -1;
  StraightMoveVia via;
};

struct RobotPath {
  std::vector<JointVector> joints;  ///< per point, continuous (unwrapped)
  std::vector<double> psi;          ///< per point (rad)
  std::vector<int> unreachable;     ///< point indices without a valid IK solution
  int branch = -1;                  ///< IK branch at the first point (inverseKinematicsBranch)
  /// Changes of configuration at air moves and seams, in path order: from joints[point] to
  /// leave by a reconfiguration move (leave = joints[point + 1] at an air move; at a seam the
  /// straight move from leave to joints[point + 1] follows).
  std::vector<Reconfiguration> reconfigurations;
  double maxJointStepDeg = 0;  ///< largest change of any joint between consecutive waypoints
  int maxJointStepAt = -1;     ///< the point where it happens (the step from the point before)
  std::vector<int>
      largeSteps;  ///< points reached by a step above RobotPathOptions::maxJointStepDeg
  std::vector<WaypointsBetween> via;   ///< in path order: moves written with waypoints between
  int coarseSamples = 0;               ///< coarse samples after refinement
  int refinements = 0;                 ///< refinement passes used
  SingularityDistance minSingularity;  ///< smallest distances along the path
  double maxTipError = 0;      ///< m: |FK(q)·partOnFlange·p − nozzle tip| over reachable points
  double maxAxisErrorDeg = 0;  ///< angle between the placed axis n and the nozzle axis
  /// m above the floor: the arm's lowest surface (lowestArmSurface) over the reachable points
  /// and the waypoints between them
  double lowestArm = 0;
  /// m above the floor: the lowest point of the part as printed so far (PartFloor.h), the same
  double lowestPart = 0;
  /// m: the least distance of the arm's surfaces (base to wrist 1) from the nozzle's axis (tip
  /// to nozzleLength along it) over the reachable points and the waypoints between them
  double minLinkNozzleDistance = 0;
  /// m: the least distance of the arm's surfaces (base to wrist 2) from the part printed so
  /// far and its plate, the same (measured up to 1 m, to 1 mm: at most 1 mm above
  /// the least; PartArmClearance::Sweep)
  double minLinkPartDistance = 0;
  double seconds = 0;

  /// Every point reachable and no step above the bound: the path can be written.
  bool works() const { return unreachable.empty() && largeSteps.empty(); }
};

/// points/normals: toolpath in part units; kind: per point 0 print, 1 perimeter, 2 air (empty:
/// no reconfiguration, step 4). Throws GeoLatticeError for an empty path, NaN or zero normals, a
/// bad cell, or a cell in which no branch reaches the coarse path at all ("unreachable cell
/// set-up").
RobotPath solveRobotPath(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
                         const std::vector<Eigen::Vector3d>& normals,
                         const RobotPathOptions& options = {}, const std::vector<int>& kind = {});

/// The joints the robot is at when its straight move to point i starts: joints[i - 1], or
/// `leave` when a reconfiguration at i - 1 brings it there (joints[i] at an air move: no move
/// is left; at a seam, point i - 1 in the new configuration). i >= 1.
const JointVector& jointsBefore(const RobotPath& path, size_t i);

/// Largest per-joint speed ratio |Δq| / (Δt · maxSpeed) over consecutive points, with Δt from
/// segment lengths (part units · scale) and feed rates (part units/s); ≤ 1 means within limits.
/// Also returns the largest joint speed in deg/s through maxSpeedDegS.
double jointSpeedRatio(const RobotCell& cell, const RobotPath& path,
                       const std::vector<Eigen::Vector3d>& points,
                       const std::vector<double>& feedRate, double& maxSpeedDegS);

}  // namespace geolattice
