// The mutable state of a run: what is needed to restart it bit for bit. Cheap to copy.
//
// One BodyState per model body (index = BodyIndex::value); kinematic bodies are set from
// time by the simulator. Stateful friction laws keep one StickAnchor per contact point,
// sorted by its persistent contact key (contact/stick_anchor.hpp); memoryless laws none.
// Dynamic friction laws (friction/dynamic_law.hpp) keep one record per contact point in
// friction_states, sorted by the same keys, whose internal state z is the slice
// [state, state + state_size) of friction_values: integrated with the bodies.
#pragma once

#include <vector>

#include "contact/stick_anchor.hpp"
#include "core/math.hpp"

namespace tribo {

struct BodyState {
  Vec3 position = Vec3::Zero();          // world [m]
  Quat orientation = Quat::Identity();   // body to world, unit
  Vec3 velocity = Vec3::Zero();          // world [m/s]
  Vec3 angular_velocity = Vec3::Zero();  // world [rad/s]
};

struct State {
  double time = 0.0;  // [s]
  std::vector<BodyState> bodies;
  std::vector<contact::StickAnchor> stick_anchors;    // stateful friction, sorted by key
  std::vector<contact::StickAnchor> friction_states;  // dynamic friction, sorted by key
  std::vector<double> friction_values;                // their internal states, z
};

}  // namespace tribo
