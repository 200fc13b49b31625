#include "robot/Pose.h"

#include <cmath>

namespace geolattice {

Eigen::Vector3d rotationVector(const Eigen::Matrix3d& r) {
  Eigen::Quaterniond q(r);  // Eigen uses Shepperd's robust conversion
  q.normalize();
  if (q.w() < 0) {
    q.coeffs() = -q.coeffs();  // angle in [0, π]
  }
  const Eigen::Vector3d v = q.vec();
  const double s = v.norm();
  const double angle = 2.0 * std::atan2(s, q.w());
  if (s < 1e-12) {
    return 2.0 * v;  // angle ≈ 2 s, axis * angle ≈ 2 v (first-order exact)
  }
  return (angle / s) * v;
}

Eigen::Matrix3d rotationMatrix(const Eigen::Vector3d& rv) {
  const double angle = rv.norm();
  if (angle < 1e-12) {
    // I + [rv]x (+ O(angle²)): exact to double precision here.
    Eigen::Matrix3d k;
    k << 0, -rv.z(), rv.y(), rv.z(), 0, -rv.x(), -rv.y(), rv.x(), 0;
    return Eigen::Matrix3d::Identity() + k;
  }
  return Eigen::AngleAxisd(angle, rv / angle).toRotationMatrix();
}

Isometry toIsometry(const UrPose& p) {
  Isometry t = Isometry::Identity();
  t.linear() = rotationMatrix(Eigen::Vector3d(p[3], p[4], p[5]));
  t.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
  return t;
}

UrPose toUrPose(const Isometry& t) {
  const Eigen::Vector3d rv = rotationVector(t.linear());
  return {t.translation().x(), t.translation().y(), t.translation().z(), rv.x(), rv.y(), rv.z()};
}

UrPose poseTrans(const UrPose& from, const UrPose& fromTo) {
  return toUrPose(toIsometry(from) * toIsometry(fromTo));
}

UrPose poseInv(const UrPose& p) {
  return toUrPose(toIsometry(p).inverse());
}

}  // namespace geolattice
