// Time signals (core/signal.hpp): each kind's value and derivative against its closed form,
// at, just before and just after its breakpoints, over several time and amplitude scales;
// the derivative against central differences away from breakpoints; the factories' checks.
#include "core/signal.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tribo {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kScales[] = {1e-3, 1.0, 1e3};

// Central difference of s at t (t at least 2 h away from a breakpoint).
double numericSlope(const Signal& s, double t, double h) {
  return (s.value(t + h) - s.value(t - h)) / (2 * h);
}

// Relative closeness on the scale `scale`.
void expectClose(double got, double want, double scale, const char* what) {
  EXPECT_NEAR(got, want, 1e-12 * std::max(1.0, std::abs(scale))) << what;
}

TEST(Signal, DefaultIsTheConstantZero) {
  const Signal s;
  EXPECT_TRUE(s.isZero());
  EXPECT_EQ(s.value(3.0), 0.0);
  EXPECT_EQ(s.derivative(3.0), 0.0);
  EXPECT_FALSE(Signal::constant(1.0).isZero());
  EXPECT_TRUE(s.breakpoints().empty());
}

TEST(Signal, ConstantIsItsValueAtAllTimes) {
  for (double a : kScales) {
    const Signal s = Signal::constant(-2.5 * a);
    for (double t : {-1e3, 0.0, 1e-9, 7.0}) {
      EXPECT_EQ(s.value(t), -2.5 * a);
      EXPECT_EQ(s.derivative(t), 0.0);
    }
  }
}

TEST(Signal, RampHoldsItsInitialValueThenRisesAtItsRate) {
  for (double ts : kScales)
    for (double a : kScales) {
      const double rate = 3.0 * a / ts, t0 = 0.4 * ts, v0 = -0.7 * a;
      const Signal s = Signal::ramp(rate, t0, v0);
      ASSERT_EQ(s.breakpoints(), std::vector<double>{t0});
      for (double t : {-ts, 0.0, t0 - 1e-9 * ts, t0, t0 + 1e-9 * ts, 2 * ts, 50 * ts}) {
        const double want = t < t0 ? v0 : v0 + rate * (t - t0);
        expectClose(s.value(t), want, a * (1 + std::abs(t / ts)), "value");
        EXPECT_EQ(s.derivative(t), t < t0 ? 0.0 : rate) << t;  // right-continuous at t0
      }
      EXPECT_NEAR(numericSlope(s, 3 * ts, 1e-4 * ts), rate, 1e-7 * std::abs(rate));
    }
  // Defaults: from t = 0 at 0.
  EXPECT_EQ(Signal::ramp(2.0).value(1.5), 3.0);
  EXPECT_EQ(Signal::ramp(2.0).value(-1.0), 0.0);
}

TEST(Signal, StepJumpsAtItsTime) {
  for (double ts : kScales)
    for (double a : kScales) {
      const Signal s = Signal::step(ts, 2 * a, -a);
      EXPECT_EQ(s.value(ts * (1 - 1e-12)), 2 * a);
      EXPECT_EQ(s.value(ts), -a);  // right-continuous
      EXPECT_EQ(s.value(ts * (1 + 1e-12)), -a);
      EXPECT_EQ(s.value(-5 * ts), 2 * a);
      EXPECT_EQ(s.value(9 * ts), -a);
      for (double t : {0.0, ts, 2 * ts}) EXPECT_EQ(s.derivative(t), 0.0);
      EXPECT_EQ(s.breakpoints(), std::vector<double>{ts});
    }
}

TEST(Signal, SmoothStepIsTheAdamsCubic) {
  for (double ts : kScales)
    for (double a : kScales) {
      const double t0 = 0.5 * ts, t1 = 2.0 * ts, h0 = -a, h1 = 3 * a;
      const Signal s = Signal::smoothStep(t0, h0, t1, h1);
      ASSERT_EQ(s.breakpoints(), (std::vector<double>{t0, t1}));
      for (double x : {-1.0, 0.0, 1e-9, 0.1, 0.25, 0.5, 0.8, 1.0 - 1e-9, 1.0, 1.5}) {
        const double t = t0 + x * (t1 - t0);
        const double sc = std::clamp(x, 0.0, 1.0);
        const double want = h0 + (h1 - h0) * sc * sc * (3 - 2 * sc);
        const double slope =
            (x < 0.0 || x >= 1.0) ? 0.0 : (h1 - h0) * 6 * sc * (1 - sc) / (t1 - t0);
        expectClose(s.value(t), want, a, "value");
        EXPECT_NEAR(s.derivative(t), slope, 1e-12 * std::abs(a / ts)) << x;
      }
      // Midpoint: half way, steepest at 1.5 (h1 - h0) / (t1 - t0).
      expectClose(s.value(0.5 * (t0 + t1)), 0.5 * (h0 + h1), a, "mid");
      EXPECT_NEAR(s.derivative(0.5 * (t0 + t1)), 1.5 * (h1 - h0) / (t1 - t0), 1e-12 * a / ts);
      // Slope continuous at both ends: zero on either side.
      EXPECT_NEAR(s.derivative(t0 + 1e-9 * ts), 0.0, 1e-7 * a / ts);
      EXPECT_NEAR(s.derivative(t1 - 1e-9 * ts), 0.0, 1e-7 * a / ts);
      const double tm = t0 + 0.3 * (t1 - t0);
      EXPECT_NEAR(numericSlope(s, tm, 1e-5 * ts), s.derivative(tm), 1e-7 * a / ts);
    }
}

