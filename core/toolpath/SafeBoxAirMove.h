#pragma once
/// @file SafeBoxAirMove.h
/// @brief Collision-free air moves between sub-graphs by the safe-box method (paper Fig. 18,
/// refs. [40, 41]): retract along the nozzle axis until the nozzle tip leaves a box around the
/// in-process part, travel on the box (up its side to the top face, across, down the side),
/// then approach the next start along its nozzle axis.
#include "mesh/TetMesh.h"

#include <Eigen/Geometry>
#include <vector>

namespace geolattice {

struct AirWaypoint {
  Vec3 point;
  Vec3 axis;  ///< nozzle axis at the waypoint (unit)
};

/// Waypoints after `from` up to and including `to` (`from` itself is not repeated). box: the
/// safe box (in-process part plus a margin); both points must be inside it. The axis turns from
/// fromAxis to +z on the way up the box and from +z to toAxis on the way down.
std::vector<AirWaypoint> safeBoxAirMove(const Vec3& from, const Vec3& fromAxis, const Vec3& to,
                                        const Vec3& toAxis, const Eigen::AlignedBox3d& box);

/// Short hop without the box, for continuing onto an upper node of the current sub-graph: lift
/// by `lift` along the axis, move to the point `lift` above the next start, approach.
std::vector<AirWaypoint> liftAirMove(const Vec3& from, const Vec3& fromAxis, const Vec3& to,
                                     const Vec3& toAxis, double lift);

}  // namespace geolattice
