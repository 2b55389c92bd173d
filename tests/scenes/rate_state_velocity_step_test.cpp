// scenes/rate_state_velocity_step.yaml: a block in steady sliding at V1 (state theta = d_c /
// V1) whose prescribed speed steps to V2 at t = 0, under rate-and-state friction with the
// aging and the slip law, against the closed forms of the law at constant slip speed:
//   direct effect:  mu(0+) - mu_ss(V1) = a ln(V2 / V1),
//   steady change:  mu_ss(V2) - mu_ss(V1) = (a - b) ln(V2 / V1),
//   transient (slip speed V2 held): aging theta(t) = d_c / V2 + (d_c / V1 - d_c / V2)
//   exp(-V2 t / d_c) (dtheta/dt = 1 - V2 theta / d_c is linear in theta); slip psi(t) =
//   psi_2 + (psi_1 - psi_2) exp(-V2 t / d_c), psi = ln(v0 theta / d_c), psi_i = ln(v0 / V_i)
//   (dpsi/dt = -(V2 / d_c)(psi - psi_2) is linear in psi);
// mu(t) = a asinh((V2 / 2 v0) exp((mu0 + b psi(t)) / a)), which differs from the logarithmic
// mu0 + a ln(V2 / v0) + b psi by exp(-2 mu / a) ~ 1e-50: the two effects above hold exactly.
// The engine integrates psi with the block's motion (RK4; each of the four corner contacts
// carries its own state) and the coefficient is read from its contact records (sum of the
// friction forces over the sum of the normal forces).
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

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/rate_state_velocity_step.yaml";
constexpr double kMu0 = 0.6, kA = 0.01, kB = 0.015, kDc = 1e-5, kV0 = 1e-6;

double muOf(double v, double psi) {
  return kA * std::asinh(v / (2 * kV0) * std::exp((kMu0 + kB * psi) / kA));
}

// psi(t) at slip speed v2 from the steady state at v1.
double psiAt(double t, double v1, double v2, bool aging) {
  const double decay = std::exp(-v2 * t / kDc);
  if (aging) return std::log(kV0 / kDc * (kDc / v2 + (kDc / v1 - kDc / v2) * decay));
  return std::log(kV0 / v2) + (std::log(kV0 / v1) - std::log(kV0 / v2)) * decay;
}

double engineMu(Simulator& sim) { return test::contactCoefficient(sim); }

void checkStep(double v1, double v2, const char* evolution) {
  const bool aging = std::string(evolution) == "aging";
  const double slip_time = kDc / v2;  // the relaxation time at V2 [s]
  // 40 relaxation times. The state's fastest rate is max(V1, V2) / d_c (aging: dpsi/dt =
  // (1 / theta - V2 / d_c) and theta starts at d_c / V1); steps of 1/100 of its inverse make
  // RK4's error per step (0.01)^5 / 120 ~ 1e-12 of the change, summed over the ~100 steps of
  // the fast part of the transient: ~1e-10 of b ln(V2 / V1) = 0.035, some 1e-12 in mu.
  const double step = kDc / std::max(v1, v2) / 100;
  const io::Scene scene = io::loadScene(
      kScene, {"v1=" + std::to_string(v1), "v2=" + std::to_string(v2),
               std::string("evolution=") + evolution, "duration=" + std::to_string(40 * slip_time),
               "dt=" + std::to_string(step)});
  Simulator sim(scene.model);
  const double mu_ss1 = muOf(v1, std::log(kV0 / v1));
  const double mu_ss2 = muOf(v2, std::log(kV0 / v2));
  // Direct effect: at t = 0 the state still holds V1's steady value.
  const double direct = engineMu(sim) - mu_ss1;
  std::printf("%s %g -> %g: direct effect %.12f (a ln(V2/V1) = %.12f)\n", evolution, v1, v2, direct,
              kA * std::log(v2 / v1));
  EXPECT_NEAR(direct, kA * std::log(v2 / v1), 1e-12) << evolution;
  // The transient at 0.5, 1, 2, 5 relaxation times, and the new steady state at 40.
  double worst = 0;
  for (double n : {0.5, 1.0, 2.0, 5.0, 40.0}) {
    while (sim.state().time < n * slip_time - 1e-12) {
      const StepStatus status = sim.step();
      ASSERT_TRUE(status.ok) << status.message;
    }
    const double t = sim.state().time;
    const double mu = engineMu(sim);
    worst = std::max(worst, std::abs(mu - muOf(v2, psiAt(t, v1, v2, aging))));
    // RK4's error above, ~1e-12; 1e-11.
    EXPECT_NEAR(mu, muOf(v2, psiAt(t, v1, v2, aging)), 1e-11) << evolution << " t " << t;
  }
  const double change = engineMu(sim) - mu_ss1;
  std::printf(
      "%s %g -> %g: steady change %.12f ((a - b) ln(V2/V1) = %.12f), transient error "
      "%.2g\n",
      evolution, v1, v2, change, (kA - kB) * std::log(v2 / v1), worst);
  // At 40 relaxation times the state is e^-40 (4e-18) of its step from steady (aging: b (V2 /
  // V1 - 1) e^-40, slip: b ln(V2 / V1) e^-40, both below 1e-18): RK4's 1e-11 remains.
  EXPECT_NEAR(change, (kA - kB) * std::log(v2 / v1), 1e-11) << evolution;
  EXPECT_NEAR(mu_ss2 - mu_ss1, (kA - kB) * std::log(v2 / v1), 1e-12);
}

TEST(RateStateVelocityStep, AgingLawUpAndDown) {
  checkStep(1e-5, 1e-4, "aging");
  checkStep(1e-4, 1e-5, "aging");
}

TEST(RateStateVelocityStep, SlipLawUpAndDown) {
  checkStep(1e-5, 1e-4, "slip");
  checkStep(1e-4, 1e-5, "slip");
}

}  // namespace
}  // namespace tribo
