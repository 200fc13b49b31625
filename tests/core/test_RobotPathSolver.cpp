// The robot path solver's step 4 (RobotPathSolver.h): a constructed path that one IK branch with
// a continuous ψ cannot follow — the nozzle axis turns by 100 degrees in one step at the end of
// every air move — is followed with reconfiguration moves at those air moves, each checked here
// on its own (straight retreat, joint move clear of the nozzle and the floor, FK at both ends),
// and written into the URScript program. A path that one branch follows keeps its plan; the
// number of threads changes nothing. The arm is kept off the nozzle.
#include "common/Error.h"
#include "program/URScriptWriter.h"
#include "robot/RobotPathSolver.h"
#include "../common/URScriptSyntax.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

using namespace geolattice;

namespace {

struct ConstructedPath {
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<int> kind;
  std::vector<double> extrusion, feedRate;
};

/// Four straight print runs of 100 points (0.2 mm apart) around a circle of radius 15 mm,
/// each with its own nozzle axis tilted `tiltDeg` from +z (turned 90 degrees about z from one
/// run to the next), joined by air moves: up to z = 40 mm turning the axis to +z, across, and
/// down with the axis still +z until the last air point, which already has the next run's axis.
ConstructedPath abruptAirMoves(double tiltDeg) {
  ConstructedPath p;
  const double tilt = tiltDeg * M_PI / 180;
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d previousAxis = up;
  auto add = [&](const Eigen::Vector3d& x, const Eigen::Vector3d& n, int kind) {
    p.points.push_back(x);
    p.normals.push_back(n.normalized());
    p.kind.push_back(kind);
    const double e = p.extrusion.empty() ? 0.0 : p.extrusion.back();
    const double len = p.points.size() > 1 ? (x - p.points[p.points.size() - 2]).norm() : 0.0;
    p.extrusion.push_back(kind == 2 ? e : e + 0.03 * len);
    p.feedRate.push_back(kind == 2 ? 50.0 : 20.0);
  };
  for (int run = 0; run < 4; ++run) {
    const double phi = run * M_PI / 2;
    const Eigen::Vector3d axis(std::sin(tilt) * std::cos(phi), std::sin(tilt) * std::sin(phi),
                               std::cos(tilt));
    const Eigen::Vector3d start(15 * std::cos(phi), 15 * std::sin(phi), 10);
    const Eigen::Vector3d along(-std::sin(phi), std::cos(phi), 0);
    if (run > 0) {
      const Eigen::Vector3d from = p.points.back(), lifted(from.x(), from.y(), 40);
      const Eigen::Vector3d top(start.x(), start.y(), 40);
      for (int j = 1; j <= 40; ++j) {
        const double t = j / 40.0;
        add(from + t * (lifted - from), (1 - t) * previousAxis + t * up, 2);
      }
      for (int j = 1; j <= 40; ++j)
        add(lifted + j / 40.0 * (top - lifted), up, 2);
      for (int j = 1; j <= 40; ++j)
        add(top + j / 40.0 * (start - top), j < 40 ? up : axis, 2);
    }
    for (int j = 0; j < 100; ++j)
      add(start + along * (0.2 * j), axis, 0);
    previousAxis = axis;
  }
  return p;
}

/// Distance of c from the segment tip .. tip + length · axis.
double segmentDistance(const RobotCell& cell, const Eigen::Vector3d& c, double length) {
  const double t = std::clamp((c - cell.nozzleTip).dot(cell.nozzleAxis), 0.0, length);
  return (c - (cell.nozzleTip + t * cell.nozzleAxis)).norm();
}

/// Steps 1–3 only (no reconfiguration).
RobotPath solveWithOneBranch(const RobotCell& cell, const ConstructedPath& p) {
  RobotPathOptions off;
  off.reconfigure = false;
  return solveRobotPath(cell, p.points, p.normals, off, p.kind);
}

size_t occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

}  // namespace

