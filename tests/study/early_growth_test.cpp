// study/early_growth on signals with a known envelope: x = x_eq + A e^(sigma t) cos(w t) (a
// growing and a decaying one, different offsets and frequencies) must give sigma from the
// first cycles whatever x_eq is; a growth that saturates (the envelope stops at a limit) is
// measured only over the cycles before it has grown tenfold; too few cycles: not measured.
#include "study/early_growth.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace tribo::study {
namespace {

std::vector<Cycle> cyclesOf(double sigma, double freq, double x_eq, double duration,
                            double limit = 1e300) {
  std::vector<double> t, x;
  const double w = 2 * std::numbers::pi * freq;
  for (double s = 0; s <= duration; s += 1e-3) {
    t.push_back(s);
    x.push_back(x_eq + std::min(1e-3 * std::exp(sigma * s), limit) * std::cos(w * s));
  }
  return summarizeOscillation(t, x, {}).cycles;
}

TEST(EarlyGrowth, RecoversTheEnvelopeRateWithoutTheEquilibrium) {
  for (const auto& [sigma, freq, x_eq] :
       {std::tuple{0.054, 0.87, 0.098}, {-0.5, 10.0, -2.0}, {2.0, 25.0, 0.0}}) {
    const EarlyGrowth g = earlyGrowth(cyclesOf(sigma, freq, x_eq, 30.0));
    ASSERT_TRUE(g.measured);
    EXPECT_NEAR(g.rate, sigma, 1e-4 * std::abs(sigma)) << freq;
    EXPECT_EQ(g.first_cycle, 1);
  }
}

TEST(EarlyGrowth, StopsBeforeTheGrowthSaturates) {
  // e-folding in 0.5 s at 10 Hz: tenfold after 1.15 s; the envelope is capped at 100 times
  // the start after 2.3 s. Only the cycles within a factor 10 of the second are used.
  const EarlyGrowth g = earlyGrowth(cyclesOf(2.0, 10.0, 0.0, 10.0, 0.1));
  ASSERT_TRUE(g.measured);
  EXPECT_NEAR(g.rate, 2.0, 2e-3);
  EXPECT_LT(g.t_end, 2.0);
}

// Cycles of a signal sampled every 1 ms.
std::vector<Cycle> cyclesOfSignal(double duration, const auto& x_of_t) {
  std::vector<double> t, x;
  for (double s = 0; s <= duration; s += 1e-3) {
    t.push_back(s);
    x.push_back(x_of_t(s));
  }
  return summarizeOscillation(t, x, {}).cycles;
}

TEST(EarlyGrowth, OneModeIsTrustedAndItsFitIsClean) {
  for (const auto& [sigma, freq] : {std::pair{0.054, 0.87}, {-0.5, 10.0}, {2.0, 25.0}}) {
    const EarlyGrowth g = earlyGrowth(cyclesOf(sigma, freq, 0.1, 30.0));
    ASSERT_TRUE(g.measured);
    EXPECT_TRUE(g.trustworthy) << freq << ": " << g.doubt;
    EXPECT_LT(g.scatter, 1e-3) << freq;
    EXPECT_LT(g.period_spread, 1e-3) << freq;
    EXPECT_TRUE(g.doubt.empty());
  }
}

TEST(EarlyGrowth, TwoModesOrAnEnvelopeJumpAreNotTrusted) {
  const double w1 = 2 * std::numbers::pi * 1.0, w2 = 2 * std::numbers::pi * 1.37;
  // A generic start: two modes of comparable size, one decaying faster (the fit mixes them).
  const auto beating = [&](double t) {
    return 1e-3 * std::exp(-0.1 * t) * std::cos(w1 * t) +
           6e-4 * std::exp(-0.4 * t) * std::cos(w2 * t);
  };
  // One mode whose amplitude jumps by 40% at t = 8 s (a contact opening in the window).
  const auto jump = [&](double t) {
    return 1e-3 * std::exp(0.05 * t) * (t < 8 ? 1.0 : 1.4) * std::cos(w1 * t);
  };
  for (const auto& [name, cycles] : {std::pair{"beating", cyclesOfSignal(25.0, beating)},
                                     {"jump", cyclesOfSignal(25.0, jump)}}) {
    const EarlyGrowth g = earlyGrowth(cycles);
    ASSERT_TRUE(g.measured) << name;
    EXPECT_FALSE(g.trustworthy) << name << " scatter " << g.scatter << " spread "
                                << g.period_spread;
    EXPECT_NE(g.doubt.find("not the linear growth rate"), std::string::npos) << g.doubt;
  }
}

TEST(EarlyGrowth, TooFewCyclesAreNotMeasured) {
  EXPECT_FALSE(earlyGrowth(cyclesOf(0.1, 1.0, 0.0, 3.2)).measured);
  EXPECT_FALSE(earlyGrowth({}).measured);
}

}  // namespace
}  // namespace tribo::study
