#pragma once
/// @file Pose.h
/// @brief Rigid poses as URScript writes them, p[x, y, z, rx, ry, rz] (metres, rotation vector
/// in radians), with the equivalents of URScript's pose_trans and pose_inv. The rotation-vector
/// conversions go through unit quaternions, so they are exact near 0 (series) and near π
/// (Shepperd's method picks the largest quaternion component; no division by sin θ → 0).
#include <Eigen/Geometry>

#include <array>

namespace geolattice {

using Isometry = Eigen::Isometry3d;
using UrPose = std::array<double, 6>;  ///< x, y, z (m), rx, ry, rz (rotation vector, rad)

/// Rotation vector (axis * angle, angle in [0, π]) of a rotation matrix.
Eigen::Vector3d rotationVector(const Eigen::Matrix3d& r);
/// Rotation matrix of a rotation vector.
Eigen::Matrix3d rotationMatrix(const Eigen::Vector3d& rv);

Isometry toIsometry(const UrPose& p);
UrPose toUrPose(const Isometry& t);

/// URScript pose_trans(p_from, p_from_to) = p_from ∘ p_from_to.
UrPose poseTrans(const UrPose& from, const UrPose& fromTo);
/// URScript pose_inv(p).
UrPose poseInv(const UrPose& p);

}  // namespace geolattice
