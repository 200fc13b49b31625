#include "program/URScriptWriter.h"

#include "common/Error.h"
#include "common/FixedNumber.h"
#include "common/ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace geolattice {

std::string urNumber(double v) {
  return fixedNumber(v, 6);
}

namespace {

/// "IK branch a -> b"; for a change within one branch (step 4 of the path solver turns a
/// joint wound to its limit back at an air move) "IK branch a kept, joint j turned back a
/// full turn".
std::string describeChange(const Reconfiguration& r) {
  if (r.fromBranch != r.toBranch || r.atSeam)
    return "IK branch " + std::to_string(r.fromBranch) + " -> " + std::to_string(r.toBranch);
  int turned = 0;
  for (int j = 1; j < 6; ++j)
    if (std::abs(r.retreatTo[j] - r.retreatFrom[j]) >
        std::abs(r.retreatTo[turned] - r.retreatFrom[turned]))
      turned = j;
  return "IK branch " + std::to_string(r.fromBranch) + " kept, joint " +
         std::to_string(turned + 1) + " turned back a full turn";
}

constexpr double kReconfigurationSpeed = 0.5;         ///< rad/s of the leading joint (movej v)
constexpr double kReconfigurationAcceleration = 1.0;  ///< rad/s² (movej a)

/// Appends the pose literal p[x, y, z, rx, ry, rz] of t.
void appendPose(std::string& s, const Isometry& t) {
  const UrPose p = toUrPose(t);
  s += "p[";
  for (int i = 0; i < 6; ++i) {
    appendFixed(s, p[i], 6);
    s += i < 5 ? ", " : "]";
  }
}

/// Appends "movej([q0, …, q5], a=…, v=…)" with q in rad.
void appendMovej(std::string& s, const JointVector& q, const char* speeds) {
  s += "  movej([";
  for (int j = 0; j < 6; ++j) {
    appendFixed(s, q[j], 6);
    s += j < 5 ? ", " : "]";
  }
  s += speeds;
}

/// The longest line of text (without its newline).
size_t longestLine(const std::string& text) {
  size_t longest = 0, start = 0;
  for (size_t end = text.find('\n'); start < text.size(); end = text.find('\n', start)) {
    const size_t stop = end == std::string::npos ? text.size() : end;
    longest = std::max(longest, stop - start);
    start = stop + 1;
  }
  return longest;
}

}  // namespace

