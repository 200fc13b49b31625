#pragma once
/// @file OrientationCsv.h
/// @brief orientation.csv: every candidate of the orientation search and its scores.
#include <string>

class vtkPolyData;

namespace geolattice {

/// One row per candidate (GL Auto Orient's Candidates output): rank (0 = chosen), source (keep,
/// hull, sphere), up_x, up_y, up_z (the part's direction, as placed, that points up),
/// base_area_mm2, feasible, evaluated, colliding_stations, plate_stations, stations,
/// forced_steps, overhang_fraction, layers, seconds; sorted by rank. Written atomically; throws
/// GeoLatticeError on missing arrays or a write failure.
void writeOrientationCsv(vtkPolyData* candidates, const std::string& path);

}  // namespace geolattice