TEST(RobotPathSolver, ReconfiguresAtAirMovesWhereOneBranchCannotFollow) {
  const ConstructedPath p = abruptAirMoves(100);
  const RobotCell cell;
  const RobotPath single = solveWithOneBranch(cell, p);
  ASSERT_FALSE(single.largeSteps.empty()) << "the constructed path must defeat steps 1-3";
  EXPECT_GT(single.maxJointStepDeg, 20.0);

  const RobotPathOptions o;
  const RobotPath rp = solveRobotPath(cell, p.points, p.normals, o, p.kind);
  std::printf(
      "[robot] abrupt air moves: one branch max step %.1f deg (%zu large steps); with "
      "step 4 max step %.1f deg, %zu reconfigurations, %.2f s\n",
      single.maxJointStepDeg, single.largeSteps.size(), rp.maxJointStepDeg,
      rp.reconfigurations.size(), rp.seconds);
  EXPECT_TRUE(rp.unreachable.empty());
  EXPECT_TRUE(rp.largeSteps.empty());
  EXPECT_LE(rp.maxJointStepDeg, o.maxJointStepDeg);
  ASSERT_GE(rp.reconfigurations.size(), 1u);
  EXPECT_LT(rp.maxTipError, 1e-6);
  EXPECT_LT(rp.maxAxisErrorDeg, 0.01);

  // The part's bounding sphere, as the solver's contract states it.
  Eigen::AlignedBox3d box;
  for (const auto& x : p.points)
    box.extend(x);
  const double radius = cell.partScale * 0.5 * box.diagonal().norm();
  auto centreAt = [&](const JointVector& q) {
    return (forwardKinematics(cell.robot, q) * cell.partOnFlange) * (cell.partScale * box.center());
  };
  int previousPoint = -1;
  for (const Reconfiguration& r : rp.reconfigurations) {
    SCOPED_TRACE("reconfiguration at point " + std::to_string(r.point));
    ASSERT_GT(r.point, previousPoint);  // in path order
    previousPoint = r.point;
    const size_t at = static_cast<size_t>(r.point);
    EXPECT_EQ(p.kind[at], 2);  // between two air points
    EXPECT_EQ(p.kind[at + 1], 2);
    EXPECT_EQ(r.arrive, rp.joints[at]);
    EXPECT_EQ(r.leave, rp.joints[at + 1]);
    EXPECT_EQ(&jointsBefore(rp, at + 1), &r.leave);
    EXPECT_GT(r.retreat, 0.0);
    EXPECT_LE(r.retreat, o.maxRetreat);
    // Both retreats: the same orientation, moved straight away from the nozzle along its axis.
    for (const auto& [near, far] : {std::pair(r.arrive, r.retreatFrom), {r.leave, r.retreatTo}}) {
      const Isometry a = forwardKinematics(cell.robot, near),
                     b = forwardKinematics(cell.robot, far);
      EXPECT_LT((a.linear() - b.linear()).norm(), 1e-6);
      const Eigen::Vector3d move = b.translation() - a.translation();
      EXPECT_GT(-move.dot(cell.nozzleAxis), 0.0);
      EXPECT_LE(move.norm(), r.retreat + 1e-9);
      EXPECT_LT((move + move.norm() * cell.nozzleAxis).norm(), 1e-6);
    }
    // The joint move (linear in joint space between its waypoints, as movej) keeps the sphere
    // clear by the margin.
    std::vector<JointVector> waypoints{r.retreatFrom};
    waypoints.insert(waypoints.end(), r.through.begin(), r.through.end());
    waypoints.push_back(r.retreatTo);
    double clearance = std::numeric_limits<double>::infinity();
    for (size_t w = 0; w + 1 < waypoints.size(); ++w) {
      for (int j = 0; j <= 400; ++j) {
        JointVector q;
        for (int a = 0; a < 6; ++a)
          q[a] = waypoints[w][a] + j / 400.0 * (waypoints[w + 1][a] - waypoints[w][a]);
        const Eigen::Vector3d c = centreAt(q);
        clearance = std::min(
            {clearance, segmentDistance(cell, c, o.nozzleLength) - radius, c.z() - radius});
        for (int a = 0; a < 6; ++a) {
          EXPECT_GE(q[a], cell.robot.lowerLimit[a]);
          EXPECT_LE(q[a], cell.robot.upperLimit[a]);
        }
      }
    }
    EXPECT_GE(clearance, o.reconfigurationMargin - 1e-3);
    EXPECT_NEAR(clearance, r.clearance, 5e-3);
  }
  double speedDeg = 0;
  EXPECT_LE(jointSpeedRatio(cell, rp, p.points, p.feedRate, speedDeg), 1.0);

  // The program: every reconfiguration where it happens, retreat, movej, approach.
  const ProgramInput in{&p.points, &p.extrusion, &p.feedRate, &p.kind};
  std::ostringstream file;
  const ProgramStats stats =
      writeURScript(cell, rp, in, URScriptOptions{}, [&](size_t) -> std::ostream& { return file; });
  const std::string text = file.str();
  checkURScriptSyntax(text, "", 1000);
  const size_t comments = occurrences(text, "# reconfiguration between");
  const size_t movejs = occurrences(text, "movej("), movels = occurrences(text, "movel(");
  const size_t R = rp.reconfigurations.size();
  size_t detours = 0;  // joint-space waypoints of the joint moves
  for (const Reconfiguration& r : rp.reconfigurations)
    detours += r.through.size();
  EXPECT_EQ(comments, R);
  size_t airMoves = 0;  // each may start a program file: its joints are restated by a movej
  for (size_t i = 1; i < p.kind.size(); ++i)
    airMoves += p.kind[i] == 2 && p.kind[i - 1] != 2;
  EXPECT_EQ(movejs, R + detours + 1 + airMoves);  // and the start
  EXPECT_EQ(movels, p.points.size() - 1 + R);     // each replaces one movel by two
  EXPECT_EQ(stats.moves, p.points.size() - 1 + 2 * R + detours);
  // Its joint move goes to the retreat of the new configuration.
  std::ostringstream first;
  first << "movej([" << urNumber(rp.reconfigurations[0].retreatTo[0]) << ", ";
  EXPECT_NE(text.find(first.str()), std::string::npos);
}

