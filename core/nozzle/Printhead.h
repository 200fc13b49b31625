#pragma once
/// @file Printhead.h
/// @brief A real printhead as the nozzle volume (issue 14, "printhead geometry"): a closed
/// triangle mesh in the nozzle frame — the tip (centre of the orifice face) at the origin, the
/// nozzle axis +z pointing from the tip up into the printhead, millimetres — replaces the
/// paper's bounding cone in the sequencer, the verifier and the toolpath's axis clearance.
///
/// Rotation about the axis. The printhead's turn about its own axis relative to the part is not
/// known when the order and the toolpath are planned: the UR5 cell's path solver chooses it
/// freely along the path afterwards (the free rotation ψ), and a 5-axis table's C axis sets it
/// per point. So every check uses the solid the printhead sweeps turning once about its axis:
/// a point at height h above the tip (along the axis) and distance r from the axis is inside
/// iff r < R(h), where R(h) is the largest distance from the axis of the printhead's solid at
/// height h. For a printhead that is a body of revolution (nozzles, heater blocks modelled by
/// their circumscribed cylinder, round heat sinks) that is the printhead itself; for any other it
/// is conservative: material outside it is outside the printhead at every rotation.
///
/// R is tabulated on height bins of equal width (at most kProfileBins over the printhead's
/// height, at least 0.005 mm); each bin holds the exact maximum of the distance from the axis
/// over the solid within the bin's closed slab, computed from the triangles (the farthest point
/// of a slab of a solid lies on its surface, and the distance from a line is convex along a
/// segment, so it is attained at a vertex of a triangle clipped to the slab). The test is then
/// one lookup, as fast as the cone's dot products. A range maximum (sparse table) gives
/// conservative ball tests for the spatial indices (the verifier's kd-tree, the sequencer's
/// bounding-sphere trees).
///
/// Validation uses CGAL: the mesh must be closed, edge-manifold, consistently oriented and
/// free of self-intersections (Polygon_mesh_processing), its lowest point must be the tip at
/// the origin (AABB tree distance) and the axis just above the tip must lie inside the solid
/// (Side_of_triangle_mesh). Each failure is a GeoLatticeError naming the file and the problem.
#include "common/RangeMax.h"
#include "mesh/TetMesh.h"

#include <algorithm>
#include <string>
#include <vector>

namespace geolattice {

class Printhead {
public:
  /// Largest number of height bins of the profile.
  static constexpr int kProfileBins = 8192;

  /// Validates `mesh` (see the file comment) and tabulates its swept profile. `name` (e.g. the
  /// file path) is used in messages and reports. Throws GeoLatticeError.
  Printhead(const TriangleSurface& mesh, const std::string& name);

  const std::string& name() const { return name_; }
  double height() const { return height_; }          ///< top of the printhead above the tip (mm)
  double maxRadius() const { return maxRadius_; }    ///< largest distance from the axis (mm)
  double reach() const { return reach_; }            ///< largest distance from the tip (mm)
  double faceRadius() const { return faceRadius_; }  ///< radius of the solid at the tip plane
  double volume() const { return volume_; }          ///< enclosed volume (mm^3)
  int triangles() const { return triangles_; }
  double binHeight() const { return bin_; }

  /// R(h): the largest distance from the axis of the swept solid at height h (mm); 0 outside
  /// [0, height].
  double radiusAt(double h) const {
    if (!(h >= 0) || h > height_) {
      return 0.0;
    }
    const int k = std::min(static_cast<int>(h * invBin_), static_cast<int>(radius_.size()) - 1);
    return radius_[k];
  }
  /// The largest R over heights in [h0, h1] (clamped to [0, height]); 0 for an empty range.
  double maxRadiusBetween(double h0, double h1) const {  // inline: the collision searches' hot path
    h0 = std::max(h0, 0.0);
    h1 = std::min(h1, height_);
    if (!(h0 <= h1)) {
      return 0.0;
    }
    return radiusMax_(static_cast<int>(h0 * invBin_), static_cast<int>(h1 * invBin_));
  }

  /// A cone that contains the swept solid: apex `boundApexOffset()` below the tip on the axis,
  /// half-angle `boundHalfAngleRad()`. The offset is chosen so that the cone is slim (a flat
  /// orifice face would make a cone with its apex at the tip nearly a half-space).
  double boundApexOffset() const { return apexOffset_; }
  double boundHalfAngleRad() const { return boundAngle_; }

  /// The largest angle from the axis (rad) of a point of the swept solid at distance rho from
  /// the tip (conservative, tabulated): a point at distance rho further than this from the axis
  /// direction is outside. Used to turn the axis off an obstacle (toolpath axis clearance).
  double clearAngleAt(double rho) const;
  /// The largest clear angle over distances in [rho0, rho1] (rad); 0 for an empty range.
  double maxClearAngleBetween(double rho0, double rho1) const;
  /// Its cosine, without trigonometry (inline: the sequencer's pair search tests every node
  /// pair with it); 1 for an empty range.
  double cosMaxClearAngleBetween(double rho0, double rho1) const {
    rho0 = std::max(rho0, 0.0);
    rho1 = std::min(rho1, reach_);
    if (!(rho0 <= rho1)) {
      return 1.0;
    }
    return -negCosClearMax_(static_cast<int>(rho0 / angleBin_), static_cast<int>(rho1 / angleBin_));
  }

private:
  std::string name_;
  double height_ = 0, maxRadius_ = 0, reach_ = 0, faceRadius_ = 0, volume_ = 0;
  int triangles_ = 0;
  double bin_ = 0, invBin_ = 0;
  std::vector<double> radius_;  ///< per height bin
  RangeMax radiusMax_;
  double apexOffset_ = 0, boundAngle_ = 0;
  double angleBin_ = 0;
  std::vector<double> clearAngle_;  ///< per distance bin
  RangeMax clearAngleMax_;
  RangeMax negCosClearMax_;  ///< of -cos(clear angle): the cosine of the largest, negated
};

}  // namespace geolattice
