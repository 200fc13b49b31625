#include "program/GCodeWriter.h"

#include "common/Error.h"
#include "common/FixedNumber.h"
#include <cstdio>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace geolattice {

namespace {

constexpr double kDeg = 180.0 / M_PI;

double unwrapNear(double angle, double near) {
  return near + std::remainder(angle - near, 360.0);
}

Eigen::Matrix3d tiltMatrix(TableKinematics k, double tiltDeg) {
  return Eigen::AngleAxisd(tiltDeg / kDeg, k == TableKinematics::AC ? Eigen::Vector3d::UnitX()
                                                                    : Eigen::Vector3d::UnitY())
      .toRotationMatrix();
}

}  // namespace

void tableAngles(TableKinematics k, const Eigen::Vector3d& nIn, double previousC,
                 double poleToleranceDeg, double& tilt, double& c) {
  const Eigen::Vector3d n = nIn.normalized();
  const double rho = std::hypot(n.x(), n.y());
  double c1 =
      k == TableKinematics::AC ? std::atan2(n.x(), n.y()) * kDeg : std::atan2(-n.y(), n.x()) * kDeg;
  double t1 =
      k == TableKinematics::AC ? std::atan2(rho, n.z()) * kDeg : std::atan2(-rho, n.z()) * kDeg;
  if (std::abs(t1) < poleToleranceDeg || rho == 0) {
    tilt = t1;
    c = previousC;  // pole: keep C
    return;
  }
  const double c2 = c1 + 180.0, t2 = -t1;
  c1 = unwrapNear(c1, previousC);
  const double c2u = unwrapNear(c2, previousC);
  if (std::abs(c1 - previousC) <= std::abs(c2u - previousC)) {
    tilt = t1;
    c = c1;
  } else {
    tilt = t2;
    c = c2u;
  }
}

GCodeFlavor parseGCodeFlavor(const std::string& name) {
  if (name == "linuxcnc") {
    return GCodeFlavor::LinuxCNC;
  }
  if (name == "reprap") {
    return GCodeFlavor::RepRap;
  }
  throw GeoLatticeError("G-code flavor must be linuxcnc or reprap (got '" + name + "')");
}

const char* gcodeFlavorName(GCodeFlavor f) {
  return f == GCodeFlavor::RepRap ? "reprap" : "linuxcnc";
}

ToolCentrePoint parseToolCentrePoint(const std::string& name) {
  if (name == "controller") {
    return ToolCentrePoint::Controller;
  }
  if (name == "cam") {
    return ToolCentrePoint::Cam;
  }
  throw GeoLatticeError("the tool centre point must be controller or cam (got '" + name + "')");
}

const char* toolCentrePointName(ToolCentrePoint t) {
  return t == ToolCentrePoint::Cam ? "cam" : "controller";
}

void GCodeOptions::validate() const {
  const char tilt = kinematics == TableKinematics::AC ? 'A' : 'B';
  const char freeRotary = kinematics == TableKinematics::AC ? 'B' : 'A';
  if (flavor == GCodeFlavor::LinuxCNC) {
    const char e = extrusionAxis;
    if (e == 'X' || e == 'Y' || e == 'Z' || e == tilt || e == 'C') {
      throw GeoLatticeError(std::string("G-code: the extrusion axis ") + e +
                            " is a motion axis of the " +
                            (kinematics == TableKinematics::AC ? "A-C" : "B-C") +
                            " table; use U, V, W or " + freeRotary);
    }
    if (e != 'U' && e != 'V' && e != 'W' && e != freeRotary) {
      throw GeoLatticeError(std::string("G-code: the extrusion axis must be U, V, W or ") +
                            freeRotary + " (got '" + std::string(1, e) + "')");
    }
  }
  if (flavor == GCodeFlavor::RepRap && toolCentrePoint == ToolCentrePoint::Controller) {
    throw GeoLatticeError(
        "G-code: RepRapFirmware has no tilting-table kinematics: the reprap flavor needs the tool "
        "centre point from the CAM (cam)");
  }
  if (!(tiltMinDeg < tiltMaxDeg)) {
    throw GeoLatticeError("G-code: the tilt limits must be MIN < MAX (got " +
                          std::to_string(tiltMinDeg) + ", " + std::to_string(tiltMaxDeg) + ")");
  }
  if (!(retractionSeconds > 0) || !pivot.allFinite() || !partOffset.allFinite()) {
    throw GeoLatticeError(
        "G-code: the pivot and part offset must be finite and the retraction "
        "time > 0");
  }
}

