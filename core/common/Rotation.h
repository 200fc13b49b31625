#pragma once
/// @file Rotation.h
/// @brief The smallest rotation taking one direction onto another, exactly orthonormal.
///
/// Eigen's Quaternion::FromTwoVectors takes its closed form until the two directions are within
/// 1e-12 of opposite; just above that, 1 + cos is known to a few digits only and the quaternion
/// it returns is off unit length by up to ~1e-5, so toRotationMatrix() scales as well as turns
/// (a part turned upside down by --orient auto came out 2e-5 taller). Normalising the quaternion
/// keeps the turn and drops the scale.
#include <Eigen/Geometry>

namespace geolattice {

/// Rotation matrix taking the direction `from` onto `to` by the smallest angle (any non-zero
/// lengths; for exactly opposite directions, a half turn about some perpendicular axis).
inline Eigen::Matrix3d rotationBetween(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(from, to);
  q.normalize();
  return q.toRotationMatrix();
}

}  // namespace geolattice
