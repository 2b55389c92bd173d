// The paper's parameter study (Roh & Yoo 2007, Figs. 5-9) through sweeps of the belt scene,
// at the settings the figures use (RK4, 4 ms, each point run until its cycle settles).
// Expectations: the linearized growth rate sigma(a) = ln(a) (mu_s - mu_k) a^-(v_b - v_s) g/2,
// largest at a = exp(1/(v_b - v_s)); the paper's statements that a leaves the amplitude
// alone and equal mu_s - mu_k gives equal amplitude (0.561 m, its Fig. 8c); and the trends
// of its Figs. 7 and 9 (amplitude up with v_b; period and amplitude down with omega_n).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "study/sweep/sweep_runner.hpp"
#include "support/sweep_support.hpp"

namespace tribo::study {
namespace {

using test::num;
using test::Row;
using test::TempDir;

// The belt scene with its wall far away: amplitudes of metres keep the spring linear.
const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";
constexpr double kVb = 1.5, kVs = 0.01, kM = 10.0;

std::vector<Row> sweep(std::vector<SweepAxis> axes) {
  TempDir dir("tribo_sweep_paper_");
  SweepSpec spec;
  spec.scene_path = kBelt;
  spec.fixed_overrides = {"dt=0.004", "output_interval=0.004", "duration=1000"};
  spec.axes = std::move(axes);
  spec.settle = SettleRule{1e-3, 5.0};
  const SweepReport r = runSweepLocally(planSweep(spec), dir.path(), {0, nullptr, 0});
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(r.unsettled, 0u);
  return test::readRows(dir / "results.csv");
}

TEST(SweepPaper, DecayBaseChangesTheTimeToTheLimitCycleNotItsAmplitude) {
  // Figs. 5-6. A coarse grid of a around exp(1/(v_b - v_s)) = 1.956.
  const double a_star = std::exp(1 / (kVb - kVs));
  const auto rows = sweep({parseListAxis("a=1.3,1.6,1.96,2.5,3.2,4")});
  ASSERT_EQ(rows.size(), 6u);
  std::size_t fastest = 0, nearest = 0;
  double lo = 1e9, hi = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].at("status"), "complete");
    if (num(rows[i], "rise_time") < num(rows[fastest], "rise_time")) fastest = i;
    if (std::abs(num(rows[i], "a") - a_star) < std::abs(num(rows[nearest], "a") - a_star))
      nearest = i;
    lo = std::min(lo, num(rows[i], "amplitude_pp"));
    hi = std::max(hi, num(rows[i], "amplitude_pp"));
  }
  EXPECT_EQ(fastest, nearest) << "fastest growth at a = " << rows[fastest].at("a");
  // The time to 98% moves in whole periods (it is the end of a cycle): none is shorter than
  // at a* by a period or more.
  const double at_star = num(rows[nearest], "time_to_98");
  for (const auto& r : rows) EXPECT_GT(num(r, "time_to_98"), at_star - 0.5 * num(r, "period"));
  EXPECT_LT((hi - lo) / hi, 0.02) << "amplitude from " << lo << " to " << hi;
}

TEST(SweepPaper, EqualFrictionDropGivesEqualAmplitude) {
  // Fig. 8. mu_s <= mu_k is no roh_yoo law: those points are errors, the rest goes on.
  const auto rows =
      sweep({parseListAxis("mu_s=0.35,0.4,0.45"), parseListAxis("mu_k=0.3,0.35,0.4")});
  ASSERT_EQ(rows.size(), 9u);
  std::map<long, std::vector<double>> by_drop;  // mu_s - mu_k in 1/100 -> amplitudes
  for (const auto& r : rows) {
    const long drop = std::lround(100 * (num(r, "mu_s") - num(r, "mu_k")));
    if (drop <= 0) {
      EXPECT_EQ(r.at("status"), "error");
      continue;
    }
    ASSERT_EQ(r.at("status"), "complete") << r.at("message");
    by_drop[drop].push_back(num(r, "amplitude_pp"));
  }
  ASSERT_EQ(by_drop.size(), 3u);
  EXPECT_EQ(by_drop[5].size(), 3u);
  EXPECT_EQ(by_drop[10].size(), 2u);
  for (const auto& [drop, amplitudes] : by_drop) {
    const auto [lo, hi] = std::minmax_element(amplitudes.begin(), amplitudes.end());
    EXPECT_LT((*hi - *lo) / *hi, 0.01) << "mu_s - mu_k = " << drop / 100.0;
  }
  EXPECT_NEAR(by_drop[5][0], 0.561, 0.01 * 0.561);  // the paper's Fig. 8c value
  EXPECT_LT(by_drop[5][0], by_drop[10][0]);         // larger drop, larger amplitude
  EXPECT_LT(by_drop[10][0], by_drop[15][0]);
}

TEST(SweepPaper, AmplitudeRisesWithBeltSpeed) {
  // Fig. 7, up to the paper's 5 m/s; the time to the limit cycle rises too.
  const auto rows = sweep({parseListAxis("v_b=0.5,1.5,2.5,3.5,5")});
  ASSERT_EQ(rows.size(), 5u);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_GT(num(rows[i], "amplitude_pp"), num(rows[i - 1], "amplitude_pp")) << i;
    EXPECT_GT(num(rows[i], "rise_time"), num(rows[i - 1], "rise_time")) << i;
  }
}

TEST(SweepPaper, PeriodAndAmplitudeFallWithNaturalFrequency) {
  // Fig. 9: omega_n = sqrt(k/m) from 1 to 10 rad/s (the range of the contour maps).
  std::string ks;
  for (const double w : {1.0, 2.0, 4.0, 6.0, 8.0, 10.0}) {
    ks += ks.empty() ? "k=" : ",";
    ks += std::to_string(kM * w * w);
  }
  const auto rows = sweep({parseListAxis(ks)});
  ASSERT_EQ(rows.size(), 6u);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_LT(num(rows[i], "period"), num(rows[i - 1], "period")) << i;
    EXPECT_LT(num(rows[i], "amplitude_pp"), num(rows[i - 1], "amplitude_pp")) << i;
  }
  // Above omega_n = mu g / v_b the cycle is a stick-slip one: its period is close to, and
  // longer than, the natural period (the stick phase adds time).
  for (std::size_t i = 2; i < rows.size(); ++i) {
    const double w = std::sqrt(num(rows[i], "k") / kM);
    EXPECT_GT(num(rows[i], "period"), 2 * std::numbers::pi / w);
    EXPECT_LT(num(rows[i], "period"), 1.15 * 2 * std::numbers::pi / w);
  }
}

}  // namespace
}  // namespace tribo::study
