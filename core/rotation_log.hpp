// The logarithm of SO(3) and the inverse right Jacobian, for the bushing's rotational
// deflection (core/force_elements.hpp).
//
//   log(q) = theta n,  q = (cos(theta/2), sin(theta/2) n),  theta in [0, pi]  (q and -q
//            are the same rotation: the one with w >= 0 is taken, the shortest rotation)
//   J_r^-1(phi) = I + 1/2 [phi]x + beta(theta) [phi]x^2,
//   beta = 1/theta^2 - (1 + cos theta) / (2 theta sin theta)
//        = 1/theta^2 - cos(theta/2) / (2 theta sin(theta/2))      (no 0/0 at theta = pi)
//        = 1/12 + theta^2/720 + theta^4/30240 + ...              (used for theta < 1e-2)
// J_r(phi) maps a change of phi to the body-fixed (right) angular displacement:
// Exp(phi + dphi) = Exp(phi) Exp(J_r(phi) dphi) = Exp(J_l(phi) dphi) Exp(phi), J_l = J_r^T.
// Citation: J. Sola, J. Deray, D. Atchuthan, "A micro Lie theory for state estimation in
// robotics", arXiv:1812.01537 (2018), eqs. (143)-(146); G. S. Chirikjian, "Stochastic Models,
// Information Theory, and Lie Groups", vol. 2 (2011), sec. 10.6.
// Not here: the exponential map (Eigen::AngleAxisd does it), other parametrizations (Euler,
// roll-pitch-yaw angles); log is discontinuous at theta = pi, where n flips to -n.
#pragma once

#include <cmath>

#include "core/math.hpp"

namespace tribo {

inline Mat3 skew(const Vec3& v) {
  Mat3 s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

// The rotation vector theta n of a unit quaternion, theta in [0, pi].
inline Vec3 rotationLog(const Quat& q) {
  const double sign = q.w() < 0.0 ? -1.0 : 1.0;
  const double w = sign * q.w();
  const Vec3 v = sign * q.vec();
  const double s = v.norm();  // sin(theta/2)
  // theta / sin(theta/2) = 2 atan2(s, w) / s; below s = 1e-8 it is 2 / w to rounding.
  const double scale = s < 1e-8 ? 2.0 / w : 2.0 * std::atan2(s, w) / s;
  return scale * v;
}

// J_r^-1(phi) (see the header comment).
inline Mat3 inverseRightJacobian(const Vec3& phi) {
  const double theta = phi.norm();
  double beta;
  if (theta < 1e-2) {
    const double t2 = theta * theta;
    beta = 1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30240.0;
  } else {
    const double half = 0.5 * theta;
    beta = 1.0 / (theta * theta) - std::cos(half) / (2.0 * theta * std::sin(half));
  }
  const Mat3 s = skew(phi);
  return Mat3::Identity() + 0.5 * s + beta * s * s;
}

}  // namespace tribo
