// scenes/andrews_squeezer.yaml: Andrews' squeezing mechanism (IFToMM benchmark library;
// Schiehlen 1990) against its published reference solution: the seven angles at t = 0.03 s
// from Hairer & Wanner 1996 (sec. VII.7) as given by the Test Set for IVP Solvers (Mazzia &
// Magherini, problem "andrews", computed with RADAU5 at tight tolerances).
#include <gtest/gtest.h>

#include <array>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "support/joint_test_models.hpp"

namespace tribo {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/andrews_squeezer.yaml";
// beta, Theta, gamma, Phi, delta, Omega, epsilon at t = 0.03 s [rad].
constexpr std::array<double, 7> kReference = {
    0.1581077119629904e+2, -0.1575637105984298e+2, 0.4082224013073101e-1, -0.5347301163226948e+0,
    0.5244099658805304e+0, 0.5347301163226948e+0,  0.1048080741042263e+1};

double yaw(const BodyState& s) {
  const Mat3 r = s.orientation.toRotationMatrix();
  return std::atan2(r(1, 0), r(0, 0));
}

// The seven test-set angles at the end of the run, from the links' absolute angles.
std::array<double, 7> angles(const std::vector<std::string>& overrides) {
  const io::Scene scene = io::loadScene(kScene, overrides);
  Simulator sim(scene.model);
  std::array<test::Unwrapper, 7> unwrap;
  std::array<double, 7> a{};
  for (int i = 0; i < 7; ++i) a[i] = unwrap[i](yaw(sim.state().bodies[i]));
  const long steps = std::lround(0.03 / scene.model->options.time_step);
  for (long k = 0; k < steps; ++k) {
    const StepStatus status = sim.step();
    EXPECT_TRUE(status.ok) << status.message;
    if (!status.ok) break;
    for (int i = 0; i < 7; ++i) a[i] = unwrap[i](yaw(sim.state().bodies[i]));
  }
  EXPECT_NEAR(sim.state().time, 0.03, 1e-12);
  EXPECT_LT(sim.stats().max_constraint_error, 1e-9);
  return {a[0], a[1] - a[0], a[2], a[3] - a[4], a[4], a[5] - a[6], a[6]};
}

double worstError(const std::array<double, 7>& q) {
  double worst = 0.0;
  for (int i = 0; i < 7; ++i) worst = std::max(worst, std::abs(q[i] - kReference[i]));
  return worst;
}

TEST(AndrewsScene, AnglesAtThirtyMillisecondsMatchThePublishedReference) {
  // Measured 2.9e-9 rad at 10 us (on beta = 15.8 rad: 2 turns and a half); 1.7e-6 at 20 us.
  const double fine = worstError(angles({"dt=1e-5"}));
  const double coarse = worstError(angles({"dt=2e-5"}));
  EXPECT_LT(fine, 1e-8);
  EXPECT_LT(fine, coarse / 8);  // converging to the reference at RK4's order
}

TEST(AndrewsScene, NineOfTheFiftyEquationsAreRedundantInThreeDimensions) {
  const io::Scene scene = io::loadScene(kScene);
  int dropped = 0;
  for (const Joint& j : scene.model->joints) dropped += __builtin_popcount(j.dropped_equations);
  // 7 links (42 coordinates), 10 revolute joints (50 equations), 1 degree of freedom.
  EXPECT_EQ(dropped, 50 - (42 - 1));
}

}  // namespace
}  // namespace tribo
