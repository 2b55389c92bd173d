// The measured choice of `threads: auto` (core/thread_choice.hpp), fed step times made up here
// so that the right choice is known: the faster count wins (by more than kGain for several
// threads), a tie stays on one, the first step after a change is not counted, a window lasts
// kWindowSteps steps and kWindowSeconds, and a run whose costs change is followed within one
// probe. The schedule (two trial windows, then one probe window after kSettledWindows, the
// windows between probes doubling up to kMostSettledWindows while the probes confirm the
// choice) gives the expected share of steps on each count, computed here from the header's
// constants.
#include "core/thread_choice.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace tribo {
namespace {

// Steps `steps` times, each taking cost(threads, step index, first step on this count);
// returns the steps run on more than one thread.
long runChoice(ThreadChoice& choice, long steps,
               const std::function<double(int, long, bool)>& cost) {
  long threaded = 0;
  int last = -1;
  for (long i = 0; i < steps; ++i) {
    const int t = choice.threads();
    if (t > 1) ++threaded;
    choice.record(cost(t, i, t != last));
    last = t;
  }
  return threaded;
}

constexpr long kWindow = ThreadChoice::kWindowSteps;  // steps of 1 ms fill a window by count
constexpr long kSettled = ThreadChoice::kSettledWindows;
constexpr long kMostSettled = ThreadChoice::kMostSettledWindows;

// The settled windows before probe k (0, 1, ...) while every probe confirms the choice.
long settledBefore(int k) { return std::min(kSettled << k, kMostSettled); }

TEST(ThreadChoice, OneThreadToChooseFromMeasuresNothing) {
  for (int most : {-1, 0, 1}) {
    ThreadChoice choice(most);
    EXPECT_FALSE(choice.measuring());
    EXPECT_EQ(runChoice(choice, 1000, [](int, long, bool) { return 1e-3; }), 0);
    EXPECT_EQ(choice.threads(), 1);
  }
}

TEST(ThreadChoice, FasterThreadsAreKeptWithOneProbeWindowAPeriod) {
  ThreadChoice choice(2);
  EXPECT_TRUE(choice.measuring());
  EXPECT_EQ(choice.threads(), 2);  // the first trial: every thread
  // 1 ms a step on one thread, 0.7 ms on two (windows of kWindow counted steps: 5.6 ms > 2 ms).
  auto cost = [](int t, long, bool) { return t > 1 ? 0.7e-3 : 1e-3; };
  // Trials: 1 + kWindow steps on two threads, then 1 + kWindow on one; then settled on two.
  EXPECT_EQ(runChoice(choice, 1 + kWindow, cost), 1 + kWindow);
  EXPECT_EQ(choice.threads(), 1);
  EXPECT_EQ(runChoice(choice, 1 + kWindow, cost), 0);
  EXPECT_EQ(choice.threads(), 2);
  // Period k: 1 + settledBefore(k) kWindow steps on two, then a probe of 1 + kWindow on one.
  long steps = 0, on_two = 0;
  for (int k = 0; k < 20; ++k) {
    on_two += 1 + settledBefore(k) * kWindow;
    steps += 1 + settledBefore(k) * kWindow + 1 + kWindow;
  }
  EXPECT_EQ(runChoice(choice, steps, cost), on_two);
  EXPECT_EQ(choice.threads(), 2);
  EXPECT_LT(static_cast<double>(steps - on_two) / static_cast<double>(steps), 0.01 + 0.001);
}

TEST(ThreadChoice, SlowerOrEqualThreadsLeaveOneThread) {
  for (double two : {1.5e-3, 1e-3, 0.97e-3}) {  // slower, equal, faster by less than kGain
    ThreadChoice choice(3);
    const long threaded =
        runChoice(choice, 10000, [&](int t, long, bool) { return t > 1 ? two : 1e-3; });
    EXPECT_EQ(choice.threads(), 1) << two;
    // The trial's window, then probes of 1 + kWindow steps after settledBefore(k) windows (no
    // first uncounted step after the trial, whose choice is the count it ended on).
    long steps = 2 * (1 + kWindow) - 1, expected = 1 + kWindow;
    for (int k = 0; steps < 10000; ++k) {
      steps += settledBefore(k) * kWindow + (k > 0 ? 1 : 0);
      if (steps < 10000) expected += std::min(1 + kWindow, 10000 - steps);
      steps += 1 + kWindow;
    }
    EXPECT_EQ(threaded, expected) << two;
  }
  ThreadChoice faster(3);  // faster by more than kGain: three threads
  runChoice(faster, 1000, [](int t, long, bool) { return t > 1 ? 0.9e-3 : 1e-3; });
  EXPECT_EQ(faster.threads(), 3);
}

TEST(ThreadChoice, TheFirstStepOnANewCountIsNotCounted) {
  // Two threads faster, but their first step after a change costs a second (helpers asleep):
  // counted, it would make one thread look faster.
  ThreadChoice choice(2);
  runChoice(choice, 5000,
            [](int t, long, bool first) { return t > 1 ? (first ? 1.0 : 0.7e-3) : 1e-3; });
  EXPECT_EQ(choice.threads(), 2);
}

TEST(ThreadChoice, AWindowLastsItsSecondsForShortSteps) {
  // Steps of 2^-20 s (about 1 us, summed exactly): a window is the first step, not counted,
  // then kWindowSeconds of counted steps.
  const double step = std::ldexp(1.0, -20);
  const auto counted = static_cast<long>(std::ceil(ThreadChoice::kWindowSeconds / step));
  ThreadChoice choice(2);
  auto cost = [&](int, long, bool) { return step; };
  EXPECT_EQ(runChoice(choice, counted, cost), counted);
  EXPECT_EQ(choice.threads(), 2);  // one counted step short of the window
  runChoice(choice, 1, cost);
  EXPECT_EQ(choice.threads(), 1);
}

TEST(ThreadChoice, FollowsARunWhoseCostsChange) {
  // Two threads faster until step 3000, then slower (another process took the second core).
  const long change = 3000, steps = 20000;
  const long period = 1 + kMostSettled * kWindow + 1 + kWindow;  // the longest
  ThreadChoice choice(2);
  long before = 0, after = 0;  // steps on two threads before the change; two periods after
  for (long i = 0; i < steps; ++i) {
    const int t = choice.threads();
    if (t > 1 && i < change) ++before;
    if (t > 1 && i >= change + 2 * period) ++after;
    choice.record(t > 1 ? (i < change ? 0.7e-3 : 1.4e-3) : 1e-3);
  }
  EXPECT_EQ(choice.threads(), 1);
  // Before: all but the trial's and the probes' windows on two threads; after: only probes,
  // the first after kSettled windows, then spaced as they confirm one thread.
  const double probes = (1.0 + kWindow) / (1 + kSettled * kWindow + 1 + kWindow);
  EXPECT_GT(before, change * (1.0 - probes) - (1 + kWindow));
  EXPECT_LE(after, (steps - change - 2 * period) * probes + 1 + kWindow);
  EXPECT_GT(after, 0);  // the probes go on: a run that gets faster again is followed too
}

}  // namespace
}  // namespace tribo
