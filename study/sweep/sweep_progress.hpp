// The progress line of a sweep on the terminal:
//   sweep [#########-----------]  180/400  45%  12.3 points/s  0:18 left  2 failed
// The rate counts the points finished in this run only (resumed ones are excluded), and
// the time left is the remaining points over that rate, so it is rough while point costs
// vary. On a terminal the line is redrawn in place at most ten times a second; otherwise a
// line is printed at every tenth of the sweep, so logs stay short. Thread-safe.
// Not here: what a point costs, what failed (the results file says).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <mutex>

namespace tribo::study {

class SweepProgress {
 public:
  // `already_done` of `total` points were finished before this run. Nothing is printed when
  // `out` is null.
  SweepProgress(std::FILE* out, std::size_t total, std::size_t already_done);

  void pointDone(bool failed);
  // Prints the final line (once).
  void finish();

 private:
  void render(bool force);

  std::FILE* out_;
  bool terminal_ = false;
  std::size_t total_, done_, done_at_start_, failed_ = 0;
  int last_tenth_ = -1;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::mutex mutex_;
};

}  // namespace tribo::study
