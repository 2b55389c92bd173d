// The compound pendulum of scenes/robots/pendulum.urdf written as a scene file's bodies and
// joints: a 2 kg arm (inertia 0.2, 0.2, 0.01 kg m^2 about its centre) whose centre hangs
// 0.5 m below a hinge about y at `hinge`, started at angle q about +y from hanging, RK4 at
// 1 ms. The reference the URDF routes are compared with. Not a general scene builder.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "core/math.hpp"

namespace tribo::test {

inline std::string pendulumSceneYaml(double q, const Vec3& hinge, double duration) {
  char text[1024];
  std::snprintf(text, sizeof text, R"(
simulation: {duration: %.17g, time_step: 0.001, integrator: rk4, gravity: [0, 0, -9.81]}
bodies:
  - {name: arm, mass: 2.0, inertia: [0.2, 0.2, 0.01], position: [%.17g, %.17g, %.17g],
     orientation: [%.17g, 0, %.17g, 0]}
joints:
  - {name: hinge, type: revolute, parent: world, child: arm, anchor: [%.17g, %.17g, %.17g],
     axis: [0, 1, 0]}
)",
                duration, hinge.x() - 0.5 * std::sin(q), hinge.y(), hinge.z() - 0.5 * std::cos(q),
                std::cos(q / 2), std::sin(q / 2), hinge.x(), hinge.y(), hinge.z());
  return text;
}

}  // namespace tribo::test
