// Small math vocabulary shared by core/: vector and rotation types (Eigen), and the
// quaternion update used by the integrators. SI units, world-frame angular velocities.
// Not a general geometry library.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace tribo {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;
using Row6 = Eigen::Matrix<double, 1, 6>;

// q advanced by a rotation of (w * h) about the world axis w (exact for constant w).
inline Quat rotateBy(const Vec3& w, double h, const Quat& q) {
  const double angle = w.norm() * h;
  if (angle < 1e-300) return q;
  return (Quat(Eigen::AngleAxisd(angle, w / w.norm())) * q).normalized();
}

// dq/dt for world-frame angular velocity w: 0.5 * [0, w] (x) q.
inline Eigen::Vector4d quaternionRate(const Vec3& w, const Quat& q) {
  const Quat r = Quat(0.0, w.x(), w.y(), w.z()) * q;
  return 0.5 * r.coeffs();
}

}  // namespace tribo