TEST(RobotPathSolver, APathOneBranchFollowsKeepsItsPlan) {
  // A gentle tilt: steps 1-3 follow it; step 4 must not change a single joint value.
  const ConstructedPath p = abruptAirMoves(20);
  const RobotCell cell;
  const RobotPath a = solveWithOneBranch(cell, p);
  const RobotPath b = solveRobotPath(cell, p.points, p.normals, RobotPathOptions{}, p.kind);
  ASSERT_TRUE(a.largeSteps.empty());
  EXPECT_TRUE(b.reconfigurations.empty());
  EXPECT_EQ(a.joints, b.joints);
  EXPECT_EQ(a.psi, b.psi);
  // Without kinds there is no step 4 either.
  const RobotPath c = solveRobotPath(cell, p.points, p.normals);
  EXPECT_EQ(a.joints, c.joints);
}

TEST(RobotPathSolver, BadReconfigurationInput) {
  const ConstructedPath p = abruptAirMoves(20);
  const RobotCell cell;
  std::vector<int> shortKind(p.kind.begin(), p.kind.end() - 1);
  EXPECT_THROW(solveRobotPath(cell, p.points, p.normals, {}, shortKind), GeoLatticeError);
  RobotPathOptions o;
  o.maxRetreat = -1;
  EXPECT_THROW(solveRobotPath(cell, p.points, p.normals, o, p.kind), GeoLatticeError);
}

TEST(RobotPathSolver, TheResultDoesNotDependOnTheThreads) {
  // 70,000 points (more than two blocks of the fine pass) of a raster whose nozzle axis tilts
  // up to ~27 degrees and turns with z, and the reconfigured path: one worker and three workers
  // give the same joints, ψ, steps and reconfigurations, to the last bit.
  ConstructedPath raster;
  for (int i = 0; i < 70000; ++i) {
    const double z = 0.6 + 30.0 * i / 70000, tilt = 0.5 * std::sin(z / 10);
    raster.points.emplace_back(20 * std::sin(0.01 * i), std::fmod(0.0005 * i, 40.0) - 20.0, z);
    raster.normals.push_back(
        Eigen::Vector3d(tilt * std::cos(z / 7), tilt * std::sin(z / 7), 1).normalized());
    raster.kind.push_back(i % 5000 == 0 ? 2 : 0);
  }
  const RobotCell cell;
  for (const ConstructedPath& p : {raster, abruptAirMoves(100)}) {
    RobotPathOptions one, three;
    one.threads = 1;
    three.threads = 3;
    const RobotPath a = solveRobotPath(cell, p.points, p.normals, one, p.kind);
    const RobotPath b = solveRobotPath(cell, p.points, p.normals, three, p.kind);
    EXPECT_TRUE(a.unreachable.empty());
    EXPECT_EQ(a.joints, b.joints);
    EXPECT_EQ(a.psi, b.psi);
    EXPECT_EQ(a.branch, b.branch);
    EXPECT_EQ(a.largeSteps, b.largeSteps);
    EXPECT_EQ(a.maxJointStepDeg, b.maxJointStepDeg);
    ASSERT_EQ(a.reconfigurations.size(), b.reconfigurations.size());
    for (size_t k = 0; k < a.reconfigurations.size(); ++k) {
      EXPECT_EQ(a.reconfigurations[k].point, b.reconfigurations[k].point);
      EXPECT_EQ(a.reconfigurations[k].leave, b.reconfigurations[k].leave);
      EXPECT_EQ(a.reconfigurations[k].retreatTo, b.reconfigurations[k].retreatTo);
    }
  }
  RobotPathOptions bad;
  bad.threads = -1;
  EXPECT_THROW(solveRobotPath(cell, raster.points, raster.normals, bad), GeoLatticeError);
}

