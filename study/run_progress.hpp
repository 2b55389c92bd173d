// The progress line of one long run, on stderr:
//   run  1234 of 10000 simulated s (12%)  3150 s/s  0:03 elapsed  0:28 left
// The rate is simulated seconds per wall second since the start, the time left the rest of
// the duration over that rate. Nothing is shown for a run's first kDelay wall seconds (short
// runs stay silent). On a terminal the line is redrawn in place; elsewhere (a log, when
// asked for) a new line is printed every kDelay seconds. Not thread-safe: the run's
// progress hook calls it (study/scene_run.hpp). Not here: whether to show it (apps/).
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace tribo::study {

// "m:ss", or "h:mm:ss" from an hour on.
std::string clockText(double seconds);

class RunProgress {
 public:
  static constexpr double kDelay = 2.0;  // [wall s]

  // Prints nothing when `out` is null. `duration` is the run's simulated duration [s].
  RunProgress(std::FILE* out, double duration);

  // The run has reached `simulated` seconds.
  void update(double simulated);
  // Ends a line drawn in place (before anything else is printed).
  void finish();

 private:
  std::FILE* out_;
  double duration_;
  bool terminal_ = false, drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_line_;
};

}  // namespace tribo::study
