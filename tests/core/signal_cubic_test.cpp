// The cubic table signal (core/signal.hpp, core/cubic_spline.hpp): the natural cubic spline
// against closed forms over several time and amplitude scales: a linear function reproduced
// exactly with its slope; the spline through (0, 0), (1, 0), (3, 2), worked out by hand from
// its defining conditions; and, for uneven data, the conditions themselves (interpolation,
// value, slope and curvature continuous at the knots, zero curvature at the ends); the hold
// outside the table; the factory's checks.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/signal.hpp"

namespace tribo {
namespace {

constexpr double kScales[] = {1e-3, 1.0, 1e3};
using Points = std::vector<std::pair<double, double>>;

TEST(CubicTable, ReproducesALinearFunctionAndItsSlope) {
  for (double ts : kScales)
    for (double a : kScales) {
      const auto line = [&](double t) { return a * (2.0 - 3.0 * t / ts); };
      Points points;
      for (double x : {-1.0, -0.3, 0.2, 1.7, 2.0, 4.5}) points.emplace_back(x * ts, line(x * ts));
      const Signal s = Signal::cubicTable(points);
      EXPECT_EQ(s.kind(), Signal::Kind::kCubicTable);
      ASSERT_EQ(s.breakpoints().size(), points.size());
      for (std::size_t i = 0; i < points.size(); ++i)
        EXPECT_EQ(s.breakpoints()[i], points[i].first);
      for (double x :
           {-1.0, -0.99, -0.3 - 1e-9, -0.3, 0.0, 0.2 + 1e-9, 1.0, 1.7, 1.99, 3.3, 4.5 - 1e-9}) {
        const double t = x * ts;
        EXPECT_NEAR(s.value(t), line(t), 1e-13 * a * 20) << ts << " " << a << " " << x;
        EXPECT_NEAR(s.derivative(t), -3.0 * a / ts, 1e-12 * 3.0 * a / ts) << x;
      }
    }
}

// The natural spline through (0, 0), (1, 0), (3, 2): M_0 = M_2 = 0 and
// 2 (1 + 2) M_1 = 6 ((2 - 0) / 2 - 0) gives M_1 = 1, so s'' rises from 0 to 1 on [0, 1] and
// falls back to 0 on [1, 3]; integrating twice with the point values:
//   [0, 1]: s = (x^3 - x) / 6,                      s' = (3 x^2 - 1) / 6
//   [1, 3]: s = (x - 1) + ((3 - x)^3 / 12 - (3 - x) / 3),  s' = 1 - (3 - x)^2 / 4 + 1 / 3
double handValue(double x) {
  if (x <= 0.0) return 0.0;
  if (x <= 1.0) return (x * x * x - x) / 6.0;
  if (x <= 3.0) return (x - 1.0) + (std::pow(3.0 - x, 3) / 12.0 - (3.0 - x) / 3.0);
  return 2.0;
}
double handSlope(double x) {
  if (x < 0.0 || x >= 3.0) return 0.0;
  if (x < 1.0) return (3.0 * x * x - 1.0) / 6.0;
  return 1.0 - (3.0 - x) * (3.0 - x) / 4.0 + 1.0 / 3.0;
}

TEST(CubicTable, IsTheNaturalSplineWorkedOutByHand) {
  // The hand forms agree with each other at x = 1 (value 0, slope 1/3 from both sides).
  ASSERT_NEAR((1.0 - 1.0) + (8.0 / 12.0 - 2.0 / 3.0), 0.0, 1e-15);
  ASSERT_NEAR(1.0 - 4.0 / 4.0 + 1.0 / 3.0, (3.0 - 1.0) / 6.0, 1e-15);
  for (double ts : kScales)
    for (double a : kScales) {
      const Signal s = Signal::cubicTable({{0.0, 0.0}, {ts, 0.0}, {3 * ts, 2 * a}});
      for (double x : {-1.0, 0.0, 1e-9, 0.25, 0.5, 1.0 - 1e-9, 1.0, 1.0 + 1e-9, 1.5, 2.2, 2.9,
                       3.0 - 1e-9, 3.0, 4.0}) {
        const double t = x * ts;
        EXPECT_NEAR(s.value(t), a * handValue(x), 1e-14 * a * 10) << ts << " " << a << " " << x;
        EXPECT_NEAR(s.derivative(t), a / ts * handSlope(x), 1e-13 * a / ts) << x;
      }
    }
}

TEST(CubicTable, MeetsTheNaturalSplineConditionsOnUnevenData) {
  for (double ts : kScales)
    for (double a : kScales) {
      const Points p{{0.0, 1.0 * a},      {0.3 * ts, -2.0 * a}, {0.5 * ts, 0.5 * a},
                     {1.4 * ts, 3.0 * a}, {1.5 * ts, 2.9 * a},  {4.0 * ts, -1.0 * a}};
      const Signal s = Signal::cubicTable(p);
      const double d = 1e-6 * ts;  // one-sided differences of the slope for s''
      auto curvatureLeft = [&](double t) {
        return (s.derivative(t - d) - s.derivative(t - 2 * d)) / d;
      };
      auto curvatureRight = [&](double t) {
        return (s.derivative(t + 2 * d) - s.derivative(t + d)) / d;
      };
      const double slope_scale = a / ts * 100, curvature_scale = a / (ts * ts) * 1000;
      for (std::size_t i = 0; i < p.size(); ++i) {
        const double t = p[i].first;
        EXPECT_NEAR(s.value(t), p[i].second, 1e-14 * a) << i;
        if (i > 0) {
          EXPECT_NEAR(s.value(t - 1e-12 * ts), p[i].second, 1e-9 * a)
              << "value continuous at " << i;
        }
        if (i > 0 && i + 1 < p.size()) {
          EXPECT_NEAR(s.derivative(t - 1e-9 * ts), s.derivative(t), 1e-7 * slope_scale) << i;
          EXPECT_NEAR(curvatureLeft(t), curvatureRight(t), 1e-4 * curvature_scale) << i;
        }
      }
      EXPECT_NEAR(curvatureRight(p.front().first), 0.0, 1e-4 * curvature_scale);
      EXPECT_NEAR(curvatureLeft(p.back().first), 0.0, 1e-4 * curvature_scale);
      // Held outside; slope 0 outside and at the last time (right-continuous).
      EXPECT_EQ(s.value(-ts), p.front().second);
      EXPECT_EQ(s.value(9 * ts), p.back().second);
      EXPECT_EQ(s.derivative(-ts), 0.0);
      EXPECT_EQ(s.derivative(4.0 * ts), 0.0);
    }
}

TEST(CubicTable, TwoPointsAreTheStraightLine) {
  const Signal s = Signal::cubicTable({{1.0, 2.0}, {3.0, 6.0}});
  EXPECT_DOUBLE_EQ(s.value(2.0), 4.0);
  EXPECT_DOUBLE_EQ(s.derivative(1.0), 2.0);
  EXPECT_DOUBLE_EQ(s.derivative(2.5), 2.0);
}

TEST(CubicTable, FactoryChecks) {
  auto message = [](const Points& p) {
    try {
      Signal::cubicTable(p);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({{0.0, 1.0}}), "cubic table: needs at least 2 points, found 1");
  EXPECT_EQ(message({}), "cubic table: needs at least 2 points, found 0");
  EXPECT_EQ(message({{0.0, 1.0}, {1.0, 2.0}, {1.0, 3.0}}),
            "cubic table: times must be strictly increasing (point 2 at t = 1 follows t = 1)");
  EXPECT_NE(message({{0.0, 1.0}, {1.0, NAN}}).find("value must be finite"), std::string::npos);
}

}  // namespace
}  // namespace tribo
