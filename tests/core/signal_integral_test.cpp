// Second derivatives and integrals of time signals (core/signal.hpp), which joint drives
// take (core/joint_elements.hpp): every kind's integral from 0 against a composite Simpson
// rule over its value between its breakpoints (or a closed form written here), and its
// second derivative against a central difference of its first away from breakpoints and
// the closed forms at them (right-continuous), over several time and amplitude scales; a
// function signal's Gauss-Kronrod integral against closed forms (periods from 1e-3 to 10 s,
// times to 25 s, a kink at a reported breakpoint, negative times), its cost per call once
// its panels are summed, and its five-point second differences against A w^2 sin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/signal.hpp"

namespace tribo {
namespace {

constexpr double kPi = std::numbers::pi;

// Composite Simpson of s.value over [a, b], n (even) intervals.
double simpson(const Signal& s, double a, double b, int n = 2000) {
  const double h = (b - a) / n;
  double sum = s.value(a) + s.value(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * s.value(a + i * h);
  return sum * h / 3.0;
}

// int_0^t by Simpson on each piece between the breakpoints inside (0, t) (t > 0). A piece's
// ends are evaluated from inside: value() is right-continuous, so a jump at the piece's
// left end is right and at its right end is avoided by stopping 1e-12 short.
double referenceIntegral(const Signal& s, double t) {
  std::vector<double> cuts{0.0};
  for (double b : s.breakpoints())
    if (b > 0.0 && b < t) cuts.push_back(b);
  cuts.push_back(t);
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double a = cuts[i], b = cuts[i + 1];
    const double shrink = 1e-13 * std::max(1.0, std::abs(b));
    sum += simpson(s, a, b - shrink) + s.value(b - shrink) * shrink;
  }
  return sum;
}

std::vector<Signal> someOfEachKind(double time, double size) {
  return {Signal::constant(-2.5 * size),
          Signal::ramp(3.0 * size / time, 0.4 * time, 0.5 * size),
          Signal::ramp(-1.0 * size / time, -0.3 * time, size),
          Signal::step(0.6 * time, size, -0.25 * size),
          Signal::smoothStep(0.2 * time, -size, 0.7 * time, 2.0 * size),
          Signal::table({{0.1 * time, size}, {0.35 * time, -size}, {0.5 * time, 0.5 * size}}),
          Signal::cubicTable({{-0.2 * time, 0.0},
                              {0.15 * time, size},
                              {0.45 * time, -0.5 * size},
                              {0.8 * time, 0.2 * size}}),
          Signal::sines({{size, 1.7 / time, 0.3, 0.1 * size}, {0.5 * size, 0.0, 1.1, 0.0}})};
}

TEST(SignalIntegral, EachKindMatchesSimpsonOverItsValue) {
  for (double time : {1e-3, 1.0, 1e3})
    for (double size : {1e-4, 1.0, 1e4}) {
      int kind = 0;
      for (const Signal& s : someOfEachKind(time, size)) {
        for (double f : {0.05, 0.2, 0.35, 0.6, 0.7, 0.93, 1.6}) {
          const double t = f * time;
          EXPECT_NEAR(s.integral(t), referenceIntegral(s, t), 1e-10 * size * time)
              << "kind " << kind << " time " << time << " size " << size << " t " << t;
        }
        EXPECT_EQ(s.integral(0.0), 0.0) << kind;
        ++kind;
      }
    }
}

TEST(SignalIntegral, ClosedFormsOfTheSimpleKinds) {
  // v0 t + r (t - t0)^2 / 2 after the ramp's start; the step's areas; the smooth step's
  // area (h1 - h0) w / 2 once it is over.
  EXPECT_NEAR(Signal::ramp(2.0, 1.0, 0.5).integral(3.0), 0.5 * 3.0 + 2.0 * 4.0 / 2.0, 1e-14);
  EXPECT_NEAR(Signal::step(1.0, 2.0, -1.0).integral(4.0), 2.0 - 3.0, 1e-14);
  EXPECT_NEAR(Signal::smoothStep(1.0, 0.0, 3.0, 4.0).integral(5.0), 4.0 + 4.0 * 2.0, 1e-13);
  EXPECT_NEAR(Signal::smoothStep(1.0, 0.0, 3.0, 4.0).integral(2.0), 4.0 * 2.0 * 3.0 / 32.0,
              1e-14);  // w (s^3 - s^4 / 2) at s = 1/2: 2 (1/8 - 1/32) = 3/16 of h1
  const Signal sine = Signal::sines({{1.5, 2.0, 0.4, 0.0}});
  for (double t : {0.1, 0.77, 12.3})
    EXPECT_NEAR(sine.integral(t),
                1.5 * (std::cos(0.4) - std::cos(4.0 * kPi * t + 0.4)) / (4.0 * kPi), 1e-14);
  // Held before the first and after the last point.
  const Signal table = Signal::table({{1.0, 2.0}, {2.0, 4.0}});
  EXPECT_NEAR(table.integral(3.5), 2.0 + 3.0 + 4.0 * 1.5, 1e-14);
  EXPECT_NEAR(table.integral(-1.0), -2.0, 1e-14);
}

TEST(SignalIntegral, SecondDerivativeIsTheSlopeOfTheFirst) {
  for (double time : {1e-3, 1.0, 1e3})
    for (double size : {1e-4, 1.0, 1e4}) {
      int kind = 0;
      for (const Signal& s : someOfEachKind(time, size)) {
        const double h = 1e-6 * time;
        for (double f : {0.05, 0.25, 0.3, 0.55, 0.65, 0.9, 1.6}) {
          const double t = f * time;
          const double slope = (s.derivative(t + h) - s.derivative(t - h)) / (2 * h);
          EXPECT_NEAR(s.secondDerivative(t), slope, 1e-6 * size / (time * time))
              << "kind " << kind << " time " << time << " size " << size << " t " << t;
        }
        ++kind;
      }
    }
}

TEST(SignalIntegral, SecondDerivativesAtBreakpointsAreRightContinuous) {
  const Signal smooth = Signal::smoothStep(1.0, 0.0, 3.0, 4.0);
  EXPECT_DOUBLE_EQ(smooth.secondDerivative(1.0), 6.0 * 4.0 / 4.0);  // 6 (h1 - h0) / w^2
  EXPECT_DOUBLE_EQ(smooth.secondDerivative(2.0), 0.0);
  EXPECT_EQ(smooth.secondDerivative(3.0), 0.0);
  EXPECT_EQ(smooth.secondDerivative(0.999), 0.0);
  // The natural spline through three points: M = (0, M1, 0), M1 from
  // h M0 + 4 h M1 + h M2 = 6 ((v2 - v1) - (v1 - v0)) / h  (h = 1).
  const Signal spline = Signal::cubicTable({{0.0, 0.0}, {1.0, 1.0}, {2.0, 0.0}});
  const double m1 = 6.0 * (-1.0 - 1.0) / 4.0;
  EXPECT_NEAR(spline.secondDerivative(1.0), m1, 1e-14);
  EXPECT_NEAR(spline.secondDerivative(0.25), 0.25 * m1, 1e-14);
  EXPECT_EQ(spline.secondDerivative(2.0), 0.0);
  const Signal sine = Signal::sines({{2.0, 0.5, 0.3, 1.0}});
  EXPECT_NEAR(sine.secondDerivative(0.7), -2.0 * kPi * kPi * std::sin(kPi * 0.7 + 0.3), 1e-13);
}

TEST(SignalIntegral, FunctionIntegralMatchesClosedFormsOverPeriodsAndTimes) {
  for (double period : {1e-3, 0.1, 10.0})
    for (double amplitude : {1e-3, 1.0, 1e3}) {
      const double w = 2 * kPi / period, c = 0.3 * amplitude;
      const Signal s = Signal::function([=](double t) { return c + amplitude * std::sin(w * t); });
      for (double t : {0.0123, 1.7, 25.3, -0.4}) {
        const double want = c * t + amplitude * (1.0 - std::cos(w * t)) / w;
        EXPECT_NEAR(s.integral(t), want, 1e-11 * (std::abs(c * t) + amplitude / w))
            << "period " << period << " amplitude " << amplitude << " t " << t;
      }
    }
}

TEST(SignalIntegral, FunctionIntegralOverAKinkAtABreakpoint) {
  // f = (t - 1)^2 from t = 1 on, 0 before: int_0^t = (t - 1)^3 / 3.
  const auto f = [](double t) { return t < 1.0 ? 0.0 : (t - 1.0) * (t - 1.0); };
  for (double scale : {1e-3, 1.0}) {
    const Signal s = Signal::function(f, {}, {1.0}, scale);
    for (double t : {0.5, 1.0, 1.0004, 2.5, 7.0})
      EXPECT_NEAR(s.integral(t), t > 1.0 ? std::pow(t - 1.0, 3) / 3.0 : 0.0,
                  1e-12 * std::max(1.0, std::pow(t - 1.0, 3)))
          << t;
  }
}

TEST(SignalIntegral, FunctionIntegralCostsAPanelPerCallOnceSummed) {
  long calls = 0;
  const Signal s = Signal::function([&calls](double t) {
    ++calls;
    return std::cos(3.0 * t);
  });
  const double first = s.integral(10.0);
  EXPECT_NEAR(first, std::sin(30.0) / 3.0, 1e-12);
  const long summed = calls;
  // 1e4 panels of 1 ms, 15 evaluations each when no panel needs splitting.
  EXPECT_GE(summed, 150000);
  EXPECT_LE(summed, 200000);
  calls = 0;
  for (int i = 1; i <= 100; ++i) s.integral(10.0 + i * 1e-4);
  EXPECT_LE(calls, 100 * 2 * 15);  // at most the new panels and a part panel each call
  // A copy shares the sums: the same bits at no new cost for summed panels.
  const Signal copy = s;
  calls = 0;
  EXPECT_EQ(copy.integral(9.9999), s.integral(9.9999));
  EXPECT_LE(calls, 4 * 15);
}

TEST(SignalIntegral, FunctionSecondDerivativeByFivePointDifferences) {
  // A sin(w t): f'' = -A w^2 sin(w t). Without a derivative callable: the second difference
  // at H = 1e-2 tau; with one: the five-point difference of the derivative.
  for (double period : {1e-3, 1e-2, 0.1, 1.0}) {
    const double w = 2 * kPi / period;
    const auto value = [w](double t) { return 2.0 * std::sin(w * t); };
    const auto slope = [w](double t) { return 2.0 * w * std::cos(w * t); };
    const Signal plain = Signal::function(value);
    const Signal with_slope = Signal::function(value, slope);
    for (double t : {0.01234, 0.9, 3.3, 7.77, 9.7}) {
      const double want = -2.0 * w * w * std::sin(w * t);
      // The header's bound, (w H)^4 / 90 + eps (5 + w t) / (w H)^2 relative, three times.
      const double wh = w * 1e-5, eps = 2.2e-16;
      const double bound = 3.0 * (std::pow(wh, 4) / 90.0 + eps * (5.0 + w * t) / (wh * wh));
      EXPECT_NEAR(plain.secondDerivative(t), want, bound * 2.0 * w * w)
          << "period " << period << " t " << t;
      EXPECT_NEAR(with_slope.secondDerivative(t), want, 1e-6 * 2.0 * w * w)
          << "period " << period << " t " << t;
    }
  }
  // Near a breakpoint the stencil stays on one side: (t - 1)^3 for t >= 1, 0 before.
  const Signal kinked = Signal::function(
      [](double t) { return t < 1.0 ? 0.0 : std::pow(t - 1.0, 3); }, {}, {1.0}, 1.0);
  EXPECT_NEAR(kinked.secondDerivative(1.0), 0.0, 1e-6);
  EXPECT_NEAR(kinked.secondDerivative(1.005), 6.0 * 0.005, 1e-6);
  EXPECT_EQ(kinked.secondDerivative(0.995), 0.0);
}

}  // namespace
}  // namespace tribo
