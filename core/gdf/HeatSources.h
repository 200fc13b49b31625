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
};

/// (a) Vertices with z <= min z + tolerance (mm). tolerance >= 0.
std::vector<int> sourcesNearLowestZ(const TetMesh& mesh, double tolerance);

/// (b) Vertices whose mask value is non-zero (mask has one value per vertex).
std::vector<int> sourcesFromMask(const TetMesh& mesh, const std::vector<double>& mask);

/// (c) Vertices of boundary faces whose outward normal is within maxAngleDeg of -z.
std::vector<int> sourcesFromDownwardFaces(const TetMesh& mesh, const TetMeshTopology& topology,
                                          double maxAngleDeg);

}  // namespace geolattice
