#pragma once
/// @file HeatSources.h
/// @brief The three ways to choose the γ-GDF source (the printing base): the lowest vertices,
/// a user mask, or boundary faces that face the platform. Each returns sorted vertex ids.
#include "mesh/TetMesh.h"

#include <vector>

namespace geolattice {

class TetMeshTopology;

/// How the base (the γ source) is chosen, with the defaults every front end uses.
struct BaseOptions {
  double tolerance = 0.05;        ///< (a): height band above the lowest point (mm, >= 0)
  double maxFaceAngleDeg = 10.0;  ///< (c): largest angle of a base face's normal from -z (deg)
  /// (a): the near-flat bottom, too: faces facing down within maxFaceAngleDeg of -z that lie
  /// within this height of the lowest point (mm, >= 0; one layer interval).
  double flatBand = 0.6;
};

/// (a) Vertices with z <= min z + tolerance (mm). tolerance >= 0.
std::vector<int> sourcesNearLowestZ(const TetMesh& mesh, double tolerance);

/// (a) with the part's near-flat bottom: the vertices of sourcesNearLowestZ(mesh, tolerance) and
/// those of the boundary faces whose outward normal is within maxAngleDeg of -z and whose
/// vertices all lie at most flatBand (mm, >= 0) above the lowest point. A bottom that is flat
/// but not level (a scan, a foot tilted a few degrees, a warped export) then starts the layers
/// on the plate everywhere it nearly touches it; with the band's lowest vertices alone, the
/// layers would fan out sideways from the patch that touches, and the first beads of that fan,
/// a fraction of a millimetre above the plate, be printed with the nozzle leaning 40–60° —
/// its face in the plate. Material over the rest of the band (at most flatBand above the plate)
/// is printed as part of the first layer, as a slicer's first layer fills what lies under it.
std::vector<int> sourcesNearLowestZ(const TetMesh& mesh, double tolerance,
                                    const TetMeshTopology& topology, double flatBand,
                                    double maxAngleDeg);

/// (b) Vertices whose mask value is non-zero (mask has one value per vertex).
std::vector<int> sourcesFromMask(const TetMesh& mesh, const std::vector<double>& mask);

/// (c) Vertices of boundary faces whose outward normal is within maxAngleDeg of -z.
std::vector<int> sourcesFromDownwardFaces(const TetMesh& mesh, const TetMeshTopology& topology,
                                          double maxAngleDeg);

}  // namespace geolattice