TEST(RobotPathSolver, ABoundThePathCannotKeepDoesNotGrowThePlan) {
  // A joint step bound of 0.001 degrees: nearly every step of a 20,000-point raster is above
  // it, and the part turns by more than that at every point (about 0.01 degrees), so no
  // waypoints between points can keep it either (StraightMove.h). Those are not flips that
  // denser samples remove; the refinement adds at most 4 · coarseSamples samples per pass (it
  // used to sample the whole path), and the steps stay reported for the caller to refuse.
  ConstructedPath raster;
  for (int i = 0; i < 20000; ++i) {
    const double z = 0.6 + 10.0 * i / 20000;
    raster.points.emplace_back(20 * std::sin(0.01 * i), std::fmod(0.0005 * i, 40.0) - 20.0, z);
    raster.normals.push_back(Eigen::Vector3d(0.3 * std::cos(z), 0.3 * std::sin(z), 1).normalized());
    raster.kind.push_back(i % 2000 == 0 ? 2 : 0);
  }
  RobotPathOptions o;
  o.maxJointStepDeg = 0.001;
  const RobotPath p = solveRobotPath(RobotCell{}, raster.points, raster.normals, o, raster.kind);
  EXPECT_GT(p.largeSteps.size(), 10000u);
  EXPECT_TRUE(p.reconfigurations.empty());
  // Passes that remove no tenth of the steps end the refinement long before its bound.
  EXPECT_LE(p.refinements, 4);
  EXPECT_LE(p.coarseSamples, 1 + o.coarseSamples + p.refinements * 5 * o.coarseSamples)
      << "refined " << p.refinements << " times";
}

namespace {

/// Laps of a circle (radius 10 mm, `perLap` points each, 0.5 mm higher every lap) whose nozzle
/// axes lean `tiltDeg` from +z towards the outside, joined by air moves up and down (or printed
/// in one run, `airBetween` false, with one air move at the end): the rim of a bowl printed
/// sideways. At 85° the part's z axis turns round through the horizontal once per lap and the
/// wrist passes near its singularity.
ConstructedPath sidewaysLaps(int laps, double tiltDeg, int perLap = 90, bool airBetween = true) {
  ConstructedPath p;
  const double tilt = tiltDeg * M_PI / 180;
  auto add = [&](const Eigen::Vector3d& x, const Eigen::Vector3d& n, int kind) {
    const double e = p.extrusion.empty() ? 0.0 : p.extrusion.back();
    const double len = p.points.empty() ? 0.0 : (x - p.points.back()).norm();
    p.points.push_back(x);
    p.normals.push_back(n);
    p.kind.push_back(kind);
    p.extrusion.push_back(kind == 2 ? e : e + 0.03 * len);
    p.feedRate.push_back(kind == 2 ? 50.0 : 20.0);
  };
  for (int lap = 0; lap < laps; ++lap) {
    for (int j = 0; j <= perLap; ++j) {
      const double phi = 2 * M_PI * j / perLap;
      add(Eigen::Vector3d(10 * std::cos(phi), 10 * std::sin(phi), 5 + 0.5 * lap),
          Eigen::Vector3d(std::sin(tilt) * std::cos(phi), std::sin(tilt) * std::sin(phi),
                          std::cos(tilt)),
          0);
    }
    const Eigen::Vector3d n = p.normals.back();
    for (int j = 1; j <= 10 && (airBetween || lap + 1 == laps); ++j) {
      add(p.points.back() + Eigen::Vector3d(0, 0, j <= 5 ? 3.0 : -2.5), n, 2);
      if (!airBetween && j == 1)
        p.extrusion.back() -= 1.0;  // the final air move retracts 1 mm of filament
    }
  }
  return p;
}

/// The movel targets of a program (TCP poses) and their times, in order.
std::vector<std::pair<Isometry, double>> movelTargets(const std::string& text) {
  std::vector<std::pair<Isometry, double>> targets;
  for (size_t at = text.find("movel(p["); at != std::string::npos;
       at = text.find("movel(p[", at + 1)) {
    UrPose pose{};
    double t = 0;
    const int read = std::sscanf(text.c_str() + at, "movel(p[%lf, %lf, %lf, %lf, %lf, %lf], t=%lf",
                                 &pose[0], &pose[1], &pose[2], &pose[3], &pose[4], &pose[5], &t);
    EXPECT_EQ(read, 7);
    targets.emplace_back(toIsometry(pose), t);
  }
  return targets;
}

}  // namespace

