// The settle rule on records with a known answer: a growing envelope is not settled, a
// steady cycle is, a motion that died out is, and a sinusoid whose growth over K cycles is
// just above or below the tolerance lands on the side the rule's formula says.
#include "study/sweep/sweep_settle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace tribo::study {
namespace {

struct Record {
  std::vector<double> t, x;
};

// x = A0 e^(sigma t) sin(2 pi t / T), sampled at h from 0 to t_end; then held at x_hold if
// t_stop < t_end.
Record sine(double sigma, double period, double t_end, double h = 1e-3, double t_stop = 1e9) {
  Record r;
  for (double t = 0; t <= t_end; t += h) {
    r.t.push_back(t);
    const double tt = std::min(t, t_stop);
    r.x.push_back(std::exp(sigma * tt) * std::sin(2 * std::numbers::pi * tt / period) *
                  (t > t_stop ? 0.0 : 1.0));
  }
  return r;
}

SettleCheck check(const Record& r, double tolerance, int cycles = 3) {
  return checkSettled(r.t, r.x, 0, cycles, tolerance);
}

TEST(SweepSettle, SteadyCycleIsSettledAndItsPeriodKnown) {
  const SettleCheck c = check(sine(0.0, 1.25, 20), 1e-3);
  EXPECT_TRUE(c.settled);
  EXPECT_NEAR(c.period, 1.25, 1e-6);
}

TEST(SweepSettle, GrowthIsSeenWhenItExceedsTheToleranceOverKCycles) {
  // Over K = 3 cycles of T = 1 s the block means differ by e^(3 sigma) - 1.
  const double tol = 1e-3;
  const double seen = std::log(1 + 3 * tol) / 3, unseen = std::log(1 + tol / 3) / 3;
  EXPECT_FALSE(check(sine(seen, 1.0, 30), tol).settled);
  EXPECT_TRUE(check(sine(unseen, 1.0, 30), tol).settled);
  EXPECT_FALSE(check(sine(-seen, 1.0, 30), tol).settled);  // decay too
}

TEST(SweepSettle, TooFewCyclesIsNotSettled) {
  const SettleCheck c = check(sine(0.0, 1.0, 5.5), 1e-3);  // 4 full cycles < 2K
  EXPECT_FALSE(c.settled);
  EXPECT_NEAR(c.period, 1.0, 1e-6);
}

TEST(SweepSettle, MotionThatDiedOutIsSettledOnceTheWindowIsStill) {
  const Record r = sine(0.0, 1.0, 30, 1e-3, 10.0);  // oscillates, then rests at 0
  const auto start = static_cast<std::size_t>(20.0 / 1e-3);
  EXPECT_TRUE(checkSettled(r.t, r.x, start, 3, 1e-3).settled);
  // A window that still holds the motion is not.
  EXPECT_FALSE(checkSettled(r.t, r.x, static_cast<std::size_t>(8.5 / 1e-3), 3, 1e-3).settled);
}

TEST(SweepSettle, WindowWithLessThanThreeSamplesFallsBackToTheWholeRecord) {
  const Record r = sine(0.0, 1.0, 10);
  EXPECT_TRUE(checkSettled(r.t, r.x, r.t.size() - 1, 3, 1e-3).settled);
  EXPECT_THROW(checkSettled(r.t, r.x, 0, 0, 1e-3), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::study
