#include "core/thread_choice.hpp"

#include <algorithm>

namespace tribo {

ThreadChoice::ThreadChoice(int most)
    : most_(most > 1 ? most : 1), threads_(most_), chosen_(most_) {}

void ThreadChoice::record(double seconds) {
  if (!measuring()) return;
  if (!warm_) {  // the first step on a new count: helpers waking, caches refilling
    warm_ = true;
    return;
  }
  ++window_steps_;
  window_seconds_ += seconds;
  if (window_steps_ >= kWindowSteps && window_seconds_ >= kWindowSeconds) closeWindow();
}

void ThreadChoice::closeWindow() {
  mean_[threads_ > 1 ? 1 : 0] = window_seconds_ / static_cast<double>(window_steps_);
  window_steps_ = 0;
  window_seconds_ = 0.0;
  int next = threads_;
  switch (phase_) {
    case 0:  // `most` tried: now one
      phase_ = 1;
      next = 1;
      break;
    case 2:  // settled: after settled_limit_ windows, one window on the other count
      if (++settled_ < settled_limit_) break;
      phase_ = 3;
      next = chosen_ > 1 ? 1 : most_;
      break;
    default: {  // both counts' last windows known (1: the first trial, 3: a probe)
      const int chosen = mean_[1] < kGain * mean_[0] ? most_ : 1;
      settled_limit_ = phase_ == 3 && chosen == chosen_
                           ? std::min(2 * settled_limit_, kMostSettledWindows)
                           : kSettledWindows;
      chosen_ = chosen;
      phase_ = 2;
      settled_ = 0;
      next = chosen_;
      break;
    }
  }
  if (next != threads_) {
    threads_ = next;
    warm_ = false;
  }
}

}  // namespace tribo