TEST(RobotPathSolver, SidewaysLapsPassTheWristSingularityWithWaypointsBetween) {
  const ConstructedPath p = sidewaysLaps(3, 85);
  // The cell before the tenth session (nozzle 300 mm up, the arm's distance to the nozzle and
  // to the part it holds not kept), where one configuration follows the laps: this test is
  // about the wrist, and the move count below assumes no change of configuration (keeping the
  // forearm off the nozzle takes two here, off the part none at all: TheArmIsKeptOff* test
  // those).
  RobotCell cell;
  cell.nozzleTip.z() = 0.30;
  RobotPathOptions o;
  o.linkNozzleClearance = 0;
  o.linkPartClearance = 0;
  const RobotPath rp = solveRobotPath(cell, p.points, p.normals, o, p.kind);
  size_t waypoints = 0;
  for (const WaypointsBetween& v : rp.via)
    waypoints += v.via.joints.size();
  std::printf(
      "[robot] 3 sideways laps: %zu large steps, %zu segments with %zu waypoints between, "
      "max step %.1f deg, |sin q5| >= %.3f, %zu reconfigurations\n",
      rp.largeSteps.size(), rp.via.size(), waypoints, rp.maxJointStepDeg, rp.minSingularity.wrist,
      rp.reconfigurations.size());
  ASSERT_TRUE(rp.works());
  EXPECT_LE(rp.maxJointStepDeg, o.maxJointStepDeg);
  // The laps do need them: without the waypoints these steps are above the bound.
  ASSERT_FALSE(rp.via.empty());
  for (const WaypointsBetween& v : rp.via) {
    const size_t i = static_cast<size_t>(v.point);
    double direct = 0;
    for (int j = 0; j < 6; ++j)
      direct = std::max(direct, std::abs(rp.joints[i][j] - jointsBefore(rp, i)[j]));
    EXPECT_GT(direct * 180 / M_PI, o.maxJointStepDeg) << "at point " << i;
    EXPECT_FALSE(v.via.joints.empty());
  }

  // The program as a controller runs it: follow its movel targets by the IK solution nearest
  // the joints before (the controller's tracking). Every step stays within the bound, every
  // joint within its speed limit at the written time, and the arm ends where the path ends.
  const ProgramInput in{&p.points, &p.extrusion, &p.feedRate, &p.kind};
  std::ostringstream file;
  const URScriptOptions uo;
  const ProgramStats stats =
      writeURScript(cell, rp, in, uo, [&](size_t) -> std::ostream& { return file; });
  const std::string text = file.str();
  checkURScriptSyntax(text, "", 1000);
  const auto targets = movelTargets(text);
  ASSERT_EQ(targets.size(), p.points.size() - 1 + waypoints);
  EXPECT_EQ(occurrences(text, " waypoint(s) between toolpath points "), rp.via.size());
  EXPECT_EQ(stats.moves, targets.size());
  JointVector q = rp.joints[0];
  double largest = 0, fastest = 0;
  for (const auto& [tcp, t] : targets) {
    const Isometry flange = tcp * cell.partOnFlange.inverse();
    double best = INFINITY;
    JointVector next{};
    for (const JointVector& s : inverseKinematics(cell.robot, flange, q[5])) {
      JointVector u;
      double d = 0;
      for (int j = 0; j < 6; ++j) {
        u[j] = q[j] + std::remainder(s[j] - q[j], 2 * M_PI);
        d = std::max(d, std::abs(u[j] - q[j]));
      }
      if (d < best) {
        best = d;
        next = u;
      }
    }
    ASSERT_TRUE(std::isfinite(best));
    largest = std::max(largest, best);
    for (int j = 0; j < 6; ++j)
      fastest = std::max(fastest, std::abs(next[j] - q[j]) / t / cell.robot.maxSpeed[j]);
    q = next;
  }
  EXPECT_LE(largest * 180 / M_PI, o.maxJointStepDeg + 0.01);
  EXPECT_LE(fastest, uo.speedFactor * 1.01);
  for (int j = 0; j < 6; ++j)
    EXPECT_NEAR(q[j], rp.joints.back()[j], 1e-4);
}

