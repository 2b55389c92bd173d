// How many threads a force evaluation may use (SimulationOptions::threads): a number, or
// kAutoThreads (0): OMP_NUM_THREADS's first number, else one per core the process may run on
// (read from the environment: another library in the process may change OpenMP's own
// setting), and a Simulator then runs each step on one thread or on all of them, whichever
// its timed steps found faster (core/thread_choice.hpp). Each stage of
// Dynamics::evaluate then starts only as many as its item count pays for (one per
// kItemsPerThread items; core/stage_threads.hpp), so small scenes never start a thread; the
// results are the same bit for bit for any count (docs/performance.md, "Two threads").
// A caller that already runs scenes on several threads of its own (a sweep with --jobs > 1)
// caps the threads of every Dynamics built on its thread with ScopedThreadLimit.
// Not here: the parallel loops themselves (contact/parallel_range.hpp).
#pragma once

namespace tribo {

inline constexpr int kAutoThreads = 0;

// While it lives, a Dynamics constructed on this thread uses at most `limit` threads
// (0: no limit). Limits nest; the innermost wins.
class ScopedThreadLimit {
 public:
  explicit ScopedThreadLimit(int limit) : previous_(current()) { current() = limit; }
  ~ScopedThreadLimit() { current() = previous_; }
  ScopedThreadLimit(const ScopedThreadLimit&) = delete;
  ScopedThreadLimit& operator=(const ScopedThreadLimit&) = delete;
  // The limit in force on this thread (0: none).
  static int limit() { return current(); }

 private:
  static int& current() {
    thread_local int value = 0;
    return value;
  }
  int previous_;
};

// The threads a Dynamics uses for a model asking for `requested` (kAutoThreads or >= 1),
// under this thread's ScopedThreadLimit. Defined in core/dynamics.cpp (it asks OpenMP for
// the cores).
int resolveThreads(int requested);
// What kAutoThreads stands for, before any limit.
int autoThreads();

}  // namespace tribo
