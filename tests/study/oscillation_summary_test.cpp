// Oscillation analysis against signals built analytically: every expectation below comes from
// the construction of the signal, not from running the analysis.
#include "study/oscillation_summary.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace tribo::study {
namespace {

constexpr double kPi = std::numbers::pi;

struct Series {
  std::vector<double> t, x, slip;
};

// n samples of f at t_i = (i + phase) * dt.
Series sample(std::size_t n, double dt, double phase, const std::function<double(double)>& f) {
  Series s;
  for (std::size_t i = 0; i < n; ++i) {
    s.t.push_back((static_cast<double>(i) + phase) * dt);
    s.x.push_back(f(s.t.back()));
  }
  return s;
}

TEST(OscillationSummary, PureSinusoid) {
  const double period = 1.3;
  const Series s =
      sample(20001, 1e-3, 0, [&](double t) { return 0.1 + 0.25 * std::sin(2 * kPi * t / period); });
  const OscillationSummary r = summarizeOscillation(s.t, s.x, {}, {});
  EXPECT_TRUE(r.oscillating);
  EXPECT_EQ(r.cycles_used, 3);
  EXPECT_NEAR(r.amplitude_pp, 0.5, 1e-6);
  EXPECT_NEAR(r.period, period, 1e-6);
  EXPECT_NEAR(r.x_mean, 0.1, 1e-4);
  EXPECT_EQ(r.stuck_fraction, 0.0);
  // Maxima at t = 1.3/4 + k*1.3 up to 20 s: 16 maxima, 15 cycles; reached from the start.
  EXPECT_EQ(r.cycles.size(), 15u);
  EXPECT_NEAR(r.cycles.front().t_start, period / 4, 1e-6);
  EXPECT_NEAR(r.time_to_98, period / 4 + period, 1e-6);
  for (const Cycle& c : r.cycles) {
    EXPECT_NEAR(c.peak_to_peak, 0.5, 1e-6);
    EXPECT_NEAR(c.mean, 0.1, 1e-4);
  }
}

TEST(OscillationSummary, NonUniformSampling) {
  Series s;
  double t = 0;
  for (int i = 0; t < 10; ++i) {
    s.t.push_back(t);
    s.x.push_back(-0.3 + 0.04 * std::cos(2 * kPi * t / 0.7 + 0.4));
    t += 1e-3 * (1 + 0.4 * std::sin(17.0 * i));  // steps between 0.6 and 1.4 ms
  }
  const OscillationSummary r = summarizeOscillation(s.t, s.x, {}, {.last_cycles = 5});
  EXPECT_EQ(r.cycles_used, 5);
  EXPECT_NEAR(r.amplitude_pp, 0.08, 1e-7);
  EXPECT_NEAR(r.period, 0.7, 1e-6);
  EXPECT_NEAR(r.x_mean, -0.3, 1e-5);
}

// x = A(t) sin(w t) with the logistic envelope A(t) = A_max / (1 + (A_max/A0 - 1) e^(-sigma t)).
// The record is 300 s rather than 120 s: with sigma = 0.0544 the envelope is only at 71% of
// A_max after 120 s and reaches 98% at t = 175 s.
TEST(OscillationSummary, LogisticEnvelope) {
  const double sigma = 0.0544, w = 5.477, a0 = 1e-3, a_max = 0.28;
  const double c = a_max / a0 - 1;
  const Series s = sample(300001, 1e-3, 0, [&](double t) {
    return a_max / (1 + c * std::exp(-sigma * t)) * std::sin(w * t);
  });
  const OscillationSummary r = summarizeOscillation(s.t, s.x, {}, {});
  ASSERT_TRUE(r.oscillating);
  const double period = 2 * kPi / w;
  EXPECT_NEAR(r.amplitude_pp, 2 * a_max, 1e-3 * 2 * a_max);
  EXPECT_NEAR(r.period, period, 1e-4);

  // Over 0..20 s A/A_max < 1.1%, so d(ln A)/dt = sigma (1 - A/A_max) is sigma within 1%.
  EXPECT_NEAR(envelopeGrowthRate(r.cycles, 0, 20), sigma, 0.01 * sigma);

  // A(t98) = 0.98 A_max  <=>  t98 = ln(c / (1/0.98 - 1)) / sigma.
  const double t98 = std::log(c / (1 / 0.98 - 1)) / sigma;
  EXPECT_NEAR(r.time_to_98, t98, period);
}

TEST(OscillationSummary, DecayingExponentialGrowthRate) {
  const double sigma = -0.2;
  const Series s = sample(30001, 1e-3, 0, [&](double t) {
    return 0.5 + 0.1 * std::exp(sigma * t) * std::sin(3 * t + 1);
  });
  const OscillationSummary r = summarizeOscillation(s.t, s.x, {}, {});
  // x(t + T) - 0.5 = e^(sigma T) (x(t) - 0.5): every cycle shrinks by the same factor.
  EXPECT_NEAR(envelopeGrowthRate(r.cycles, 0, 30), sigma, 1e-5);
  EXPECT_NEAR(envelopeGrowthRate(r.cycles, 10, 20), sigma, 1e-5);
}

// Stick-slip sawtooth: stuck on the belt (slip 0) x rises at v from x_lo to x_hi, then slips
// back along a half cosine of duration t_ret (velocity zero at both ends, so both extrema
// are corners). phase shifts the sample grid: 0 puts samples on the corners, 0.37 between.
Series sawtooth(double phase) {
  const double v = 1.5, x_lo = -0.16, x_hi = 0.11, dt = 1e-3;
  const int n_rise = 180, n_ret = 120;  // t_rise = 0.27 / 1.5 = 0.18 s, t_ret = 0.12 s
  const double t_ret = n_ret * dt, xc = 0.5 * (x_hi + x_lo), r = 0.5 * (x_hi - x_lo);
  Series s;
  for (int i = 0; i <= 70 * (n_rise + n_ret); ++i) {           // 70 whole periods
    const double tau = ((i % (n_rise + n_ret)) + phase) * dt;  // time within the period
    s.t.push_back((i + phase) * dt);
    if (tau < n_rise * dt) {
      s.x.push_back(x_lo + v * tau);
      s.slip.push_back(0);
    } else {
      const double arg = kPi * (tau - n_rise * dt) / t_ret;
      s.x.push_back(xc + r * std::cos(arg));
      s.slip.push_back(v + r * kPi / t_ret * std::sin(arg));  // belt speed - box speed
    }
  }
  return s;
}

TEST(OscillationSummary, StickSlipSawtooth) {
  for (const double phase : {0.0, 0.37}) {
    SCOPED_TRACE(phase);
    const Series s = sawtooth(phase);
    const OscillationSummary r = summarizeOscillation(s.t, s.x, s.slip, {});
    ASSERT_TRUE(r.oscillating);
    EXPECT_EQ(r.cycles.size(), 69u);  // 70 maxima at the end of each rise
    EXPECT_NEAR(r.amplitude_pp, 0.27, 1e-3 * 0.27);
    EXPECT_NEAR(r.period, 0.30, 1e-3 * 0.30);
    EXPECT_NEAR(r.stuck_fraction, 0.18 / 0.30, 1e-3 * 0.6);
    // Corners refined between samples, not just the highest sample.
    for (const Cycle& c : r.cycles) EXPECT_NEAR(c.peak_to_peak, 0.27, 1e-4);
  }
}

TEST(OscillationSummary, RippleOnConstantIsNotAnOscillation) {
  for (const double level : {0.0, 0.05}) {
    const Series s = sample(10001, 1e-3, 0, [&](double t) {
      return level + 1e-9 * std::sin(2 * kPi * t / 0.01) + 0.5e-9 * std::sin(977 * t);
    });
    const OscillationSummary r = summarizeOscillation(s.t, s.x, {}, {});
    EXPECT_TRUE(r.cycles.empty());
    EXPECT_FALSE(r.oscillating);
    EXPECT_EQ(r.cycles_used, 0);
    EXPECT_EQ(r.period, 0.0);
    EXPECT_EQ(r.time_to_98, 0.0);
    EXPECT_LE(r.amplitude_pp, 3e-9);  // max - min of the last half
    EXPECT_NEAR(r.x_mean, level, 1e-9);
  }
}

TEST(OscillationSummary, FewerCyclesThanRequested) {
  // Maxima of sin(2 pi t) at 0.25, 1.25, 2.25 within [0, 2.6]: two full cycles.
  const Series s = sample(2601, 1e-3, 0, [](double t) { return std::sin(2 * kPi * t); });
  const OscillationSummary r = summarizeOscillation(s.t, s.x, {}, {.last_cycles = 3});
  EXPECT_TRUE(r.oscillating);
  EXPECT_EQ(r.cycles_used, 2);
  EXPECT_NEAR(r.period, 1.0, 1e-6);
  EXPECT_NEAR(r.amplitude_pp, 2.0, 1e-6);
}

TEST(OscillationSummary, StuckFractionWeightsSamplesByTheirInterval) {
  // Samples at 0, 1, 3 s; slip below threshold only at t = 3: weight (3 - 1) / 2 of 3 s.
  const std::vector<double> t{0, 1, 3}, x{0, 1, 0}, slip{1, 1, 0};
  const OscillationSummary r = summarizeOscillation(t, x, slip, {});
  EXPECT_NEAR(r.stuck_fraction, 1.0 / 3.0, 1e-15);
}

TEST(OscillationSummary, RejectsBadInput) {
  const std::vector<double> t{0, 1, 2, 3}, x{0, 1, 0, 1};
  const std::vector<double> x3{0, 1, 0}, two{0, 1};
  EXPECT_THROW(summarizeOscillation(t, x3, {}, {}), std::invalid_argument);     // size
  EXPECT_THROW(summarizeOscillation(t, x, x3, {}), std::invalid_argument);      // slip size
  EXPECT_THROW(summarizeOscillation(two, two, {}, {}), std::invalid_argument);  // too few
  const std::vector<double> t_equal{0, 1, 1, 2}, t_back{0, 2, 1, 3};
  EXPECT_THROW(summarizeOscillation(t_equal, x, {}, {}), std::invalid_argument);
  EXPECT_THROW(summarizeOscillation(t_back, x, {}, {}), std::invalid_argument);
  const std::vector<double> x_nan{0, std::numeric_limits<double>::quiet_NaN(), 0, 1};
  EXPECT_THROW(summarizeOscillation(t, x_nan, {}, {}), std::invalid_argument);
  EXPECT_THROW(summarizeOscillation(t, x, {}, {.last_cycles = 0}), std::invalid_argument);
  EXPECT_THROW(summarizeOscillation(t, x, {}, {.stick_speed = -1}), std::invalid_argument);
  try {
    summarizeOscillation(t, x3, {}, {});
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("differ in size"), std::string::npos) << e.what();
  }
}

TEST(OscillationEnvelopeGrowthRate, NeedsTwoCyclesInTheWindow) {
  const std::vector<Cycle> cycles{{0, 1, 1.0, 0}, {1, 2, 2.0, 0}, {2, 3, 4.0, 0}};
  EXPECT_NEAR(envelopeGrowthRate(cycles, 0, 3), std::log(2.0), 1e-12);
  EXPECT_THROW(envelopeGrowthRate(cycles, 0, 1), std::invalid_argument);  // one mid-time
  EXPECT_THROW(envelopeGrowthRate(cycles, 3, 0), std::invalid_argument);
  EXPECT_THROW(envelopeGrowthRate({}, 0, 10), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::study
