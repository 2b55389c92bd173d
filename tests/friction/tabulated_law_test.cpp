// The tabulated law (friction/tabulated_law.hpp) against what its definition promises:
// exact at the points, no wiggle and no overshoot (monotone data give a monotone curve, a
// peak is never exceeded), third-order convergence to a smooth curve it samples, odd, slope
// equal to the finite difference of the value, constant past the last point, and bad tables
// refused at the point that breaks a rule.
#include "friction/tabulated_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace tribo::friction {
namespace {

// A Stribeck-like curve: rises to a peak near 0.02 m/s, decays to 0.3.
double stribeck(double v) { return (0.3 + 0.1 * std::exp(-v / 0.05)) * std::tanh(v / 0.01); }

TabulatedLaw sampled(const std::function<double(double)>& f, double from, double to, int n) {
  std::vector<double> v, mu;
  for (int i = 0; i <= n; ++i) {
    v.push_back(from + (to - from) * i / n);
    mu.push_back(f(v.back()));
  }
  return TabulatedLaw(v, mu);
}

TEST(TabulatedLaw, ExactAtPointsJoinedToTheOriginAndConstantPastTheEnd) {
  const TabulatedLaw law({0.01, 0.02, 0.1, 0.5}, {0.35, 0.4, 0.32, 0.3});
  EXPECT_EQ(law.speeds().front(), 0.0);  // (0, 0) joined
  EXPECT_DOUBLE_EQ(law.coefficient(0.0), 0.0);
  EXPECT_DOUBLE_EQ(law.coefficient(0.01), 0.35);
  EXPECT_DOUBLE_EQ(law.coefficient(0.02), 0.4);
  EXPECT_DOUBLE_EQ(law.coefficient(0.1), 0.32);
  EXPECT_DOUBLE_EQ(law.coefficient(0.5), 0.3);
  EXPECT_DOUBLE_EQ(law.coefficient(7.0), 0.3);
  EXPECT_DOUBLE_EQ(law.slope(7.0), 0.0);
  EXPECT_DOUBLE_EQ(law.stickSpeed(), 0.02);  // the peak
  EXPECT_DOUBLE_EQ(law.maxCoefficient(1.0), 0.4);
  EXPECT_DOUBLE_EQ(law.maxCoefficient(0.01), 0.35);
  // Two points: the straight line through them.
  const TabulatedLaw line({0.0, 2.0}, {0.0, 0.5});
  for (double v : {0.1, 0.7, 1.9}) EXPECT_NEAR(line.coefficient(v), 0.25 * v, 1e-15);
}

TEST(TabulatedLaw, NoWiggleNoOvershoot) {
  // Monotone data with a sharp knee: a cubic spline would ring; this must stay monotone.
  const TabulatedLaw rising({0.0, 0.001, 0.002, 0.1, 1.0}, {0.0, 0.29, 0.3, 0.3, 0.31});
  double last = 0.0;
  for (double v = 0.0; v <= 1.2; v += 1e-4) {
    const double mu = rising.coefficient(v);
    EXPECT_GE(mu, last - 1e-15) << v;
    last = mu;
  }
  // A peak: nothing above the largest measured value, each interval within its end values.
  const std::vector<double> v{0.0, 0.005, 0.01, 0.015, 0.05, 0.2, 1.0};
  const std::vector<double> mu{0.0, 0.3, 0.45, 0.4, 0.33, 0.3, 0.3};
  const TabulatedLaw peak(v, mu);
  for (std::size_t k = 0; k + 1 < v.size(); ++k)
    for (int j = 0; j <= 100; ++j) {
      const double x = v[k] + (v[k + 1] - v[k]) * j / 100.0;
      const double y = peak.coefficient(x);
      EXPECT_GE(y, std::min(mu[k], mu[k + 1]) - 1e-15) << x;
      EXPECT_LE(y, std::max(mu[k], mu[k + 1]) + 1e-15) << x;
    }
}

TEST(TabulatedLaw, ConvergesToTheCurveItSamples) {
  // Away from the turn, the monotone cubic converges like h^3 or better.
  const auto error = [](int n) {
    const TabulatedLaw law = sampled(stribeck, 0.0, 0.5, n);
    double worst = 0.0;
    for (double v = 0.1; v <= 0.45; v += 1e-4)
      worst = std::max(worst, std::abs(law.coefficient(v) - stribeck(v)));
    return worst;
  };
  const double coarse = error(100), fine = error(200);
  EXPECT_LT(fine, 1e-6);
  EXPECT_GT(coarse / fine, std::pow(2.0, 2.8)) << coarse << " " << fine;
}

TEST(TabulatedLaw, OddWithASlopeThatIsTheDerivative) {
  const TabulatedLaw law = sampled(stribeck, 0.0, 0.5, 60);
  for (double v : {1e-4, 0.003, 0.0171, 0.09, 0.333, 0.49}) {
    EXPECT_DOUBLE_EQ(law.coefficient(-v), -law.coefficient(v));
    EXPECT_DOUBLE_EQ(law.slope(-v), law.slope(v));
    const double h = 1e-7;
    const double fd = (law.coefficient(v + h) - law.coefficient(v - h)) / (2 * h);
    EXPECT_NEAR(law.slope(v), fd, 1e-5 * std::max(1.0, std::abs(fd))) << v;
  }
}

TEST(TabulatedLaw, BadTablesNameThePoint) {
  const auto point = [](std::vector<double> v, std::vector<double> mu) -> long {
    try {
      TabulatedLaw law(v, mu);
    } catch (const TabulatedPointError& e) {
      return static_cast<long>(e.point);
    }
    return -1;
  };
  EXPECT_EQ(point({0.1, 0.3, 0.2}, {0.3, 0.3, 0.3}), 2);           // not increasing
  EXPECT_EQ(point({0.1, 0.2, 0.2}, {0.3, 0.3, 0.3}), 2);           // repeated speed
  EXPECT_EQ(point({-0.1, 0.2}, {0.3, 0.3}), 0);                    // negative speed
  EXPECT_EQ(point({0.1, 0.2}, {0.3, -0.3}), 1);                    // negative coefficient
  EXPECT_EQ(point({0.0, 0.2}, {0.1, 0.3}), 0);                     // mu(0) != 0
  EXPECT_EQ(point({0.1, std::nan(""), 0.3}, {0.3, 0.3, 0.3}), 1);  // not finite
  EXPECT_THROW(TabulatedLaw({0.1}, {0.3}), FrictionParameterError);
  EXPECT_THROW(TabulatedLaw({0.1, 0.2}, {0.3}), FrictionParameterError);
}

}  // namespace
}  // namespace tribo::friction
