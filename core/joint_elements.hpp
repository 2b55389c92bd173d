// What acts on the scalar coordinate q of a revolute (angle [rad]) or prismatic (slide [m])
// joint, as a generalized force tau along the joint axis (torque [N m] or force [N]):
//   limit:    tau = -max(0, k (q - upper) + c q')  above upper, +max(0, k (lower - q) - c q')
//             below lower: a penalty that only pushes back into the range, like a contact
//   spring:   tau = -k (q - reference)
//   damping:  tau = -c q'
//   effort:   tau = constant (a motor torque or force)
//   friction: tau = -mu(v) N r s/|s| through the (memoryless) friction-law strategy, with the
//             slip speed v = r q' (revolute, r = pin radius) or v = q' (prismatic, r = 1), and
//             the normal load N either the joint's reaction force (revolute: its magnitude;
//             prismatic: its part normal to the axis) or a constant
//   actuator: a motor or a position or velocity servo commanded by a time signal, saturated
//             at its effort limit (core/joint_actuator.hpp)
//   drive:    a rheonomic constraint q = f(t) (position) or q' = f(t) (velocity), with
//             f(t) = c0 + c1 t + A sin(w t + phi) or any time signal (core/signal.hpp: its
//             derivatives, and in velocity mode its integral from 0, give the rest; a step
//             in a velocity drive is a jump of the prescribed rate that Baumgarte or the
//             velocity projection, core/constraint_options.hpp, catches up with)
// and couplings (URDF mimic): q_follower = multiplier q_leader + offset, a constraint.
// q = 0 where the joint frames coincide (the initial configuration for scene joints);
// angles are wrapped to (-pi, pi], so limits and springs see |q| <= pi.
// Not here: evaluating any of it (core/joint_forces.hpp, core/constraint_rows.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "core/joint_actuator.hpp"
#include "core/signal.hpp"
#include "friction/friction_law.hpp"

namespace tribo {

struct JointLimit {
  double lower = 0.0;      // [rad or m]
  double upper = 0.0;      // [rad or m]
  double stiffness = 0.0;  // [N m/rad or N/m]; 0: derived by ModelBuilder::build
  double damping = 0.0;    // [N m s/rad or N s/m]; used with a derived stiffness when 0
};

struct JointSpring {
  double stiffness = 0.0;  // [N m/rad or N/m]
  double reference = 0.0;  // q where the spring is relaxed [rad or m]
};

enum class JointFrictionLoad { kReaction, kConstant };

struct JointFriction {
  std::shared_ptr<const friction::FrictionLaw> law;
  JointFrictionLoad load = JointFrictionLoad::kReaction;
  double normal_force = 0.0;  // constant load [N] (kConstant)
  double radius = 1.0;        // revolute: pin radius [m]; prismatic: unused
};

// f(t) = c0 + c1 t + A sin(w t + phi), and its first two derivatives.
struct DriveFunction {
  double constant = 0.0;   // c0
  double slope = 0.0;      // c1 [1/s]
  double amplitude = 0.0;  // A
  double frequency = 0.0;  // w [rad/s]
  double phase = 0.0;      // phi [rad]

  double value(double t) const {
    return constant + slope * t + amplitude * std::sin(frequency * t + phase);
  }
  double rate(double t) const {
    return slope + amplitude * frequency * std::cos(frequency * t + phase);
  }
  double acceleration(double t) const {
    return -amplitude * frequency * frequency * std::sin(frequency * t + phase);
  }
  // Integral over [0, t].
  double integral(double t) const {
    const double periodic =
        frequency != 0.0
            ? amplitude * (std::cos(phase) - std::cos(frequency * t + phase)) / frequency
            : amplitude * std::sin(phase) * t;
    return constant * t + 0.5 * slope * t * t + periodic;
  }
};

enum class DriveMode { kPosition, kVelocity };

struct JointDrive {
  DriveMode mode = DriveMode::kPosition;
  DriveFunction function;
  std::optional<Signal> signal = std::nullopt;  // when set, f(t) in place of `function`

  // Prescribed q(t), q'(t), q''(t); in velocity mode q(0) = 0.
  double position(double t) const {
    if (signal) return mode == DriveMode::kPosition ? signal->value(t) : signal->integral(t);
    return mode == DriveMode::kPosition ? function.value(t) : function.integral(t);
  }
  double velocity(double t) const {
    if (signal) return mode == DriveMode::kPosition ? signal->derivative(t) : signal->value(t);
    return mode == DriveMode::kPosition ? function.rate(t) : function.value(t);
  }
  double acceleration(double t) const {
    if (signal)
      return mode == DriveMode::kPosition ? signal->secondDerivative(t) : signal->derivative(t);
    return mode == DriveMode::kPosition ? function.acceleration(t) : function.rate(t);
  }
  // The largest |q'| over [0, duration]: the function's bound, or the signal's largest at
  // 1001 even samples and at its breakpoints.
  double speedBound(double duration) const {
    if (!signal) {
      const DriveFunction& f = function;
      return mode == DriveMode::kPosition
                 ? std::abs(f.slope) + std::abs(f.amplitude * f.frequency)
                 : std::abs(f.constant) + std::abs(f.slope) * duration + std::abs(f.amplitude);
    }
    return sampledBound(duration, signal->breakpoints(),
                        [&](double t) { return std::abs(velocity(t)); });
  }
};

struct JointElements {
  std::optional<JointLimit> limit;
  std::optional<JointSpring> spring;
  double damping = 0.0;  // [N m s/rad or N s/m]
  double effort = 0.0;   // [N m or N]
  std::optional<JointFriction> friction;
  std::optional<JointDrive> drive;
  std::optional<JointActuator> actuator;
  // The joint's rated effort and speed (URDF <limit effort velocity>; infinite where none is
  // given): the defaults of an actuator's saturation.
  double rated_effort = std::numeric_limits<double>::infinity();    // [N m or N]
  double rated_velocity = std::numeric_limits<double>::infinity();  // [rad/s or m/s]

  // True when a force (not a constraint) acts on the coordinate.
  bool hasForces() const {
    return limit || spring || damping != 0.0 || effort != 0.0 || friction || actuator;
  }
};

// q_follower = multiplier * q_leader + offset between the coordinates of two revolute or
// prismatic joints (multiplier in units of q_follower per unit of q_leader).
struct JointCoupling {
  std::string name;
  int leader = -1;    // joint index
  int follower = -1;  // joint index
  double multiplier = 1.0;
  double offset = 0.0;
};

}  // namespace tribo
