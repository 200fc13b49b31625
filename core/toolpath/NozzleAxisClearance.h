#pragma once
/// @file NozzleAxisClearance.h
/// @brief Tilts the nozzle axis where the layer normal would drive the nozzle into material
/// printed earlier on the same path (issue: toolpaths, acceptance "the collision verifier passes
/// on the full toolpath").
///
/// The printing order (Section 3.1) keeps other sub-graphs out of the nozzle, but inside one
/// sub-graph a strongly curved layer can rise into the cone: e.g. a branch's tip cap whose far
/// side climbs 45° within a few millimetres of the nozzle, printed before the near side. The
/// paper's fixed axis ∇γ then collides. Here such a station gets the smallest tilt away from
/// ∇γ (at most maxTilt) that puts every earlier obstacle at least `margin` outside the nozzle
/// cone, found by projecting the axis off the deepest obstacle (a few iterations) or, if that
/// fails, by scanning rings of tilts around ∇γ. The tilt fades out linearly along the path over
/// blendLength in both directions, so the axis changes gradually (the largest tilt wins where
/// fades overlap; a station always keeps its own). Material is the path's points, so callers
/// sample the path finely (PathSubdivision.h); the verifier remains the judge.
///
/// Cost: one nozzle query per station against a kd-tree (TimedPointTree.h), O(N log N); the
/// obstacle search and tilt only for colliding stations.
#include "nozzle/NozzleModel.h"
#include "mesh/TetMesh.h"
#include "toolpath/PathObstacleTrees.h"

#include <functional>
#include <vector>

namespace geolattice {

struct AxisClearanceOptions {
  /// Largest angle between the axis and the layer normal (deg, in [0, 60]); 0 = off. 30 by
  /// default: on parts nobody tuned for, 15 left stations colliding that 30 clears (auto-oriented
  /// spot 1 -> 0, knight 922 -> 82, topopt 1 414 -> 318 stations; docs/performance.md), and a
  /// tilt is only ever the least that clears, where the normal would collide.
  double maxTiltDeg = 30.0;
  double marginDeg = 0.5;    ///< obstacles end at least this far outside the cone (deg, >= 0)
  double blendLength = 5.0;  ///< a tilt fades out over this path length on each side (mm, >= 0)
  /// A fade that would turn a point's axis into earlier material is not applied (the point keeps
  /// its axis). Off: every fade is applied, and a point it pushes into material is a colliding
  /// station of the next pass (which is how a region of stations finds a common side; the
  /// toolpath planner's first rounds do this, its later ones settle with the check on).
  bool fadeOnlyWhereClear = false;
  int threads = 0;  ///< workers over the stations (0 = hardware concurrency); same result
  /// Polled every 4096 stations; true stops with GeoLatticeError "nozzle axis clearance
  /// aborted". Optional.
  std::function<bool()> shouldAbort;
  /// Throws GeoLatticeError naming the first parameter out of its range.
  void validate() const;
};

struct AxisClearanceResult {
  int collidingStations = 0;   ///< stations with earlier material inside the nozzle, before tilting
  std::vector<int> colliding;  ///< their indices
  int tiltedStations = 0;      ///< of those, given a tilt that clears all of their obstacles
  int unresolvedStations = 0;  ///< of those, no tilt within maxTilt clears them (left as they were)
  int blendedPoints = 0;       ///< other points whose axis was turned by a fading tilt
  int keptPoints = 0;  ///< with fadeOnlyWhereClear: points a fade would have turned into material
  double seconds = 0;
};

/// The detection and least-tilt searches of one pass, for a later pass over a path whose
/// material differs only after some point (the toolpath planner's attempts differ only in their
/// air moves, which are not material): a material station whose earlier material and fixed
/// obstacles are those of the memo's pass takes that pass's answer where its axis (and, for the
/// search, its reference) is the same (both are functions of exactly these: the result is the
/// same).
struct AxisSearchMemo {
  struct Entry {
    Vec3 reference, axis;  ///< the station's reference and current axis in that pass
    bool cleared = false;  ///< a clearing tilt was found (else: none within the limit)
    Vec3 clearAxis;        ///< that tilt's axis
  };
  std::vector<Vec3> material;                ///< the pass's material points, in path order
  std::vector<Vec3> fixed;                   ///< its fixed obstacles
  std::vector<Vec3> detectAxis;              ///< by material ordinal: the axis it was checked at
  std::vector<char> detectHit;               ///< by material ordinal: material inside the nozzle
  std::vector<std::pair<int, Entry>> found;  ///< by material ordinal (sorted): searched stations
  long long reused = 0;                      ///< searches a pass took from the memo (counter)
};

/// Stations an earlier pass over the same path found clear, for a pass after points were
/// inserted into the path (none moved, as PathSubdivision does): such a station whose axis has
/// not changed since is checked against the inserted material only (material only grows, so the
/// answer is that of a full check).
struct KnownClear {
  std::vector<char> clear;     ///< per point: found clear by the last pass, axis unchanged since
  std::vector<char> inserted;  ///< per point: inserted into the path since that pass
};

/// One pass over the path, time = point index. axes: current unit axes (modified);
/// reference: the untilted unit layer normals (the tilt limit is measured from them); material:
/// per point, non-zero if it is deposited material (an obstacle for later stations). Throws
/// GeoLatticeError for mismatched sizes or bad options. fixedObstacles (optional): points that are
/// obstacles at every station, e.g. the build plate's samples (nozzle/BuildPlate.h).
/// unresolvable (optional, one flag per point, in/out): a flagged station that collides is
/// counted unresolved without a new search, and every station found unresolved is flagged. For
/// repeated passes over one path: a station's obstacles only grow between passes (points are
/// inserted, none move), so one no tilt cleared stays so. memo (optional, in/out): searches of
/// an earlier pass reused where their inputs are the same (AxisSearchMemo); then replaced by
/// this pass's. known (optional, in/out): KnownClear; on return `clear` holds this pass's clear
/// stations whose axes it left as they were, `inserted` is untouched. obstacleTrees (optional,
/// in/out): the obstacles' kd-trees of an earlier pass, kept where they still hold
/// (PathObstacleTrees.h), and this pass's for the next; the result is the same without.
AxisClearanceResult clearNozzleAxes(const std::vector<Vec3>& points, std::vector<Vec3>& axes,
                                    const std::vector<Vec3>& reference,
                                    const std::vector<char>& material, const NozzleModel& nozzle,
                                    const AxisClearanceOptions& options,
                                    const std::vector<Vec3>* fixedObstacles = nullptr,
                                    std::vector<char>* unresolvable = nullptr,
                                    AxisSearchMemo* memo = nullptr, KnownClear* known = nullptr,
                                    PathObstacleTrees* obstacleTrees = nullptr);

}  // namespace geolattice
