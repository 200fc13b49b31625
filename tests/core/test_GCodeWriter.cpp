// 5-axis G-code for A-C and B-C tables: the table angles turn every nozzle axis onto +Z, C is
// continuous and does not spin near the pole, machine positions follow the table kinematics,
// and the waypoint CSV has one row per point.
#include "common/Error.h"
#include "program/GCodeWriter.h"
#include "program/WaypointCsvWriter.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <sstream>

using namespace geolattice;

namespace {

Eigen::Matrix3d tableRotation(TableKinematics k, double tilt, double c) {
  const Eigen::Vector3d axis =
      k == TableKinematics::AC ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return (Eigen::AngleAxisd(tilt * M_PI / 180, axis) *
          Eigen::AngleAxisd(c * M_PI / 180, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

}  // namespace

TEST(GCodeWriter, AnglesTurnTheAxisUp) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  for (TableKinematics k : {TableKinematics::AC, TableKinematics::BC}) {
    double previous = 0;
    for (int i = 0; i < 2000; ++i) {
      Eigen::Vector3d n(g(rng), g(rng), g(rng));
      n.normalize();
      double tilt, c;
      tableAngles(k, n, previous, 0.01, tilt, c);
      EXPECT_LT((tableRotation(k, tilt, c) * n - Eigen::Vector3d::UnitZ()).norm(), 1e-12);
      EXPECT_LE(std::abs(c - previous), 180.0 + 1e-9);  // unwrapped next to the previous C
      previous = c;
    }
  }
}

TEST(GCodeWriter, NoSpinNearThePole) {
  // Axes wobbling around +Z by 1e-5 rad: C must stay put.
  double c = 37.0, tilt = 0;
  for (int i = 0; i < 100; ++i) {
    const double a = i * 0.7;
    const Eigen::Vector3d n(1e-7 * std::cos(a), 1e-7 * std::sin(a), 1.0);
    tableAngles(TableKinematics::AC, n, c, 0.01, tilt, c);
    EXPECT_EQ(c, 37.0);
    EXPECT_LT(std::abs(tilt), 0.01);
  }
}

TEST(GCodeWriter, TableTurnsSmoothlyNearThePole) {
  // Nearly vertical axes (tilt 0.3° in random directions), as on a flat first layer: C would
  // jump by up to 180° between neighbours; within the pole band it is interpolated instead.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 2 * M_PI);
  std::vector<Eigen::Vector3d> p, n;
  std::vector<double> e, f;
  std::vector<int> kind;
  for (int i = 0; i < 200; ++i) {
    const double a = u(rng),
                 t = (i < 100 ? 0.3 : 0.3 + 0.2 * (i - 100)) * M_PI / 180;  // then a tilt ramp
    p.push_back(Eigen::Vector3d(i * 0.5, 0, 0.6));
    n.push_back(Eigen::Vector3d(std::sin(t) * std::cos(i < 100 ? a : 0.3),
                                std::sin(t) * std::sin(i < 100 ? a : 0.3), std::cos(t)));
    e.push_back(0.01 * i);
    f.push_back(10);
    kind.push_back(0);
  }
  std::ostringstream g;
  GCodeOptions o;
  const GCodeStats s = writeGCode(p, n, e, f, kind, o, g);
  EXPECT_LE(s.maxAxisErrorDeg, o.axisToleranceDeg + 1e-9);
  EXPECT_EQ(s.forcedRotarySteps, 0u);
  EXPECT_LT(s.maxRotaryStepDeg, 5.0);  // spread over the 100 flat points
}

TEST(GCodeWriter, ProgramAndCsv) {
  std::vector<Eigen::Vector3d> p, n;
  std::vector<double> e, f;
  std::vector<int> kind, layer;
  for (int i = 0; i < 50; ++i) {
    const double a = i * 0.1;
    p.push_back(Eigen::Vector3d(10 * std::cos(a), 10 * std::sin(a), 0.6 + 0.01 * i));
    n.push_back(Eigen::Vector3d(0.3 * std::cos(a), 0.3 * std::sin(a), 1).normalized());
    e.push_back(0.05 * i);
    f.push_back(10);
    kind.push_back(i == 25 ? 2 : 0);
    layer.push_back(0);
  }
  GCodeOptions o;
  o.pivot = Eigen::Vector3d(0, 0, 100);
  o.partOffset = Eigen::Vector3d(0, 0, 5);
  o.toolCentrePoint = ToolCentrePoint::Cam;  // machine coordinates
  std::ostringstream g;
  const GCodeStats s = writeGCode(p, n, e, f, kind, o, g);
  EXPECT_EQ(s.moves, p.size());
  EXPECT_EQ(s.outOfLimits, 0u);
  EXPECT_LT(s.maxRotaryStepDeg, 10.0);
  const std::string text = g.str();
  EXPECT_NE(text.find("G93"), std::string::npos);
  // First move: the machine position is pivot + R(A, C) (p + offset) with the angles written,
  // and those angles turn the nozzle axis to +Z within the axis tolerance.
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line) && line.rfind("G0 X", 0) != 0) {
  }
  double gx, gy, gz, ga, gc;
  ASSERT_EQ(std::sscanf(line.c_str(), "G0 X%lf Y%lf Z%lf A%lf C%lf", &gx, &gy, &gz, &ga, &gc), 5)
      << line;
  const Eigen::Matrix3d rotation = tableRotation(TableKinematics::AC, ga, gc);
  const Eigen::Vector3d x = o.pivot + rotation * (p[0] + o.partOffset);
  EXPECT_NEAR(gx, x.x(), 1e-5);  // 5 decimals
  EXPECT_NEAR(gy, x.y(), 1e-5);
  EXPECT_NEAR(gz, x.z(), 1e-5);
  EXPECT_LE(std::acos(std::clamp((rotation * n[0]).z(), -1.0, 1.0)) * 180 / M_PI,
            o.axisToleranceDeg + 1e-4);
  // The exact angles are within the tolerance of these.
  double tilt, c;
  tableAngles(TableKinematics::AC, n[0], gc, 0.01, tilt, c);
  EXPECT_LE(std::abs(std::remainder(c - gc, 360.0)), 90.0);
  std::ostringstream csv;
  writeWaypointCsv(p, n, e, kind, layer, csv);
  const std::string c2 = csv.str();
  EXPECT_EQ(std::count(c2.begin(), c2.end(), '\n'), 51);
  EXPECT_EQ(c2.substr(0, c2.find('\n')), "x,y,z,nx,ny,nz,e,kind,layer");
  // Bad input.
  std::ostringstream sink;
  EXPECT_THROW(writeGCode({}, {}, {}, {}, {}, o, sink), GeoLatticeError);
  n[3] = Eigen::Vector3d(NAN, 0, 1);
  EXPECT_THROW(writeGCode(p, n, e, f, kind, o, sink), GeoLatticeError);
}
