// The mutable state of a run: what is needed to restart it bit for bit. Cheap to copy.
//
// One BodyState per model body (index = BodyIndex::value); kinematic bodies are set from
// time by the simulator. Memoryless friction laws keep no state, so there is none here yet.
#pragma once

#include <vector>

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
};

}  // namespace tribo
