#pragma once
/// @file PathObstacleTrees.h
/// @brief The obstacles of an axis-clearance pass over a toolpath (NozzleAxisClearance.h): the
/// material printed before each station and the fixed obstacles (the build plate's samples), as
/// two kd-trees (collision/TimedPointTree.h). The base tree is kept from an earlier pass for as
/// long as that pass's material is still on the path in the same order: the planner's later
/// passes only insert points (rotation steps) or change air moves (not material), so one tree
/// serves every round of every planning attempt. The material added since is in a second,
/// small tree. The trees hold the obstacles' coordinates; which ones are earlier than a station
/// follows from where the base material lies on the current path (now()).
///
/// Cost: a rebuild is O(M log M) for M material points; a reuse is one O(N) walk over the path
/// plus a tree over the added points.
#include "collision/TimedPointTree.h"
#include "mesh/TetMesh.h"

#include <memory>
#include <vector>

namespace geolattice {

class PathObstacleTrees {
public:
  PathObstacleTrees() = default;
  PathObstacleTrees(const PathObstacleTrees&) = delete;  // the trees point into the members
  PathObstacleTrees& operator=(const PathObstacleTrees&) = delete;

  /// Indexes the obstacles of a pass over `points` (material[i] non-zero: deposited material,
  /// an obstacle for later stations; fixed: present at every station, may be null). Keeps the
  /// base tree when its material is an in-order subsequence of this path's and at most an
  /// eighth of it (and at least 1024 points) was added; otherwise builds it again.
  void index(const std::vector<Vec3>& points, const std::vector<char>& material,
             const std::vector<Vec3>* fixed);

  /// The trees: 0 the base (material of the pass it was built for, then the fixed obstacles),
  /// 1 the material added since. An obstacle of tree s is points(s)[q] for a q it reports.
  static constexpr int kTrees = 2;
  const TimedPointTree& tree(int s) const { return s == 0 ? *base_ : *added_; }
  const std::vector<Vec3>& points(int s) const { return s == 0 ? basePoints_ : addedPoints_; }
  /// The time to query tree s with for the station at path index `station`: its obstacles
  /// are then exactly the material before the station and the fixed obstacles.
  int now(int s, int station) const {
    return s == 0 ? baseNow_[static_cast<size_t>(station)] : station;
  }

  /// Calls visit(x) for every obstacle x of the station in a leaf the bound may touch (the
  /// caller applies its exact test); stops when visit returns true.
  template <class Bound, class Visit>
  void forEachCandidate(const Bound& bound, int station, Visit&& visit) const {
    bool stop = false;
    for (int s = 0; s < kTrees && !stop; ++s) {
      const std::vector<Vec3>& x = points(s);
      tree(s).forEachCandidate(bound, now(s, station), [&](int q) { return stop = visit(x[q]); });
    }
  }

  long long builds = 0;  ///< base trees built (counter)
  long long reuses = 0;  ///< passes that kept the base tree (counter)

private:
  std::vector<Vec3> basePoints_;  ///< the base pass's material in path order, then the fixed
  std::vector<int> baseTime_;     ///< its material ordinal; -1 for the fixed obstacles
  size_t baseMaterial_ = 0;       ///< material points in basePoints_
  std::unique_ptr<TimedPointTree> base_;
  std::vector<int> baseNow_;  ///< per station of this pass: base material points before it
  std::vector<Vec3> addedPoints_;
  std::vector<int> addedTime_;  ///< their path index in this pass
  std::unique_ptr<TimedPointTree> added_;
};

}  // namespace geolattice
