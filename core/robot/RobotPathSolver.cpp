#include "robot/RobotPathSolver.h"

#include "common/Error.h"
#include "common/ParallelFor.h"
#include "common/SegmentDistance.h"
#include "nozzle/Printhead.h"
#include "robot/PartArmClearance.h"
#include "robot/PartFloor.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <unordered_map>

namespace geolattice {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// "35" for 0.035 m: a length in whole millimetres, for messages.
std::string millimetres(double m) {
  return std::to_string(static_cast<int>(std::lround(1000 * m)));
}
constexpr int kReconfigurationRounds = 12;  ///< step 4: plans made before giving up
/// Steps 1–3: refinement passes in a row that leave no fewer problems before the refinement
/// ends (planAndRefine).
constexpr int kPassesWithoutProgress = 3;
/// m: RobotPath::minLinkPartDistance is measured up to this (farther: reported as this).
constexpr double kLinkPartReportLimit = 1.0;
constexpr double kOverBoundCost = 1000;  ///< step 4: cost per rad of a step over the bound
/// Step 4: where a change may be made (per point i, for i -> i + 1): at an air move, or at a
/// seam inside a print stretch where the wrist flips or a joint reaches its limit (module
/// comment), which costs kSeamCostFactor times a change at an air move.
constexpr char kChangeAtAir = 1, kChangeAtSeam = 2;
constexpr double kSeamCostFactor = 4;
/// Step 4: seams are offered only where a plan has at most this many large steps (thousands
/// are a bound the path cannot keep, and a seam each would only make the plans slower).
constexpr size_t kMostStepsForSeams = 100;
/// Step 4: |sin θ5| below which the plan is penalised where the wrist swung round (module
/// comment); singularityMargin elsewhere.
constexpr double kWideWristMargin = 0.25;

/// Points between the coarse samples of an N-point path (module comment, step 1).
size_t coarseStride(size_t N, const RobotPathOptions& o) {
  return std::max<size_t>(1, N / static_cast<size_t>(o.coarseSamples));
}

/// Every stride-th point of the path (coarseStride) and its last: the coarse samples.
std::vector<size_t> coarseSamplesOf(size_t N, const RobotPathOptions& o) {
  const size_t stride = coarseStride(N, o);
  std::vector<size_t> coarse;
  for (size_t i = 0; i < N; i += stride)
    coarse.push_back(i);
  if (coarse.back() != N - 1)
    coarse.push_back(N - 1);
  return coarse;
}

/// Unreachable points and large steps: what keeps a path from being written.
size_t problemCount(const RobotPath& p) {
  return p.unreachable.size() + p.largeSteps.size();
}

/// x − 2πk nearest to 0 (the value of std::remainder(x, 2π) away from the ties at ±π, several
/// times faster; the dynamic programming calls it for every joint of every transition).
inline double wrapToPi(double x) {
  return x - std::floor((x + M_PI) / (2 * M_PI)) * (2 * M_PI);
}

/// std::remainder(x, 2π), with the common case |x| ≤ π (where it is x itself) taken first.
inline double remainderTwoPi(double x) {
  return std::abs(x) <= M_PI ? x : std::remainder(x, 2 * M_PI);
}

/// q (each joint in (-π, π]) shifted by multiples of 2π to be nearest to `near`, inside limits.
JointVector unwrapNear(const RobotModel& r, JointVector q, const JointVector& near) {
  for (int i = 0; i < 6; ++i) {
    double v = near[i] + wrapToPi(q[i] - near[i]);
    if (v > r.upperLimit[i])
      v -= 2 * M_PI;
    if (v < r.lowerLimit[i])
      v += 2 * M_PI;
    q[i] = v;
  }
  return q;
}

/// Least distance (m) of the arm's surfaces near the nozzle (ArmCapsules.h: base to wrist 1)
/// from the nozzle's axis between `from` and `to` m above the tip.
double linkNozzleDistance(const RobotCell& cell, const ArmCapsules& arm, double from, double to) {
  return armSegmentDistance(arm, kFirstNearNozzle, kLastNearNozzle,
                            cell.nozzleTip + from * cell.nozzleAxis,
                            cell.nozzleTip + to * cell.nozzleAxis);
}

/// ... from the whole axis (tip to nozzleLength).
double linkNozzleDistance(const RobotCell& cell, const ArmCapsules& arm,
                          const RobotPathOptions& o) {
  return linkNozzleDistance(cell, arm, 0.0, o.nozzleLength);
}

/// Whether the arm's surfaces near the nozzle keep linkNozzleClearance off its axis, or each
/// section's own clearance along its stretch and linkNozzleClearance above the last.
bool armClearOfNozzle(const RobotCell& cell, const ArmCapsules& arm, const RobotPathOptions& o) {
  double from = 0;
  for (const NozzleSection& s : o.nozzleSections) {
    if (linkNozzleDistance(cell, arm, s.from, s.to) < s.clearance)
      return false;
    from = std::max(from, s.to);
  }
  return from >= o.nozzleLength ||
         linkNozzleDistance(cell, arm, from, o.nozzleLength) >= o.linkNozzleClearance;
}

/// The part the robot holds, as printed up to a toolpath point: against the floor the robot
/// stands on (PartFloor.h) and against the arm's own links (PartArmClearance.h). Built once per
/// solve.
struct HeldPart {
  HeldPart(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
           const std::vector<int>& kind)
      : floor(cell, points), arm(cell, points, kind) {}
  PartFloor floor;
  PartArmClearance arm;
};

/// Whether the part printed up to point i is floorClearance above the floor with the flange
/// at `flange` (PartFloor.h).
bool partAboveFloor(const HeldPart& part, const Isometry& flange, size_t i,
                    const RobotPathOptions& o) {
  return part.floor.lowest(flange, i) >= o.floorClearance;
}

/// Whether the arm at q, holding the part printed up to point i with the flange at `flange`
/// (= forwardKinematics(q)), is clear of the cell and of that part (ArmCapsules.h, each when
/// > 0): the surfaces of upper arm to wrist 3 floorClearance above the floor (base z = 0), of
/// base to wrist 1 linkNozzleClearance from the nozzle's axis, and of base to wrist 2
/// linkPartClearance from the part.
bool armClearHolding(const RobotCell& cell, const JointVector& q, const Isometry& flange,
                     const HeldPart& part, size_t i, const RobotPathOptions& o) {
  const ArmCapsules arm = armCapsules(cell.robot, q);
  if (lowestArmSurface(arm) < o.floorClearance)
    return false;
  if (o.linkNozzleClearance > 0 && !armClearOfNozzle(cell, arm, o))
    return false;
  return part.arm.clear(flange, arm, i, o.linkPartClearance);
}

double singularityPenalty(const RobotModel& r, const JointVector& q, const Isometry& flange,
                          double margin) {
  const SingularityDistance s = singularityDistance(r, q, flange);
  double p = 0;
  for (double d : {s.shoulder, s.elbow, s.wrist}) {
    if (d < margin)
      p += (margin - d) / margin * 10.0;  // up to 10 rad-equivalents per singularity
  }
  return p;
}

/// IK of the ψ grid of one branch at one toolpath point: joints, whether the branch reaches
/// it, and the singularity penalty (∞ where it does not).
struct BranchStates {
  std::vector<JointVector> q;
  std::vector<char> ok;
  std::vector<double> penalty;
};

/// BranchStates solved once per (point, branch) and kept for the later plans of the same path
/// (refinement passes, step 4's rounds); missing ones are solved in parallel.
class StateCache {
public:
  StateCache(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
             const std::vector<Eigen::Vector3d>& normals, const RobotPathOptions& o, int threads,
             const HeldPart& part)
      : cell_(cell), points_(points), normals_(normals), o_(o), threads_(threads), part_(part) {}

  /// The part held, for every step of the solver that uses this cache.
  const HeldPart& part() const { return part_; }

