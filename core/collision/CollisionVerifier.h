#pragma once
/// @file CollisionVerifier.h
/// @brief Independent check that a print never drives the nozzle into material already
/// printed (issue: collision verifier). It shares nothing with the sequencer's envelope code
/// but the definition of the nozzle volume (NozzleVolume in NozzleModel.h): given every printed
/// point with its nozzle axis and the time it is printed, it asks, for each point as a nozzle
/// station, whether any point printed strictly earlier lies inside the nozzle volume there. Exact point-in-nozzle test (dot products, no angles), points in
/// a static kd-tree whose nodes store their bounding sphere and earliest print time
/// (TimedPointTree.h), so a query skips material printed later and space outside a cone that
/// bounds the nozzle.
///
/// For a sub-graph order, time = the sub-graph's position (all of its points share it, a
/// sub-graph is not tested against itself); for a toolpath, time = the point's index on it.
/// With the build plate the tree's root splits the material from the plate's samples, so each
/// kind can be searched alone. With an exemption, a station whose first obstacle found is the
/// plate or exempt material is searched on for material an order could have kept out, in a
/// second tree whose material is grouped as the exemption groups it (TimedPointTree's groups):
/// exempt groups, e.g. the skeleton ancestors that fill a nozzle low over a long part, are
/// skipped whole, so the cost does not grow with the material they hold.
#include "nozzle/BuildPlate.h"
#include "nozzle/NozzleModel.h"

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace geolattice {

struct CollisionViolation {
  int station = 0;   ///< index of the point being printed
  int obstacle = 0;  ///< index of the earlier point inside the nozzle there
  Eigen::Vector3d stationPoint = Eigen::Vector3d::Zero();
  Eigen::Vector3d obstaclePoint = Eigen::Vector3d::Zero();
  double height = 0;         ///< obstacle height above the tip along the axis (mm)
  double radial = 0;         ///< obstacle distance from the axis (mm)
  bool unavoidable = false;  ///< every obstacle of this station is exempt (see CollisionExemption)
};

/// @brief Optional classification of obstacles that no printing order can avoid, e.g. material
/// of a skeleton ancestor, which Criterion 1 forces to be printed first. The verifier still
/// reports them (collisionFree stays strict); orderCollisionFree ignores them.
struct CollisionExemption {
  std::vector<int> group;  ///< per point: a group id (e.g. its sub-graph)
  std::function<bool(int stationGroup, int obstacleGroup)> unavoidable;
};

struct CollisionReport {
  bool collisionFree = true;
  long long stations = 0;                ///< points checked
  long long violatingStations = 0;       ///< stations with at least one obstacle inside the nozzle
  long long unavoidableStations = 0;     ///< of those, stations whose obstacles are all exempt
  bool orderCollisionFree = true;        ///< no station with an obstacle that is not exempt
  std::vector<int> violatingStationIds;  ///< every violating station, in print time order
  long long plateStations = 0;  ///< of the violating stations, those whose obstacle is the plate
  std::vector<int> plateStationIds;  ///< those stations, in print time order
  std::vector<CollisionViolation>
      violations;  ///< the first ones in print time order (at most maxReported)
  double seconds = 0;
};

/// Reporting options of the verifier.
struct VerifierOptions {
  int maxReported = 20;  ///< violations listed in the report (the first in print time), >= 0
};

/// points, normals (unit axes; re-normalised) and time have one entry per printed point.
/// Throws GeoLatticeError for mismatched sizes, a zero or non-finite normal, non-finite points,
/// or a bad nozzle, or an exemption or material mask whose size does not match. material
/// (optional, one flag per point): only points with a non-zero flag are obstacles, e.g. the
/// print points of a toolpath but not its air moves; every point is still a station. plate
/// (optional): the build plate under the material's footprint is an obstacle at every station
/// (nozzle/BuildPlate.h); violations it causes are counted in plateStations, and a station whose
/// tip lies inside the plate is one. With an exemption (a printing order to judge), no order
/// avoids the plate, so its violations count as unavoidable (orderCollisionFree ignores them);
/// without one the first obstacle found decides. The reported obstacle of a plate violation is
/// the plate sample (obstacle index -1). checked (optional, one flag per point): only stations
/// with a non-zero flag are searched, the others are known to be clear (a caller that has
/// proved it, e.g. the orientation search from the sub-graphs' potential collisions); they are
/// still obstacles and are still counted in `stations`.
CollisionReport verifyNozzleClearance(const std::vector<Eigen::Vector3d>& points,
                                      const std::vector<Eigen::Vector3d>& normals,
                                      const std::vector<int>& time, const NozzleModel& nozzle,
                                      int maxReported = VerifierOptions{}.maxReported,
                                      const CollisionExemption* exemption = nullptr,
                                      const std::vector<char>* material = nullptr,
                                      const BuildPlate* plate = nullptr,
                                      const std::vector<char>* checked = nullptr);

}  // namespace geolattice
