// A kinematic body's `velocity` and `angular_velocity` given as signals in a scene
// (io/scene_bodies.cpp, core/prescribed_motion.hpp): a shaker whose velocity is an
// expression of t drives a block on a spring as the closed form of the forced undamped
// oscillator says; a turntable given a ramped rate about z turns by a t^2 / 2 while a
// constant angular velocity keeps its old meaning; and the refusals with file:line and key:
// a signal on a dynamic body, a varying turn about two axes, a joint to the body.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/prescribed_motion.hpp"
#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo::io {
namespace {

using test::replaced;
using test::sceneErrorOf;

// Shaker x = X sin(W t) (X = 0.05 m, W = 4 rad/s) written as its velocity, a block of 2 kg
// on a 200 N/m spring of rest length 1 m to it; no gravity.
const std::string kShaker = R"yaml(parameters: {X: 0.05, W: 4}
simulation: {duration: 3, time_step: 0.001, integrator: rk4, gravity: [0, 0, 0]}
bodies:
  - name: shaker
    kind: kinematic
    velocity: [{expression: "$X * $W * cos($W * t)"
}, 0, 0]
  - {name: block, mass: 2, inertia: [0.01, 0.01, 0.01], position: [1, 0, 0]}
springs:
  - {name: spring, a: shaker, point_a: [0, 0, 0], b: block, point_b: [1, 0, 0], stiffness: 200,
     rest_length: 1}
)yaml";

TEST(ScenePrescribedMotion, AShakerAlongAnExpressionDrivesTheForcedOscillator) {
  const Scene scene = loadSceneFromString(kShaker, "shaker.yaml");
  const Body& shaker = scene.model->bodies[0];
  ASSERT_TRUE(shaker.motion != nullptr);
  EXPECT_NEAR(shaker.velocity.x(), 0.2, 1e-15);  // the value at t = 0, reported as before
  Simulator sim(scene.model);
  const double amplitude = 0.05, omega = 4.0, w = 10.0;
  double worst_shaker = 0.0, worst_block = 0.0;
  for (int i = 0; i < 3000; ++i) {
    ASSERT_TRUE(sim.step().ok);
    const double t = sim.state().time;
    worst_shaker = std::max(worst_shaker, std::abs(sim.state().bodies[0].position.x() -
                                                   amplitude * std::sin(omega * t)));
    const double u = amplitude * w * w / (w * w - omega * omega) *
                     (std::sin(omega * t) - omega / w * std::sin(w * t));
    worst_block = std::max(worst_block, std::abs(sim.state().bodies[1].position.x() - 1.0 - u));
  }
  // The expression's integral is Gauss-Kronrod's (1e-12 of the panel); rk4 at 1 ms as in
  // tests/core/prescribed_motion_test.cpp.
  EXPECT_LT(worst_shaker, 1e-13);
  EXPECT_LT(worst_block, 3e-9 * amplitude);  // measured 1.1e-9
}

const std::string kTurntable = R"(simulation: {duration: 1, time_step: 0.001, gravity: [0, 0, 0]}
bodies:
  - {name: table, kind: kinematic, angular_velocity: [0, 0, {ramp: {rate: 0.5}}]}
  - {name: wheel, kind: kinematic, velocity: [{step: {time: 0.5, before: 0, after: 1}}, 0, 0],
     angular_velocity: [0, 3, 4]}
)";

TEST(ScenePrescribedMotion, ARampedRateTurnsAboutItsAxisAndAConstantOneAsBefore) {
  const Scene scene = loadSceneFromString(kTurntable, "turntable.yaml");
  Simulator sim(scene.model);
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(sim.step().ok);
  const double t = sim.state().time;
  const BodyState& table = sim.state().bodies[0];
  EXPECT_LT(table.orientation.angularDistance(Quat(Eigen::AngleAxisd(0.25 * t * t, Vec3::UnitZ()))),
            1e-14);
  EXPECT_LT((table.angular_velocity - Vec3(0, 0, 0.5 * t)).norm(), 1e-14);
  // The wheel moves along x from 0.5 s on and turns at 5 rad/s about (0, 0.6, 0.8).
  const BodyState& wheel = sim.state().bodies[1];
  EXPECT_NEAR(wheel.position.x(), t - 0.5, 1e-14);
  EXPECT_LT(wheel.orientation.angularDistance(Quat(Eigen::AngleAxisd(5 * t, Vec3(0, 0.6, 0.8)))),
            1e-13);
  EXPECT_LT((wheel.angular_velocity - Vec3(0, 3, 4)).norm(), 1e-14);
}

TEST(ScenePrescribedMotion, RefusalsNameTheFileLineAndKey) {
  // A dynamic body's velocity is an initial value.
  const std::string dynamic = sceneErrorOf(
      replaced(kShaker, "    kind: kinematic\n", "    mass: 1\n    inertia: [1, 1, 1]\n"),
      "shaker.yaml");
  EXPECT_NE(dynamic.find("shaker.yaml:7"), std::string::npos) << dynamic;
  EXPECT_NE(dynamic.find("bodies[0].velocity"), std::string::npos) << dynamic;
  EXPECT_NE(dynamic.find("is for a kinematic body"), std::string::npos) << dynamic;
  // A varying turn about two axes has no closed-form orientation.
  const std::string two = sceneErrorOf(
      replaced(kTurntable, "[0, 0, {ramp: {rate: 0.5}}]", "[0, 1, {ramp: {rate: 0.5}}]"),
      "turntable.yaml");
  EXPECT_NE(two.find("turntable.yaml:3"), std::string::npos) << two;
  EXPECT_NE(two.find("bodies[0].angular_velocity"), std::string::npos) << two;
  EXPECT_NE(two.find("about one world axis"), std::string::npos) << two;
  // A joint cannot follow the body's acceleration.
  const std::string joint =
      sceneErrorOf(kShaker +
                       "joints:\n  - {name: hinge, type: revolute, parent: shaker, child: block, "
                       "anchor: [0, 0, 0], axis: [0, 0, 1]}\n",
                   "shaker.yaml");
  EXPECT_NE(joint.find("joint 'hinge': body 'shaker' moves along signals"), std::string::npos)
      << joint;
}

}  // namespace
}  // namespace tribo::io