  /// Solves every (coarse point, branch) not solved yet; the ψ grid's flange poses once per
  /// point for all its branches.
  void prepare(const std::vector<size_t>& coarse, const std::vector<int>& branches) {
    std::vector<BranchStates*> missing;
    std::vector<std::pair<size_t, int>> keys;
    std::vector<size_t> firstOfPoint;  // groups of `missing` with the same point
    for (size_t point : coarse) {
      firstOfPoint.push_back(missing.size());
      for (int branch : branches) {
        auto [it, added] = states_.try_emplace(point * 8 + static_cast<size_t>(branch));
        if (added) {
          missing.push_back(&it->second);
          keys.emplace_back(point, branch);
        }
      }
    }
    firstOfPoint.push_back(missing.size());
    const int P = o_.psiSamples;
    const double dpsi = 2 * M_PI / P;
    parallelFor(coarse.size(), threads_, [&](size_t g, int) {
      if (firstOfPoint[g] == firstOfPoint[g + 1])
        return;
      const size_t point = keys[firstOfPoint[g]].first;
      std::vector<Isometry> flange(P);
      for (int k = 0; k < P; ++k)
        flange[k] = cell_.flangePose(points_[point], normals_[point], k * dpsi);
      std::vector<char> partClear(P);  // the same in every branch
      for (int k = 0; k < P; ++k)
        partClear[k] = partAboveFloor(part_, flange[k], point, o_);
      for (size_t i = firstOfPoint[g]; i < firstOfPoint[g + 1]; ++i) {
        const int branch = keys[i].second;
        BranchStates& st = *missing[i];
        st.q.resize(P);
        st.ok.resize(P);
        st.penalty.resize(P);
        for (int k = 0; k < P; ++k) {
          st.ok[k] = partClear[k] &&
                     inverseKinematicsBranch(cell_.robot, flange[k], branch, st.q[k]) &&
                     armClearHolding(cell_, st.q[k], flange[k], part_, point, o_);
          st.penalty[k] =
              st.ok[k] ? singularityPenalty(cell_.robot, st.q[k], flange[k], o_.singularityMargin)
                       : kInf;
        }
      }
    });
  }
  const BranchStates& at(size_t point, int branch) const {
    return states_.at(point * 8 + static_cast<size_t>(branch));
  }

private:
  const RobotCell& cell_;
  const std::vector<Eigen::Vector3d>& points_;
  const std::vector<Eigen::Vector3d>& normals_;
  const RobotPathOptions& o_;
  int threads_;
  const HeldPart& part_;
  std::unordered_map<size_t, BranchStates> states_;
};

/// The coarse plan: an IK branch and a ψ grid index per coarse sample, and where the plan
/// changes configuration (step 4 only).
struct CoarsePlan {
  std::vector<int> branch;        ///< per coarse sample; empty: no plan reaches the path
  std::vector<int> psi;           ///< per coarse sample
  std::vector<char> reconfigure;  ///< per coarse sample s: s - 1 -> s is a reconfiguration
};

/// The joints reached from `from` towards the IK solution q without folding turns (module
/// comment, step 1), the largest step, and whether they stay inside the limits.
bool reachFrom(const RobotModel& robot, const JointVector& from, const JointVector& q,
               JointVector& reached, double& step) {
  step = 0;
  for (int a = 0; a < 6; ++a) {
    const double d = wrapToPi(q[a] - from[a]);
    reached[a] = from[a] + d;
    step = std::max(step, std::abs(d));
    if (reached[a] < robot.lowerLimit[a] || reached[a] > robot.upperLimit[a])
      return false;
  }
  return true;
}

/// What the joint move of a change costs the plan besides reconfigurationCost (rad): the turns
/// of joints 1-5, which swing the part through the cell (a long move may find no clear path),
/// and a tenth of joint 6's, which spins it in place about the flange axis.
double changeMoveCost(const JointVector& from, const JointVector& to) {
  double c = 0;
  for (int j = 0; j < 5; ++j)
    c += std::abs(to[j] - from[j]);
  return c + 0.1 * std::abs(to[5] - from[5]);
}

/// Dynamic programming over the (branch, ψ) states of the coarse samples (module comment).
/// Without `mayChange` (steps 1–3) the branches that reach a subsample of the path are planned
/// each on its own, and the plan of every branch that reaches the end is returned, cheapest
/// first; with it (step 4) all eight are planned together and
/// at a coarse sample s with mayChange[s] the state may change from the cheapest state at s - 1
/// at the cost of a reconfiguration (a joint move from the old state at s - 1 to the new one
/// at s, whose joints are taken in (-π, π]: the move also unwinds joints turned towards their
/// limits); blocked[s] (a bit per branch) forbids staying in a branch from s - 1 to s (the
/// fine pass found it flipping there), and the one cheapest plan is returned. Empty: no plan
/// reaches the end. Memory: the back pointers of every state; the joints of two samples.
std::vector<CoarsePlan> planCoarse(const RobotCell& cell,
                                   const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<Eigen::Vector3d>& normals,
                                   const std::vector<size_t>& coarse, const RobotPathOptions& o,
                                   StateCache& cache, const std::vector<char>& mayChange = {},
                                   const std::vector<unsigned>& blocked = {},
                                   const std::vector<char>& nearWrist = {}) {
  const RobotModel& robot = cell.robot;
  const bool step4 = !mayChange.empty();
  const int P = o.psiSamples;
  const double dpsi = 2 * M_PI / P;
  const size_t S = coarse.size();
  std::vector<Isometry> flange(P);
  auto flangesAt = [&](size_t s) {
    for (int k = 0; k < P; ++k)
      flange[k] = cell.flangePose(points[coarse[s]], normals[coarse[s]], k * dpsi);
  };
  // Branches that reach a subsample of the coarse path at some ψ everywhere are candidates.
  std::vector<int> branches;
  if (step4) {
    branches = {0, 1, 2, 3, 4, 5, 6, 7};
  } else {
    std::vector<char> reaches(8, 1);
    for (size_t s = 0; s < S; s += std::max<size_t>(1, S / 50)) {
      flangesAt(s);
      for (int branch = 0; branch < 8; ++branch) {
        bool any = false;
        for (int k = 0; k < P && !any && reaches[branch]; k += 3) {
          JointVector qq;
          any = partAboveFloor(cache.part(), flange[k], coarse[s], o) &&
                inverseKinematicsBranch(robot, flange[k], branch, qq) && withinLimits(robot, qq) &&
                armClearHolding(cell, qq, flange[k], cache.part(), coarse[s], o);
        }
        reaches[branch] = reaches[branch] && any;
      }
    }
    for (int branch = 0; branch < 8; ++branch)
      if (reaches[branch])
        branches.push_back(branch);
  }
  const size_t B = branches.size(), W = B * static_cast<size_t>(P);
  if (B == 0)
    return {};
  cache.prepare(coarse, branches);
  std::vector<double> cost(W);  // at the last sample
  std::vector<int> from(S * W, -1);
  std::vector<char> changed(step4 ? S * W : 0, 0);
  // Where the fine pass swung the wrist round near its singularity (step 4): a wider margin
  // keeps the plan's ψ away from it there.
  auto nearWristPenalty = [&](size_t s, const JointVector& q) {
    if (nearWrist.empty() || !nearWrist[coarse[s]])
      return 0.0;
    const double d = std::abs(std::sin(q[4]));
    return d < kWideWristMargin ? (kWideWristMargin - d) / kWideWristMargin * 10.0 : 0.0;
  };
  // The plan of the states [lo, hi) (whole branches) over all samples: step 4 runs it once on
  // every state, steps 1–3 once per branch, in parallel (the branches do not interact).
  auto plan = [&](size_t lo, size_t hi) {
    const size_t n = hi - lo;
    std::vector<JointVector> wound(n), woundBefore(n);
    std::vector<double> here(n), before(n);
    auto states = [&](size_t s, size_t id) -> const BranchStates& {
      return cache.at(coarse[s], branches[id / P]);
    };
    for (size_t id = lo; id < hi; ++id) {
      here[id - lo] = states(0, id).penalty[id % P] + nearWristPenalty(0, states(0, id).q[id % P]);
      wound[id - lo] = states(0, id).q[id % P];
    }
    for (size_t s = 1; s < S; ++s) {
      std::swap(here, before);
      std::swap(wound, woundBefore);
      // A reconfiguration into sample s leaves from the cheapest state at s - 1.
      size_t cheapest = hi;
      if (step4 && mayChange[s]) {
        for (size_t id = lo; id < hi; ++id)
          if (std::isfinite(before[id - lo]) &&
              (cheapest == hi || before[id - lo] < before[cheapest - lo]))
            cheapest = id;
      }
      // Step 4: a step that no fine path between the samples can make within the bound costs
      // more than a reconfiguration (steps 1–3: the step itself).
      const double stepBound =
          step4 ? static_cast<double>(coarse[s] - coarse[s - 1]) * o.maxJointStepDeg * M_PI / 180.0
                : kInf;
      auto stepCost = [&](double step) {
        return step > stepBound ? step + kOverBoundCost * (step - stepBound) : step;
      };
      for (size_t first = lo; first < hi; first += P) {
        const BranchStates& st = states(s, first);
        const int branch = branches[first / P];
        const bool stay = blocked.empty() || !(blocked[s] & (1u << branch));
        for (int k = 0; k < P; ++k) {
          const size_t id = first + k;
          double& c = here[id - lo];
          c = kInf;
          if (!st.ok[k])
            continue;
          const double penalty = st.penalty[k] + nearWristPenalty(s, st.q[k]);
          for (int dk = -o.maxPsiStep; dk <= o.maxPsiStep && stay; ++dk) {
            const size_t pid = first + ((k + dk) % P + P) % P;
            if (!std::isfinite(before[pid - lo]))
              continue;
            // The joints as the robot reaches them along this path (turns add up, no ±2π
            // folding): a path that would wind a joint past its limit is infeasible, since the
            // fine pass could only get back by a full turn between two points.
            JointVector reached;
            double step = 0;
            if (!reachFrom(robot, woundBefore[pid - lo], st.q[k], reached, step))
              continue;
            const double cc = before[pid - lo] + stepCost(step) + penalty;
            if (cc < c) {
              c = cc;
              from[s * W + id] = static_cast<int>(pid);
              wound[id - lo] = reached;
            }
          }
          if (cheapest < hi && withinLimits(robot, st.q[k])) {
            const double cc =
                before[cheapest - lo] +
                o.reconfigurationCost * (mayChange[s] == kChangeAtSeam ? kSeamCostFactor : 1.0) +
                changeMoveCost(woundBefore[cheapest - lo], st.q[k]) + penalty;
            if (cc < c) {
              c = cc;
              from[s * W + id] = static_cast<int>(cheapest);
              changed[s * W + id] = mayChange[s];
              wound[id - lo] = st.q[k];
            }
          }
        }
      }
    }
    std::copy(here.begin(), here.end(), cost.begin() + lo);
  };
  if (step4)
    plan(0, W);
  else
    parallelFor(B, o.threads, [&](size_t b, int) { plan(b * P, (b + 1) * P); });
  // Steps 1–3: the cheapest end of each branch, cheapest branch first (of equal costs the
  // first branch, then the first ψ); step 4: the cheapest end over all states.
  std::vector<size_t> ends;
  for (size_t b = 0; b < (step4 ? 1 : B); ++b) {
    size_t end = W;
    for (size_t id = step4 ? 0 : b * P; id < (step4 ? W : (b + 1) * P); ++id)
      if (std::isfinite(cost[id]) && (end == W || cost[id] < cost[end]))
        end = id;
    if (end < W)
      ends.push_back(end);
  }
  std::stable_sort(ends.begin(), ends.end(), [&](size_t x, size_t y) { return cost[x] < cost[y]; });
  std::vector<CoarsePlan> plans;
  for (size_t end : ends) {
    CoarsePlan plan;
    plan.branch.assign(S, 0);
    plan.psi.assign(S, 0);
    plan.reconfigure.assign(S, 0);
    size_t id = end;
    for (size_t s = S; s-- > 0;) {
      plan.branch[s] = branches[id / P];
      plan.psi[s] = static_cast<int>(id % P);
      if (step4)
        plan.reconfigure[s] = changed[s * W + id];
      if (s > 0)
        id = static_cast<size_t>(from[s * W + id]);
    }
    plans.push_back(std::move(plan));
  }
  return plans;
}

/// Whether the part turns by at most maxDeg from joints a to joints b (the TCP's rotation).
bool turnsByAtMost(const RobotCell& cell, const JointVector& a, const JointVector& b,
                   double maxDeg) {
  const Eigen::Matrix3d ra = (forwardKinematics(cell.robot, a) * cell.partOnFlange).linear();
  const Eigen::Matrix3d rb = (forwardKinematics(cell.robot, b) * cell.partOnFlange).linear();
  const double c = std::clamp(0.5 * ((ra.transpose() * rb).trace() - 1), -1.0, 1.0);
  return std::acos(c) * 180.0 / M_PI <= maxDeg;
}

/// Joints at every point: ψ interpolated between the coarse samples, IK of the plan's branch,
/// unwrapped next to the previous joints (checked by checkEmittedJoints). At a change of
/// configuration (step 4) the path continues in the new branch and the change is recorded (its
/// move is planned by the caller); a change at a seam comes back to the point it left, in the
/// new configuration at the ψ of the next point, and the segment to the next point follows.
/// The IK at the planned ψ runs in parallel; a point where it fails (retried at nearby ψ) or
/// where the wrist is singular (θ6 is then taken from the point before) is solved in the
/// serial pass that unwraps, so the result does not depend on threads.
/// With stopAtLargeStep the pass ends early (incomplete) once a large step or an unreachable
/// point is found: the path is then only known not to work.
/// unwindAt (per point, or empty; step 4): ±(j + 1) at the air move from point i − 1 to i turns
/// joint j back by a full turn against the direction ± it wound in (a change of configuration
/// in the same branch at the same ψ, made as any other), where that stays inside its limits.
RobotPath solveFine(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
                    const std::vector<Eigen::Vector3d>& normals, const std::vector<size_t>& coarse,
                    const CoarsePlan& plan, const HeldPart& part, const RobotPathOptions& o,
                    bool stopAtLargeStep = false, const std::vector<signed char>& unwindAt = {}) {
  const RobotModel& robot = cell.robot;
  const size_t N = points.size(), S = coarse.size();
  const double dpsi = 2 * M_PI / o.psiSamples;
  // The plan at every point: ψ, the branch, and whether a change of configuration from point
  // i - 1 to point i is made there (a joint move, planned by the caller).
  std::vector<double> psiAt(N);
  std::vector<int> branchAt(N);
  std::vector<char> changeAt(N, 0);
  {
    int branch = plan.branch[0];
    size_t seg = 0, nextChange = 1;
    for (size_t i = 0; i < N; ++i) {
      while (seg + 1 < S - 1 && coarse[seg + 1] <= i)
        ++seg;
      const size_t a = coarse[seg], b = coarse[std::min(seg + 1, S - 1)];
      double pa = plan.psi[seg] * dpsi, pb = plan.psi[std::min(seg + 1, S - 1)] * dpsi;
      pb = pa + remainderTwoPi(pb - pa);
      const double t = b > a ? static_cast<double>(i - a) / static_cast<double>(b - a) : 0.0;
      psiAt[i] = (1 - t) * pa + t * pb;
      while (nextChange < S && coarse[nextChange] < i)
        ++nextChange;
      if (nextChange < S && coarse[nextChange] == i && plan.reconfigure[nextChange] && i > 0) {
        branch = plan.branch[nextChange];
        changeAt[i] = plan.reconfigure[nextChange];
      }
      branchAt[i] = branch;
    }
  }
  std::vector<JointVector> direct(N);
  std::vector<char> directOk(N, 0);
  constexpr size_t kChunk = 4096, kBlock = 8 * kChunk;  // parallel items; serial pass blocks
  auto solveDirect = [&](size_t first, size_t last) {
    const size_t chunks = (last - first + kChunk - 1) / kChunk;
    parallelFor(chunks, o.threads, [&](size_t c, int) {
      for (size_t i = first + c * kChunk; i < std::min(last, first + (c + 1) * kChunk); ++i) {
        const Isometry f = cell.flangePose(points[i], normals[i], psiAt[i]);
        directOk[i] = partAboveFloor(part, f, i, o) &&
                      inverseKinematicsBranch(robot, f, branchAt[i], direct[i]) &&
                      std::abs(std::sin(direct[i][4])) > 1e-9 &&
                      armClearHolding(cell, direct[i], f, part, i, o);
      }
    });
  };
  RobotPath path;
  path.branch = plan.branch[0];
  path.joints.resize(N);
  path.psi.resize(N);
  JointVector previous{};
  bool havePrevious = false;
  for (size_t i = 0; i < N; ++i) {
    if (i % kBlock == 0) {
      if (stopAtLargeStep && (!path.largeSteps.empty() || !path.unreachable.empty()))
        break;
      solveDirect(i, std::min(N, i + kBlock));
    }
    const int branch = branchAt[i];
    double psi = psiAt[i];
    // A change at a seam: the joints at point i - 1 in the new configuration (`leave`); the
    // step from there to point i is judged as any other.
    JointVector leave{};
    bool leaveFound = false;
    if (changeAt[i] == kChangeAtSeam) {
      const Isometry f = cell.flangePose(points[i - 1], normals[i - 1], psi);
      leaveFound = partAboveFloor(part, f, i - 1, o) &&
                   inverseKinematicsBranch(robot, f, branch, leave) && withinLimits(robot, leave) &&
                   armClearHolding(cell, leave, f, part, i - 1, o);
    }
    if (changeAt[i]) {
      havePrevious = leaveFound;
      previous = leave;
    }
    JointVector qi = direct[i];
    bool found = directOk[i];
    if (!found) {
      Isometry f = cell.flangePose(points[i], normals[i], psi);
      found = partAboveFloor(part, f, i, o) &&
              inverseKinematicsBranch(robot, f, branch, qi, havePrevious ? previous[5] : 0.0) &&
              armClearHolding(cell, qi, f, part, i, o);
      for (int retry = 1; !found && retry <= 3; ++retry) {
        for (double sign : {1.0, -1.0}) {
          const double p2 = psi + sign * retry * dpsi;
          f = cell.flangePose(points[i], normals[i], p2);
          if (partAboveFloor(part, f, i, o) &&
              inverseKinematicsBranch(robot, f, branch, qi, havePrevious ? previous[5] : 0.0) &&
              armClearHolding(cell, qi, f, part, i, o)) {
            found = true;
            psi = p2;
            break;
          }
        }
      }
    }
    if (found && havePrevious) {
      qi = unwrapNear(robot, qi, previous);
    }
    bool unwound = false;
    if (found && havePrevious && !changeAt[i] && !unwindAt.empty() && unwindAt[i] != 0) {
      const int j = std::abs(unwindAt[i]) - 1;
      const double v = qi[j] - (unwindAt[i] > 0 ? 2 * M_PI : -2 * M_PI);
      if (v >= robot.lowerLimit[j] && v <= robot.upperLimit[j]) {
        qi[j] = v;
        unwound = true;
      }
    }
    if (!found || !withinLimits(robot, qi)) {
      path.unreachable.push_back(static_cast<int>(i));
      qi = havePrevious ? previous : JointVector{};
      unwound = false;
    }
    if (havePrevious && !unwound) {
      double step = 0;
      for (int j = 0; j < 6; ++j)
        step = std::max(step, std::abs(qi[j] - previous[j]));
      if (step * 180.0 / M_PI > o.maxJointStepDeg) {
        WaypointsBetween v;
        v.point = static_cast<int>(i);
        if (turnsByAtMost(cell, previous, qi, o.maxJointStepDeg) &&
            followStraightMove(robot, cell.partOnFlange, previous, qi,
                               o.maxJointStepDeg * M_PI / 180.0, v.via) &&
            std::all_of(v.via.joints.begin(), v.via.joints.end(), [&](const JointVector& q) {
              const Isometry f = forwardKinematics(robot, q);
              return partAboveFloor(part, f, i, o) && armClearHolding(cell, q, f, part, i, o);
            })) {
          step = v.via.maxStep;
          path.via.push_back(std::move(v));
        } else {
          path.largeSteps.push_back(static_cast<int>(i));
        }
      }
      if (step * 180.0 / M_PI > path.maxJointStepDeg) {
        path.maxJointStepDeg = step * 180.0 / M_PI;
        path.maxJointStepAt = static_cast<int>(i);
      }
    }
    if (changeAt[i] || unwound) {
      Reconfiguration r;
      r.point = static_cast<int>(i - 1);
      r.fromBranch =
          path.reconfigurations.empty() ? path.branch : path.reconfigurations.back().toBranch;
      r.toBranch = branch;
      r.arrive = path.joints[i - 1];
      r.atSeam = changeAt[i] == kChangeAtSeam;
      r.leave = r.atSeam ? leave : qi;
      if (r.atSeam && !leaveFound)
        path.largeSteps.push_back(static_cast<int>(i));  // point i - 1 not reached again
      path.reconfigurations.push_back(r);
      havePrevious = true;
    }
    path.joints[i] = qi;
    path.psi[i] = psi;
    previous = qi;
    havePrevious = havePrevious || found;
  }
  return path;
}

/// Independent check of the emitted joints, once for the path finally chosen: forward
/// kinematics puts every reachable point at the tip with its axis along the nozzle (largest
/// errors), and the smallest singularity distances along the path.
void checkEmittedJoints(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
                        const std::vector<Eigen::Vector3d>& normals, const HeldPart& held,
                        const RobotPathOptions& o, RobotPath& path) {
  const RobotModel& robot = cell.robot;
  path.maxTipError = 0;
  path.maxAxisErrorDeg = 0;
  path.minSingularity = {kInf, kInf, kInf};
  path.lowestArm = kInf;
  path.lowestPart = kInf;
  path.minLinkNozzleDistance = kInf;
  path.minLinkPartDistance = kLinkPartReportLimit;
  size_t next = 0;  // the next unreachable point (sorted)
  for (size_t i = 0; i < points.size(); ++i) {
    if (next < path.unreachable.size() && static_cast<size_t>(path.unreachable[next]) == i) {
      ++next;
      continue;
    }
    const Isometry flange = forwardKinematics(robot, path.joints[i]);
    const SingularityDistance sd = singularityDistance(robot, path.joints[i], flange);
    const Isometry part = flange * cell.partOnFlange;
    path.maxTipError =
        std::max(path.maxTipError, (part * (cell.partScale * points[i]) - cell.nozzleTip).norm());
    const double c = (part.linear() * normals[i].normalized()).dot(cell.nozzleAxis);
    path.maxAxisErrorDeg =
        std::max(path.maxAxisErrorDeg, std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI);
    path.minSingularity.shoulder = std::min(path.minSingularity.shoulder, sd.shoulder);
    path.minSingularity.elbow = std::min(path.minSingularity.elbow, sd.elbow);
    path.minSingularity.wrist = std::min(path.minSingularity.wrist, sd.wrist);
    const ArmCapsules arm = armCapsules(robot, path.joints[i]);
    path.lowestArm = std::min(path.lowestArm, lowestArmSurface(arm));
    path.lowestPart = std::min(path.lowestPart, held.floor.lowest(flange, i));
    path.minLinkNozzleDistance =
        std::min(path.minLinkNozzleDistance, linkNozzleDistance(cell, arm, o));
  }
  // The arm to the part held (the one costly measure: a search of the material near each
  // link; PartArmClearance::Sweep skips most), in chunks on every core.
  constexpr size_t kChunk = 16384;
  std::vector<double> chunkLeast((points.size() + kChunk - 1) / kChunk, kLinkPartReportLimit);
  parallelFor(chunkLeast.size(), o.threads, [&](size_t c, int) {
    PartArmClearance::Sweep sweep(held.arm, kLinkPartReportLimit);
    for (size_t i = c * kChunk; i < std::min(points.size(), (c + 1) * kChunk); ++i) {
      if (std::binary_search(path.unreachable.begin(), path.unreachable.end(), static_cast<int>(i)))
        continue;
      const JointVector& q = path.joints[i];
      sweep.add(forwardKinematics(robot, q), armCapsules(robot, q), i);
    }
    chunkLeast[c] = sweep.least();
  });
  for (double least : chunkLeast)
    path.minLinkPartDistance = std::min(path.minLinkPartDistance, least);
  for (const WaypointsBetween& v : path.via) {  // the program moves through these too
    for (const JointVector& q : v.via.joints) {
      const ArmCapsules arm = armCapsules(robot, q);
      path.lowestArm = std::min(path.lowestArm, lowestArmSurface(arm));
      path.minLinkNozzleDistance =
          std::min(path.minLinkNozzleDistance, linkNozzleDistance(cell, arm, o));
      const Isometry flange = forwardKinematics(robot, q);
      path.lowestPart =
          std::min(path.lowestPart, held.floor.lowest(flange, static_cast<size_t>(v.point)));
      path.minLinkPartDistance = std::min(
          path.minLinkPartDistance,
          held.arm.distance(flange, arm, static_cast<size_t>(v.point), path.minLinkPartDistance));
    }
  }
}

/// Why a cell may be unreachable, from the part alone: "; the part itself ..." naming the first
/// coarse sample where no turn ψ about the nozzle axis holds the part printed so far
/// floorClearance above the floor (whatever the arm does), or "" when there is none.
std::string partUnderTheFloor(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
                              const std::vector<Eigen::Vector3d>& normals,
                              const std::vector<size_t>& coarse, const HeldPart& part,
                              const RobotPathOptions& o) {
  const double dpsi = 2 * M_PI / o.psiSamples;
  size_t count = 0, first = 0;
  double highest = -kInf;  // at the first such sample: the best any ψ does
  for (size_t point : coarse) {
    double best = -kInf;
    for (int k = 0; k < o.psiSamples; ++k)
      best = std::max(
          best, part.floor.lowest(cell.flangePose(points[point], normals[point], k * dpsi), point));
    if (best < o.floorClearance) {
      if (count++ == 0) {
        first = point;
        highest = best;
      }
    }
  }
  if (count == 0)
    return "";
  std::ostringstream s;
  s << "; the part itself (printed so far, on its plate) comes lower than that at " << count
    << " of " << coarse.size() << " sampled toolpath points, first point " << first << " ("
    << std::lround(1000 * highest) << " mm above the floor at best): raise the nozzle";
  return s.str();
}

/// Steps 1–3 (step 4 with changePoint, the points where a change may be made, and flips, the
/// (point, branch) pairs where the fine pass stepped too far in that branch; see planCoarse): plan, fine pass, and refinement around
/// large steps. Throws "unreachable cell set-up" when no plan reaches the coarse path.
RobotPath planAndRefine(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
                        const std::vector<Eigen::Vector3d>& normals, std::vector<size_t>& coarse,
                        const RobotPathOptions& o, StateCache& cache,
                        const std::vector<char>& changePoint = {},
                        const std::vector<std::pair<int, int>>& flips = {},
                        const std::vector<char>& nearWrist = {},
                        const std::vector<signed char>& unwindAt = {}) {
  const size_t N = points.size();
  const size_t stride = coarseStride(N, o);
  RobotPath path;
  size_t fewestProblems = std::numeric_limits<size_t>::max();  // over the passes so far
  int passesWithoutProgress = 0;
  for (int pass = 0;; ++pass) {
    std::vector<char> mayChange;
    std::vector<unsigned> blocked;
    if (!changePoint.empty()) {
      mayChange.assign(coarse.size(), 0);
      for (size_t s = 1; s < coarse.size(); ++s)
        mayChange[s] = coarse[s] == coarse[s - 1] + 1 ? changePoint[coarse[s - 1]] : 0;
      blocked.assign(coarse.size(), 0);
      for (const auto& [point, branch] : flips) {
        const auto s = std::lower_bound(coarse.begin(), coarse.end(), static_cast<size_t>(point));
        if (s != coarse.begin() && s != coarse.end())
          blocked[static_cast<size_t>(s - coarse.begin())] |= 1u << branch;
      }
    }
    const std::vector<CoarsePlan> plans =
        planCoarse(cell, points, normals, coarse, o, cache, mayChange, blocked, nearWrist);
    if (plans.empty()) {
      throw GeoLatticeError(
          "robot path: unreachable cell set-up: no IK branch reaches the whole path continuously "
          "with the arm and the part " +
          millimetres(o.floorClearance) + " mm above the floor and the arm " +
          nozzleClearanceText(o) + " off the nozzle and " + millimetres(o.linkPartClearance) +
          " mm off the part it holds (check the nozzle position, the part-on-flange transform "
          "and the part size)" +
          partUnderTheFloor(cell, points, normals, coarse, cache.part(), o));
    }
    path = solveFine(cell, points, normals, coarse, plans[0], cache.part(), o, false, unwindAt);
    // The cheapest plan flips between its samples or misses points: the plan of the next
    // branch that the fine pass follows, if any, before refining the cheapest one (a flip
    // between samples often stays under denser samples; another branch may have none).
    // A probe that works ran to the end: it is that branch's whole fine pass.
    for (size_t k = 1; k < plans.size() && !path.works(); ++k) {
      RobotPath probe =
          solveFine(cell, points, normals, coarse, plans[k], cache.part(), o, true, unwindAt);
      if (probe.works())
        path = std::move(probe);
    }
    path.refinements = pass;
    path.coarseSamples = static_cast<int>(coarse.size());
    // Progress: a tenth fewer unreachable points and large steps than every pass before. A
    // pass may fix one stretch and expose another (the tilted-cap mushroom: 1,271 → 855 → 991
    // → 521 → 15 → 38 → 30 → 0), so only kPassesWithoutProgress passes in a row without it
    // end the refinement before `refinements` passes.
    const size_t problems = problemCount(path);
    if (pass == 0 || 10 * problems < 9 * fewestProblems) {
      passesWithoutProgress = 0;
    } else {
      ++passesWithoutProgress;
    }
    fewestProblems = std::min(fewestProblems, problems);
    // Points missed between samples where some state reaches them (ψ interpolated into a pose
    // the arm cannot take, e.g. the forearm at the nozzle): refined like large steps, when they
    // are no more than a pass's budget of new samples (below).
    std::vector<int> refineAt = path.largeSteps;
    if (!path.unreachable.empty() && pass < o.refinements) {
      std::vector<size_t> missed;
      for (int i : path.unreachable)
        if (!std::binary_search(coarse.begin(), coarse.end(), static_cast<size_t>(i)))
          missed.push_back(static_cast<size_t>(i));
      if (missed.size() <= 4 * static_cast<size_t>(o.coarseSamples)) {
        const std::vector<int> all{0, 1, 2, 3, 4, 5, 6, 7};
        cache.prepare(missed, all);
        for (size_t i : missed) {
          bool reachable = false;
          for (int b = 0; b < 8 && !reachable; ++b) {
            const BranchStates& st = cache.at(i, b);
            reachable = std::any_of(st.ok.begin(), st.ok.end(), [](char ok) { return ok != 0; });
          }
          if (reachable)
            refineAt.push_back(static_cast<int>(i));
        }
        std::sort(refineAt.begin(), refineAt.end());
      } else if (o.denserPlanFactor > 1) {
        // More points missed between samples than a pass may add: the denser plan that
        // follows (solveRobotPath) is the way, not this plan's passes at its large steps (the
        // demo bunny: 4,553 → 3,086 unreachable in 3 passes, then the denser plan; 6.0 → 5.3 s).
        break;
      }
    }
    if (refineAt.empty() || pass == o.refinements ||
        passesWithoutProgress >= kPassesWithoutProgress) {
      break;
    }
    // Between two coarse samples ψ was only interpolated, and the joints jumped (a wrist flip
    // near a singularity, or a joint reaching its limit): sample the path densely there
    // (stride / 64 apart over the coarse interval around each jump) and plan again. At most
    // 4 · coarseSamples new samples per pass, in path order: thousands of large steps are a
    // bound the path cannot keep, not flips, and would only make every later plan slower.
    const size_t fine = std::max<size_t>(1, stride / 64);
    const size_t budget = 4 * static_cast<size_t>(o.coarseSamples);
    std::vector<size_t> added;
    size_t lastFrom = N, count = 0;
    for (int i : refineAt) {
      const auto hi = std::upper_bound(coarse.begin(), coarse.end(), static_cast<size_t>(i));
      const size_t from = hi == coarse.begin() ? 0 : *(hi - 1);
      const size_t to = hi == coarse.end() ? N - 1 : *hi;
      if (from != lastFrom) {  // the large steps are sorted: one interval's are together
        if (count >= budget)
          break;
        for (size_t j = from; j <= to; j += fine)
          added.push_back(j);
        count += (to - from) / fine + 1;
        lastFrom = from;
      }
      added.push_back(static_cast<size_t>(i - 1));
      added.push_back(static_cast<size_t>(i));
    }
    coarse.insert(coarse.end(), added.begin(), added.end());
    std::sort(coarse.begin(), coarse.end());
    coarse.erase(std::unique(coarse.begin(), coarse.end()), coarse.end());
  }
  return path;
}

/// The part's bounding sphere in the base frame when the robot is at q: centre (m) of the
/// toolpath's bounding box, the radius given.
Eigen::Vector3d sphereCentre(const RobotCell& cell, const Eigen::Vector3d& centre,
                             const JointVector& q) {
  return (forwardKinematics(cell.robot, q) * cell.partOnFlange) * (cell.partScale * centre);
}

/// Clearance (m) of a sphere at c of radius r from the nozzle segment (tip to tip + L axis) and
/// from the floor the robot stands on (base z = 0); negative: they overlap.
double sphereClearance(const RobotCell& cell, const Eigen::Vector3d& c, double r, double L) {
  const double t = std::clamp((c - cell.nozzleTip).dot(cell.nozzleAxis), 0.0, L);
  const double nozzle = (c - (cell.nozzleTip + t * cell.nozzleAxis)).norm() - r;
  return std::min(nozzle, c.z() - r);
}

/// The straight move of the part away from the nozzle by d along the nozzle axis, solved point
/// by point every 5 mm in `branch`; false when a point is out of reach, out of the limits or
/// a joint steps by more than the bound.
bool retreatLine(const RobotCell& cell, const JointVector& q0, int branch, double d,
                 const HeldPart& part, size_t point, const RobotPathOptions& o, JointVector& qEnd) {
  const RobotModel& robot = cell.robot;
  const Isometry f0 = forwardKinematics(robot, q0);
  const int steps = std::max(1, static_cast<int>(std::ceil(d / 0.005)));
  JointVector previous = q0;
  for (int j = 1; j <= steps; ++j) {
    const Isometry f = Eigen::Translation3d(-cell.nozzleAxis * (d * j / steps)) * f0;
    JointVector q;
    if (!inverseKinematicsBranch(robot, f, branch, q, previous[5]))
      return false;
    q = unwrapNear(robot, q, previous);
    double step = 0;
    for (int a = 0; a < 6; ++a)
      step = std::max(step, std::abs(q[a] - previous[a]));
    if (!withinLimits(robot, q) || !armClearHolding(cell, q, f, part, point, o) ||
        step * 180.0 / M_PI > o.maxJointStepDeg)
      return false;
    previous = q;
  }
  qEnd = previous;
  return true;
}

/// The least clearance (m) of the part's bounding sphere from the nozzle and the floor during
/// the joint-space move from a to b (checked every degree of the largest joint's turn), stopping
/// early once it is below `enough`; -∞ where the arm is not clear (armClearHolding: a joint
/// nearer the floor than floorClearance, or a link nearer the nozzle than linkNozzleClearance
/// or nearer the part printed up to `point` than linkPartClearance).
double jointMoveClearance(const RobotCell& cell, const Eigen::Vector3d& centre, double radius,
                          const HeldPart& part, size_t point, const RobotPathOptions& o,
                          const JointVector& a, const JointVector& b, double enough) {
  double largest = 0;
  for (int j = 0; j < 6; ++j)
    largest = std::max(largest, std::abs(b[j] - a[j]));
  const int samples = std::max(2, static_cast<int>(std::ceil(largest * 180.0 / M_PI)));
  double clearance = kInf;
  for (int k = 0; k <= samples && clearance >= enough; ++k) {
    const double t = static_cast<double>(k) / samples;
    JointVector q;
    for (int j = 0; j < 6; ++j)
      q[j] = (1 - t) * a[j] + t * b[j];
    if (!armClearHolding(cell, q, forwardKinematics(cell.robot, q), part, point, o))
      return -kInf;
    clearance = std::min(
        clearance, sphereClearance(cell, sphereCentre(cell, centre, q), radius, o.nozzleLength));
  }
  return clearance;
}

/// Waypoints tried when the straight joint move between two configurations sweeps the part
/// into the floor or the nozzle (a change of shoulder or elbow swings the wrist low): the
/// move's middle with the base turned (swinging the part sideways, at its height) and the
/// shoulder and elbow turned (lifting or lowering it), smallest changes first.
std::vector<JointVector> detourCandidates(const RobotModel& robot, const JointVector& a,
                                          const JointVector& b) {
  std::vector<std::array<double, 3>> offsets;
  for (double d1 : {0.0, 0.5, -0.5, 1.0, -1.0})
    for (double d2 : {0.0, -0.3, 0.3, -0.6, 0.6})
      for (double d3 : {0.0, 0.5, -0.5})
        if (d1 != 0 || d2 != 0 || d3 != 0)
          offsets.push_back({d1, d2, d3});
  std::stable_sort(offsets.begin(), offsets.end(), [](const auto& x, const auto& y) {
    return std::abs(x[0]) + std::abs(x[1]) + std::abs(x[2]) <
           std::abs(y[0]) + std::abs(y[1]) + std::abs(y[2]);
  });
  std::vector<JointVector> candidates;
  for (const auto& d : offsets) {
    JointVector q;
    for (int j = 0; j < 6; ++j)
      q[j] = 0.5 * (a[j] + b[j]);
    for (int j = 0; j < 3; ++j)
      q[j] += d[j];
    if (withinLimits(robot, q))
      candidates.push_back(q);
  }
  return candidates;
}

/// The move of a reconfiguration (module comment, step 4): retreat, joint move, approach.
/// Fills r's retreat joints, distance and clearance; false when no retreat up to maxRetreat
/// gives a joint move (straight in joint space, or through one detour waypoint) that keeps the
/// part's bounding sphere (centre in part units, radius in m) reconfigurationMargin clear of
/// the nozzle and the floor.
bool planReconfigurationMove(const RobotCell& cell, const Eigen::Vector3d& centre, double radius,
                             const HeldPart& part, const RobotPathOptions& o, Reconfiguration& r) {
  const size_t point = static_cast<size_t>(r.point);
  const double margin = o.reconfigurationMargin;
  auto depth = [&](const JointVector& q) {
    // How far the sphere must move along -axis to be the margin (and 1 mm) behind the tip plane.
    return std::max(0.0, (sphereCentre(cell, centre, q) - cell.nozzleTip).dot(cell.nozzleAxis) +
                             radius + margin + 0.001);
  };
  const double dA = depth(r.arrive), dB = depth(r.leave);
  for (double extra = 0.0; std::max(dA, dB) + extra <= o.maxRetreat; extra += 0.05) {
    if (!retreatLine(cell, r.arrive, r.fromBranch, dA + extra, part, point, o, r.retreatFrom) ||
        !retreatLine(cell, r.leave, r.toBranch, dB + extra, part, point, o, r.retreatTo))
      return false;  // farther away is out of reach too
    r.through.clear();
    double clearance = jointMoveClearance(cell, centre, radius, part, point, o, r.retreatFrom,
                                          r.retreatTo, margin);
    if (clearance < margin) {
      for (const JointVector& via : detourCandidates(cell.robot, r.retreatFrom, r.retreatTo)) {
        const double c = std::min(
            jointMoveClearance(cell, centre, radius, part, point, o, r.retreatFrom, via, margin),
            jointMoveClearance(cell, centre, radius, part, point, o, via, r.retreatTo, margin));
        if (c >= margin) {
          clearance = c;
          r.through = {via};
          break;
        }
      }
    }
    if (clearance >= margin) {
      r.retreat = std::max(dA, dB) + extra;
      r.clearance = clearance;
      return true;
    }
  }
  return false;
}

/// Where the step from point at to at + 1 of `path` turns a joint by more than half a turn (it
/// was wound to a limit, and unwrapping it inside the limits turned it back), marks the last
/// air move a → a + 1 with a ≤ at, not excluded and not yet marked, to turn that joint back
/// a full turn (unwindAt, as solveFine reads it). Whether one was marked.
bool unwindAtLastAirMove(const RobotPath& path, const std::vector<int>& kind,
                         const std::vector<char>& excluded, size_t at,
                         std::vector<signed char>& unwindAt) {
  const JointVector &before = path.joints[at], &after = path.joints[at + 1];
  for (int j = 0; j < 6; ++j) {
    const double step = after[j] - before[j];
    if (std::abs(step) <= M_PI)
      continue;
    const signed char code = static_cast<signed char>(step < 0 ? j + 1 : -(j + 1));
    for (size_t a = at + 1; a-- > 0;) {
      if (kind[a] == 2 && kind[a + 1] == 2 && !excluded[a] && unwindAt[a + 1] == 0) {
        unwindAt[a + 1] = code;
        return true;
      }
    }
    return false;
  }
  return false;
}

/// Step 4 (module comment): true and the path with its reconfigurations at air moves in
/// `result`, or false when no path without unreachable points and large steps is found so.
bool solveReconfigured(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
                       const std::vector<Eigen::Vector3d>& normals, const std::vector<int>& kind,
                       const std::vector<size_t>& coarse, const HeldPart& part,
                       const RobotPathOptions& o, RobotPath& result) {
  const size_t N = points.size();
  // Where a change may be made: the highest point of every air move (with a next air point),
  // and any air point where a plan steps too far (added below).
  std::vector<char> changePoint(N, 0);
  for (size_t a = 0; a < N;) {
    if (kind[a] != 2) {
      ++a;
      continue;
    }
    size_t b = a;
    while (b + 1 < N && kind[b + 1] == 2)
      ++b;
    if (b > a) {
      size_t top = a;
      for (size_t i = a; i < b; ++i)
        if (points[i].z() > points[top].z())
          top = i;
      changePoint[top] = kChangeAtAir;
    }
    a = b + 1;
  }
  // The part's bounding sphere (every toolpath point, air moves included), plus the margin.
  Eigen::AlignedBox3d box;
  for (const auto& p : points)
    box.extend(p);
  const Eigen::Vector3d centre = box.center();
  const double radius = cell.partScale * 0.5 * box.diagonal().norm();
  StateCache cache(cell, points, normals, o, o.threads, part);  // all rounds
  std::vector<std::pair<int, int>> flips;
  std::vector<char> excluded(N, 0);   // a change there could not be made
  std::vector<char> nearWrist(N, 0);  // a large step near the wrist singularity was found here
  std::vector<signed char> unwindAt(N, 0);  // a joint turned back a full turn here (solveFine)
  const size_t stride = coarseStride(N, o);
  // The coarse samples with both points of every change; kept (densified) across the rounds.
  std::vector<size_t> withChanges = coarse;
  for (size_t i = 0; i + 1 < N; ++i) {
    if (changePoint[i]) {
      withChanges.push_back(i);
      withChanges.push_back(i + 1);
    }
  }
  std::sort(withChanges.begin(), withChanges.end());
  withChanges.erase(std::unique(withChanges.begin(), withChanges.end()), withChanges.end());
  // One densification per round: a step the rounds bar (a flip, a joint at its limit) does not
  // go away with denser samples, and each round keeps the samples of the one before.
  RobotPathOptions perRound = o;
  perRound.refinements = std::min(o.refinements, 1);
  perRound.denserPlanFactor = 1;      // the rounds are the plan: none follows them
  size_t fewestLarge = N + 1;         // over the rounds so far
  std::vector<char> seenLarge(N, 0);  // points where a plan of a round stepped too far
  int roundsWithoutProgress = 0;
  for (int round = 0; round < kReconfigurationRounds; ++round) {
    RobotPath path;
    try {
      path = planAndRefine(cell, points, normals, withChanges, perRound, cache, changePoint, flips,
                           nearWrist, unwindAt);
    } catch (const GeoLatticeError&) {
      return false;
    }
    if (!path.unreachable.empty())
      return false;
    // Two plans in a row with neither fewer large steps nor all of them at new places: the
    // changes the rounds can make do not remove them (e.g. a joint step bound below what the
    // path needs between its points, whose steps recur where they were). Large steps all at
    // new places are progress: barring the branch where the last plans flipped removed those,
    // and the next plan knows more (the bunny's demo path at one edge length: 1, 1, 6, 0).
    bool allNew = !path.largeSteps.empty();
    for (int i : path.largeSteps) {
      allNew = allNew && !seenLarge[static_cast<size_t>(i)];
    }
    for (int i : path.largeSteps) {
      seenLarge[static_cast<size_t>(i)] = 1;
    }
    if (path.largeSteps.size() < fewestLarge || allNew) {
      fewestLarge = std::min(fewestLarge, path.largeSteps.size());
      roundsWithoutProgress = 0;
    } else if (++roundsWithoutProgress >= 2) {
      return false;
    }
    // A step too large inside an air move becomes a place for a change; inside a stretch,
    // the branch may not be kept there, and a change at a seam may be made there instead (the
    // wrist crossing its singularity where the part's axis sweeps round, a joint at its
    // limit). Plan again.
    bool newChange = false;
    for (int i : path.largeSteps) {
      const size_t at = static_cast<size_t>(i - 1);
      // A joint wound to its limit (its step is nearly a full turn: unwrapped inside the
      // limits): whatever the branch and ψ, it turns back a full turn at the last air move
      // before (the Y with the nozzle at the edge of the reach: wrist 3 round once per layer).
      if (unwindAtLastAirMove(path, kind, excluded, at, unwindAt))
        continue;
      if (std::min(std::abs(std::sin(path.joints[at][4])), std::abs(std::sin(path.joints[i][4]))) <
          kWideWristMargin) {
        std::fill(nearWrist.begin() + static_cast<long>(at - std::min(at, stride)),
                  nearWrist.begin() + static_cast<long>(std::min(N, at + 2 * stride)), 1);
      }
      const bool air = kind[at] == 2 && kind[at + 1] == 2;
      if (!excluded[at] && changePoint[at] != kChangeAtAir &&
          (air || path.largeSteps.size() <= kMostStepsForSeams)) {
        newChange = newChange || !changePoint[at];
        changePoint[at] = air ? kChangeAtAir : kChangeAtSeam;
        withChanges.push_back(at);
        withChanges.push_back(at + 1);
      }
      if (air && !excluded[at])
        continue;
      int branch = path.branch;
      for (const Reconfiguration& r : path.reconfigurations)
        if (r.point < i)
          branch = r.toBranch;
      flips.emplace_back(i, branch);
    }
    if (newChange) {
      std::sort(withChanges.begin(), withChanges.end());
      withChanges.erase(std::unique(withChanges.begin(), withChanges.end()), withChanges.end());
    }
    bool allMade = path.largeSteps.empty();
    for (Reconfiguration& r : path.reconfigurations) {
      if (!planReconfigurationMove(cell, centre, radius, part, o, r)) {
        changePoint[static_cast<size_t>(r.point)] = 0;  // excluded; plan again
        unwindAt[static_cast<size_t>(r.point) + 1] = 0;
        excluded[static_cast<size_t>(r.point)] = 1;
        allMade = false;
      }
    }
    if (allMade) {
      result = std::move(path);
      return true;
    }
  }
  return false;
}

}  // namespace