namespace {

/// "(text)" for LinuxCNC (no parentheses inside: "Nested comment found"), "; text" for RRF.
std::string comment(GCodeFlavor f, std::string text) {
  if (f == GCodeFlavor::RepRap) {
    return "; " + text;
  }
  for (char& c : text) {
    if (c == '(' || c == ')') {
      c = c == '(' ? '[' : ']';
    }
  }
  return "(" + text + ")";
}

}  // namespace

GCodeStats writeGCode(const std::vector<Eigen::Vector3d>& points,
                      const std::vector<Eigen::Vector3d>& normals,
                      const std::vector<double>& extrusion, const std::vector<double>& feedRate,
                      const std::vector<int>& kind, const GCodeOptions& o, std::ostream& out) {
  const size_t N = points.size();
  if (N == 0) {
    throw GeoLatticeError("G-code: the toolpath is empty");
  }
  if (normals.size() != N || extrusion.size() != N || feedRate.size() != N || kind.size() != N) {
    throw GeoLatticeError("G-code: toolpath arrays differ in length");
  }
  o.validate();
  const char tiltAxis = o.kinematics == TableKinematics::AC ? 'A' : 'B';
  const bool linuxcnc = o.flavor == GCodeFlavor::LinuxCNC;
  const bool controller = o.toolCentrePoint == ToolCentrePoint::Controller;
  const std::string table = o.kinematics == TableKinematics::AC ? "A-C" : "B-C";
  const GCodeFlavor f = o.flavor;
  out << comment(f, "GeoLattice 5-axis print, " + table +
                        " tilting-rotary table, fixed vertical nozzle")
      << '\n';
  if (linuxcnc) {
    out << comment(f, std::string("LinuxCNC RS274NGC, extruder on axis ") + o.extrusionAxis +
                          " (absolute filament mm), inverse-time feed G93")
        << '\n';
    out << comment(f,
                   controller
                       ? "tool centre point: the controller (" +
                             std::string(o.kinematics == TableKinematics::AC ? "xyzac" : "xyzbc") +
                             "-trt-kins); X Y Z are part coordinates, see machines/linuxcnc/"
                       : "tool centre point: pre-computed (trivial kinematics); X Y Z are machine "
                         "coordinates")
        << '\n';
    out << "G21 G90 G93\n";
  } else {
    out << comment(f, std::string("RepRapFirmware 3: axes X Y Z ") + tiltAxis +
                          " C (configure the rotary axes with M584 ... R1), relative extrusion E, "
                          "feed mm/min; tool centre point pre-computed; not machine-verified")
        << '\n';
    out << "G21\nG90\nM83\nG92 E0\n";
  }
  GCodeStats stats;
  // Pass 1: angles per point; points at the pole (C undefined) are marked.
  std::vector<double> tilts(N), cs(N);
  std::vector<char> pole(N, 0);
  double previousC = 0;
  for (size_t i = 0; i < N; ++i) {
    if (!points[i].allFinite() || !normals[i].allFinite() || !(normals[i].norm() > 0)) {
      throw GeoLatticeError("G-code: toolpath point " + std::to_string(i) +
                            " has a NaN position or normal");
    }
    double tilt = 0, c = 0;
    tableAngles(o.kinematics, normals[i], previousC, o.poleToleranceDeg, tilt, c);
    pole[i] = std::abs(tilt) < o.poleToleranceDeg;
    if (tilt < o.tiltMinDeg || tilt > o.tiltMaxDeg) {
      // The other branch (c + 180, -tilt) may be inside the limits.
      const double c2 = unwrapNear(c + 180.0, previousC), t2 = -tilt;
      if (t2 >= o.tiltMinDeg && t2 <= o.tiltMaxDeg) {
        tilt = t2;
        c = c2;
        ++stats.branchFlips;
      } else {
        ++stats.outOfLimits;
      }
    }
    tilts[i] = tilt;
    cs[i] = c;
    previousC = c;
  }
  // Near the pole C is ill-conditioned: a 1° tilt in a new direction asks for any C. C may
  // deviate from the exact value by δ_i as long as the axis error stays within the tolerance
  // (a C off by δ leaves the axis asin(sin θ · sin δ) out of the tilt plane, θ = |tilt|; the tilt
  // is then re-optimised for that C). Among the C sequences inside these tubes, a forward pass
  // of reachable intervals with the rotary step bound r and a backward pass that moves C as
  // little as possible pick one that turns at most r per point wherever that is possible at all.
  const double tol = o.axisToleranceDeg / kDeg, r = o.maxRotaryStepDeg;
  const double any = 1e12;  // a tube that allows every C
  std::vector<double> lo(N), hi(N),
      ref(N);                      // reachable C interval, a C inside it near the exact one
  std::vector<char> forced(N, 0);  // the tube is beyond r: C turns faster here
  for (size_t i = 0; i < N; ++i) {
    const double sinTheta =
        std::sin(std::min(std::abs(tilts[i]), 180.0 - std::abs(tilts[i])) / kDeg);
    const double delta =
        sinTheta <= std::sin(tol) ? 180.0 : std::asin(std::sin(tol) / sinTheta) * kDeg;
    const double previous = i > 0 ? ref[i - 1] : cs[i];
    const double reachLo = i > 0 ? lo[i - 1] - r : -any, reachHi = i > 0 ? hi[i - 1] + r : any;
    if (delta >= 180.0) {
      lo[i] = std::max(reachLo, -any);
      hi[i] = std::min(reachHi, any);
      ref[i] = previous;
      continue;
    }
    // The tube of the branch nearer to the C so far (the other branch: C + 180°, tilt negated,
    // if the tilt limits allow it).
    double centre = unwrapNear(cs[i], previous);
    const double other = unwrapNear(cs[i] + 180.0, previous);
    if (-tilts[i] >= o.tiltMinDeg && -tilts[i] <= o.tiltMaxDeg &&
        std::abs(other - previous) < std::abs(centre - previous)) {
      centre = other;
    }
    lo[i] = centre - delta;
    hi[i] = centre + delta;
    if (reachHi <
        lo[i]) {  // C must turn faster than r here: by the least step that reaches the tube
      forced[i] = 1;
      hi[i] = lo[i];
    } else if (reachLo > hi[i]) {
      forced[i] = 1;
      lo[i] = hi[i];
    } else {
      lo[i] = std::max(lo[i], reachLo);
      hi[i] = std::min(hi[i], reachHi);
    }
    ref[i] = std::clamp(centre, lo[i], hi[i]);
  }
  // Backward: stay where the next point is (least motion); inside the reachable intervals that
  // is at most r away except after a forced jump.
  std::vector<double> chosen(N);
  chosen[N - 1] = ref[N - 1];
  for (size_t i = N - 1; i-- > 0;) {
    chosen[i] = std::clamp(chosen[i + 1], lo[i], hi[i]);
  }
  for (size_t k = 0; k < N; ++k) {
    const double c = chosen[k];
    // Best tilt for this C: rotate R_C(c)·n within the tilt plane as close to +Z as possible.
    const Eigen::Vector3d m =
        Eigen::AngleAxisd(c / kDeg, Eigen::Vector3d::UnitZ()) * normals[k].normalized();
    const double tilt = o.kinematics == TableKinematics::AC ? std::atan2(m.y(), m.z()) * kDeg
                                                            : std::atan2(-m.x(), m.z()) * kDeg;
    const Eigen::Vector3d up = tiltMatrix(o.kinematics, tilt) * m;
    stats.maxAxisErrorDeg =
        std::max(stats.maxAxisErrorDeg, std::acos(std::clamp(up.z(), -1.0, 1.0)) * kDeg);
    stats.forcedRotarySteps += forced[k];
    cs[k] = c;
    tilts[k] = tilt;
  }
  // Pass 2: positions and moves.
  double previousTilt = 0, previousE = extrusion[0];
  previousC = cs[0];
  Eigen::Vector3d previousX = Eigen::Vector3d::Zero();
  const char u = o.extrusionAxis;
  std::string moves;
  for (size_t i = 0; i < N; ++i) {
    const double tilt = tilts[i], c = cs[i];
    const Eigen::Matrix3d r =
        tiltMatrix(o.kinematics, tilt) *
        Eigen::AngleAxisd(c / kDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d x = controller
                                  ? Eigen::Vector3d(points[i] + o.partOffset)
                                  : Eigen::Vector3d(o.pivot + r * (points[i] + o.partOffset));
    if (i > 0) {
      stats.maxRotaryStepDeg = std::max(
          {stats.maxRotaryStepDeg, std::abs(c - previousC), std::abs(tilt - previousTilt)});
    }
    const double len = i > 0 ? (points[i] - points[i - 1]).norm() : 0.0;
    const double t = feedRate[i] > 0 && len > 0 ? len / feedRate[i] : 0.001;  // s
    const bool air = kind[i] == 2;
    const bool rapid = air || i == 0;
    // The moves are built in `moves` and written every 4096 points (one stream call per block);
    // numbers in fixed point, at most 5 decimals (3 for F), no exponent (RS274NGC reads "1e3"
    // as an E word), no "-0" (FixedNumber.h).
    auto put = [&moves](const char* word, double v, int decimals = 5) {
      moves += word;
      appendFixed(moves, v, decimals);
    };
    moves += rapid ? "G0" : "G1";
    put(" X", x.x());
    put(" Y", x.y());
    put(" Z", x.z());
    moves += ' ';
    moves += tiltAxis;
    appendFixed(moves, tilt, 5);
    put(" C", c);
    const double de = extrusion[i] - previousE;
    if (!rapid) {
      if (linuxcnc) {
        moves += ' ';
        moves += u;
        appendFixed(moves, extrusion[i], 5);
        put(" F", 60.0 / t);  // G93: 1 / minutes
      } else {
        if (de != 0) {
          put(" E", de);
        }
        // The nozzle moves `len` along the part in t seconds: the machine axes cover their own
        // displacement in the same time (a pure table turn: its degrees).
        const double machine = (x - previousX).norm();
        const double rotary = std::max(std::abs(c - previousC), std::abs(tilt - previousTilt));
        put(" F", 60.0 * (machine > 1e-6 ? machine : rotary) / t, 3);
      }
    } else if (!linuxcnc && air && i > 0) {
      put(" F", 60.0 * (feedRate[i] > 0 ? feedRate[i] : 50.0), 3);  // travel speed
    }
    moves += '\n';
    if (air && de != 0) {  // retract or prime at the air point
      if (linuxcnc) {
        moves += "G1 ";
        moves += u;
        appendFixed(moves, extrusion[i], 5);
        put(" F", 60.0 / o.retractionSeconds);
      } else {
        put("G1 E", de);
        put(" F", 60.0 * std::abs(de) / o.retractionSeconds, 3);
      }
      moves += ' ' + comment(f, de < 0 ? "retract" : "prime") + '\n';
    }
    if (i % 4096 == 4095 || i + 1 == N) {
      out.write(moves.data(), static_cast<std::streamsize>(moves.size()));
      moves.clear();
    }
    previousE = extrusion[i];
    previousC = c;
    previousTilt = tilt;
    previousX = x;
    ++stats.moves;
  }
  if (linuxcnc) {
    out << "G94\nM2\n";
  } else {
    out << "M400\n" << comment(f, "end") << '\n';
  }
  return stats;
}

}  // namespace geolattice
