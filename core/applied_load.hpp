// An applied load: a force and a torque given as functions of time (core/signal.hpp) acting
// on one dynamic body, the external inputs of a test rig (a pushing actuator, a shaker, a
// motor torque), as opposed to the force elements, which depend on the state.
//
// Components (f, tau) are in the world frame, or with frame: body in the body's frame,
// turning with it (a follower load). The force acts at `point` r (body frame, from the
// body origin, which is its centre of mass). On the body, world, at time t:
//   F = f(t)             or  R f(t)        (frame: body)
//   T = tau(t) + r_W x F with r_W = R r,   tau(t) or R tau(t)
// Power delivered: P = F . (v + w x r_W) + tau_W . w = F . v + T . w, counted by the energy
// account as a source (core/energy.hpp), like the joint elements.
// Not here: loads on kinematic bodies or between two bodies (no reaction is applied
// anywhere: the load comes from outside the model), loads depending on the state
// (actuators with feedback), time signals driving kinematic bodies or surface velocities;
// evaluating it in the step (core/applied_loads.hpp).
#pragma once

#include <array>
#include <string>

#include "core/body_kinematics.hpp"
#include "core/signal.hpp"

namespace tribo {

enum class LoadFrame { kWorld, kBody };

struct AppliedLoad {
  std::string name;
  BodyIndex body;
  std::array<Signal, 3> force{};   // f_x, f_y, f_z [N]
  std::array<Signal, 3> torque{};  // tau_x, tau_y, tau_z [N m]
  LoadFrame frame = LoadFrame::kWorld;
  Vec3 point = Vec3::Zero();  // where the force acts, body frame from the origin [m]
};

}  // namespace tribo