namespace {

/// Which of the arm's clearances keeps a coarse path that no plan reaches out of reach (module
/// comment, "The nozzle", "The part"): the coarse plan of steps 1–3 (one configuration for
/// the whole path; step 4 may still need a change where this says one clearance alone is
/// enough) made again with the arm allowed near the part it holds, near the nozzle, or both,
/// and then with the arm and the part allowed down to the floor (a part too tall for the
/// nozzle's height: the robot cannot hold its base low enough). "; ..." naming it, or "" (the
/// reach or the joint limits stop it, or explainUnreachable is off). Only after everything else
/// failed: two to four coarse plans.
std::string bindingClearance(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
                             const std::vector<Eigen::Vector3d>& normals,
                             const std::vector<size_t>& coarse, const HeldPart& part,
                             const RobotPathOptions& o) {
  if (!o.explainUnreachable)
    return "";
  auto reachesWith = [&](double nozzle, double held, double floor) {
    RobotPathOptions r = o;
    r.linkNozzleClearance = nozzle;
    r.linkPartClearance = held;
    r.floorClearance = floor;
    StateCache cache(cell, points, normals, r, r.threads, part);
    return !planCoarse(cell, points, normals, coarse, r, cache).empty();
  };
  const double floor = o.floorClearance;
  const bool withoutPart = o.linkPartClearance > 0 && reachesWith(o.linkNozzleClearance, 0, floor);
  const bool withoutNozzle =
      o.linkNozzleClearance > 0 && reachesWith(0, o.linkPartClearance, floor);
  if (withoutPart && withoutNozzle)
    return "; what stops it is keeping the arm off the nozzle and off the part at once (one "
           "configuration throughout reaches the path with either alone)";
  if (withoutPart)
    return "; what stops it is the part it holds: one configuration throughout reaches the path "
           "with the arm nearer than " +
           millimetres(o.linkPartClearance) + " mm to the part (it would pass against it)";
  if (withoutNozzle)
    return "; what stops it is the nozzle: one configuration throughout reaches the path with "
           "the arm nearer than " +
           nozzleClearanceText(o) + " to the nozzle";
  if ((o.linkPartClearance > 0 || o.linkNozzleClearance > 0) && reachesWith(0, 0, floor))
    return "; one configuration throughout reaches the path only with the arm near both the "
           "nozzle and the part";
  // At any height (the floor is z = 0 of the base frame).
  if (reachesWith(o.linkNozzleClearance, o.linkPartClearance, -1e9))
    return "; what stops it is the floor: one configuration throughout reaches the path only "
           "with the arm or the part nearer than " +
           millimetres(floor) +
           " mm to the floor (the part is too tall for the nozzle's height: raise the nozzle "
           "tip, mount the part nearer the flange or print it lying lower)";
  return "";
}

}  // namespace

