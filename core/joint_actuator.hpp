// An actuator on the scalar coordinate q of a revolute (angle [rad]) or prismatic (slide [m])
// joint: a generalized force tau along the joint axis, commanded by a time signal
// (core/signal.hpp), the input of a positioning system or a robot's joint controller.
//   motor:           tau = u(t)                                    (u: the signal, an effort)
//   position servo:  tau = kp e + kd (r'(t) - q'),  e = r(t) - q   (PD to the target r)
//   velocity servo:  tau = kd (s(t) - q'),  s = clamp(r(t), -v_max, v_max)
// then saturated: tau = clamp(tau, -tau_max, tau_max). For a revolute joint the angle error
// e is wrapped to (-pi, pi] (q is, core/joint_elements.hpp), so a servo takes the short way
// to its target. tau_max and v_max default to the joint's rated effort and speed (URDF
// <limit effort velocity>; infinite where none is given). r' is the signal's derivative,
// right-continuous at a breakpoint (a step's jump gives no impulse).
// A servo is a spring-damper to a moving reference: unsaturated, a coordinate of inertia I
// answers a step of r with I e'' + kd e' + kp e = 0 (natural frequency sqrt(kp / I), damping
// ratio kd / (2 sqrt(kp I))), and the stable step estimate (core/stability.hpp) counts kp
// and kd as it counts a joint spring and damper.
// Not here: a speed limit on a motor's or a position servo's output (v_max only bounds a
// velocity servo's command), motor dynamics (current, back-EMF, gear inertia), integral
// action, actuators on ball or free joints; evaluating it in the step (core/joint_forces.hpp).
#pragma once

#include <limits>
#include <string>

#include "core/signal.hpp"

namespace tribo {

enum class ActuatorKind { kMotor, kPositionServo, kVelocityServo };

struct JointActuator {
  std::string name;
  ActuatorKind kind = ActuatorKind::kMotor;
  Signal target;    // u(t) [N m or N], r(t) [rad or m] or r(t) [rad/s or m/s]
  double kp = 0.0;  // position servo [N m/rad or N/m]
  double kd = 0.0;  // position and velocity servo [N m s/rad or N s/m]
  double max_effort = std::numeric_limits<double>::infinity();    // tau_max [N m or N]
  double max_velocity = std::numeric_limits<double>::infinity();  // v_max [rad/s or m/s]
};

// What an actuator commanded and gave at one evaluation, for the output channels.
struct ActuatorOutput {
  double target = 0.0;  // u, r or the clamped s at t
  double effort = 0.0;  // tau after saturation
  bool saturated = false;
};

// tau at time t on a coordinate at q (wrapped when `angular`) moving at `rate`
// (core/joint_actuator.cpp).
ActuatorOutput actuatorEffort(const JointActuator& a, double t, double q, double rate,
                              bool angular);
// The same for a given target value and rate in place of the signal's (a command set from
// outside between steps, held over the step: its rate is 0).
ActuatorOutput actuatorEffortFor(const JointActuator& a, double target, double target_rate,
                                 double q, double rate, bool angular);

}  // namespace tribo
