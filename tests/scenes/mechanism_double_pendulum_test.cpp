// scenes/double_pendulum.yaml: an undamped double pendulum released horizontally, a chaotic
// motion whose energy must stay constant over 20 s (RK4: to its fourth order).
#include <gtest/gtest.h>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "support/joint_test_models.hpp"

namespace tribo {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/double_pendulum.yaml";

struct Swing {
  double max_energy_error = 0.0;  // [J]
  double max_phi = 0.0;
  double max_speed = 0.0;  // of the lower rod's centre [m/s]
};

Swing run(const std::vector<std::string>& overrides) {
  const io::Scene scene = io::loadScene(kScene, overrides);
  Simulator sim(scene.model);
  const double e0 = test::mechanicalEnergy(*scene.model, sim.state());
  Swing out;
  while (sim.state().time < 20.0 - 1e-9) {
    const StepStatus status = sim.step();
    EXPECT_TRUE(status.ok) << status.message;
    if (!status.ok) break;
    out.max_energy_error = std::max(
        out.max_energy_error, std::abs(test::mechanicalEnergy(*scene.model, sim.state()) - e0));
    out.max_speed = std::max(out.max_speed, sim.state().bodies[1].velocity.norm());
  }
  out.max_phi = sim.stats().max_constraint_error;
  return out;
}

TEST(DoublePendulumScene, KeepsItsEnergyOverTwentySeconds) {
  // Measured 8.5e-8 J at 1 ms (of m g L = 9.81 J swung through); 2^4 less per halving.
  const Swing h1 = run({"dt=0.001"}), h2 = run({"dt=0.0005"});
  EXPECT_LT(h1.max_energy_error, 1e-6);
  EXPECT_LT(h2.max_energy_error, h1.max_energy_error / 8);
  EXPECT_LT(h1.max_phi, 1e-8);
  EXPECT_GT(h1.max_speed, 5.0);  // it did swing hard
}

}  // namespace
}  // namespace tribo