RobotPath solveRobotPath(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
                         const std::vector<Eigen::Vector3d>& normals, const RobotPathOptions& o,
                         const std::vector<int>& kind) {
  const auto t0 = std::chrono::steady_clock::now();
  cell.validate();
  const size_t N = points.size();
  if (N == 0) {
    throw GeoLatticeError("robot path: the toolpath is empty");
  }
  if (normals.size() != N || (!kind.empty() && kind.size() != N)) {
    throw GeoLatticeError(
        "robot path: one normal (and one kind, if given) per toolpath point is needed");
  }
  for (size_t i = 0; i < N; ++i) {
    if (!points[i].allFinite() || !normals[i].allFinite() || !(normals[i].norm() > 0)) {
      std::ostringstream s;
      s << "robot path: toolpath point " << i << " has a NaN position or a NaN/zero normal";
      throw GeoLatticeError(s.str());
    }
  }
  if (o.psiSamples < 4 || o.maxPsiStep < 1 || o.coarseSamples < 2 || o.denserPlanFactor < 1 ||
      !(o.maxJointStepDeg > 0) || o.refinements < 0 || !(o.reconfigurationCost >= 0) ||
      !(o.nozzleLength >= 0) || !(o.reconfigurationMargin >= 0) || !(o.maxRetreat >= 0) ||
      !std::isfinite(o.floorClearance) || !std::isfinite(o.linkNozzleClearance) ||
      !std::isfinite(o.linkPartClearance) || o.threads < 0) {
    throw GeoLatticeError(
        "robot path: bad options (psi samples >= 4, max psi step >= 1, coarse samples >= 2, "
        "denser plan factor >= 1, "
        "max joint step > 0, refinements >= 0, reconfiguration cost, nozzle length, margin and "
        "retreat >= 0, finite floor, nozzle and part clearances, threads >= 0)");
  }
  const std::vector<size_t> coarse = coarseSamplesOf(N, o);

  // Steps 1–3, then on denser samples; step 4 only where they fail (a path they can follow
  // keeps its plan).
  const bool step4 = o.reconfigure && !kind.empty();
  const HeldPart part(cell, points, kind);
  RobotPath path;
  std::string noPlan;  // steps 1–3 found no plan: why
  // The samples (as refined) and options of the plan kept: step 4 starts from them; with no
  // plan at all, from the denser samples (the generated coil, its nozzle tilted up to 102°:
  // no plan on 500 or 2,000 samples; step 4 on 2,000 changes configuration three times).
  std::vector<size_t> planSamples = coarse;
  RobotPathOptions planOptions = o;
  {
    StateCache cache(cell, points, normals, o, o.threads, part);
    try {
      std::vector<size_t> refined = coarse;
      path = planAndRefine(cell, points, normals, refined, o, cache);
      planSamples = std::move(refined);
    } catch (const GeoLatticeError& e) {
      noPlan = e.what();
    }
    // ψ turns by at most maxPsiStep grid cells from one coarse sample to the next: on denser
    // samples it may turn faster where the path needs it (the demo bunny with the arm off the
    // part it holds: 5,070 points unreachable on 500 samples, none on 2,000).
    if ((!noPlan.empty() || !path.works()) && o.denserPlanFactor > 1) {
      RobotPathOptions dense = o;
      dense.coarseSamples = o.coarseSamples * o.denserPlanFactor;
      dense.denserPlanFactor = 1;  // none follows it
      std::vector<size_t> refined = coarseSamplesOf(N, dense);
      if (!noPlan.empty()) {  // step 4 starts from these if no plan is found on them either
        planSamples = refined;
        planOptions = dense;
      }
      try {
        RobotPath denser = planAndRefine(cell, points, normals, refined, dense, cache);
        if (!noPlan.empty() || problemCount(denser) < problemCount(path)) {
          path = std::move(denser);
          planSamples = std::move(refined);
          planOptions = dense;
          noPlan.clear();
        }
      } catch (const GeoLatticeError&) {
        // no plan on denser samples either: the first attempt's outcome stands
      }
    }
  }
  if (!noPlan.empty() && (!step4 || !solveReconfigured(cell, points, normals, kind, planSamples,
                                                       part, planOptions, path)))
    throw GeoLatticeError(noPlan + bindingClearance(cell, points, normals, coarse, part, o));
  if (noPlan.empty() && step4 && !path.works()) {
    RobotPath reconfigured;
    if (solveReconfigured(cell, points, normals, kind, planSamples, part, planOptions,
                          reconfigured))
      path = std::move(reconfigured);
  }
  checkEmittedJoints(cell, points, normals, part, o, path);
  path.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return path;
}

