// Force elements: a linear spring-damper between a point of one body and a point of
// another body (or the world).
//
//   F_B = -(k (L - L0) + c dL/dt) e,   e = (p_B - p_A) / L,   F_A = -F_B
// with L the distance between the attachment points. Not here: nonlinear springs; bushings
// (core/bushing.hpp) and torsional springs (core/torsional_spring.hpp).
#pragma once

#include <string>

#include "core/body.hpp"

namespace tribo {

struct SpringDamper {
  std::string name;
  BodyIndex body_a = BodyIndex::world();
  Vec3 point_a = Vec3::Zero();  // in A's frame (world frame for the world) [m]
  BodyIndex body_b;
  Vec3 point_b = Vec3::Zero();  // in B's frame [m]
  double stiffness = 0.0;       // k [N/m]
  double damping = 0.0;         // c [N s/m]
  double rest_length = 0.0;     // L0 [m]
};

}  // namespace tribo
