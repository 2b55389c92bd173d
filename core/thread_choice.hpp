// The measured choice behind `threads: auto`: while a run goes, it times the simulator's own
// steps on one thread and on every thread the scene may use, and runs on whichever was faster.
// The results are the same bit for bit on any count of threads (docs/performance.md, "Two
// threads"), so the choice changes the speed only, never what is computed. A small scene on a
// machine whose other cores are busy (or whose wake-ups are slow: a virtual machine) runs
// slower on two threads than on one; no fixed threshold of items knows that, a measurement
// does.
// The steps are timed in windows (kWindowSteps steps and kWindowSeconds at least, the first
// step after a change of threads not counted: the helpers wake and the caches refill). The
// first two windows try both counts; afterwards one window on the other count follows every
// kSettledWindows windows on the chosen one, so a run whose load changes (a pile settling, a
// chute filling, another process starting) follows it. A probe that confirms the choice
// doubles the windows to the next (up to kMostSettledWindows: the probes' cost, a window on
// the slower count, falls below 1 % of the steps); one that changes it starts again from
// kSettledWindows. Several threads are chosen only when
// their window's mean step is below kGain times one thread's: a tie leaves the cores free.
// Not here: the clock (the caller times its steps: core/simulator.cpp), the threads each stage
// starts (core/stage_threads.hpp), a fixed count (`threads: N` is never second-guessed).
#pragma once

namespace tribo {

class ThreadChoice {
 public:
  static constexpr long kWindowSteps = 8;
  static constexpr double kWindowSeconds = 2e-3;  // [s] of counted steps a window
  static constexpr int kSettledWindows = 16;
  static constexpr int kMostSettledWindows = 128;
  static constexpr double kGain = 0.95;

  // Chooses between 1 and `most` threads; `most` <= 1 measures nothing and answers 1.
  explicit ThreadChoice(int most = 1);

  // Whether steps are to be timed (more than one count to choose from).
  bool measuring() const { return most_ > 1; }
  // The threads the next step should run on.
  int threads() const { return threads_; }
  // The step just taken, on threads(), took `seconds` of wall time.
  void record(double seconds);

 private:
  void closeWindow();

  int most_ = 1;
  int threads_ = 1;
  int chosen_ = 1;   // the count a settled window runs on
  int phase_ = 0;    // 0: trying `most`, 1: trying one, 2: settled, 3: probing the other
  int settled_ = 0;  // settled windows since the last probe
  int settled_limit_ = kSettledWindows;  // settled windows before the next probe
  bool warm_ = false;                    // the window's first step (not counted) has been taken
  long window_steps_ = 0;
  double window_seconds_ = 0.0;
  double mean_[2] = {0.0, 0.0};  // the last window's mean step [s]: [0] one thread, [1] most
};

}  // namespace tribo