const JointVector& jointsBefore(const RobotPath& path, size_t i) {
  const auto& r = path.reconfigurations;
  const auto it = std::lower_bound(r.begin(), r.end(), static_cast<int>(i) - 1,
                                   [](const Reconfiguration& x, int p) { return x.point < p; });
  if (it != r.end() && it->point == static_cast<int>(i) - 1)
    return it->leave;
  return path.joints[i - 1];
}

double jointSpeedRatio(const RobotCell& cell, const RobotPath& path,
                       const std::vector<Eigen::Vector3d>& points,
                       const std::vector<double>& feedRate, double& maxSpeedDegS) {
  double ratio = 0;
  maxSpeedDegS = 0;
  for (size_t i = 1; i < path.joints.size() && i < points.size() && i < feedRate.size(); ++i) {
    const double len = (points[i] - points[i - 1]).norm();
    if (!(feedRate[i] > 0) || len == 0)
      continue;
    const double dt = len / feedRate[i];
    // The joints' travel over the segment (through its waypoints between points, if any).
    JointVector travel{};
    const JointVector* from = &jointsBefore(path, i);
    const auto via =
        std::lower_bound(path.via.begin(), path.via.end(), static_cast<int>(i),
                         [](const WaypointsBetween& v, int point) { return v.point < point; });
    if (via != path.via.end() && via->point == static_cast<int>(i)) {
      for (const JointVector& q : via->via.joints) {
        for (int j = 0; j < 6; ++j)
          travel[j] += std::abs(q[j] - (*from)[j]);
        from = &q;
      }
    }
    for (int j = 0; j < 6; ++j) {
      const double speed = (travel[j] + std::abs(path.joints[i][j] - (*from)[j])) / dt;
      maxSpeedDegS = std::max(maxSpeedDegS, speed * 180.0 / M_PI);
      ratio = std::max(ratio, speed / cell.robot.maxSpeed[j]);
    }
  }
  return ratio;
}