TEST(RobotPathSolver, LapsPrintedInOneRunChangeConfigurationAtSeams) {
  // Sideways laps (axes horizontal) without air moves between them: where the wrist swings
  // round near its singularity no air move is at hand, and one branch flips (two steps of about
  // 176 degrees before seams were allowed). Changes at seams: leave the point, change, come
  // back to the same point in the new configuration, print on.
  const ConstructedPath p = sidewaysLaps(3, 90, 100, false);
  const RobotCell cell;
  const RobotPathOptions o;
  const RobotPath rp = solveRobotPath(cell, p.points, p.normals, o, p.kind);
  std::vector<const Reconfiguration*> seams;
  for (const Reconfiguration& r : rp.reconfigurations)
    if (r.atSeam)
      seams.push_back(&r);
  std::printf(
      "[robot] 3 sideways laps in one run: %zu large steps, %zu reconfigurations, %zu at "
      "seams, max step %.1f deg\n",
      rp.largeSteps.size(), rp.reconfigurations.size(), seams.size(), rp.maxJointStepDeg);
  ASSERT_TRUE(rp.works());
  ASSERT_FALSE(seams.empty());
  for (const Reconfiguration* r : seams) {
    const size_t at = static_cast<size_t>(r->point);
    EXPECT_NE(p.kind[at + 1], 2) << "inside the print run";
    // The robot comes back to the point it left: the same part pose at the tip, other joints.
    const Isometry left = forwardKinematics(cell.robot, r->arrive) * cell.partOnFlange;
    const Isometry back = forwardKinematics(cell.robot, r->leave) * cell.partOnFlange;
    EXPECT_LT((left * (cell.partScale * p.points[at]) - cell.nozzleTip).norm(), 1e-6);
    EXPECT_LT((back * (cell.partScale * p.points[at]) - cell.nozzleTip).norm(), 1e-6);
    EXPECT_GT((back.linear().transpose() * (left.linear() * p.normals[at])).dot(p.normals[at]),
              1 - 1e-9);
    double step = 0;  // and prints on from there to the next point within the bound
    for (int j = 0; j < 6; ++j)
      step = std::max(step, std::abs(rp.joints[at + 1][j] - jointsBefore(rp, at + 1)[j]));
    EXPECT_LE(step * 180 / M_PI, o.maxJointStepDeg);
    EXPECT_EQ(&jointsBefore(rp, at + 1), &r->leave);
  }

  // The program: at a seam the extruder stops and retracts as at the air moves (1 mm here),
  // the part moves away and back, primes, and the segment to the next point is printed.
  const ProgramInput in{&p.points, &p.extrusion, &p.feedRate, &p.kind};
  std::ostringstream file;
  writeURScript(cell, rp, in, URScriptOptions{}, [&](size_t) -> std::ostream& { return file; });
  const std::string text = file.str();
  checkURScriptSyntax(text, "", 1000);
  for (const Reconfiguration* r : seams) {
    const std::string head = "# reconfiguration at a seam at toolpath points " +
                             std::to_string(r->point) + " and " + std::to_string(r->point + 1);
    const size_t at = text.find(head);
    ASSERT_NE(at, std::string::npos) << head;
    const size_t retract = text.find("# retract 1 mm of filament", at);
    const size_t movej = text.find("movej(", at);
    const size_t prime = text.find("# prime 1 mm of filament", at);
    const size_t extrude = text.find("set_standard_analog_out(0, 0.", at);
    ASSERT_NE(extrude, std::string::npos);
    EXPECT_LT(retract, movej);
    EXPECT_LT(movej, prime);
    EXPECT_LT(prime, extrude);
    // After the extruder is on again, the next move is the print move to point + 1.
    UrPose pose{};
    ASSERT_EQ(std::sscanf(text.c_str() + text.find("movel(p[", extrude),
                          "movel(p[%lf, %lf, %lf, %lf, %lf, %lf]", &pose[0], &pose[1], &pose[2],
                          &pose[3], &pose[4], &pose[5]),
              6);
    const Isometry next =
        forwardKinematics(cell.robot, rp.joints[r->point + 1]) * cell.partOnFlange;
    EXPECT_LT((toIsometry(pose).translation() - next.translation()).norm(), 1e-5);
  }
}

