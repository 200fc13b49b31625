#pragma once
/// @file PartArmClearance.h
/// @brief The part the robot holds, against the robot's own arm: how near do the arm's bodies
/// (ArmCapsules.h: base to wrist 2) come to the part as printed up to a toolpath point?
///
/// Measured on the programs of the tenth session (forward kinematics of the written joints, the
/// links as the lines between their joints): the demo bunny's forearm passed through the bunny
/// it held (0.1 mm from a printed point; within 45 mm, a UR5 link's radius, at 1,507 of 35,670
/// sampled points), the three-branch tree's within 27 mm. Nothing checked it.
///
/// The part is modelled by its material, the toolpath's print points (not its air moves) in
/// 2 mm voxels (one sample per occupied voxel: its first point, there from that point's index
/// on; a distance is taken less the voxel's diagonal, so it is a lower bound), and by the plate
/// under it (the footprint of the whole toolpath at its lowest z, as in PartFloor.h, sampled
/// every kPlateSpacing mm), there from the start; in a TimedPointTree (collision/
/// TimedPointTree.h: a kd-tree of spheres that knows the earliest index below each node), so a
/// query visits only the material near the arm. Distances are from the capsules' surfaces
/// (kFirstNearPart to kLastNearPart: wrist 3 carries the plate and is not checked). Material
/// between two toolpath points is within half a line spacing of one of them, the plate within
/// kPlateSpacing / √2 of a sample: the clearance kept must cover both.
#include "collision/TimedPointTree.h"
#include "robot/ArmCapsules.h"
#include "robot/RobotCell.h"

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace geolattice {

class PartArmClearance {
  static constexpr int kParts = kLastNearPart - kFirstNearPart + 1;
  /// The capsules checked, in the part's frame and units.
  using Body = std::array<Capsule, kParts>;

public:
  /// Spacing of the plate's samples (part units, mm).
  static constexpr double kPlateSpacing = 5.0;

  /// `points`: the toolpath in part units (cell.partScale converts them to metres); kind (one
  /// per point, or empty: every point is material): 2 = an air move, not material.
  PartArmClearance(const RobotCell& cell, const std::vector<Eigen::Vector3d>& points,
                   const std::vector<int>& kind = {});
  ~PartArmClearance();
  PartArmClearance(const PartArmClearance&) = delete;
  PartArmClearance& operator=(const PartArmClearance&) = delete;

  /// Least distance (m, 0 when they touch) of the arm's surfaces (`arm`: its capsules at some
  /// q, base frame) from the part printed up to point i (its points 0 .. i and the plate) when
  /// the flange is at `flange`; `limit` (m) when every one is farther than that (the search
  /// stops there).
  double distance(const Isometry& flange, const ArmCapsules& arm, size_t i, double limit) const {
    return nearest(flange, arm, i, limit, false);
  }
  /// Whether the arm's surfaces are at least `clearance` (m) from the part printed up to point
  /// i (the search stops at the first point nearer).
  bool clear(const Isometry& flange, const ArmCapsules& arm, size_t i, double clearance) const {
    return !(clearance > 0) || nearest(flange, arm, i, clearance, true) >= clearance;
  }

  /// The least distance() over the arm states of a path, in path order (`add` each state
  /// with its toolpath index, increasing), to 1 mm (never below it, at most 1 mm above),
  /// without searching at most states: a state cannot come nearer than the state before's
  /// distance less how far the capsules moved (in the part frame), except to material printed in
  /// between, which is measured directly; only a state whose bound is more than 1 mm below the
  /// least so far is searched (exactly: a raster of 1M points under a compact part searched at
  /// nearly every state, 5.1 s instead of 1.9 s for the whole path solve).
  class Sweep {
  public:
    Sweep(const PartArmClearance& part, double limit) : part_(part), least_(limit) {}
    void add(const Isometry& flange, const ArmCapsules& arm, size_t i);
    double least() const { return least_; }  ///< m (the limit when none is nearer)

  private:
    const PartArmClearance& part_;
    double least_;
    bool have_ = false;
    size_t index_ = 0;
    double raw_ = 0;  ///< a lower bound of the state before's sample distance (part units)
    Body body_;
  };

private:
  Body inPart(const Isometry& flange, const ArmCapsules& arm) const;
  /// The least distance (part units) of the body's surfaces from the samples of the part up to
  /// point i, searched below `bound` (part units; `bound` when none is nearer), stopping at the
  /// first sample nearer than `stop`.
  double nearestSample(const Body& body, size_t i, double bound, double stop) const;
  double nearest(const Isometry& flange, const ArmCapsules& arm, size_t i, double limit,
                 bool firstBelow) const;

  Isometry partOnFlange_;
  double scale_ = 1;
  std::vector<Eigen::Vector3d> samples_;  ///< material and plate, part units
  std::vector<int> time_;                 ///< per sample: the toolpath index it is there from
  size_t material_ = 0;  ///< samples [0, material_) are the material's, in toolpath order
  std::unique_ptr<TimedPointTree> tree_;
};

}  // namespace geolattice
