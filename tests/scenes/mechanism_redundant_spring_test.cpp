// A joint dropped as redundant (simulation.constraints.redundant: remove) loses its
// constraint equations only: its elements (spring, damper, friction) still act. A flywheel
// (inertia I about z, no gravity) on a revolute axle to the world, and a second revolute
// joint on the same axis carrying a torsional spring k: the second joint's 5 equations are
// redundant, and the flywheel must oscillate at w = sqrt(k / I) with amplitude q0 (its
// closed form q0 cos(w t)), for inertias and stiffnesses over orders of magnitude. A joint's
// coordinate is 0 at the configuration the scene starts in, so the spring's reference -q0
// is the wheel's yaw 0.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

std::string flywheel(double inertia, double k, double q0, double dt) {
  char text[2048];
  std::snprintf(text, sizeof text, R"(
simulation:
  duration: 10
  time_step: %.17g
  integrator: rk4
  gravity: [0, 0, 0]
  constraints: {redundant: remove}
bodies:
  - {name: wheel, mass: 2, inertia: [%.17g, %.17g, %.17g], rpy: [0, 0, %.17g]}
joints:
  - {name: axle, type: revolute, parent: world, child: wheel, anchor: [0, 0, 0], axis: [0, 0, 1]}
  - {name: drive, type: revolute, parent: world, child: wheel, anchor: [0, 0, 0], axis: [0, 0, 1],
     spring: {stiffness: %.17g, reference: %.17g}}
output: {interval: 0.01, channels: [position, joints]}
)",
                dt, inertia, inertia, inertia, q0, k, -q0);
  return text;
}

TEST(RedundantJointSpring, DroppedJointsSpringStillActs) {
  for (const auto& [inertia, k] : {std::pair{0.01, 1.0}, {0.5, 200.0}, {20.0, 5.0}}) {
    const double w = std::sqrt(k / inertia), q0 = 0.3;
    // 1/200 of the period: RK4's phase error over a few periods stays below 1e-7.
    const double dt = 2 * M_PI / w / 200;
    const io::Scene scene = io::loadSceneFromString(flywheel(inertia, k, q0, dt), "fly.yaml");
    Simulator sim(scene.model);
    const int wheel = scene.model->findBody("wheel")->value;
    double worst = 0;
    while (sim.state().time < 3 * 2 * M_PI / w) {
      const StepStatus status = sim.step();
      ASSERT_TRUE(status.ok) << status.message;
      const Quat& q = sim.state().bodies[wheel].orientation;
      const double yaw = 2 * std::atan2(q.z(), q.w());
      worst = std::max(worst, std::abs(yaw - q0 * std::cos(w * sim.state().time)));
    }
    std::printf("I %g, k %g: worst |yaw - q0 cos(w t)| %.3g rad\n", inertia, k, worst);
    EXPECT_LT(worst, 1e-6 * q0) << inertia << " " << k;
  }
}

}  // namespace
}  // namespace tribo
