#pragma once
/// @file AirMoveRealignment.h
/// @brief Air moves laid again along the nozzle axes the clearance chose (a toolpath planner
/// step after the axis clearance, ToolpathPlanner.h).
///
/// The planner lays an air move (SafeBoxAirMove.h) along the untilted layer normals of the
/// stations it leaves and reaches; the axis clearance then tilts those stations, so the retract
/// and the approach no longer run along the nozzle's own axis and the nozzle moves sideways
/// next to the material (topopt auto-oriented under the example printhead: 32 stations of a
/// 34 mm approach into a channel between two branches collided). Here each air move with a
/// colliding station is laid again by the same safe-box method, leaving along the final axis of
/// the last material point before it and approaching along that of the first material point
/// after it, the axis constant along both. For a nozzle whose radius does not shrink upwards
/// (the cone, the holder, a printhead's swept radius), a pose moved back along its own axis
/// holds only what the pose holds, so the approach is clear wherever the station it reaches is
/// clear. The new air points are checked (strict, the build plate included) and a move is kept
/// only where fewer of its stations collide than before. Material is unchanged (air points are
/// no obstacles), so no other station's verdict changes.
///
/// Cost: linear in the path for the splice, plus one nozzle query per new air point against the
/// material's kd-tree (built once, O(N log N)), only when an air station collides.
#include "toolpath/ToolpathPlanner.h"

#include <vector>

namespace geolattice {

/// Lays again the air moves (maximal runs of air points between two material points) that hold
/// a station of `colliding` (the stations left colliding by the axis clearance, ascending),
/// keeping those with fewer colliding stations. Updates path's arrays (axisTilt 0 on the new
/// points: they follow their planned axes), airLength, rotationSteps, subdivisionPoints,
/// alignedTransitions, unclearedStations and maxAxisTiltDeg. Returns the stations left colliding
/// (indices into the new path, ascending).
std::vector<int> realignCollidingAirMoves(Toolpath& path, const std::vector<int>& colliding,
                                          const ToolpathOptions& options);

}  // namespace geolattice
