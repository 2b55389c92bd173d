// The motion of a kinematic body whose velocity varies in time: each component of the
// origin's velocity is a signal (core/signal.hpp) and the body may turn at a rate that is a
// signal about one fixed world axis (or at a constant angular velocity):
//
//   v(t) = (v_x(t), v_y(t), v_z(t)),      p(t) = p_0 + int_0^t v
//   w(t) = r(t) e,                        q(t) = R(e, int_0^t r) q_0
//
// with the integrals in closed form (or the signal's Gauss-Kronrod sum for an expression), so
// the pose and velocity at any time are exact whatever the integrator: the Simulator places
// the body after each step, rk4 at each stage, the SUNDIALS systems at each evaluation (so
// every force evaluation sees the body where its signals put it); v'(t) and r'(t) e are its
// accelerations. A kinematic body moving at one constant velocity has no PrescribedMotion
// and moves as before (core/body.hpp).
// Not here: a turn whose axis changes direction (no closed form for the orientation: a
// revolute joint driven along a signal turns a body about any axis, core/joint_elements.hpp),
// joints to such a body (ModelBuilder refuses them: the constraint rows carry dynamic bodies'
// accelerations only), reading the scene keys (io/scene_bodies.cpp).
#pragma once

#include <array>
#include <vector>

#include "core/body.hpp"
#include "core/math.hpp"
#include "core/signal.hpp"
#include "core/state.hpp"

namespace tribo {

struct PrescribedMotion {
  std::array<Signal, 3> velocity;  // world [m/s]
  Vec3 spin_axis = Vec3::UnitZ();  // e, unit, world
  Signal spin_rate;                // r [rad/s]

  // The pose and velocity at time t of `body` (whose position and orientation are p_0 and
  // q_0), exact up to the signals' integrals.
  BodyState at(const Body& body, double t) const;
  Vec3 linearAcceleration(double t) const;   // v'(t) [m/s^2]
  Vec3 angularAcceleration(double t) const;  // r'(t) e [rad/s^2]
  // Times where a component is not smooth, increasing and unique.
  std::vector<double> breakpoints() const;
  // Largest |v| and |r| over [0, duration] at 1001 even samples and the breakpoints (a peak
  // narrower than duration / 1000 may be missed), for the step estimate and energy scales.
  double speedBound(double duration) const;
  double spinBound(double duration) const;
  // Room for expression signals' running integrals up to `until` (Signal::reserveIntegral).
  void reserveIntegrals(double until) const;
};

// The bodies that have a PrescribedMotion, in index order: found once a model, so that a
// step does not read every body to find the few it must place (a 20 000-box scene has none).
std::vector<std::size_t> prescribedBodies(const std::vector<Body>& bodies);

// Sets each body of `prescribed` (prescribedBodies(bodies)) to its pose and velocity at
// state.time (after each step, and wherever a state at a time is made from a base).
void placePrescribedBodies(const std::vector<Body>& bodies,
                           const std::vector<std::size_t>& prescribed, State& state);

}  // namespace tribo
