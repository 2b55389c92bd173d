// scenes/experiments/velocity_steps.yaml: a block in steady sliding at V1 whose prescribed
// speed (a velocity drive along an expression signal with its breakpoints) steps to V2 at
// t_up and back to V1 at t_down, under rate-and-state friction with the aging and the slip
// law, against the law's closed form at piecewise-constant slip speed (written here):
//   aging (d theta/dt = 1 - V theta / d_c, linear in theta): on each interval of speed V from
//     theta_s at t_s, theta(t) = d_c / V + (theta_s - d_c / V) exp(-V (t - t_s) / d_c);
//   slip (d psi/dt = -(V / d_c)(psi - ln(v0 / V)), psi = ln(v0 theta / d_c)): psi relaxes to
//     ln(v0 / V) the same way;
//   mu = a asinh((V / 2 v0) exp((mu0 + b psi) / a)),
// so the coefficient jumps by a ln(V2 / V1) at t_up and by a ln(V1 / V2) at t_down, and
// relaxes to (a - b) ln(V2 / V1) from the first level and back. The scene's step (2^-10 s)
// lands on both jumps; the state then follows the speed exactly up to RK4's error, ~1e-12 in
// mu at 1/100 of the fastest relaxation time (tests/scenes/rate_state_velocity_step_test.cpp
// measures it at a single step). Also checked: the block's position is the area under the
// speed signal (the drive's integral), and its speed is V2 from t_up on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "support/contact_coefficient.hpp"

namespace tribo {
namespace {

const std::string kScene =
    std::string(TRIBO_SOURCE_DIR) + "/scenes/experiments/velocity_steps.yaml";
constexpr double kMu0 = 0.6, kA = 0.01, kB = 0.015, kDc = 1e-5, kV0 = 1e-6;
constexpr double kV1 = 1e-5, kV2 = 1e-4, kUp = 1.0, kDown = 2.0;

double speedAt(double t) { return t < kUp ? kV1 : t < kDown ? kV2 : kV1; }

// psi(t) from the steady state at V1, through the two steps.
double psiAt(double t, bool aging) {
  auto relax = [&](double from, double v, double dt) {
    const double decay = std::exp(-v * dt / kDc);
    if (aging) {
      const double theta = kDc / kV0 * std::exp(from);  // psi -> theta
      return std::log(kV0 / kDc * (kDc / v + (theta - kDc / v) * decay));
    }
    return std::log(kV0 / v) + (from - std::log(kV0 / v)) * decay;
  };
  double psi = std::log(kV0 / kV1);
  if (t <= kUp) return psi;
  psi = relax(psi, kV2, std::min(t, kDown) - kUp);
  if (t <= kDown) return psi;
  return relax(psi, kV1, t - kDown);
}

double muOf(double v, double psi) {
  return kA * std::asinh(v / (2 * kV0) * std::exp((kMu0 + kB * psi) / kA));
}

double engineMu(Simulator& sim) { return test::contactCoefficient(sim); }

void checkSteps(const char* evolution) {
  const bool aging = std::string(evolution) == "aging";
  const io::Scene scene = io::loadScene(kScene, {std::string("evolution=") + evolution});
  Simulator sim(scene.model);
  const double x0 = sim.state().bodies[1].position.x();
  // Just after each jump, through each relaxation, and at the end.
  const std::vector<double> times = {0.5,          kUp + 0.0009765625,   1.05, 1.1, 1.2, 1.5,
                                     1.9990234375, kDown + 0.0009765625, 2.5,  3.0, 4.0, 8.0};
  double worst_mu = 0, worst_x = 0, worst_v = 0;
  for (double at : times) {
    while (sim.state().time < at - 1e-12) {
      const StepStatus status = sim.step();
      ASSERT_TRUE(status.ok) << status.message;
      const double t = sim.state().time;
      // The area under the speed signal, and the speed (the new one from a jump's step on).
      const double area = kV1 * t + (kV2 - kV1) * std::clamp(t - kUp, 0.0, kDown - kUp);
      worst_x = std::max(worst_x, std::abs(sim.state().bodies[1].position.x() - x0 - area));
      worst_v = std::max(worst_v, std::abs(sim.state().bodies[1].velocity.x() - speedAt(t)));
    }
    const double t = sim.state().time;
    const double mu = engineMu(sim);
    // The contacts' forces at the step's end: the state at t, the speed after any jump at t.
    const double want = muOf(speedAt(t), psiAt(t, aging));
    worst_mu = std::max(worst_mu, std::abs(mu - want));
    EXPECT_NEAR(mu, want, 1e-11) << evolution << " t " << t;
  }
  std::printf("%s: worst |mu - closed form| %.2g, |x - area| %.2g m, |v - V| %.2g m/s\n", evolution,
              worst_mu, worst_x, worst_v);
  EXPECT_LT(worst_x, 1e-12);  // of 1.6e-4 m travelled
  EXPECT_LT(worst_v, 1e-14);  // of speeds 1e-5 .. 1e-4 m/s
  // The direct effects and the steady change, read off the closed form's own levels.
  EXPECT_NEAR(muOf(kV2, std::log(kV0 / kV1)) - muOf(kV1, std::log(kV0 / kV1)),
              kA * std::log(kV2 / kV1), 1e-12);
  EXPECT_NEAR(muOf(kV2, std::log(kV0 / kV2)) - muOf(kV1, std::log(kV0 / kV1)),
              (kA - kB) * std::log(kV2 / kV1), 1e-12);
}

TEST(RateStateVelocitySteps, AgingLawUpAndDownFollowsTheClosedForm) { checkSteps("aging"); }

TEST(RateStateVelocitySteps, SlipLawUpAndDownFollowsTheClosedForm) { checkSteps("slip"); }

}  // namespace
}  // namespace tribo
