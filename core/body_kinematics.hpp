// The pose and velocity of one body's origin at a state, as the force elements read them
// (core/bushing.hpp, core/torsional_spring.hpp); the world's for BodyIndex::world(): at the
// origin, unrotated, at rest. Kinematic bodies move as their state says.
// Not here: the state itself (core/state.hpp), accelerations.
#pragma once

#include <vector>

#include "core/body.hpp"
#include "core/state.hpp"

namespace tribo {

struct BodyKinematics {
  Vec3 position = Vec3::Zero();          // origin, world [m]
  Quat orientation = Quat::Identity();   // body to world, unit
  Mat3 rotation = Mat3::Identity();      // the same as a matrix
  Vec3 velocity = Vec3::Zero();          // of the origin, world [m/s]
  Vec3 angular_velocity = Vec3::Zero();  // world [rad/s]

  // Velocity of the body's material point at world position p [m/s].
  Vec3 pointVelocity(const Vec3& p) const {
    return velocity + angular_velocity.cross(p - position);
  }
};

// Body `b` at `state`; `rotation`: the state's body-to-world rotations (Workspace::rotation).
inline BodyKinematics bodyKinematics(const State& state, const std::vector<Mat3>& rotation,
                                     BodyIndex b) {
  if (b.isWorld()) return {};
  const BodyState& s = state.bodies[b.value];
  return {s.position, s.orientation, rotation[b.value], s.velocity, s.angular_velocity};
}

}  // namespace tribo
