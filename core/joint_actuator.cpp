#include "core/joint_actuator.hpp"

#include <algorithm>

#include "core/constraint_rows.hpp"

namespace tribo {

ActuatorOutput actuatorEffort(const JointActuator& a, double t, double q, double rate,
                              bool angular) {
  const bool servo = a.kind == ActuatorKind::kPositionServo;
  return actuatorEffortFor(a, a.target.value(t), servo ? a.target.derivative(t) : 0.0, q, rate,
                           angular);
}

ActuatorOutput actuatorEffortFor(const JointActuator& a, double target, double target_rate,
                                 double q, double rate, bool angular) {
  ActuatorOutput out;
  double tau = 0.0;
  switch (a.kind) {
    case ActuatorKind::kMotor:
      out.target = target;
      tau = target;
      break;
    case ActuatorKind::kPositionServo: {
      out.target = target;
      const double e = target - q;
      tau = a.kp * (angular ? wrapAngle(e) : e) + a.kd * (target_rate - rate);
      break;
    }
    case ActuatorKind::kVelocityServo:
      out.target = std::clamp(target, -a.max_velocity, a.max_velocity);
      tau = a.kd * (out.target - rate);
      break;
  }
  out.effort = std::clamp(tau, -a.max_effort, a.max_effort);
  out.saturated = out.effort != tau;
  return out;
}

}  // namespace tribo
