// The signal memo (core/signal_memo.hpp): what it returns is the signal's own value, bit for
// bit, at every time asked for, repeated or not; a repeated time does not evaluate again; a
// constant component is never evaluated after the memo is made.
#include "core/signal_memo.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <vector>

namespace tribo {
namespace {

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// RK4's order of times over a few steps of h: t, t + h/2, t + h/2, t + h, then the next step.
std::vector<double> rk4Times(double h, int steps) {
  std::vector<double> times;
  double t = 0.0;
  for (int i = 0; i < steps; ++i) {
    for (double c : {0.0, 0.5, 0.5, 1.0}) times.push_back(t + c * h);
    t += h;
  }
  return times;
}

TEST(SignalMemo, VectorComponentsAreTheSignalsValuesBitForBit) {
  const std::array<Signal, 3> s = {Signal::ramp(0.7, 0.01, -0.2),
                                   Signal::sines({{0.3, 5.0, 0.4, 0.1}}), Signal::constant(-0.0)};
  SignalVectorMemo memo(s);
  EXPECT_FALSE(memo.zero());
  for (double t : rk4Times(3e-3, 20)) {
    const Vec3 v = memo.at(t);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(bits(v[k]), bits(s[k].value(t))) << "t " << t;
  }
  // Back to an earlier time: evaluated again, not the last time's values.
  EXPECT_EQ(bits(memo.at(0.0)[0]), bits(s[0].value(0.0)));
}

TEST(SignalMemo, ZeroOnlyWhenEveryComponentIsTheConstantZero) {
  const std::array<Signal, 3> zero{};
  EXPECT_TRUE(SignalVectorMemo(zero).zero());
  EXPECT_EQ(SignalVectorMemo(zero).at(1.0), Vec3::Zero());
  const std::array<Signal, 3> ramp_from_zero = {Signal(), Signal::ramp(1.0), Signal()};
  EXPECT_FALSE(SignalVectorMemo(ramp_from_zero).zero());  // 0 at t = 0, not after
}

TEST(SignalMemo, ARepeatedTimeDoesNotEvaluateAgain) {
  int calls = 0;
  const std::array<Signal, 3> s = {Signal::function([&calls](double t) {
                                     ++calls;
                                     return 2.0 * t;
                                   }),
                                   Signal::constant(1.0), Signal()};
  calls = 0;  // the factory may have sampled it
  SignalVectorMemo memo(s);
  const std::vector<double> times = rk4Times(1e-3, 10);
  for (double t : times) EXPECT_EQ(memo.at(t)[0], 2.0 * t);
  // 10 steps: t, t + h/2, t + h each once (a step's t + h is the next step's t): 21 times.
  EXPECT_EQ(calls, 21);
}

TEST(SignalMemo, ScalarGivesTheValueAndTheDerivativeWhenAskedFor) {
  const Signal s = Signal::smoothStep(0.1, -1.0, 0.4, 2.0);
  SignalMemo with(s, true), without(s, false);
  for (double t : rk4Times(0.02, 30)) {
    EXPECT_EQ(bits(with.at(t).value), bits(s.value(t)));
    EXPECT_EQ(bits(with.at(t).derivative), bits(s.derivative(t)));
    EXPECT_EQ(bits(without.at(t).value), bits(s.value(t)));
    EXPECT_EQ(without.at(t).derivative, 0.0);
  }
}

TEST(SignalMemo, SameTimeIsBitEquality) {
  EXPECT_TRUE(sameTime(0.25, 0.25));
  EXPECT_FALSE(sameTime(0.0, -0.0));
  EXPECT_FALSE(sameTime(std::numeric_limits<double>::quiet_NaN(), 0.0));
  EXPECT_FALSE(sameTime(0.1 + 0.2, 0.3));
}

}  // namespace
}  // namespace tribo
