// Bushings and torsional springs from scene files: scenes/flywheel_torsion.yaml against its
// closed forms (sqrt(k/I), and the decay rate c / (2I) with damping) for parameters given on
// the command line, a bushing whose gains and frames are expressions (a frame turned so a
// mixed-up axis gives another frequency), and mistakes located at their key.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo {
namespace {

constexpr double kPi = std::numbers::pi;
const std::string kFlywheel = std::string(TRIBO_SOURCE_DIR) + "/scenes/flywheel_torsion.yaml";

double yaw(const BodyState& s) { return 2 * std::atan2(s.orientation.z(), s.orientation.w()); }

TEST(ForceElementScenes, FlywheelTorsionOscillatesAtSqrtKOverI) {
  // The scene's own parameters, and overrides over orders of magnitude.
  for (const auto& [iz, k] : {std::pair{0.05, 8.0}, {2e-6, 0.5}, {30.0, 1e5}}) {
    const io::Scene scene =
        io::loadScene(kFlywheel, {"i_z=" + std::to_string(iz), "k=" + std::to_string(k)});
    const double w = std::sqrt(k / iz), q0 = 0.3;
    // The scene's step, dt = 2 pi / w / 200, computed here from the same closed form.
    EXPECT_NEAR(scene.model->options.time_step, 2 * kPi / w / 200, 1e-12 / w);
    Simulator sim(scene.model);
    const int wheel = scene.model->findBody("flywheel")->value;
    double worst = 0.0;
    for (int s = 0; s < 600; ++s) {
      const StepStatus status = sim.step();
      ASSERT_TRUE(status.ok) << status.message;
      worst = std::max(
          worst, std::abs(yaw(sim.state().bodies[wheel]) - q0 * std::cos(w * sim.state().time)));
    }
    std::printf("flywheel_torsion I %g, k %g: worst |yaw - q0 cos(w t)| / q0 %.2e\n", iz, k,
                worst / q0);
    // RK4, 600 steps at w h = 2 pi / 200: phase error 1.5e-7 (tests/core/bushing_test.cpp).
    EXPECT_LT(worst, 1e-6 * q0);
  }
}

TEST(ForceElementScenes, FlywheelTorsionDampedDecaysAtCOver2I) {
  const double iz = 0.05, k = 8.0, c = 0.03, q0 = 0.3;
  const io::Scene scene = io::loadScene(kFlywheel, {"c=0.03"});
  const double wn = std::sqrt(k / iz), s = c / (2 * iz), wd = std::sqrt(wn * wn - s * s);
  Simulator sim(scene.model);
  double worst = 0.0;
  while (sim.state().time < 3 * 2 * kPi / wd) {
    ASSERT_TRUE(sim.step().ok);
    const double t = sim.state().time;
    const double q = q0 * std::exp(-s * t) * (std::cos(wd * t) + s / wd * std::sin(wd * t));
    worst = std::max(worst, std::abs(yaw(sim.state().bodies[0]) - q));
  }
  std::printf("damped: worst |yaw - closed form| / q0 %.2e\n", worst / q0);
  EXPECT_LT(worst, 1e-6 * q0);  // as undamped (the damping is slow: s / wn = 0.024)
}

// A 0.5 kg block on a bushing to the world. Frame A is turned by 90 degrees about z, so its
// x axis is the world's y: the block, displaced 1 mm along world y or turned 0.1 rad about
// it, moves on A's x gains (k, kr), not on A's y gains (2 k, 2 kr) as unturned frames would.
const std::string kBushing = R"(
parameters:
  m: 0.5
  k: 2.0e4
  kr: 3.0
  i_y: 2.0e-4
simulation:
  duration: 1
  time_step: '2 * pi / sqrt($k / $m) / 200'
  integrator: rk4
  gravity: [0, 0, 0]
bodies:
  - {name: block, mass: $m, inertia: ['2 * $i_y', $i_y, '2 * $i_y'], position: [0, 0.001, 1]}
bushings:
  - name: mount
    a: world
    b: block
    frame_a: {position: [0, 0, 1], rpy: [0, 0, pi / 2]}
    frame_b: {rpy: [0, 0, pi / 2]}
    stiffness: [$k, '2 * $k', '4 * $k']
    damping: [0, 0, 0]
    rotational_stiffness: [$kr, '2 * $kr', '4 * $kr']
    rotational_damping: [0, 0, 0]
)";

