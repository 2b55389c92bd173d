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
// contactWrench gives one point's force on either body and its moment about that body's
// origin:   tau_B = (p - o_B) x F_B + M,   tau_A = (p - o_A) x (-F_B) - M
// with M the rolling and spinning moment (contact/rolling_resistance.hpp).
// Not here: collision detection, the sums of the points' wrenches on each body (core does
// that), keeping the state of stateful laws (contact/stick_anchor.hpp).
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
};

// A pair's contact material: how the surfaces push and how they rub.
struct Material {
  NormalLaw normal;
  std::shared_ptr<const friction::FrictionLaw> friction;  // never null in a built model
  Anisotropy anisotropy;         // direction-dependent ratios of the law (contact/anisotropy.hpp)
  RollingResistance resistance;  // rolling and spinning (contact/rolling_resistance.hpp)
};

// Kinematics stage: fills out.point, out.depth_rate and out.slip for point `cp` between A
// and B (inline: the hot path of every contact scene). Written on components, not with
// Eigen's cross and dot: GCC packed pairs of the cross products' scalars into 2-wide
// registers through the stack, a store-to-load forwarding stall that was half of the stage's
// time on the box grids (docs/performance.md). The same operations in the same order as the
// formulas above, so the same bits (tests/contact/contact_force_test.cpp).
inline void contactKinematics(const ContactPoint& cp, const GeometryMotion& a,
                              const GeometryMotion& b, ContactRecord& out) {
  const double px = cp.position.x(), py = cp.position.y(), pz = cp.position.z();
  const double nx = cp.normal.x(), ny = cp.normal.y(), nz = cp.normal.z();
  const double rax = px - a.origin.x(), ray = py - a.origin.y(), raz = pz - a.origin.z();
  const double rbx = px - b.origin.x(), rby = py - b.origin.y(), rbz = pz - b.origin.z();
  const Eigen::Vector3d& wa = a.angular_velocity;
  const Eigen::Vector3d& wb = b.angular_velocity;
  const double vax = a.velocity.x() + (wa.y() * raz - wa.z() * ray);
  const double vay = a.velocity.y() + (wa.z() * rax - wa.x() * raz);
  const double vaz = a.velocity.z() + (wa.x() * ray - wa.y() * rax);
  const double vbx = b.velocity.x() + (wb.y() * rbz - wb.z() * rby);
  const double vby = b.velocity.y() + (wb.z() * rbx - wb.x() * rbz);
  const double vbz = b.velocity.z() + (wb.x() * rby - wb.y() * rbx);
  const double vx = vbx - vax, vy = vby - vay, vz = vbz - vaz;
  const double vn = nx * vx + ny * vy + nz * vz;
  out.point = cp;
  out.depth_rate = -vn;
  out.moment.setZero();
  const double wx = vx + b.surface_velocity.x() - a.surface_velocity.x();
  const double wy = vy + b.surface_velocity.y() - a.surface_velocity.y();
  const double wz = vz + b.surface_velocity.z() - a.surface_velocity.z();
  const double wn = nx * wx + ny * wy + nz * wz;
  out.slip = Eigen::Vector3d(wx - wn * nx, wy - wn * ny, wz - wn * nz);
}

// Wrench stage, after the friction: the point's force on one side's body and its moment
// about that body's origin o, on B F_B and (p - o) x F_B + M, on A -F_B and
// (p - o) x (-F_B) - M (each side's sum is formed where it is needed: the other is not).
// On components, like contactKinematics; the sign flips are exact.
inline void contactWrench(const ContactRecord& rec, const Eigen::Vector3d& origin, bool on_b,
                          Eigen::Vector3d& force, Eigen::Vector3d& torque) {
  const Eigen::Vector3d& n = rec.point.normal;
  const Eigen::Vector3d& p = rec.point.position;
  const double fn = rec.normal_force;
  const double s = on_b ? 1.0 : -1.0;
  const double fx = s * (fn * n.x() + rec.friction_force.x());
  const double fy = s * (fn * n.y() + rec.friction_force.y());
  const double fz = s * (fn * n.z() + rec.friction_force.z());
  force = Eigen::Vector3d(fx, fy, fz);
  const double rx = p.x() - origin.x(), ry = p.y() - origin.y(), rz = p.z() - origin.z();
  torque = Eigen::Vector3d((ry * fz - rz * fy) + s * rec.moment.x(),
                           (rz * fx - rx * fz) + s * rec.moment.y(),
                           (rx * fy - ry * fx) + s * rec.moment.z());
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
