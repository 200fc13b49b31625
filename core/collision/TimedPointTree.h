#pragma once
/// @file TimedPointTree.h
/// @brief A static kd-tree over printed points whose nodes know their bounding sphere and the
/// earliest print time below them, so a nozzle query at time t skips material printed later and
/// space outside a cone that bounds the nozzle (NozzleBound). Used by the collision verifier and
/// by the toolpath's nozzle axis clearance.
#include "nozzle/NozzleModel.h"

#include <Eigen/Core>
#include <limits>
#include <vector>

namespace geolattice {

/// Conservative reject test for a nozzle at (tip, axis): can any point of a ball be inside a cone
/// of half-angle `angle` about the axis with its apex `apexOffset` below the tip (cut at `reach`
/// from the tip, above the tip plane by more than `clearance`)? angle >= 90° keeps only the reach
/// test. With `volume` (a printhead's swept profile) the ball must also reach into that profile.
struct NozzleBound {
  NozzleBound(double angleRad, double reachMm, double clearanceMm, double apexOffsetMm = 0.0,
              const NozzleVolume* profile = nullptr);
  /// The bound of a nozzle model: its bounding cone, reach and tip clearance, and the printhead
  /// profile test through `volume` (made from the same model) when it has a printhead.
  NozzleBound(const NozzleModel& model, const NozzleVolume& volume);
  void setStation(const Eigen::Vector3d& tipPoint, const Eigen::Vector3d& unitAxis) {
    tip = tipPoint;
    axis = unitAxis;
  }
  bool mayTouch(const Eigen::Vector3d& centre, double radius) const;

  Eigen::Vector3d tip = Eigen::Vector3d::Zero(), axis = Eigen::Vector3d::UnitZ();
  double sinAngle = 0, cosAngle = 1;
  bool halfSpaceOrMore = false;
  double reach = std::numeric_limits<double>::infinity();
  double clearance = 0;  ///< -infinity disables the tip-plane test
  double apexOffset = 0;
  const NozzleVolume* volume = nullptr;
};

class TimedPointTree {
public:
  struct Node {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double radius = 0;
    int minTime = 0;
    int begin = 0, end = 0;  ///< range in order()
    int left = -1, right = -1;
  };

  /// time: one entry per point; a point with time INT_MAX is never reported (not material).
  /// Both vectors must outlive the tree.
  TimedPointTree(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& time);

  /// Calls visit(q) for every point q with time[q] < now in a leaf whose sphere the bound may
  /// touch (candidates: the caller applies its exact test); stops when visit returns true.
  /// Bound: anything with `bool mayTouch(centre, radius) const`, e.g. NozzleBound.
  template <class Bound, class Visit>
  void forEachCandidate(const Bound& bound, int now, Visit&& visit) const {
    if (nodes_.empty()) {
      return;
    }
    stack_.assign(1, 0);
    while (!stack_.empty()) {
      const Node& node = nodes_[stack_.back()];
      stack_.pop_back();
      if (node.minTime >= now || !bound.mayTouch(node.centre, node.radius)) {
        continue;
      }
      if (node.left >= 0) {
        stack_.push_back(node.left);
        stack_.push_back(node.right);
        continue;
      }
      for (int i = node.begin; i < node.end; ++i) {
        const int q = order_[i];
        if (time_[q] < now && visit(q)) {
          return;
        }
      }
    }
  }

private:
  static constexpr int kLeafSize = 8;
  int build(int begin, int end);

  const std::vector<Eigen::Vector3d>& points_;
  const std::vector<int>& time_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
  mutable std::vector<int> stack_;  ///< query scratch: one tree per thread
};

}  // namespace geolattice
