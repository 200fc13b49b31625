#pragma once
/// @file FoldedSurface.h
/// @brief A body that crosses itself, for the tests of the self-intersection checks.
#include "mesh/TetMesh.h"

#include <algorithm>

/// Pushes the vertex of `box` (an axis-aligned box surface with vertices inside its faces)
/// nearest the middle of its top face to `below` mm under its bottom face: still closed and
/// manifold, one body, but its top folds through its bottom. Returns that vertex's index.
inline int foldTopThroughBottom(geolattice::TriangleSurface& box, double below) {
  using geolattice::Vec3;
  Vec3 lo = box.points.front(), hi = box.points.front();
  for (const Vec3& p : box.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec3 middle(0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()), hi.z());
  const auto top = std::min_element(
      box.points.begin(), box.points.end(),
      [&](const Vec3& a, const Vec3& b) { return (a - middle).norm() < (b - middle).norm(); });
  top->z() = lo.z() - below;
  return static_cast<int>(top - box.points.begin());
}
