// Sweeps of periodic orbits (--analysis orbit, study/sweep/sweep_point.hpp) against closed
// forms: over the forcing frequency of scenes/forced_oscillator.yaml each row is the forced
// linear oscillator's steady response 2 F0 / |k - m w^2 + i c w| (the frequency-response
// curve, through resonance) with the slide's multiplier exp(-c T / 2m); over the paper's belt
// speed each row is the one-degree-of-freedom model's stick-slip cycle; a point with no orbit
// is an error row with the reason; the run-only options are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "one_dof_cycle.hpp"
#include "study/sweep/sweep_runner.hpp"
#include "support/sweep_support.hpp"

namespace tribo::study {
namespace {

using test::num;
using test::readRows;
using test::TempDir;

const std::string kForced = std::string(TRIBO_SOURCE_DIR) + "/scenes/forced_oscillator.yaml";
const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

TEST(SweepOrbit, AForcingFrequencySweepIsTheFrequencyResponseCurve) {
  TempDir dir("tribo_sweep_orbit_");
  SweepSpec spec;
  spec.scene_path = kForced;
  spec.analysis = SweepAnalysis::kOrbit;
  spec.fixed_overrides = {"duration=10"};
  spec.axes = {parseListAxis("f=0.5,1.2,1.5,1.59,1.7,3")};  // resonance at 1.5915 Hz
  const SweepReport report = runSweepLocally(planSweep(spec), dir.path(), {2, nullptr, 0});
  EXPECT_TRUE(report.complete);
  EXPECT_EQ(report.failed, 0u);
  const auto rows = readRows(dir / "results.csv");
  ASSERT_EQ(rows.size(), 6u);
  const double m = 1, k = 100, c = 2, F0 = 10;  // the scene's
  for (const auto& row : rows) {
    const double f = num(row, "f"), w = 2 * std::numbers::pi * f;
    EXPECT_NEAR(num(row, "period") * f, 1.0, 1e-9);  // results.csv: 10 significant digits
    EXPECT_NEAR(num(row, "amplitude_pp") / (2 * F0 / std::hypot(k - m * w * w, c * w)), 1.0, 1e-6)
        << "f = " << f;
    EXPECT_NEAR(num(row, "largest_multiplier"), std::exp(-c / f / (2 * m)), 1e-6) << f;
    EXPECT_EQ(row.at("stable"), "1");
  }
}

TEST(SweepOrbit, ABeltSpeedSweepIsTheOneDofModelsCycleAndAPointWithoutOneIsAnErrorRow) {
  TempDir dir("tribo_sweep_orbit_belt_");
  SweepSpec spec;
  spec.scene_path = kBelt;
  spec.analysis = SweepAnalysis::kOrbit;
  spec.fixed_overrides = {"duration=30"};
  spec.axes = {parseListAxis("v_b=0,1,1.5")};
  const SweepReport report = runSweepLocally(planSweep(spec), dir.path(), {2, nullptr, 0});
  EXPECT_EQ(report.failed, 1u);
  const auto rows = readRows(dir / "results.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].at("status"), "error");
  EXPECT_NE(rows[0].at("message").find("no oscillation"), std::string::npos)
      << rows[0].at("message");
  for (std::size_t i = 1; i < 3; ++i) {
    const double v_b = num(rows[i], "v_b");
    const ReferenceCycle ref = oneDofCycle(10.0, v_b);
    EXPECT_NEAR(num(rows[i], "period") / ref.period, 1.0, 1e-3) << v_b;
    EXPECT_NEAR(num(rows[i], "amplitude_pp") / ref.amplitude_pp, 1.0, 1e-3) << v_b;
    EXPECT_NEAR(num(rows[i], "x_max") - num(rows[i], "x_min"), num(rows[i], "amplitude_pp"), 1e-9);
    EXPECT_LT(num(rows[i], "largest_multiplier"), 0.05);  // the stick phase collapses them
    EXPECT_EQ(rows[i].at("stable"), "1");
  }
}

TEST(SweepOrbit, RunOnlyOptionsAreRefusedNamingTheAnalysis) {
  SweepSpec spec;
  spec.scene_path = kBelt;
  spec.analysis = SweepAnalysis::kOrbit;
  spec.axes = {parseListAxis("v_b=1,1.5")};
  spec.keep_trajectories = true;
  try {
    planSweep(spec);
    ADD_FAILURE() << "keep_trajectories accepted";
  } catch (const SweepSpecError& e) {
    EXPECT_NE(std::string(e.what()).find("not to --analysis orbit"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tribo::study
