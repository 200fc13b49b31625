#pragma once
/// @file TetMesh.h
/// @brief Plain mesh containers shared by every core stage (no VTK).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace geolattice {

using Vec3 = Eigen::Vector3d;

/// @brief Closed triangle surface. points: #V positions (mm), triangles: #F vertex triples,
/// counter-clockwise seen from outside (outward normals).
struct TriangleSurface {
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
};

/// @brief Linear tetrahedral mesh. points: #V positions (mm), tets: #T vertex quadruples.
/// Positive orientation: (p1-p0) x (p2-p0) . (p3-p0) > 0.
struct TetMesh {
  std::vector<Vec3> points;
  std::vector<std::array<int, 4>> tets;
};

/// v / |v|, or `fallback` for a zero (or non-finite length) vector.
inline Vec3 unitOr(const Vec3& v, const Vec3& fallback) {
  const double n = v.norm();
  return n > 0 && n < std::numeric_limits<double>::infinity() ? Vec3(v / n) : fallback;
}

/// The points with a NaN or infinite coordinate (how many, the first one's index or -1) and the
/// bounding box of the others: what the mesh checks report.
struct FinitePointScan {
  int nonFinite = 0;
  int firstNonFinite = -1;
  Eigen::AlignedBox3d box;  ///< empty when no point is finite
  double diagonal() const { return box.isEmpty() ? 0.0 : box.diagonal().norm(); }
};
inline FinitePointScan scanPoints(const std::vector<Vec3>& points) {
  FinitePointScan s;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) {
      if (s.nonFinite++ == 0) {
        s.firstNonFinite = static_cast<int>(i);
      }
    } else {
      s.box.extend(points[i]);
    }
  }
  return s;
}

/// @brief Signed volume of tet (a, b, c, d): positive for positive orientation.
inline double signedTetVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

/// A tet is flat (holds no volume: its corners in one plane, or a corner repeated) when
/// |volume| < kFlatTetRatio * (its longest edge)^3, about 1e-5 of a regular tet's volume. The
/// bound is relative to the tet's own size, not the part's: TetGen's 0.02 mm tets where a
/// pedestal meets a tilted part are well shaped (|volume| ~ 0.04 edge^3), and the rounding of a
/// volume computed from coordinates of magnitude D is ~1e-16 D edge^2, far below the bound.
constexpr double kFlatTetRatio = 1e-6;

/// Whether a tet with these corners and signed volume is flat (a NaN volume, or all corners in
/// one point, count as flat).
inline bool isFlatTet(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, double volume) {
  const double longest2 =
      std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (d - a).squaredNorm(),
                (c - b).squaredNorm(), (d - b).squaredNorm(), (d - c).squaredNorm()});
  return !(std::abs(volume) > kFlatTetRatio * longest2 * std::sqrt(longest2));
}

}  // namespace geolattice