TEST(ForceElementScenes, BushingGainsAndFramesFromExpressions) {
  for (bool rotation : {false, true}) {
    std::string yaml = kBushing;
    if (rotation) {
      yaml =
          test::replaced(yaml, "position: [0, 0.001, 1]", "position: [0, 0, 1], rpy: [0, 0.1, 0]");
      yaml = test::replaced(yaml, "time_step: '2 * pi / sqrt($k / $m) / 200'",
                            "time_step: '2 * pi / sqrt($kr / $i_y) / 200'");
    }
    const io::Scene scene = io::loadSceneFromString(yaml, "bushing.yaml");
    ASSERT_EQ(scene.model->bushings.size(), 1u);
    const double w = rotation ? std::sqrt(3.0 / 2e-4) : std::sqrt(2e4 / 0.5);
    const double x0 = rotation ? 0.1 : 1e-3;
    Simulator sim(scene.model);
    double worst = 0.0;
    for (int s = 0; s < 600; ++s) {
      const StepStatus status = sim.step();
      ASSERT_TRUE(status.ok) << status.message;
      const BodyState& b = sim.state().bodies[0];
      // Turned about world y only: the angle is 2 atan2(q_y, q_w).
      const double x =
          rotation ? 2 * std::atan2(b.orientation.y(), b.orientation.w()) : b.position.y();
      worst = std::max(worst, std::abs(x - x0 * std::cos(w * sim.state().time)));
    }
    std::printf("bushing scene %s: worst |x - x0 cos(w t)| / x0 %.2e\n",
                rotation ? "rotation" : "translation", worst / x0);
    EXPECT_LT(worst, 1e-6 * x0);  // RK4, 600 steps at 1/200 of the period
  }
}

std::string errorOf(const std::string& yaml) { return test::sceneErrorOf(yaml, "bushing.yaml"); }

#define EXPECT_HAS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

TEST(ForceElementScenes, MistakesAreLocatedAtTheirKey) {
  using test::replaced;
  // Lines count from the newline that opens kBushing (parameters: is line 2): stiffness is
  // line 20, its '[' at column 16; the rotational stiffness line 22, its second item at 33.
  EXPECT_HAS(errorOf(replaced(kBushing, "[$kr, '2 * $kr', '4 * $kr']", "[$kr, -1, 2]")),
             "bushing.yaml:22:33: bushings[0].rotational_stiffness[1]: expected a number >= 0, "
             "found '-1'");
  EXPECT_HAS(errorOf(replaced(kBushing, "[$k, '2 * $k', '4 * $k']", "[$k, '2 * $k']")),
             "bushing.yaml:20:16: bushings[0].stiffness: expected 3 numbers >= 0 [x, y, z] (per "
             "axis of frame A), found a sequence of 2 items");
  EXPECT_HAS(errorOf(replaced(kBushing, "b: block", "b: blok")),
             "bushing.yaml:17:8: bushings[0].b: unknown body 'blok' (known bodies: world, block)");
  EXPECT_HAS(errorOf(replaced(kBushing, "frame_b: {rpy", "frame_b: {turn")),
             "bushings[0].frame_b.turn: unknown key 'turn' (accepted keys: position, "
             "orientation, rpy)");
  EXPECT_HAS(errorOf(replaced(kBushing, "a: world", "a: block")),
             "bushing.yaml:15:5: bushings[0]: bushing 'mount': both frames on the same body");
  // Torsional springs, on the flywheel scene's text.
  const std::string torsion = R"(
bodies:
  - {name: wheel, mass: 1, inertia: [0.1, 0.1, 0.1]}
torsional_springs:
  - {name: t, a: world, b: wheel, axis: [0, 0, 1], stiffness: 5, damping: 0.1}
)";
  EXPECT_HAS(errorOf(replaced(torsion, "stiffness: 5", "stiffness: -5")),
             "bushing.yaml:5:63: torsional_springs[0].stiffness: expected a number >= 0, found "
             "'-5'");
  EXPECT_HAS(errorOf(replaced(torsion, "damping: 0.1", "damping: -0.1")),
             "torsional_springs[0].damping: expected a number >= 0, found '-0.1'");
  EXPECT_HAS(errorOf(replaced(torsion, "axis: [0, 0, 1]", "axis: [0, 1]")),
             "torsional_springs[0].axis: expected 3 numbers [x, y, z] (the axis, world), found a "
             "sequence of 2 items");
  EXPECT_HAS(errorOf(replaced(torsion, "axis: [0, 0, 1]", "axis: [0, 0, 0]")),
             "torsional_springs[0].axis: expected a non-zero axis");
  EXPECT_HAS(errorOf(replaced(torsion, "b: wheel", "b: wheal")),
             "bushing.yaml:5:28: torsional_springs[0].b: unknown body 'wheal' (known bodies: "
             "world, wheel)");
  EXPECT_HAS(errorOf(replaced(torsion, "damping: 0.1", "damping: 0.1, reference: 1")),
             "torsional_springs[0].reference: unknown key 'reference' (accepted keys: name, a, b, "
             "axis, stiffness, damping, rest_angle)");
}

}  // namespace
}  // namespace tribo
