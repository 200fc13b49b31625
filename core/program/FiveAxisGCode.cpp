#include "program/FiveAxisGCode.h"

#include "common/Error.h"
#include "program/URScriptProgram.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace geolattice {

namespace {

constexpr double kDeg = 180.0 / M_PI;

double unwrapNear(double angle, double near) { return near + std::remainder(angle - near, 360.0); }

Eigen::Matrix3d tiltMatrix(TableKinematics k, double tiltDeg) {
  return Eigen::AngleAxisd(tiltDeg / kDeg, k == TableKinematics::AC ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY())
      .toRotationMatrix();
}

} // namespace

void tableAngles(TableKinematics k, const Eigen::Vector3d& nIn, double previousC, double poleToleranceDeg, double& tilt,
                 double& c) {
  const Eigen::Vector3d n = nIn.normalized();
  const double rho = std::hypot(n.x(), n.y());
  double c1 = k == TableKinematics::AC ? std::atan2(n.x(), n.y()) * kDeg : std::atan2(-n.y(), n.x()) * kDeg;
  double t1 = k == TableKinematics::AC ? std::atan2(rho, n.z()) * kDeg : std::atan2(-rho, n.z()) * kDeg;
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

GCodeStats writeFiveAxisGCode(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normals,
                              const std::vector<double>& extrusion, const std::vector<double>& feedRate,
                              const std::vector<int>& kind, const GCodeOptions& o, std::ostream& out) {
  const size_t N = points.size();
  if (N == 0) {
    throw GeoLatticeError("G-code: the toolpath is empty");
  }
  if (normals.size() != N || extrusion.size() != N || feedRate.size() != N || kind.size() != N) {
    throw GeoLatticeError("G-code: toolpath arrays differ in length");
  }
  const char tiltAxis = o.kinematics == TableKinematics::AC ? 'A' : 'B';
  out << "; GeoLattice 5-axis print, " << (o.kinematics == TableKinematics::AC ? "A-C" : "B-C")
      << " tilting-rotary table, fixed vertical nozzle\n";
  out << "G21 ; mm\nG90 ; absolute\nM83 ; relative extrusion\nG93 ; inverse-time feed\n";
  GCodeStats stats;
  // Pass 1: angles per point; points at the pole (C undefined) are marked.
  std::vector<double> tilts(N), cs(N);
  std::vector<char> pole(N, 0);
  double previousC = 0;
  for (size_t i = 0; i < N; ++i) {
    if (!points[i].allFinite() || !normals[i].allFinite() || !(normals[i].norm() > 0)) {
      throw GeoLatticeError("G-code: toolpath point " + std::to_string(i) + " has a NaN position or normal");
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
  // Near the pole C is ill-conditioned: over each run of points within the pole band, C moves
  // linearly from the C before the run to the C after it, and the tilt is the best one for that
  // C (the axis is then off by at most about the band), so the table turns smoothly while it is
  // almost flat instead of spinning between neighbouring points.
  std::vector<char> band(N, 0);
  for (size_t i = 0; i < N; ++i) band[i] = std::abs(tilts[i]) < o.poleBandDeg;
  for (size_t i = 0; i < N;) {
    if (!band[i]) {
      ++i;
      continue;
    }
    size_t j = i;
    while (j < N && band[j]) ++j;
    const double before = i > 0 ? cs[i - 1] : (j < N ? cs[j] : cs[i]);
    const double after = j < N ? unwrapNear(cs[j], before) : before;
    for (size_t k = i; k < j; ++k) {
      const double c = before + (after - before) * static_cast<double>(k - i + 1) / static_cast<double>(j - i + 1);
      // Best tilt for this C: rotate R_C(c)·n within the tilt plane as close to +Z as possible.
      const Eigen::Vector3d m = Eigen::AngleAxisd(c / kDeg, Eigen::Vector3d::UnitZ()) * normals[k].normalized();
      const double tilt = o.kinematics == TableKinematics::AC ? std::atan2(m.y(), m.z()) * kDeg
                                                              : std::atan2(-m.x(), m.z()) * kDeg;
      const Eigen::Vector3d up = tiltMatrix(o.kinematics, tilt) * m;
      stats.maxAxisErrorDeg = std::max(stats.maxAxisErrorDeg, std::acos(std::clamp(up.z(), -1.0, 1.0)) * kDeg);
      cs[k] = c;
      tilts[k] = tilt;
    }
    if (j < N) {
      const double shift = after - cs[j];  // C after the run continues from the interpolated value
      for (size_t k = j; k < N; ++k) cs[k] += shift;
    }
    i = j;
  }
  // Pass 2: machine positions and moves.
  double previousTilt = 0, previousE = extrusion[0];
  previousC = cs[0];
  for (size_t i = 0; i < N; ++i) {
    const double tilt = tilts[i], c = cs[i];
    const Eigen::Matrix3d r = tiltMatrix(o.kinematics, tilt) *
                              Eigen::AngleAxisd(c / kDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d x = o.pivot + r * (points[i] + o.partOffset);
    if (i > 0) {
      stats.maxRotaryStepDeg = std::max({stats.maxRotaryStepDeg, std::abs(c - previousC), std::abs(tilt - previousTilt)});
    }
    const double len = i > 0 ? (points[i] - points[i - 1]).norm() : 0.0;
    const double t = feedRate[i] > 0 && len > 0 ? len / feedRate[i] : 0.001;  // s
    const bool air = kind[i] == 2;
    out << (air || i == 0 ? "G0" : "G1") << " X" << urNumber(x.x()) << " Y" << urNumber(x.y()) << " Z"
        << urNumber(x.z()) << ' ' << tiltAxis << urNumber(tilt) << " C" << urNumber(c);
    const double de = extrusion[i] - previousE;
    if (!air && i > 0 && de != 0) {
      out << " E" << urNumber(de);
    }
    if (!air && i > 0) {
      out << " F" << urNumber(60.0 / t);  // G93: moves per minute
    }
    out << '\n';
    if (air && de != 0) {
      out << "G1 E" << urNumber(de) << " F" << urNumber(60.0 / 0.05) << " ; " << (de < 0 ? "retract" : "prime") << '\n';
    }
    previousE = extrusion[i];
    previousC = c;
    previousTilt = tilt;
    ++stats.moves;
  }
  out << "G94\nM2\n";
  return stats;
}

void writeWaypointCsv(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normals,
                      const std::vector<double>& extrusion, const std::vector<int>& kind, const std::vector<int>& layer,
                      std::ostream& out) {
  const size_t N = points.size();
  if (normals.size() != N || extrusion.size() != N || kind.size() != N || layer.size() != N) {
    throw GeoLatticeError("waypoint CSV: toolpath arrays differ in length");
  }
  out << "x,y,z,nx,ny,nz,e,kind,layer\n";
  for (size_t i = 0; i < N; ++i) {
    const Eigen::Vector3d n = normals[i].normalized();
    out << urNumber(points[i].x()) << ',' << urNumber(points[i].y()) << ',' << urNumber(points[i].z()) << ','
        << urNumber(n.x()) << ',' << urNumber(n.y()) << ',' << urNumber(n.z()) << ',' << urNumber(extrusion[i]) << ','
        << kind[i] << ',' << layer[i] << '\n';
  }
}

} // namespace geolattice
