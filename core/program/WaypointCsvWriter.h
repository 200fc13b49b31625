#pragma once
/// @file WaypointCsvWriter.h
/// @brief The toolpath as a plain waypoint table for other controllers and for inspection:
/// header "x,y,z,nx,ny,nz,e,kind,layer", one row per toolpath point (part frame, mm; unit nozzle
/// axis; cumulative filament E, mm; move kind 0 print, 1 perimeter, 2 air; lattice layer, -1 on
/// air moves).
#include <Eigen/Core>

#include <ostream>
#include <vector>

namespace geolattice {

/// Writes the table. Throws GeoLatticeError when the arrays differ in length.
void writeWaypointCsv(const std::vector<Eigen::Vector3d>& points,
                      const std::vector<Eigen::Vector3d>& normals,
                      const std::vector<double>& extrusion, const std::vector<int>& kind,
                      const std::vector<int>& layer, std::ostream& out);

}  // namespace geolattice
