#pragma once
/// @file PathSubdivision.h
/// @brief Inserts points into toolpath segments that are too long or turn the nozzle axis too
/// much (issue: toolpaths, item 5 "rotation steps"). A segment from point i-1 to i is cut into
/// max(ceil(turn / maxTurn), ceil(length / maxLength)) equal pieces: positions linear, axes
/// by slerp, thickness linear, kind, width, feed rate, layer, sub-graph and path index of the
/// segment's end point. The cumulative extrusion E of an inserted point is exact for the
/// segment's deposited volume μ w L (h0 + h)/2 (Eq. 14 integrated over the piece with h
/// linear), so the sum of the pieces' ΔE equals the segment's ΔE and every piece obeys Eq. 14
/// with the mean thickness of its ends. Short pieces (≤ maxLength) make the collision check of
/// the path's points a check of the path sampled at that spacing.
#include "toolpath/ToolpathPlanner.h"

#include <vector>

namespace geolattice {

struct SubdivisionCounts {
  int inserted = 0;       ///< points added
  int rotationSteps = 0;  ///< of those, needed to keep the axis turn below maxTurn
};

/// maxTurnRad > 0; maxLength > 0 or 0 for no length limit. extraAxes (optional, one unit
/// vector per point, e.g. the untilted layer normals) are interpolated like the axes. flags
/// (optional, one per point) stay with their points; inserted points get 0.
SubdivisionCounts subdivideToolpath(Toolpath& path, double maxTurnRad, double maxLength,
                                    std::vector<Vec3>* extraAxes = nullptr,
                                    std::vector<char>* flags = nullptr);

/// Spherical interpolation between unit vectors a and b (t in [0, 1]); antipodal vectors turn
/// about an arbitrary perpendicular.
Vec3 slerpAxis(const Vec3& a, const Vec3& b, double t);

}  // namespace geolattice
