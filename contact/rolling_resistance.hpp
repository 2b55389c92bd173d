// Rolling resistance and spinning friction at a contact point, with stiction: resisting
// moments about the contact's tangent axes (rolling) and its normal (spinning), proportional
// to the normal load, that hold a ball or a wheel at rest below their threshold instead of
// letting it creep.
//
// With w = w_B - w_A the relative angular velocity, n the contact normal and theta the
// rotation of B relative to A since the contact's angular spring was anchored (world frame),
// each part (rolling: the tangential parts w_r, theta_r; spinning: the normal parts w_s,
// theta_s) is the elastic_stick state machine on angles (friction/elastic_stick_law.hpp, the
// law reused as is):
//   stuck:    M = -k theta - c w           while |M| <= L F_n
//   sliding:  M = -L F_n w / |w|           (rolling or spinning at the threshold)
// with L the rolling resistance length mu_r [m] (the lever of the normal load's offset in
// the contact patch; Popov, Contact Mechanics and Friction, ch. 17) for rolling, and
// mu_spin r_c [m] (a friction coefficient times a contact radius; 2/3 r of a uniform disc of
// radius r) for spinning. A ball on a slope of angle alpha rolls when tan(alpha) > mu_r / R.
// The angular anchor is B's orientation in A's frame, re-set after every step keeping the
// elongation the state machine decided, as the linear anchors are (contact/stick_anchor.hpp):
//   theta = R_A log(q_A^-1 q_B q_ref^-1),   rebase: q_ref = exp(R_A^T theta)^-1 q_A^-1 q_B.
// Not here: where the moments are summed (core/dynamics.cpp), when anchors are re-set
// (core/friction_states.cpp).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>

#include "friction/elastic_stick_law.hpp"

namespace tribo::contact {

// One part (rolling or spinning) as the scene gives it.
struct AngularStickParams {
  double limit = 0.0;         // L: moment per unit normal load [m], > 0
  double stiffness = 0.0;     // k: angular spring per contact point [N m/rad], > 0
  double damping = 0.0;       // c: [N m s/rad], >= 0
  double stick_speed = 1e-3;  // relative angular speed below which it re-sticks [rad/s], > 0
};

// A material's rolling and spinning resistance; either part may be absent (null).
struct RollingResistance {
  std::shared_ptr<const friction::ElasticStickLaw> rolling;
  std::shared_ptr<const friction::ElasticStickLaw> spinning;
  bool active() const { return rolling || spinning; }
};

// The state machine of one part. Throws std::invalid_argument naming `what` ("rolling",
// "spinning") and the key for a value out of range.
std::shared_ptr<const friction::ElasticStickLaw> angularStick(const AngularStickParams& p,
                                                              const char* what);

// The angular state of one contact point: B's orientation in A's frame when anchored (unit
// quaternion, coefficients x, y, z, w) and each part's mode.
struct AngularAnchor {
  Eigen::Vector4d reference = Eigen::Vector4d(0.0, 0.0, 0.0, 1.0);
  bool rolling_sliding = false;
  bool spinning_sliding = false;
  bool operator==(const AngularAnchor&) const = default;
};

// The rotation of B relative to A since `anchor` (world), from the geometries' orientations.
Eigen::Vector3d angularElongation(const AngularAnchor& anchor, const Eigen::Matrix3d& rot_a,
                                  const Eigen::Matrix3d& rot_b);

// The resisting moment on B (A gets the opposite) at relative angular velocity w, load fn.
// `anchored` false: a contact new within the step (stuck, zero elongation).
Eigen::Vector3d resistingMoment(const RollingResistance& r, const Eigen::Vector3d& n,
                                const Eigen::Vector3d& w, double fn, bool anchored,
                                const AngularAnchor& anchor, const Eigen::Vector3d& theta);

// The anchor after a step: each part's mode and elongation from its state machine, stored
// as the reference orientation that gives them back.
AngularAnchor advanceAngular(const RollingResistance& r, const Eigen::Vector3d& n,
                             const Eigen::Vector3d& w, double fn, bool anchored,
                             const AngularAnchor& anchor, const Eigen::Vector3d& theta,
                             const Eigen::Matrix3d& rot_a, const Eigen::Matrix3d& rot_b);

}  // namespace tribo::contact
