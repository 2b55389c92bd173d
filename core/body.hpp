// Description of one rigid body in the model (immutable once built).
//
// A dynamic body obeys Newton-Euler: m a = F, I_W dw/dt = T - w x I_W w (I_W = R I_B R^T,
// inertia about the centre of mass, which is the body origin). A kinematic body moves with
// a prescribed velocity, whatever acts on it: constant, or varying in time along signals
// (core/prescribed_motion.hpp). Either may carry a surface velocity
// (body frame): its surface slides past contacts while its geometry stays put (a belt),
// constant or, with a signal per component (core/signal.hpp), varying in time (a belt whose
// speed is modulated: Popp & Stelter 1990's road to period doubling).
// Not here: state (core/state.hpp), geometry (Model::geometries).
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/math.hpp"
#include "core/signal.hpp"

namespace tribo {

// Typed body index; kWorld is the fixed world frame.
struct BodyIndex {
  int value = -1;
  static constexpr int kWorldValue = -1;
  static BodyIndex world() { return {kWorldValue}; }
  bool isWorld() const { return value == kWorldValue; }
  bool operator==(const BodyIndex&) const = default;
};

enum class BodyKind { kDynamic, kKinematic };

struct PrescribedMotion;  // core/prescribed_motion.hpp

struct Body {
  std::string name;
  BodyKind kind = BodyKind::kDynamic;
  double mass = 1.0;                     // [kg]
  Mat3 inertia = Mat3::Identity();       // about the origin, body frame [kg m^2]
  Vec3 position = Vec3::Zero();          // initial, world [m]
  Quat orientation = Quat::Identity();   // initial, body to world
  Vec3 velocity = Vec3::Zero();          // initial (or prescribed), world [m/s]
  Vec3 angular_velocity = Vec3::Zero();  // initial (or prescribed), world [rad/s]
  Vec3 surface_velocity = Vec3::Zero();  // each geometry's frame [m/s] (surfaceVelocityOf)
  // When set, the surface velocity at time t is (s_x(t), s_y(t), s_z(t)); surface_velocity
  // then holds its value at t = 0. Held apart (three signals are most of a kilobyte) so that
  // a body is a few cache lines and the steps' loops over bodies read them densely.
  std::shared_ptr<const std::array<Signal, 3>> surface_velocity_signal = nullptr;
  // Kinematic bodies only: when set, the pose and velocity at time t follow signals;
  // position, orientation, velocity and angular_velocity then hold their values at t = 0.
  std::shared_ptr<const PrescribedMotion> motion = nullptr;

  // Its mass if it is dynamic, 0 if it is kinematic (ModelBuilder accepts a dynamic body only
  // with a finite mass > 0, so 0 marks a kinematic body): the per-body lists the step's
  // passes read instead of this record (Dynamics, EnergyTerms).
  double dynamicMass() const { return kind == BodyKind::kDynamic ? mass : 0.0; }

  Vec3 surfaceVelocityAt(double t) const {
    if (!surface_velocity_signal) return surface_velocity;
    const auto& s = *surface_velocity_signal;
    return {s[0].value(t), s[1].value(t), s[2].value(t)};
  }
  // The largest |surface velocity| over [0, duration], for the step estimate and the energy
  // guard's scales: a constant's norm; a signal's largest at 1001 even samples and at its
  // breakpoints (a bound up to the sampling: a peak narrower than duration / 1000 may be
  // missed).
  double surfaceSpeedBound(double duration) const {
    if (!surface_velocity_signal) return surface_velocity.norm();
    std::vector<double> breaks;
    for (const Signal& s : *surface_velocity_signal)
      for (double t : s.breakpoints()) breaks.push_back(t);
    return sampledBound(duration, breaks, [&](double t) { return surfaceVelocityAt(t).norm(); });
  }
};

}  // namespace tribo