TEST(Signal, TableInterpolatesLinearlyAndHoldsOutside) {
  for (double ts : kScales)
    for (double a : kScales) {
      const Signal s = Signal::table({{0.0, a}, {ts, 3 * a}, {3 * ts, -a}});
      ASSERT_EQ(s.breakpoints(), (std::vector<double>{0.0, ts, 3 * ts}));
      const double k1 = 2 * a / ts, k2 = -2 * a / ts;  // the two segments' slopes
      auto want = [&](double t) {
        if (t <= 0.0) return a;
        if (t <= ts) return a + k1 * t;
        if (t <= 3 * ts) return 3 * a + k2 * (t - ts);
        return -a;
      };
      for (double t : {-ts, -1e-9 * ts, 0.0, 1e-9 * ts, 0.5 * ts, ts * (1 - 1e-9), ts,
                       ts * (1 + 1e-9), 2 * ts, 3 * ts * (1 - 1e-9), 3 * ts, 4 * ts})
        expectClose(s.value(t), want(t), a, "value");
      // Right-continuous slopes: the segment that starts at a breakpoint; 0 past the end.
      EXPECT_EQ(s.derivative(-1e-9 * ts), 0.0);
      EXPECT_NEAR(s.derivative(0.0), k1, 1e-12 * std::abs(k1));
      EXPECT_NEAR(s.derivative(0.5 * ts), k1, 1e-12 * std::abs(k1));
      EXPECT_NEAR(s.derivative(ts * (1 - 1e-9)), k1, 1e-12 * std::abs(k1));
      EXPECT_NEAR(s.derivative(ts), k2, 1e-12 * std::abs(k2));
      EXPECT_NEAR(s.derivative(2 * ts), k2, 1e-12 * std::abs(k2));
      EXPECT_EQ(s.derivative(3 * ts), 0.0);
      EXPECT_EQ(s.derivative(5 * ts), 0.0);
    }
  // One point: a constant.
  const Signal one = Signal::table({{2.0, 5.0}});
  EXPECT_EQ(one.value(-1.0), 5.0);
  EXPECT_EQ(one.value(2.0), 5.0);
  EXPECT_EQ(one.value(9.0), 5.0);
  EXPECT_EQ(one.derivative(2.0), 0.0);
}

TEST(Signal, SinesAddTheirTerms) {
  for (double ts : kScales)
    for (double a : kScales) {
      const double f1 = 1.0 / ts, f2 = 3.7 / ts;
      const Signal s = Signal::sines({{a, f1, 0.3, 0.5 * a}, {-0.2 * a, f2, 0.0, 0.0}});
      EXPECT_TRUE(s.breakpoints().empty());
      for (double x : {0.0, 0.123, 1.0, 2.71, 40.0}) {
        const double t = x * ts;
        const double w1 = 2 * kPi * f1, w2 = 2 * kPi * f2;
        const double want = 0.5 * a + a * std::sin(w1 * t + 0.3) - 0.2 * a * std::sin(w2 * t);
        const double slope = a * w1 * std::cos(w1 * t + 0.3) - 0.2 * a * w2 * std::cos(w2 * t);
        // sin at 2 pi f t of ~250 rad: rounding of the argument, 1e-14 of it.
        EXPECT_NEAR(s.value(t), want, 1e-11 * a) << x;
        EXPECT_NEAR(s.derivative(t), slope, 1e-11 * a / ts) << x;
        EXPECT_NEAR(numericSlope(s, t, 1e-5 * ts), slope, 1e-6 * a / ts) << x;
      }
    }
  // A zero frequency term is its offset plus A sin(phase).
  EXPECT_NEAR(Signal::sines({{2.0, 0.0, kPi / 2, 1.0}}).value(123.0), 3.0, 1e-15);
}

TEST(Signal, FactoriesRefuseWhatIsNotAFunction) {
  EXPECT_THROW(Signal::constant(NAN), std::invalid_argument);
  EXPECT_THROW(Signal::ramp(INFINITY), std::invalid_argument);
  EXPECT_THROW(Signal::step(0.0, 1.0, NAN), std::invalid_argument);
  EXPECT_THROW(Signal::smoothStep(1.0, 0.0, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(Signal::smoothStep(2.0, 0.0, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(Signal::table({}), std::invalid_argument);
  EXPECT_THROW(Signal::table({{0.0, 1.0}, {0.0, 2.0}}), std::invalid_argument);
  EXPECT_THROW(Signal::sines({{1.0, -1.0, 0.0, 0.0}}), std::invalid_argument);
  try {
    Signal::table({{0.0, 1.0}, {1.0, 2.0}, {0.5, 3.0}});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("strictly increasing"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tribo
