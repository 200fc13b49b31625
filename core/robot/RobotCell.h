#pragma once
/// @file RobotCell.h
/// @brief The printing cell of the paper (Section 4, Fig. 19): a UR arm holds the part under a
/// fixed nozzle. For each toolpath point p (part frame, mm) with nozzle axis n, the robot puts
/// the part so that p is at the nozzle tip and n points along the nozzle body; the remaining
/// rotation ψ about the nozzle axis is free.
///
/// Frames: base (robot base, metres); flange; part = the platform frame of the toolpath
/// (z = 0 is the platform), fixed on the flange by partOnFlange (the TCP); the nozzle: tip
/// position and body axis (unit, from the tip into the nozzle) in the base frame.
/// For a point: R_part(ψ) = Rot(axis, ψ) · Align(n -> axis), t_part = tip − R_part · p, and
/// flange = part · partOnFlange⁻¹.
#include "robot/URKinematics.h"

#include <Eigen/Core>

namespace geolattice {

struct RobotCell {
  RobotModel robot = ur5Model();
  /// m, base frame: 350 mm up leaves the forearm room under the nozzle (at 300 mm it passed
  /// through the nozzle's axis on three of five bundled models: RobotPathOptions)
  Eigen::Vector3d nozzleTip = Eigen::Vector3d(0.0, -0.40, 0.35);
  Eigen::Vector3d nozzleAxis = Eigen::Vector3d(0, 0, 1);  ///< from the tip into the nozzle (unit)
  /// Part (platform) frame in the flange frame: the platform plate 40 mm in front of the
  /// flange, part z along the flange z.
  Isometry partOnFlange = Isometry(Eigen::Translation3d(0, 0, 0.04));
  double partScale = 0.001;  ///< part units -> metres (toolpaths are in mm)

  /// Throws GeoLatticeError for a non-unit/zero nozzle axis, non-finite values or scale <= 0.
  void validate() const;
  /// Flange pose that puts part point p (part units) at the tip with n along the nozzle axis,
  /// turned by psi (rad) about the nozzle axis.
  Isometry flangePose(const Eigen::Vector3d& p, const Eigen::Vector3d& n, double psi) const;
};

}  // namespace geolattice
