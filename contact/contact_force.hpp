// Contact kinematics and forces at one contact point, as three stages of the step (each a
// loop over all points in core/dynamics.cpp): kinematics (depth rate, tangential slip
// including the surface velocity of belts and conveyors), penalty normal force, and the
// pair's friction law.
//
//   v_rel = (v_B + w_B x (p - o_B)) - (v_A + w_A x (p - o_A))
//   d' = -n . v_rel,   slip = tangential part of (v_rel + s_B - s_A)
//   F_B = F_n n + F_t,  F_n from the normal law, F_t = -mu(|slip|) F_n slip/|slip|
// where s is a body's surface velocity (world frame; it never changes the depth rate). A
// stateful law gets the contact's StickView instead and returns F_t itself.
// Not here: collision detection, wrench accumulation on bodies (core does that), keeping
// the state of stateful laws (contact/stick_anchor.hpp).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>

#include "contact/anisotropy.hpp"
#include "contact/contact_point.hpp"
#include "contact/normal_law.hpp"
#include "contact/rolling_resistance.hpp"
#include "friction/friction_law.hpp"

namespace tribo::contact {

// Motion of the body carrying a geometry, world frame.
struct GeometryMotion {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();            // body origin [m]
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // of the origin [m/s]
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // [rad/s]
  Eigen::Vector3d surface_velocity = Eigen::Vector3d::Zero();  // belt surface [m/s]

  Eigen::Vector3d pointVelocity(const Eigen::Vector3d& p) const {
    return velocity + angular_velocity.cross(p - origin);
  }
};

// A pair's contact material: how the surfaces push and how they rub.
struct Material {
  NormalLaw normal;
  std::shared_ptr<const friction::FrictionLaw> friction;  // never null in a built model
  Anisotropy anisotropy;         // direction-dependent ratios of the law (contact/anisotropy.hpp)
  RollingResistance resistance;  // rolling and spinning (contact/rolling_resistance.hpp)
};

// Kinematics stage: fills out.point, out.depth_rate and out.slip for point `cp` between A
// and B (inline: the hot path of every contact scene).
inline void contactKinematics(const ContactPoint& cp, const GeometryMotion& a,
                              const GeometryMotion& b, ContactRecord& out) {
  const Eigen::Vector3d& n = cp.normal;
  const Eigen::Vector3d v_rel = b.pointVelocity(cp.position) - a.pointVelocity(cp.position);
  const double vn = n.dot(v_rel);
  out.point = cp;
  out.depth_rate = -vn;
  out.moment.setZero();
  const Eigen::Vector3d v_slide = v_rel + b.surface_velocity - a.surface_velocity;
  out.slip = v_slide - n.dot(v_slide) * n;
}

// Normal-force stage, after the kinematics: out.normal_force.
inline void normalForce(const Material& material, ContactRecord& out) {
  out.normal_force = material.normal.force(out.point.depth, out.depth_rate);
}

// Friction stage, after the normal force: out.friction_force and out.mu with a memoryless
// law, or with a stateful law given the contact's state view.
void frictionForce(const Material& material, ContactRecord& out);
void frictionForce(const Material& material, const friction::StickView& view, ContactRecord& out);

// All three stages for one point (memoryless law; for tests and single-contact callers).
void evaluateContact(const ContactPoint& cp, const GeometryMotion& a, const GeometryMotion& b,
                     const Material& material, ContactRecord& out);

// The same for a stateful law, given the contact's state view.
void evaluateContact(const ContactPoint& cp, const GeometryMotion& a, const GeometryMotion& b,
                     const Material& material, const friction::StickView& view, ContactRecord& out);

}  // namespace tribo::contact
