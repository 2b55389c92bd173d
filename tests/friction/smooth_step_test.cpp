// Haversine and cubic STEP: end values, midpoint, flat ends, derivative against finite
// differences, and agreement between the precomputed structs and the free functions.
#include "friction/smooth_step.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tribo::friction {
namespace {

struct StepCase {
  double x0, h0, x1, h1;
};

class FrictionSmoothStep : public testing::TestWithParam<StepCase> {};

TEST_P(FrictionSmoothStep, HavsinEndsMidpointAndOutside) {
  const auto [x0, h0, x1, h1] = GetParam();
  EXPECT_EQ(havsin(x0, x0, h0, x1, h1), h0);
  EXPECT_EQ(havsin(x1, x0, h0, x1, h1), h1);
  EXPECT_EQ(havsin(x0 - 1.0, x0, h0, x1, h1), h0);
  EXPECT_EQ(havsin(x1 + 1.0, x0, h0, x1, h1), h1);
  EXPECT_NEAR(havsin(0.5 * (x0 + x1), x0, h0, x1, h1), 0.5 * (h0 + h1), 1e-15);
  // Quarter point: (1 - cos(pi/4)) / 2 of the way.
  const double quarter = (1.0 - std::sqrt(0.5)) / 2.0;
  EXPECT_NEAR(havsin(x0 + 0.25 * (x1 - x0), x0, h0, x1, h1), h0 + (h1 - h0) * quarter, 1e-15);
}

TEST_P(FrictionSmoothStep, StepEndsMidpointAndOutside) {
  const auto [x0, h0, x1, h1] = GetParam();
  EXPECT_EQ(step(x0, x0, h0, x1, h1), h0);
  EXPECT_EQ(step(x1, x0, h0, x1, h1), h1);
  EXPECT_EQ(step(x0 - 1.0, x0, h0, x1, h1), h0);
  EXPECT_EQ(step(x1 + 1.0, x0, h0, x1, h1), h1);
  EXPECT_NEAR(step(0.5 * (x0 + x1), x0, h0, x1, h1), 0.5 * (h0 + h1), 1e-15);
  // Quarter point: s^2 (3 - 2 s) = 0.15625 at s = 1/4.
  EXPECT_NEAR(step(x0 + 0.25 * (x1 - x0), x0, h0, x1, h1), h0 + (h1 - h0) * 0.15625, 1e-15);
}

TEST_P(FrictionSmoothStep, DerivativesVanishAtAndBeyondTheEnds) {
  const auto [x0, h0, x1, h1] = GetParam();
  for (const double x : {x0 - 1.0, x0, x1, x1 + 1.0}) {
    EXPECT_EQ(havsinDerivative(x, x0, h0, x1, h1), 0.0) << x;
    EXPECT_EQ(stepDerivative(x, x0, h0, x1, h1), 0.0) << x;
  }
  // Peak slopes at the midpoint: pi/2 and 3/2 times the mean slope.
  const double mean = (h1 - h0) / (x1 - x0);
  const double mid = 0.5 * (x0 + x1);
  EXPECT_NEAR(havsinDerivative(mid, x0, h0, x1, h1), std::numbers::pi / 2.0 * mean,
              1e-12 * std::abs(mean));
  EXPECT_NEAR(stepDerivative(mid, x0, h0, x1, h1), 1.5 * mean, 1e-12 * std::abs(mean));
}

TEST_P(FrictionSmoothStep, DerivativesMatchCentralDifferences) {
  const auto [x0, h0, x1, h1] = GetParam();
  const double width = x1 - x0;
  const double h = 1e-6 * width;
  const double scale = std::abs(h1 - h0) / width;
  for (int i = 1; i < 100; ++i) {
    const double x = x0 + width * i / 100.0;
    const double fd_havsin =
        (havsin(x + h, x0, h0, x1, h1) - havsin(x - h, x0, h0, x1, h1)) / (2.0 * h);
    const double fd_step = (step(x + h, x0, h0, x1, h1) - step(x - h, x0, h0, x1, h1)) / (2.0 * h);
    EXPECT_NEAR(havsinDerivative(x, x0, h0, x1, h1), fd_havsin, 1e-6 * scale) << x;
    EXPECT_NEAR(stepDerivative(x, x0, h0, x1, h1), fd_step, 1e-6 * scale) << x;
  }
}

TEST_P(FrictionSmoothStep, MonotoneBetweenTheEnds) {
  const auto [x0, h0, x1, h1] = GetParam();
  const double direction = h1 > h0 ? 1.0 : -1.0;
  double prev_havsin = h0;
  double prev_step = h0;
  for (int i = 1; i <= 1000; ++i) {
    const double x = x0 + (x1 - x0) * i / 1000.0;
    const double hv = havsin(x, x0, h0, x1, h1);
    const double st = step(x, x0, h0, x1, h1);
    EXPECT_GE(direction * (hv - prev_havsin), 0.0) << x;
    EXPECT_GE(direction * (st - prev_step), 0.0) << x;
    prev_havsin = hv;
    prev_step = st;
  }
}

TEST_P(FrictionSmoothStep, PrecomputedStructsAgreeWithFreeFunctions) {
  const auto [x0, h0, x1, h1] = GetParam();
  const Haversine haversine(x0, h0, x1, h1);
  const CubicStep cubic(x0, h0, x1, h1);
  for (int i = -10; i <= 110; ++i) {
    const double x = x0 + (x1 - x0) * i / 100.0;
    EXPECT_DOUBLE_EQ(haversine.value(x), havsin(x, x0, h0, x1, h1));
    EXPECT_DOUBLE_EQ(haversine.derivative(x), havsinDerivative(x, x0, h0, x1, h1));
    EXPECT_DOUBLE_EQ(cubic.value(x), step(x, x0, h0, x1, h1));
    EXPECT_DOUBLE_EQ(cubic.derivative(x), stepDerivative(x, x0, h0, x1, h1));
  }
}

INSTANTIATE_TEST_SUITE_P(Steps, FrictionSmoothStep,
                         testing::Values(StepCase{0.0, 0.0, 0.01, 0.35},    // RecurDyn rise
                                         StepCase{0.01, 0.35, 0.15, 0.3},   // RecurDyn fall
                                         StepCase{-2.0, 1.0, 3.0, -4.0},    // negative, wide
                                         StepCase{0.0, 0.0, 1e-6, 0.35}));  // tiny width

}  // namespace
}  // namespace tribo::friction
