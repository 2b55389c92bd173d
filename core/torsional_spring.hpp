// A torsional spring-damper between body A (or the world) and body B about an axis fixed in A:
//
//   tau_B = -(k delta + c theta') g,   tau_A = -tau_B,   delta = wrap(theta - theta0)
//   theta = atan2(v_A . u_B, u_A . u_B)   in (-pi, pi]
//   theta' = (w_B - w_A) . g,   g = u_B x (x v_A - y u_A) / (x^2 + y^2),
//            x = u_A . u_B,  y = v_A . u_B
// with a_A the axis (unit, fixed in A), u_A a unit vector normal to it fixed in A, v_A =
// a_A x u_A, and u_B fixed in B, equal to u_A at the initial configuration (theta = 0 there;
// the spring is relaxed at theta0, `rest_angle`). theta is the angle, about A's axis, of
// u_B's projection on A's plane normal to the axis; g is its gradient (d theta = g . (rotation
// of B - rotation of A)), so the torque is the exact gradient of V = 1/2 k delta^2: energy
// (without damping) and angular momentum are conserved, and the damper dissipates c theta'^2.
// While the bodies stay coaxial (a revolute joint, or any motion that keeps u_B normal to
// the axis) g = a_A and this is the familiar tau = -(k (theta - theta0) + c theta') a_A, the
// rotational spring-damper of multibody codes (Adams' SPRINGDAMPER with ROTATION, Simbody's
// Force::MobilityLinearSpring on a pin); g is derived here: d/dt atan2(y, x) with u_A, v_A
// turning with A and u_B with B.
// When they also rotate about other axes, theta remains the angle, about A's axis, of u_B's
// projection on A's plane normal to that axis: a tilt changes it only as far as it turns that
// projection. g then leaves the axis, so the torque has components normal to a_A (those of
// the same potential, still equal and opposite on the two bodies); nothing resists the tilt
// itself (hold the bodies coaxial with a joint for that). When u_B is parallel to A's axis
// (B tilted by 90 degrees) theta is undefined and the element carries no torque.
// Not here: windings (theta is taken in (-pi, pi], as joint springs' angles: a spring wound
// past half a turn from its rest angle flips, and the potential has a ridge there), stiffness
// about other axes (core/bushing.hpp), nonlinear springs.
#pragma once

#include <string>

#include "core/body_kinematics.hpp"

namespace tribo {

struct TorsionalSpring {
  std::string name;
  BodyIndex body_a = BodyIndex::world();
  BodyIndex body_b;
  Vec3 axis_a = Vec3::UnitZ();       // a_A in A's body frame (world for the world), unit
  Vec3 reference_a = Vec3::UnitX();  // u_A in A's body frame, unit, normal to axis_a
  Vec3 reference_b = Vec3::UnitX();  // u_B in B's body frame, unit
  double stiffness = 0.0;            // k [N m/rad]
  double damping = 0.0;              // c [N m s/rad]
  double rest_angle = 0.0;           // theta0 [rad], from the initial configuration
};

struct TorsionalDeflection {
  double angle = 0.0;            // delta = wrap(theta - theta0) [rad]
  double rate = 0.0;             // theta' [rad/s]
  Vec3 gradient = Vec3::Zero();  // g, world (zero where theta is undefined)
};

TorsionalDeflection torsionalDeflection(const TorsionalSpring& spring, const BodyKinematics& a,
                                        const BodyKinematics& b);
// tau_B (world) [N m]; body A gets -tau_B.
Vec3 torsionalTorque(const TorsionalSpring& spring, const TorsionalDeflection& deflection);
// V = 1/2 k delta^2 [J].
double torsionalEnergy(const TorsionalSpring& spring, const TorsionalDeflection& deflection);

}  // namespace tribo
