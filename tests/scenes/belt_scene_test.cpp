// The paper's belt scene (Roh & Yoo 2007, Fig. 3) through the whole engine: scene file,
// contact with the belt, constraint, integrator, summary. Expectations are independent:
// the linearized growth rate, the harmonic amplitude of a flat friction curve, and a
// converged one-degree-of-freedom reference integrated by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "friction/friction_law.hpp"
#include "io/scene_loader.hpp"
#include "study/scene_run.hpp"
#include "support/one_dof_belt.hpp"

namespace tribo {
namespace {

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";
constexpr double kM = 10.0, kK = 300.0, kG = 9.81, kVb = 1.5;
constexpr double kMuS = 0.35, kMuK = 0.3, kVs = 0.01, kA = 1.5, kBeta = 1.0 / 3.0;

study::RunResult runBelt(const std::vector<std::string>& overrides) {
  const io::Scene scene = io::loadScene(kBelt, overrides);
  study::RunResult r = study::runScene(scene);
  EXPECT_TRUE(r.complete) << r.message;
  return r;
}

std::string set(const std::string& name, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return name + "=" + buf;
}

// Roh-Yoo coefficient on the slip branch, from the paper's closed form (not the library).
double rohYooMu(double v) {
  const double b = -std::log(kMuS - kMuK) / std::log(kA) - kVs;
  return std::pow(kA, -(v + b)) + kMuK;
}

TEST(BeltScene, RohYooEarlyGrowthMatchesLinearizedRate) {
  // Equilibrium: k x_eq = mu(v_b) m g. Start 1 mm away; the envelope grows as e^(sigma t)
  // with sigma = -mu'(v_b) N / (2 m), mu'(v_b) = -ln(a) (mu_s - mu_k) a^-(v_b - v_s).
  const double x_eq = rohYooMu(kVb) * kM * kG / kK;
  const double slope = -std::log(kA) * (kMuS - kMuK) * std::pow(kA, -(kVb - kVs));
  const double sigma = -slope * kM * kG / (2 * kM);
  const study::RunResult r = runBelt({"friction=roh_yoo", set("x0", x_eq + 1e-3), "duration=30"});
  ASSERT_GE(r.summary.cycles.size(), 20u);
  const double measured = study::envelopeGrowthRate(r.summary.cycles, 1.0, 30.0);
  // Asked: within 5%. Measured: 5e-5 (RK4, 1 ms), so hold it to 1%.
  EXPECT_NEAR(measured / sigma, 1.0, 0.01) << "measured " << measured << " expected " << sigma;
  EXPECT_NEAR(r.summary.x_mean, x_eq, 1e-3 * x_eq);
}

TEST(BeltScene, RecurDynAmplitudeDoesNotGrow) {
  // Beyond v_d the RecurDyn curve is flat (mu_k): no negative damping. Released at the
  // spring's neutral point the box oscillates about mu_k m g / k with peak-to-peak
  // 2 mu_k m g / k, and keeps it.
  const study::RunResult r = runBelt({"friction=recurdyn", "duration=60"});
  const double expected = 2 * kMuK * kM * kG / kK;
  EXPECT_NEAR(r.summary.amplitude_pp, expected, 1e-3 * expected);
  ASSERT_GE(r.summary.cycles.size(), 40u);
  EXPECT_NEAR(r.summary.cycles.front().peak_to_peak, expected, 1e-3 * expected);
  EXPECT_LT(std::abs(study::envelopeGrowthRate(r.summary.cycles, 0.0, 60.0)), 1e-4);
  EXPECT_EQ(r.summary.stuck_fraction, 0.0);
}

TEST(BeltScene, RohYooSaturatesIntoTheStickSlipCycleOfTheReference) {
  // Converged 1-DOF reference (RK4, 10 us): the limit-cycle peak-to-peak amplitude.
  const auto law = friction::makeFrictionLaw(
      {"roh_yoo", {{"mu_s", kMuS}, {"mu_k", kMuK}, {"v_s", kVs}, {"a", kA}, {"beta", kBeta}}, {}});
  test::OneDofBelt ref{kM, kK, kVb, kG, law.get()};
  double x = 0.0, v = 0.0, lo = 1e9, hi = -1e9;
  const double h = 1e-5;
  long stuck = 0;
  const long n = std::lround(60.0 / h);
  ref.run(x, v, h, n, [&](double t, double xs, double vs) {
    if (t > 50.0) lo = std::min(lo, xs), hi = std::max(hi, xs);
    stuck += std::abs(kVb - vs) < kVs;
  });
  const double reference = hi - lo;
  const double reference_stuck = static_cast<double>(stuck) / static_cast<double>(n);

  const study::RunResult r = runBelt({"friction=roh_yoo"});
  EXPECT_TRUE(r.summary.oscillating);
  EXPECT_NEAR(r.summary.amplitude_pp, reference, 1e-3 * reference)
      << "engine " << r.summary.amplitude_pp << " reference " << reference;
  // It grew: the first cycle is far smaller than the limit cycle, and it sticks.
  ASSERT_FALSE(r.summary.cycles.empty());
  EXPECT_LT(r.summary.cycles.front().peak_to_peak, 0.6 * r.summary.amplitude_pp);
  EXPECT_GT(reference_stuck, 0.01);
  EXPECT_NEAR(r.summary.stuck_fraction, reference_stuck, 0.05 * reference_stuck);
  EXPECT_GT(r.summary.time_to_98, 0.0);
  EXPECT_LT(r.summary.time_to_98, 60.0);
}

TEST(BeltScene, LimitCycleAmplitudeConvergesAsTheStepIsRefined) {
  // Successive halvings: the change in amplitude must shrink; the finest two agree to 0.2%.
  std::vector<double> amp;
  for (double dt : {2e-3, 1e-3, 5e-4, 2.5e-4})
    amp.push_back(runBelt({"friction=roh_yoo", set("dt", dt), "duration=40"}).summary.amplitude_pp);
  const double d1 = std::abs(amp[1] - amp[0]), d3 = std::abs(amp[3] - amp[2]);
  EXPECT_LT(d3, d1) << amp[0] << " " << amp[1] << " " << amp[2] << " " << amp[3];
  EXPECT_NEAR(amp[2] / amp[3], 1.0, 2e-3);
}

TEST(BeltScene, StepBeyondTheContactStabilityLimitStopsWithAClearError) {
  // Contact: 4 corners of 2.5e5 N/m on 10 kg, omega = 316 rad/s; RK4 needs h < 2.8/omega.
  const io::Scene scene = io::loadScene(kBelt, {"dt=0.02", "duration=5"});
  const study::RunResult r = study::runScene(scene);
  EXPECT_FALSE(r.complete);
  EXPECT_NE(r.message.find("diverged at step"), std::string::npos) << r.message;
  for (std::size_t c = 0; c < r.trajectory.columns().size(); ++c)
    for (double v : r.trajectory.column(c)) ASSERT_TRUE(std::isfinite(v));
}

TEST(BeltScene, StepJustAboveTheEstimatedLimitIsFlaggedBeforeTheRun) {
  // Vertical contact mode: omega = sqrt(4 k_c / m), zeta = 4 c_c / (2 sqrt(4 k_c m)); the
  // estimate must sit between the steps that are observed to work and to fail.
  const io::Scene ok = io::loadScene(kBelt, {"dt=0.008", "duration=1"});
  const study::RunResult r_ok = study::runScene(ok);
  EXPECT_TRUE(r_ok.warnings.empty());
  EXPECT_GT(r_ok.stability.limit.max_step, 0.008);
  EXPECT_LT(r_ok.stability.limit.max_step, 0.0095);
  const study::RunResult r_bad = study::runScene(io::loadScene(kBelt, {"dt=0.0095", "duration=1"}));
  ASSERT_EQ(r_bad.warnings.size(), 1u);
  EXPECT_NE(r_bad.warnings[0].find("belt_surface, box_shape"), std::string::npos);
  // roh_yoo's stick branch (beta < 1) has no finite slope at zero slip: said in the notes.
  ASSERT_FALSE(r_ok.stability.notes.empty());
  EXPECT_NE(r_ok.stability.notes[0].find("roh_yoo"), std::string::npos);
}

}  // namespace
}  // namespace tribo