namespace {

/// The least distance of the surfaces of the arm's parts near the nozzle (base to wrist 1) from
/// the nozzle's axis segment over the path, by sampling each capsule's segment every mm.
double sampledLinkNozzleDistance(const RobotCell& cell, const RobotPath& path, double length) {
  double least = 1e9;
  const Eigen::Vector3d a = cell.nozzleTip, b = cell.nozzleTip + length * cell.nozzleAxis;
  for (const JointVector& q : path.joints) {
    const ArmCapsules arm = armCapsules(cell.robot, q);
    for (int part = kFirstNearNozzle; part <= kLastNearNozzle; ++part) {
      const Capsule& c = arm[part];
      const int n = 1 + static_cast<int>((c.b - c.a).norm() / 0.001);
      for (int k = 0; k <= n; ++k) {
        const Eigen::Vector3d x = c.a + (c.b - c.a) * (static_cast<double>(k) / n);
        const double t = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
        least = std::min(least, (x - (a + t * (b - a))).norm() - c.radius);
      }
    }
  }
  return least;
}

}  // namespace

TEST(RobotPathSolver, TheArmIsKeptOffTheNozzle) {
  // A ring printed with the nozzle axis leaning 70 degrees outwards, the nozzle 300 mm up (the
  // default cell before the tenth session): the forearm of the plan chosen without the
  // constraint passes through the nozzle's axis above the tip; with it (the default), the
  // solver keeps the arm's surfaces 35 mm off.
  RobotCell cell;
  cell.nozzleTip.z() = 0.30;
  std::vector<Eigen::Vector3d> points, normals;
  for (int k = 0; k < 720; ++k) {
    const double a = k * M_PI / 360, tilt = 70 * M_PI / 180;
    points.emplace_back(20 * std::cos(a), 20 * std::sin(a), 10);
    normals.emplace_back(std::sin(tilt) * std::cos(a), std::sin(tilt) * std::sin(a),
                         std::cos(tilt));
  }
  RobotPathOptions o;
  EXPECT_EQ(o.linkNozzleClearance, kLinkNozzleSafeDistance);
  o.linkPartClearance = 0;    // the nozzle alone (TheArmIsKeptOffThePartItHolds: the part)
  o.linkNozzleClearance = 0;  // measured only
  const RobotPath free = solveRobotPath(cell, points, normals, o);
  ASSERT_TRUE(free.works());
  EXPECT_LT(free.minLinkNozzleDistance, 0.01);
  EXPECT_NEAR(free.minLinkNozzleDistance, sampledLinkNozzleDistance(cell, free, o.nozzleLength),
              1e-3);
  o.linkNozzleClearance = kLinkNozzleSafeDistance;
  const RobotPath kept = solveRobotPath(cell, points, normals, o);
  ASSERT_TRUE(kept.works());
  EXPECT_GE(kept.minLinkNozzleDistance, kLinkNozzleSafeDistance);
  EXPECT_GE(sampledLinkNozzleDistance(cell, kept, o.nozzleLength), kLinkNozzleSafeDistance - 1e-3);
}
