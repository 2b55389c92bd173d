// The mutable state of a run: what is needed to restart it bit for bit. Cheap to copy.
//
// One BodyState per model body (index = BodyIndex::value); kinematic bodies are set from
// time by the simulator. Friction memory (its layout and updates: core/friction_states.hpp):
// stateful laws keep one StickAnchor per contact point (contact/stick_anchor.hpp), dynamic
// laws one FrictionStateRecord per contact point (contact/dynamic_friction.hpp), each list
// sorted by the persistent contact key (contact/contact_identity.hpp); friction_values holds
// the dynamic laws' internal states z (the joints' slices, then the records'): integrated
// with the bodies. Memoryless laws keep nothing.
#pragma once

#include <vector>

#include "contact/dynamic_friction.hpp"
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
  std::vector<contact::StickAnchor> stick_anchors;            // stateful friction, sorted by key
  std::vector<contact::FrictionStateRecord> friction_states;  // dynamic friction, by key
  std::vector<double> friction_values;                        // their internal states, z
};

}  // namespace tribo
