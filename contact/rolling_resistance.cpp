#include "contact/rolling_resistance.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace tribo::contact {

namespace {

Eigen::Vector3d normalPart(const Eigen::Vector3d& v, const Eigen::Vector3d& n) {
  return n.dot(v) * n;
}

Eigen::Quaterniond relative(const Eigen::Matrix3d& rot_a, const Eigen::Matrix3d& rot_b) {
  return Eigen::Quaterniond(rot_a.transpose() * rot_b).normalized();
}

// The rotation vector of q (angle in [0, pi]).
Eigen::Vector3d logOf(Eigen::Quaterniond q) {
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const double s = q.vec().norm();
  if (s < 1e-12) return 2.0 * q.vec();  // first order: angle 2 s about q.vec()
  return (2.0 * std::atan2(s, q.w()) / s) * q.vec();
}

// The rotation vector of rotation matrix m, from its skew part (2 sin(angle) times the axis)
// and its trace (1 + 2 cos(angle)): no conversion to a quaternion, one atan2. Near a half
// turn the skew part vanishes and the axis is lost, so there (angle > 154 degrees, far past
// any spring's elongation) it goes through the quaternion.
Eigen::Vector3d logOf(const Eigen::Matrix3d& m) {
  const Eigen::Vector3d v(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
  const double c = m.trace() - 1.0;  // 2 cos(angle)
  if (c < -1.8) return logOf(Eigen::Quaterniond(m).normalized());
  const double s = v.norm();      // 2 sin(angle)
  if (s < 1e-12) return 0.5 * v;  // first order
  return (std::atan2(s, c) / s) * v;
}

Eigen::Quaterniond expOf(const Eigen::Vector3d& v) {
  const double angle = v.norm();
  if (angle < 1e-12) return Eigen::Quaterniond(1.0, 0.5 * v.x(), 0.5 * v.y(), 0.5 * v.z());
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, v / angle));
}

std::string text(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

}  // namespace

std::shared_ptr<const friction::ElasticStickLaw> angularStick(const AngularStickParams& p,
                                                              const char* what) {
  auto require = [&](bool ok, const char* key, const char* rule, double value) {
    if (!ok)
      throw std::invalid_argument(std::string(what) + ": " + key + " must be " + rule + " (got " +
                                  text(value) + ")");
  };
  require(std::isfinite(p.limit) && p.limit > 0.0, "limit", "finite and > 0", p.limit);
  require(std::isfinite(p.stiffness) && p.stiffness > 0.0, "stiffness", "finite and > 0",
          p.stiffness);
  require(std::isfinite(p.damping) && p.damping >= 0.0, "damping", "finite and >= 0", p.damping);
  require(std::isfinite(p.stick_speed) && p.stick_speed > 0.0, "stick_speed", "finite and > 0",
          p.stick_speed);
  return std::make_shared<const friction::ElasticStickLaw>(
      friction::ElasticStickParams{.mu_s = p.limit,
                                   .mu_k = p.limit,
                                   .stiffness = p.stiffness,
                                   .damping = p.damping,
                                   .stick_speed = p.stick_speed});
}

Eigen::Vector3d angularElongation(const AngularAnchor& anchor, const Eigen::Matrix3d& rot_a,
                                  const Eigen::Matrix3d& rot_b) {
  const Eigen::Matrix3d ref = Eigen::Quaterniond(anchor.reference.w(), anchor.reference.x(),
                                                 anchor.reference.y(), anchor.reference.z())
                                  .toRotationMatrix();
  return rot_a * logOf(Eigen::Matrix3d(rot_a.transpose() * rot_b * ref.transpose()));
}

Eigen::Vector3d resistingMoment(const RollingResistance& r, const Eigen::Vector3d& n,
                                const Eigen::Vector3d& w, double fn, bool anchored,
                                const AngularAnchor& anchor, const Eigen::Vector3d& theta) {
  const Eigen::Vector3d w_s = normalPart(w, n), theta_s = normalPart(theta, n);
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  if (r.rolling)
    m += r.rolling->stickForce(w - w_s, fn, {anchored, anchor.rolling_sliding, theta - theta_s},
                               nullptr);
  if (r.spinning)
    m += r.spinning->stickForce(w_s, fn, {anchored, anchor.spinning_sliding, theta_s}, nullptr);
  return m;
}

AngularAnchor advanceAngular(const RollingResistance& r, const Eigen::Vector3d& n,
                             const Eigen::Vector3d& w, double fn, bool anchored,
                             const AngularAnchor& anchor, const Eigen::Vector3d& theta,
                             const Eigen::Matrix3d& rot_a, const Eigen::Matrix3d& rot_b) {
  const Eigen::Vector3d w_s = normalPart(w, n), theta_s = normalPart(theta, n);
  AngularAnchor next;
  Eigen::Vector3d kept = Eigen::Vector3d::Zero();
  if (r.rolling) {
    const friction::StickUpdate u =
        r.rolling->advance(w - w_s, fn, {anchored, anchor.rolling_sliding, theta - theta_s});
    next.rolling_sliding = u.sliding;
    kept += u.elongation - normalPart(u.elongation, n);
  }
  if (r.spinning) {
    const friction::StickUpdate u =
        r.spinning->advance(w_s, fn, {anchored, anchor.spinning_sliding, theta_s});
    next.spinning_sliding = u.sliding;
    kept += normalPart(u.elongation, n);
  }
  const Eigen::Quaterniond ref =
      (expOf(rot_a.transpose() * kept).conjugate() * relative(rot_a, rot_b)).normalized();
  next.reference = Eigen::Vector4d(ref.x(), ref.y(), ref.z(), ref.w());
  return next;
}

}  // namespace tribo::contact