std::vector<NozzleSection> nozzleSectionsFor(const Printhead& head, double margin, double step,
                                             int maxSections) {
  constexpr double kMetresPerMm = 0.001;
  const double height = head.height();  // mm, as the printhead's profile
  const double dh = 0.5;                // mm: where a section may end
  std::vector<NozzleSection> sections;
  for (double from = 0; from < height;) {
    const double first = head.maxRadiusBetween(from, from + dh);
    double to = std::min(from + dh, height);
    if (static_cast<int>(sections.size()) + 1 < maxSections) {
      while (to < height &&
             head.maxRadiusBetween(to, std::min(to + dh, height)) <= first + step / kMetresPerMm)
        to = std::min(to + dh, height);
    } else {
      to = height;
    }
    sections.push_back({from * kMetresPerMm, to * kMetresPerMm,
                        head.maxRadiusBetween(from, to) * kMetresPerMm + margin});
    from = to;
  }
  return sections;
}

double tallestPart(const RobotCell& cell, const RobotPathOptions& o, double step) {
  cell.validate();
  if (!(step > 0)) {
    throw GeoLatticeError("robot path: the height step must be > 0");
  }
  auto reachable = [&](double h) {
    const Eigen::Vector3d p(0, 0, h), up(0, 0, 1);
    for (int k = 0; k < o.psiSamples; ++k) {
      const Isometry flange = cell.flangePose(p, up, 2 * M_PI * k / o.psiSamples);
      for (const JointVector& q : inverseKinematics(cell.robot, flange)) {
        if (!withinLimits(cell.robot, q)) {
          continue;
        }
        const ArmCapsules arm = armCapsules(cell.robot, q);
        if (lowestArmSurface(arm) >= o.floorClearance &&
            (o.linkNozzleClearance <= 0 || armClearOfNozzle(cell, arm, o))) {
          return true;
        }
      }
    }
    return false;
  };
  if (!reachable(0)) {
    return 0;
  }
  const double farthest = 2.0 / cell.partScale;  // 2 m: beyond any UR's reach
  double h = 0;
  while (h + step <= farthest && reachable(h + step)) {
    h += step;
  }
  return h;
}

std::string nozzleClearanceText(const RobotPathOptions& o) {
  double least = o.linkNozzleClearance;
  for (const NozzleSection& s : o.nozzleSections)
    least = std::min(least, s.clearance);
  if (o.nozzleSections.empty() || millimetres(least) == millimetres(o.linkNozzleClearance))
    return millimetres(o.linkNozzleClearance) + " mm";
  return millimetres(least) + "-" + millimetres(o.linkNozzleClearance) +
         " mm (along the printhead's profile)";
}

}  // namespace geolattice
