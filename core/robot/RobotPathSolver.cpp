#include "robot/RobotPathSolver.h"

#include "common/Error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

namespace geolattice {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool withinLimits(const RobotModel& r, const JointVector& q) {
  for (int i = 0; i < 6; ++i) {
    if (q[i] < r.lowerLimit[i] || q[i] > r.upperLimit[i])
      return false;
  }
  return true;
}

/// q (each joint in (-π, π]) shifted by multiples of 2π to be nearest to `near`, inside limits.
JointVector unwrapNear(const RobotModel& r, JointVector q, const JointVector& near) {
  for (int i = 0; i < 6; ++i) {
    double v = near[i] + std::remainder(q[i] - near[i], 2 * M_PI);
    if (v > r.upperLimit[i])
      v -= 2 * M_PI;
    if (v < r.lowerLimit[i])
      v += 2 * M_PI;
    q[i] = v;
  }
  return q;
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

/// The coarse plan: one IK branch and a ψ grid index per coarse sample.
struct CoarsePlan {
  int branch = -1;
  std::vector<int> psi;
};

/// Dynamic programming over the ψ grid at the coarse samples, for every branch that reaches a
/// subsample of them; the cheapest branch wins (module comment). branch -1: none reaches.
CoarsePlan planCoarse(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
                      const std::vector<Eigen::Vector3d>& normals,
                      const std::vector<size_t>& coarse, const RobotPathOptions& o) {
  const RobotModel& robot = cell.robot;
  const int P = o.psiSamples;
  const double dpsi = 2 * M_PI / P;
  const size_t S = coarse.size();
  // Flange poses of the coarse samples on the ψ grid (shared by the branches).
  std::vector<Isometry> flange(S * P);
  for (size_t s = 0; s < S; ++s) {
    for (int k = 0; k < P; ++k) {
      flange[s * P + k] = cell.flangePose(points[coarse[s]], normals[coarse[s]], k * dpsi);
    }
  }
  // Branches that reach a subsample of the coarse path at some ψ everywhere are candidates.
  std::vector<int> branches;
  for (int branch = 0; branch < 8; ++branch) {
    bool reaches = true;
    for (size_t s = 0; s < S && reaches; s += std::max<size_t>(1, S / 50)) {
      bool any = false;
      for (int k = 0; k < P && !any; k += 3) {
        JointVector qq;
        any = inverseKinematicsBranch(robot, flange[s * P + k], branch, qq) &&
              withinLimits(robot, qq);
      }
      reaches = any;
    }
    if (reaches)
      branches.push_back(branch);
  }
  CoarsePlan best;
  double bestCost = kInf;
  std::vector<JointVector> q(S * P);
  std::vector<char> ok(S * P);
  std::vector<double> cost(S * P), penalty(S * P);
  std::vector<int> from(S * P);
  std::vector<JointVector> wound(S * P);
  for (int branch : branches) {
    for (size_t s = 0; s < S; ++s) {
      for (int k = 0; k < P; ++k) {
        const size_t id = s * P + k;
        ok[id] = inverseKinematicsBranch(robot, flange[id], branch, q[id]);
        penalty[id] =
            ok[id] ? singularityPenalty(robot, q[id], flange[id], o.singularityMargin) : kInf;
      }
    }
    for (int k = 0; k < P; ++k) {
      cost[k] = penalty[k];
      from[k] = -1;
      wound[k] = q[k];
    }
    for (size_t s = 1; s < S; ++s) {
      for (int k = 0; k < P; ++k) {
        const size_t id = s * P + k;
        cost[id] = kInf;
        from[id] = -1;
        if (!ok[id])
          continue;
        for (int dk = -o.maxPsiStep; dk <= o.maxPsiStep; ++dk) {
          const int j = ((k + dk) % P + P) % P;
          const size_t pid = (s - 1) * P + j;
          if (!std::isfinite(cost[pid]))
            continue;
          // The joints as the robot reaches them along this path (turns add up, no ±2π
          // folding): a path that would wind a joint past its limit is infeasible, since the
          // fine pass could only get back by a full turn between two points.
          JointVector reached;
          double step = 0;
          bool inside = true;
          for (int a = 0; a < 6; ++a) {
            const double d = std::remainder(q[id][a] - wound[pid][a], 2 * M_PI);
            reached[a] = wound[pid][a] + d;
            step = std::max(step, std::abs(d));
            inside =
                inside && reached[a] >= robot.lowerLimit[a] && reached[a] <= robot.upperLimit[a];
          }
          if (!inside)
            continue;
          const double c = cost[pid] + step + penalty[id];
          if (c < cost[id]) {
            cost[id] = c;
            from[id] = j;
            wound[id] = reached;
          }
        }
      }
    }
    int end = -1;
    for (int k = 0; k < P; ++k) {
      if (std::isfinite(cost[(S - 1) * P + k]) &&
          (end < 0 || cost[(S - 1) * P + k] < cost[(S - 1) * P + end]))
        end = k;
    }
    if (end >= 0 && cost[(S - 1) * P + end] < bestCost) {
      bestCost = cost[(S - 1) * P + end];
      best.branch = branch;
      best.psi.assign(S, 0);
      int k = end;
      for (size_t s = S; s-- > 0;) {
        best.psi[s] = k;
        k = from[s * P + k];
      }
    }
  }
  return best;
}

/// Joints at every point: ψ interpolated between the coarse samples, IK of the plan's branch,
/// unwrapped next to the previous joints; FK check and singularity distances.
RobotPath solveFine(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
                    const std::vector<Eigen::Vector3d>& normals, const std::vector<size_t>& coarse,
                    const CoarsePlan& plan, const RobotPathOptions& o) {
  const RobotModel& robot = cell.robot;
  const size_t N = points.size(), S = coarse.size();
  const double dpsi = 2 * M_PI / o.psiSamples;
  RobotPath path;
  path.branch = plan.branch;
  path.joints.resize(N);
  path.psi.resize(N);
  path.minSingularity = {kInf, kInf, kInf};
  JointVector previous{};
  bool havePrevious = false;
  size_t seg = 0;
  for (size_t i = 0; i < N; ++i) {
    while (seg + 1 < S - 1 && coarse[seg + 1] <= i)
      ++seg;
    const size_t a = coarse[seg], b = coarse[std::min(seg + 1, S - 1)];
    double pa = plan.psi[seg] * dpsi, pb = plan.psi[std::min(seg + 1, S - 1)] * dpsi;
    pb = pa + std::remainder(pb - pa, 2 * M_PI);
    const double t = b > a ? static_cast<double>(i - a) / static_cast<double>(b - a) : 0.0;
    double psi = (1 - t) * pa + t * pb;
    JointVector qi;
    Isometry f = cell.flangePose(points[i], normals[i], psi);
    bool found =
        inverseKinematicsBranch(robot, f, plan.branch, qi, havePrevious ? previous[5] : 0.0);
    for (int retry = 1; !found && retry <= 3; ++retry) {
      for (double sign : {1.0, -1.0}) {
        const double p2 = psi + sign * retry * dpsi;
        f = cell.flangePose(points[i], normals[i], p2);
        if (inverseKinematicsBranch(robot, f, plan.branch, qi, havePrevious ? previous[5] : 0.0)) {
          found = true;
          psi = p2;
          break;
        }
      }
    }
    if (found && havePrevious) {
      qi = unwrapNear(robot, qi, previous);
    }
    if (!found || !withinLimits(robot, qi)) {
      path.unreachable.push_back(static_cast<int>(i));
      qi = havePrevious ? previous : JointVector{};
    } else {
      const SingularityDistance sd = singularityDistance(robot, qi, f);
      // Independent check of the emitted joints: forward kinematics puts p at the tip, n along the nozzle.
      const Isometry part = forwardKinematics(robot, qi) * cell.partOnFlange;
      path.maxTipError =
          std::max(path.maxTipError, (part * (cell.partScale * points[i]) - cell.nozzleTip).norm());
      const double c = (part.linear() * normals[i].normalized()).dot(cell.nozzleAxis);
      path.maxAxisErrorDeg =
          std::max(path.maxAxisErrorDeg, std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI);
      path.minSingularity.shoulder = std::min(path.minSingularity.shoulder, sd.shoulder);
      path.minSingularity.elbow = std::min(path.minSingularity.elbow, sd.elbow);
      path.minSingularity.wrist = std::min(path.minSingularity.wrist, sd.wrist);
    }
    if (havePrevious) {
      double step = 0;
      for (int j = 0; j < 6; ++j)
        step = std::max(step, std::abs(qi[j] - previous[j]));
      if (step * 180.0 / M_PI > path.maxJointStepDeg) {
        path.maxJointStepDeg = step * 180.0 / M_PI;
        path.maxJointStepAt = static_cast<int>(i);
      }
      if (step * 180.0 / M_PI > o.maxJointStepDeg) {
        path.largeSteps.push_back(static_cast<int>(i));
      }
    }
    path.joints[i] = qi;
    path.psi[i] = psi;
    previous = qi;
    havePrevious = havePrevious || found;
  }
  return path;
}

}  // namespace

RobotPath solveRobotPath(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
                         const std::vector<Eigen::Vector3d>& normals, const RobotPathOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  cell.validate();
  const size_t N = points.size();
  if (N == 0) {
    throw GeoLatticeError("robot path: the toolpath is empty");
  }
  if (normals.size() != N) {
    throw GeoLatticeError("robot path: one normal per toolpath point is needed");
  }
  for (size_t i = 0; i < N; ++i) {
    if (!points[i].allFinite() || !normals[i].allFinite() || !(normals[i].norm() > 0)) {
      std::ostringstream s;
      s << "robot path: toolpath point " << i << " has a NaN position or a NaN/zero normal";
      throw GeoLatticeError(s.str());
    }
  }
  if (o.psiSamples < 4 || o.maxPsiStep < 1 || o.coarseSamples < 2 || !(o.maxJointStepDeg > 0) ||
      o.refinements < 0) {
    throw GeoLatticeError(
        "robot path: bad options (psi samples >= 4, max psi step >= 1, coarse samples >= 2, "
        "max joint step > 0, refinements >= 0)");
  }
  const size_t stride = std::max<size_t>(1, N / static_cast<size_t>(o.coarseSamples));
  std::vector<size_t> coarse;
  for (size_t i = 0; i < N; i += stride)
    coarse.push_back(i);
  if (coarse.back() != N - 1)
    coarse.push_back(N - 1);

  RobotPath path;
  for (int pass = 0;; ++pass) {
    const CoarsePlan plan = planCoarse(cell, points, normals, coarse, o);
    if (plan.branch < 0) {
      throw GeoLatticeError(
          "robot path: unreachable cell set-up: no IK branch reaches the whole path continuously "
          "(check the nozzle "
          "position, the part-on-flange transform and the part size)");
    }
    path = solveFine(cell, points, normals, coarse, plan, o);
    path.refinements = pass;
    if (path.largeSteps.empty() || pass == o.refinements) {
      break;
    }
    // Between two coarse samples ψ was only interpolated, and the joints jumped (a wrist flip
    // near a singularity, or a joint reaching its limit): sample the path densely there
    // (stride / 64 apart over the coarse interval around each jump) and plan again.
    const size_t fine = std::max<size_t>(1, stride / 64);
    std::vector<size_t> added;
    for (int i : path.largeSteps) {
      const auto hi = std::upper_bound(coarse.begin(), coarse.end(), static_cast<size_t>(i));
      const size_t from = hi == coarse.begin() ? 0 : *(hi - 1);
      const size_t to = hi == coarse.end() ? N - 1 : *hi;
      for (size_t j = from; j <= to; j += fine)
        added.push_back(j);
      added.push_back(static_cast<size_t>(i - 1));
      added.push_back(static_cast<size_t>(i));
    }
    coarse.insert(coarse.end(), added.begin(), added.end());
    std::sort(coarse.begin(), coarse.end());
    coarse.erase(std::unique(coarse.begin(), coarse.end()), coarse.end());
  }
  path.coarseSamples = static_cast<int>(coarse.size());
  path.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return path;
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
    for (int j = 0; j < 6; ++j) {
      const double speed = std::abs(path.joints[i][j] - path.joints[i - 1][j]) / dt;
      maxSpeedDegS = std::max(maxSpeedDegS, speed * 180.0 / M_PI);
      ratio = std::max(ratio, speed / cell.robot.maxSpeed[j]);
    }
  }
  return ratio;
}

}  // namespace geolattice
