// The function signal (core/signal.hpp): a callable's value and given derivative passed
// through; the five-point difference against the closed-form slope of sines over time
// scales 1e-3, 1, 1e3 s and amplitudes 1e-3 .. 1e3, within the error the header states,
// with the time scale given and with the default one; the one-sided stencils beside a
// breakpoint (exact for polynomials up to degree 4, so only rounding remains); copies; the
// factory's checks.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/signal.hpp"

namespace tribo {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kScales[] = {1e-3, 1.0, 1e3};

TEST(FunctionSignal, PassesValueAndGivenDerivativeThrough) {
  const Signal s =
      Signal::function([](double t) { return t * t; }, [](double t) { return 7 * t; }, {1.0, 2.0});
  EXPECT_EQ(s.kind(), Signal::Kind::kFunction);
  EXPECT_FALSE(s.isZero());
  EXPECT_EQ(s.value(3.0), 9.0);
  EXPECT_EQ(s.derivative(3.0), 21.0);  // the given one, not a difference
  EXPECT_EQ(s.breakpoints(), (std::vector<double>{1.0, 2.0}));
  const Signal copy = s;
  EXPECT_EQ(copy.value(-2.0), 4.0);
}

// Relative to the slope's amplitude A w: (2 pi h / P)^4 / 30 + 5e-17 P / h + 2e-16 |t| / h.
double statedError(double period, double h, double t) {
  return std::pow(2 * kPi * h / period, 4) / 30 + 5e-17 * period / h + 2e-16 * std::abs(t) / h;
}

TEST(FunctionSignal, FivePointDifferenceMatchesTheSlopeOfASine) {
  for (double period : kScales)
    for (double a : kScales) {
      const double w = 2 * kPi / period;
      const auto f = [=](double t) { return a * std::sin(w * t + 0.4); };
      for (double tau : {period, 1e-3}) {  // the time scale given, and the default
        const Signal s = tau == 1e-3 ? Signal::function(f) : Signal::function(f, {}, {}, tau);
        const double h = 1e-3 * tau;
        for (double x : {0.0, 0.1, 0.77, 3.0, 41.3}) {
          const double t = x * period;
          if (std::abs(t) > 1e3) continue;  // the stated range
          const double want = a * w * std::cos(w * t + 0.4);
          // 2x the stated bound: the bound's rounding terms are estimates, not maxima.
          const double bound = 2 * statedError(period, h, t);
          EXPECT_NEAR(s.derivative(t), want, bound * a * w) << period << " " << a << " " << x;
          // And the documented overall claims.
          EXPECT_LT(bound / 2, tau == period ? 1e-9 : 1e-6) << period << " " << x;
        }
      }
    }
}

TEST(FunctionSignal, TheDefaultTimeScaleCoversPeriodsFrom1e4To1e3Seconds) {
  for (double period : {1e-4, 1e-2, 1.0, 1e3}) {
    const double w = 2 * kPi / period;
    const Signal s = Signal::function([=](double t) { return std::sin(w * t); });
    for (double t : {0.0, 0.3 * period, 1e3 - 0.3 * period}) {
      EXPECT_NEAR(s.derivative(t), w * std::cos(w * t), 1e-6 * w) << period << " " << t;
    }
  }
}

TEST(FunctionSignal, DifferencesStayOnOneSideOfABreakpoint) {
  for (double ts : kScales)
    for (double a : kScales) {
      const double b = 0.5 * ts;
      // (t/ts)^2 before b, then a line of slope 3 / ts: a kink at b.
      const auto f = [=](double t) {
        return t < b ? a * (t / ts) * (t / ts) : a * 0.25 + 3 * a * (t - b) / ts;
      };
      const auto slope = [=](double t) { return t < b ? 2 * a * t / (ts * ts) : 3 * a / ts; };
      const Signal s = Signal::function(f, {}, {b}, ts);
      const double h = 1e-3 * ts;
      for (double x : {-3.0, -2.0, -1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.99, 2.0, 2.5, 5.0}) {
        const double t = b + x * h;
        // Exact for these polynomials: rounding only, ~eps |f| / h.
        EXPECT_NEAR(s.derivative(t), slope(t), 1e-9 * a / ts) << ts << " " << a << " " << x;
      }
    }
}

TEST(FunctionSignal, FactoryChecks) {
  auto message = [](auto make) {
    try {
      make();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const auto one = [](double) { return 1.0; };
  EXPECT_EQ(message([] { Signal::function({}); }), "function: needs a value callable");
  EXPECT_EQ(message([&] { Signal::function(one, {}, {}, 0.0); }),
            "function: time scale must be > 0 (got 0)");
  EXPECT_EQ(message([&] {
              Signal::function(one, {}, {2.0, 1.0});
            }),
            "function: breakpoints must be strictly increasing");
}

}  // namespace
}  // namespace tribo