ProgramStats writeURScript(const RobotCell& cell, const RobotPath& rp, const ProgramInput& in,
                           const URScriptOptions& o,
                           const std::function<std::ostream&(size_t)>& openFile) {
  if (!in.points || !in.extrusion || !in.feedRate || !in.kind) {
    throw GeoLatticeError("URScript: toolpath arrays missing");
  }
  const size_t N = in.points->size();
  if (N == 0) {
    throw GeoLatticeError("URScript: the toolpath is empty");
  }
  if (rp.joints.size() != N || in.extrusion->size() != N || in.feedRate->size() != N ||
      in.kind->size() != N) {
    throw GeoLatticeError("URScript: toolpath arrays and joint solutions differ in length");
  }
  if (!(o.speedFactor > 0 && o.speedFactor <= 1) || !(o.maxFilamentRate > 0) ||
      !(o.blendFraction >= 0) || o.maxFileBytes < 10000) {
    throw GeoLatticeError(
        "URScript: bad options (speed factor in (0, 1], max filament rate > 0, file size >= 10 "
        "kB)");
  }
  const auto& pts = *in.points;
  const auto& kind = *in.kind;
  const RobotModel& robot = cell.robot;
  // TCP (part frame) poses and segment times.
  std::vector<Isometry> tcp(N);
  constexpr size_t kChunk = 8192;
  parallelFor((N + kChunk - 1) / kChunk, 0, [&](size_t c, int) {
    for (size_t i = c * kChunk; i < std::min(N, (c + 1) * kChunk); ++i)
      tcp[i] = forwardKinematics(robot, rp.joints[i]) * cell.partOnFlange;
  });
  ProgramStats stats;
  // Waypoints between points (RobotPath::via): where they are, their TCP poses.
  std::vector<int> viaAt(N, -1);
  std::vector<std::vector<Isometry>> viaTcp(rp.via.size());
  for (size_t k = 0; k < rp.via.size(); ++k) {
    const size_t i = static_cast<size_t>(rp.via[k].point);
    if (i == 0 || i >= N || rp.via[k].via.t.size() != rp.via[k].via.joints.size()) {
      throw GeoLatticeError("URScript: waypoints between points outside the toolpath");
    }
    viaAt[i] = static_cast<int>(k);
    for (const JointVector& q : rp.via[k].via.joints)
      viaTcp[k].push_back(forwardKinematics(robot, q) * cell.partOnFlange);
  }
  // Segment times: each straight move (to a waypoint between points or to the point) takes the
  // longer of its share of the segment at the feed rate and its largest joint change at the
  // joint speed limit; time[i] is their sum.
  std::vector<double> time(N, 0.0), lastMove(N, 0.0);  // lastMove: the move onto point i
  std::vector<std::vector<double>> viaTime(rp.via.size());
  for (size_t i = 1; i < N; ++i) {
    const double len = (pts[i] - pts[i - 1]).norm();
    const double feed = (*in.feedRate)[i];
    auto moveTime = [&](const JointVector& a, const JointVector& b, double share) {
      double t = feed > 0 ? share * len / feed : 0.0;
      for (int j = 0; j < 6; ++j)
        t = std::max(t, std::abs(b[j] - a[j]) / (o.speedFactor * robot.maxSpeed[j]));
      t = std::max(t, 0.002);  // one controller cycle at least
      for (int j = 0; j < 6; ++j)
        stats.maxJointSpeedDegS =
            std::max(stats.maxJointSpeedDegS, std::abs(b[j] - a[j]) / t * 180 / M_PI);
      return t;
    };
    const JointVector* from = &jointsBefore(rp, i);
    double t0 = 0;
    if (viaAt[i] >= 0) {
      const StraightMoveVia& v = rp.via[static_cast<size_t>(viaAt[i])].via;
      for (size_t k = 0; k < v.joints.size(); ++k) {
        const double t = moveTime(*from, v.joints[k], v.t[k] - t0);
        viaTime[static_cast<size_t>(viaAt[i])].push_back(t);
        time[i] += t;
        from = &v.joints[k];
        t0 = v.t[k];
      }
    }
    lastMove[i] = moveTime(*from, rp.joints[i], 1 - t0);
    time[i] += lastMove[i];
    stats.duration += time[i];
  }
  // TCP positions of the straight moves next to point i (a waypoint between points, if any).
  auto tcpBefore = [&](size_t i) -> const Isometry& {
    return viaAt[i] >= 0 ? viaTcp[static_cast<size_t>(viaAt[i])].back() : tcp[i - 1];
  };
  auto tcpAfter = [&](size_t i) -> const Isometry& {
    return viaAt[i + 1] >= 0 ? viaTcp[static_cast<size_t>(viaAt[i + 1])].front() : tcp[i + 1];
  };
  auto blendAt = [&](const Eigen::Vector3d& before, const Eigen::Vector3d& here,
                     const Eigen::Vector3d& after) {
    return std::min(o.maxBlend,
                    o.blendFraction * std::min((here - before).norm(), (after - here).norm()));
  };
  auto appendMovel = [&](std::string& out, const Isometry& pose, double t, double blend) {
    out += "  movel(";
    appendPose(out, pose);
    out += ", t=";
    appendFixed(out, t, 6);
    out += ", r=";
    appendFixed(out, blend, 6);
    out += ")\n";
    ++stats.moves;
  };
  // A reconfiguration (RobotPathSolver.h, step 4): away from the part in a straight line, a
  // joint move, the approach to the next point along its nozzle axis; no extrusion.
  double slowest = robot.maxSpeed[0];
  for (int j = 1; j < 6; ++j)
    slowest = std::min(slowest, robot.maxSpeed[j]);
  const double jointSpeed = std::min(kReconfigurationSpeed, o.speedFactor * slowest);
  auto lineTime = [&](const JointVector& a, const JointVector& b, double length, double feed) {
    double t = feed > 0 ? length / (feed * cell.partScale) : 0.0;
    for (int j = 0; j < 6; ++j)
      t = std::max(t, std::abs(b[j] - a[j]) / (o.speedFactor * robot.maxSpeed[j]));
    return std::max(t, 0.002);
  };
  // An extruder move while the robot waits: a retraction (de < 0) or a prime.
  auto appendFilamentMove = [&](std::string& out, double de) {
    out += de < 0 ? "  # retract " : "  # prime ";
    appendFixed(out, std::abs(de), 6);
    out += " mm of filament\n  sleep(";
    appendFixed(out, std::abs(de) / o.retractionRate, 6);
    out += ")\n";
  };
  // A seam (a reconfiguration inside a print stretch) retracts and primes as the toolpath's
  // air moves do: by the largest retraction found at them.
  double seamRetraction = 0;
  for (size_t i = 1; i < N; ++i)
    if (kind[i] == 2)
      seamRetraction = std::max(seamRetraction, (*in.extrusion)[i - 1] - (*in.extrusion)[i]);
  auto reconfiguration = [&](const Reconfiguration& r, std::string& out) {
    const double feed = (*in.feedRate)[static_cast<size_t>(r.point)];
    const double away = lineTime(r.arrive, r.retreatFrom, r.retreat, feed);
    const double back = lineTime(r.retreatTo, r.leave, r.retreat, feed);
    out += "  # reconfiguration " + std::string(r.atSeam ? "at a seam at" : "between") +
           " toolpath points " + std::to_string(r.point) + " and " + std::to_string(r.point + 1) +
           ": " + describeChange(r) + ", " + urNumber(1000 * r.retreat) +
           " mm away from the nozzle, joint move clear of it by " + urNumber(1000 * r.clearance) +
           " mm" + (r.atSeam ? "; the print goes on from point " + std::to_string(r.point) : "") +
           "\n";
    out += "  set_standard_analog_out(0, 0)\n";
    if (r.atSeam && seamRetraction > 0) {
      appendFilamentMove(out, -seamRetraction);
      stats.duration += 2 * seamRetraction / o.retractionRate;
    }
    out += "  movel(";
    appendPose(out, forwardKinematics(robot, r.retreatFrom) * cell.partOnFlange);
    out += ", t=" + urNumber(away) + ", r=0)\n";
    const std::string movejTail =
        ", a=" + urNumber(kReconfigurationAcceleration) + ", v=" + urNumber(jointSpeed) + ")\n";
    const JointVector* from = &r.retreatFrom;
    auto jointMove = [&](const JointVector& to) {
      appendMovej(out, to, movejTail.c_str());
      double largest = 0;
      for (int j = 0; j < 6; ++j)
        largest = std::max(largest, std::abs(to[j] - (*from)[j]));
      stats.duration += largest / jointSpeed + jointSpeed / kReconfigurationAcceleration;
      ++stats.moves;
      from = &to;
    };
    for (const JointVector& q : r.through)
      jointMove(q);
    jointMove(r.retreatTo);
    out += "  movel(";
    appendPose(out, forwardKinematics(robot, r.leave) * cell.partOnFlange);
    out += ", t=" + urNumber(back) + ", r=0)\n";
    if (r.atSeam && seamRetraction > 0)
      appendFilamentMove(out, seamRetraction);
    stats.moves += 2;
    stats.duration += away + back;
  };
  auto nextReconfiguration = rp.reconfigurations.begin();

  // Moves as chunks that start at an air move (the only places a program may end), packed into
  // files below the size limit.
  std::vector<std::string> chunks;
  std::string chunk;
  double previousRate = 0;
  for (size_t i = 1; i < N; ++i) {
    const bool air = kind[i] == 2;
    if (air && kind[i - 1] != 2 && !chunk.empty()) {
      chunks.push_back(std::move(chunk));
      chunk.clear();
      // A new program may start here: restate the joints and the analog output.
      appendMovej(chunk, jointsBefore(rp, i), ", a=0.5, v=0.2)\n");
      previousRate = -1;
    }
    while (nextReconfiguration != rp.reconfigurations.end() &&
           nextReconfiguration->point < static_cast<int>(i) - 1)
      ++nextReconfiguration;
    if (nextReconfiguration != rp.reconfigurations.end() &&
        nextReconfiguration->point == static_cast<int>(i) - 1) {
      reconfiguration(*nextReconfiguration, chunk);  // it ends at point i, or i - 1 at a seam
      previousRate = 0;
      if (!nextReconfiguration->atSeam)
        continue;
    }
    const double de = (*in.extrusion)[i] - (*in.extrusion)[i - 1];
    const double rate = air ? 0.0 : de / time[i];
    if (air && de != 0) {  // retraction / prime
      chunk += "  set_standard_analog_out(0, 0)\n";
      appendFilamentMove(chunk, de);
      previousRate = 0;
    }
    const double volts = std::clamp(rate / o.maxFilamentRate, 0.0, 1.0);
    if (std::abs(volts - previousRate) > 1e-6) {
      chunk += "  set_standard_analog_out(0, ";  // relative level 0..1
      appendFixed(chunk, volts, 6);
      chunk += ")\n";
      previousRate = volts;
    }
    if (viaAt[i] >= 0) {  // waypoints between points: blended, at the segment's extrusion level
      const size_t k = static_cast<size_t>(viaAt[i]);
      const std::vector<Isometry>& poses = viaTcp[k];
      chunk += "  # " + std::to_string(poses.size()) + " waypoint(s) between toolpath points " +
               std::to_string(i - 1) + " and " + std::to_string(i) +
               " (the wrist near its singularity)\n";
      for (size_t j = 0; j < poses.size(); ++j) {
        const Isometry& before = j > 0 ? poses[j - 1] : tcp[i - 1];
        const Isometry& after = j + 1 < poses.size() ? poses[j + 1] : tcp[i];
        appendMovel(chunk, poses[j], viaTime[k][j],
                    blendAt(before.translation(), poses[j].translation(), after.translation()));
      }
    }
    // Blend: 0 where the kind changes or at the path's ends.
    double blend = 0;
    if (i + 1 < N && kind[i + 1] == kind[i] && kind[i - 1] == kind[i]) {
      blend = blendAt(tcpBefore(i).translation(), tcp[i].translation(), tcpAfter(i).translation());
    }
    appendMovel(chunk, tcp[i], lastMove[i], blend);
  }
  chunks.push_back(std::move(chunk));

  size_t file = 0;
  std::string body;
  auto flush = [&]() {
    std::ostringstream head;
    head << "def " << o.programName << (file > 0 ? "_" + std::to_string(file) : std::string())
         << "():\n";
    head << "  # GeoLattice multi-axis print, program " << file + 1
         << "; the robot holds the part under a fixed nozzle\n";
    for (const std::string& line : o.headerComments) {
      head << "  # " << line << "\n";
    }
    std::string tcpPose;
    appendPose(tcpPose, cell.partOnFlange);
    head << "  set_tcp(" << tcpPose << ")\n";
    head << "  # analog out 0 drives the extruder: level 0..1 (0-10 V) = 0-"
         << urNumber(o.maxFilamentRate) << " mm/s of filament\n";
    head << "  set_standard_analog_out(0, 0)\n";
    if (file == 0) {
      head << "  movej([";
      for (int j = 0; j < 6; ++j)
        head << urNumber(rp.joints[0][j]) << (j < 5 ? ", " : "]");
      head << ", a=0.5, v=0.2)\n";
    }
    const std::string text = head.str() + body + "  set_standard_analog_out(0, 0)\nend\n";
    openFile(file) << text;
    stats.maxLineLength = std::max(stats.maxLineLength, longestLine(text));
    body.clear();
    ++file;
  };
  constexpr size_t kFrame = 600;  // header and footer
  for (const std::string& c : chunks) {
    if (c.size() + kFrame > o.maxFileBytes) {
      std::ostringstream m;
      m << "URScript: one print run between air moves needs " << c.size()
        << " bytes, more than the file size limit " << o.maxFileBytes << "; raise the limit";
      throw GeoLatticeError(m.str());
    }
    if (!body.empty() && body.size() + c.size() + kFrame > o.maxFileBytes) {
      flush();
    }
    body += c;
  }
  flush();
  stats.files = file;
  return stats;
}

}  // namespace geolattice
