// Small math vocabulary shared by core/: vector and rotation types (Eigen), the quaternion
// update used by the integrators, and a body tensor turned to the world. SI units,
// world-frame angular velocities. Not a general geometry library.
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

// The moment I of a body-frame inertia that is exactly I times the identity (a sphere, a
// cube), else 0: such a body's world inertia is I in every orientation (R I R^T = I), and
// I w is parallel to w (no gyroscopic term). 0 too for an I whose inverse is not finite.
inline double isotropicMoment(const Mat3& inertia) {
  const double s = inertia(0, 0);
  const bool isotropic = s > 0.0 && std::isfinite(s) && std::isfinite(1.0 / s) &&
                         inertia == Mat3(s * Mat3::Identity());
  return isotropic ? s : 0.0;
}

// dq/dt for world-frame angular velocity w: 0.5 * [0, w] (x) q.
inline Eigen::Vector4d quaternionRate(const Vec3& w, const Quat& q) {
  const Quat r = Quat(0.0, w.x(), w.y(), w.z()) * q;
  return 0.5 * r.coeffs();
}

// R T R^T: a body-frame tensor T (an inertia or its inverse) in the world, R the body's
// rotation. Written on components with the products and sums of Eigen's `r * t *
// r.transpose()` in the order this build evaluates it, so the same bits: rows 0 and 1 of
// each product sum left to right, row 2 adds its first term to the sum of the other two
// (two-wide vectors for rows 0-1, a scalar tail; tests/core/rotated_tensor_test.cpp checks
// the bits). GCC had packed the expression's scalars through the stack into 2-wide
// registers, a store-to-load forwarding stall a body (docs/performance.md, "The rotated
// inertia on components").
inline Mat3 rotatedTensor(const Mat3& r, const Mat3& t) {
  auto left = [](double a0, double a1, double a2, double b0, double b1, double b2) {
    return a0 * b0 + a1 * b1 + a2 * b2;
  };
  auto tail = [](double a0, double a1, double a2, double b0, double b1, double b2) {
    return a0 * b0 + (a1 * b1 + a2 * b2);
  };
  double rt[3][3];  // R T
  for (int j = 0; j < 3; ++j) {
    rt[0][j] = left(r(0, 0), r(0, 1), r(0, 2), t(0, j), t(1, j), t(2, j));
    rt[1][j] = left(r(1, 0), r(1, 1), r(1, 2), t(0, j), t(1, j), t(2, j));
    rt[2][j] = tail(r(2, 0), r(2, 1), r(2, 2), t(0, j), t(1, j), t(2, j));
  }
  Mat3 out;  // (R T) R^T
  for (int j = 0; j < 3; ++j) {
    out(0, j) = left(rt[0][0], rt[0][1], rt[0][2], r(j, 0), r(j, 1), r(j, 2));
    out(1, j) = left(rt[1][0], rt[1][1], rt[1][2], r(j, 0), r(j, 1), r(j, 2));
    out(2, j) = tail(rt[2][0], rt[2][1], rt[2][2], r(j, 0), r(j, 1), r(j, 2));
  }
  return out;
}

}  // namespace tribo
