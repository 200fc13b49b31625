// Robot program generation at scale: 1 million toolpath waypoints (a 40 mm part's worth of
// raster layers with tilting nozzle axes) through the UR5 cell's path solver (free rotation
// optimised along the path, IK at every point) and the URScript writer (split files), plus the
// 5-axis G-code writer. Run: build/bin/bench_program
#include "program/GCodeWriter.h"
#include "program/URScriptWriter.h"
#include "robot/RobotPathSolver.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <sstream>

using namespace geolattice;

namespace {

struct Path {
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<double> extrusion, feed;
  std::vector<int> kind, layer;
};

const Path& spiral() {
  static const Path p = [] {
    Path r;
    const int n = 1000000;
    double e = 0;
    for (int i = 0; i < n; ++i) {
      const double z = 0.6 + 40.0 * i / n;
      const double tilt =
          0.5 * std::sin(z / 10);  // up to ~27° of nozzle tilt, turning slowly with z
      // Raster: 0.2 mm steps back and forth along x, rows 1 mm apart, ~33 layers of 30 000 points.
      r.points.push_back(
          Eigen::Vector3d(20 * std::sin(0.01 * i), std::fmod(0.0005 * i, 40.0) - 20.0, z));
      r.normals.push_back(
          Eigen::Vector3d(tilt * std::cos(z / 7), tilt * std::sin(z / 7), 1).normalized());
      const bool air = i % 5000 == 0;
      e += air ? 0 : 0.01;
      r.extrusion.push_back(e);
      r.feed.push_back(air ? 50 : 10);
      r.kind.push_back(air ? 2 : 0);
      r.layer.push_back(static_cast<int>(z / 0.6));
    }
    return r;
  }();
  return p;
}

class NullBuffer : public std::streambuf {
protected:
  int overflow(int c) override { return c; }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

/// The path solver and the URScript writer (to a null stream) on p; withKinds: the solver gets
/// the move kinds (reconfigurations at air moves where one branch cannot follow).
ProgramStats solveAndWrite(const Path& p, bool withKinds, RobotPath& rp) {
  const RobotCell cell;
  NullBuffer nb;
  std::ostream sink(&nb);
  rp = withKinds ? solveRobotPath(cell, p.points, p.normals, RobotPathOptions{}, p.kind)
                 : solveRobotPath(cell, p.points, p.normals);
  const ProgramInput in{&p.points, &p.extrusion, &p.feed, &p.kind};
  return writeURScript(cell, rp, in, URScriptOptions{},
                       [&](size_t) -> std::ostream& { return sink; });
}

void BM_IkAndURScript(benchmark::State& state) {
  const Path& p = spiral();
  ProgramStats stats;
  RobotPath rp;
  for (auto _ : state) {
    stats = solveAndWrite(p, false, rp);
  }
  state.counters["waypoints"] = static_cast<double>(p.points.size());
  state.counters["unreachable"] = static_cast<double>(rp.unreachable.size());
  state.counters["files"] = static_cast<double>(stats.files);
  state.counters["max_joint_step_deg"] = rp.maxJointStepDeg;
}
BENCHMARK(BM_IkAndURScript)->Unit(benchmark::kMillisecond)->Iterations(1);

/// 400 laps of 90 points (radius 10 mm, 4° of axis turn per point, 0.05 mm higher each lap) whose nozzle axes lean 85°
/// outwards, air moves between laps: the wrist passes near its singularity twice a lap, and
/// the moves there get waypoints between points (core/robot/StraightMove.h).
const Path& sidewaysLaps() {
  static const Path p = [] {
    Path r;
    const double tilt = 85 * M_PI / 180;
    double e = 0;
    for (int lap = 0; lap < 400; ++lap) {
      for (int j = 0; j <= 90; ++j) {
        const double phi = 2 * M_PI * j / 90;
        r.points.emplace_back(10 * std::cos(phi), 10 * std::sin(phi), 5 + 0.05 * lap);
        r.normals.emplace_back(std::sin(tilt) * std::cos(phi), std::sin(tilt) * std::sin(phi),
                               std::cos(tilt));
        e += j > 0 ? 0.02 : 0;
        r.extrusion.push_back(e);
        r.feed.push_back(10);
        r.kind.push_back(0);
        r.layer.push_back(lap);
      }
      for (int j = 1; j <= 10; ++j) {
        r.points.push_back(r.points.back() + Eigen::Vector3d(0, 0, j <= 5 ? 3.0 : -2.9));
        r.normals.push_back(r.normals.back());
        r.extrusion.push_back(e);
        r.feed.push_back(50);
        r.kind.push_back(2);
        r.layer.push_back(-1);
      }
    }
    return r;
  }();
  return p;
}

void BM_SidewaysLapsAndURScript(benchmark::State& state) {
  const Path& p = sidewaysLaps();
  RobotPath rp;
  for (auto _ : state) {
    benchmark::DoNotOptimize(solveAndWrite(p, true, rp).moves);
  }
  size_t waypoints = 0;
  for (const WaypointsBetween& v : rp.via)
    waypoints += v.via.joints.size();
  state.counters["points"] = static_cast<double>(p.points.size());
  state.counters["large_steps"] = static_cast<double>(rp.largeSteps.size());
  state.counters["via_segments"] = static_cast<double>(rp.via.size());
  state.counters["via_waypoints"] = static_cast<double>(waypoints);
  state.counters["reconfigurations"] = static_cast<double>(rp.reconfigurations.size());
  state.counters["max_joint_step_deg"] = rp.maxJointStepDeg;
}
BENCHMARK(BM_SidewaysLapsAndURScript)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_GCodeWriter(benchmark::State& state) {
  const Path& p = spiral();
  NullBuffer nb;
  std::ostream sink(&nb);
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        writeGCode(p.points, p.normals, p.extrusion, p.feed, p.kind, GCodeOptions{}, sink).moves);
  }
}
BENCHMARK(BM_GCodeWriter)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
