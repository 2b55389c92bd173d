// scenes/slider_crank.yaml: a crank driven at 2 pi rad/s moves a slider through a connecting
// rod (a closed loop written with revolute joints and a prismatic rail, whose 3 repeated
// equations are dropped). The slider follows the closed-form kinematics
//   x = r cos(w t) + sqrt(l^2 - r^2 sin^2(w t)).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "study/scene_run.hpp"

namespace tribo {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/slider_crank.yaml";
constexpr double kR = 0.1, kL = 0.4, kW = 2 * std::numbers::pi;

TEST(SliderCrankScene, SliderFollowsTheClosedFormKinematics) {
  for (const char* projection : {"false", "true"}) {
    const io::Scene scene = io::loadScene(kScene, {std::string("projection=") + projection});
    Simulator sim(scene.model);
    const int slider = scene.model->findBody("slider")->value;
    double worst_x = 0.0, worst_v = 0.0;
    for (int i = 0; i < 2000; ++i) {
      ASSERT_TRUE(sim.step().ok);
      const double th = kW * sim.state().time, s = std::sin(th), c = std::cos(th);
      const double root = std::sqrt(kL * kL - kR * kR * s * s);
      const double x = kR * c + root, v = -kR * kW * s - kR * kR * kW * s * c / root;
      worst_x = std::max(worst_x, std::abs(sim.state().bodies[slider].position.x() - x));
      worst_v = std::max(worst_v, std::abs(sim.state().bodies[slider].velocity.x() - v));
    }
    // Measured 3e-11 m and 9e-10 m/s (RK4, 1 ms).
    EXPECT_LT(worst_x, 1e-9) << "projection " << projection;
    EXPECT_LT(worst_v, 1e-8) << "projection " << projection;
    EXPECT_LT(sim.stats().max_constraint_error, 1e-10) << "projection " << projection;
  }
}

TEST(SliderCrankScene, TheLoopsRepeatedEquationsAreDroppedAndReported) {
  const io::Scene scene = io::loadScene(kScene, {"duration=0.01"});
  int dropped = 0;
  for (const Joint& j : scene.model->joints) dropped += __builtin_popcount(j.dropped_equations);
  EXPECT_EQ(dropped, 3);  // 3 bodies, 21 equations, no degree of freedom left
  const study::RunResult r = study::runScene(scene);
  ASSERT_TRUE(r.complete) << r.message;
  bool warned = false;
  for (const auto& w : r.warnings) warned = warned || w.find("redundant") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(SliderCrankScene, WithoutPermissionTheRedundancyIsALocatedError) {
  std::ifstream in(kScene);
  std::string yaml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  yaml.replace(yaml.find("redundant: remove}"), 17, "redundant: error");
  try {
    io::loadSceneFromString(yaml, "crank.yaml");
    FAIL() << "no error";
  } catch (const io::SceneError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("crank.yaml"), std::string::npos) << m;
    EXPECT_NE(m.find("redundant constraints"), std::string::npos) << m;
    EXPECT_NE(m.find("joint 'rail'"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace tribo
