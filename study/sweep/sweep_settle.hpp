// Has a run's oscillation settled onto its limit cycle? Lets a sweep run each point exactly
// as long as it needs instead of one fixed duration for all: the scene's duration becomes an
// upper bound, and the run stops at the first check where
//   |A_last - A_prev| <= tolerance * A_last
// with A_last the mean peak-to-peak of the last K cycles of the observed coordinate and
// A_prev that of the K cycles before them (K = the summary's last_cycles; cycles as
// study/oscillation_summary.hpp detects them). A record whose recent window holds no cycle is
// settled when x stands still there: its range is at most tolerance times the range of the
// whole record (a motion that died out).
//
// Why this suffices for friction-driven limit cycles: while the envelope grows as
// e^(sigma t), A_last / A_prev = e^(sigma K T) (T the period), so growth is seen as long
// as sigma K T > tolerance; for the belt scene over the paper's ranges sigma K T >= 1e-2.
// Once the box sticks, the stick phase maps every state onto the belt's velocity, so the
// stick-slip cycle is reached within a cycle or two and A_last = A_prev to round-off.
// Not here: running (study/scene_run.hpp calls the monitor), what a sweep records.
#pragma once

#include <cstddef>
#include <span>

#include "io/scene_loader.hpp"
#include "study/scene_run.hpp"
#include "study/trajectory_recorder.hpp"

namespace tribo::study {

struct SettleRule {
  double tolerance = 1e-3;    // relative change of the amplitude between cycle blocks (> 0)
  double check_interval = 5;  // simulated seconds between checks (> 0)
};

struct SettleCheck {
  bool settled = false;
  double period = 0;  // mean duration of the last K cycles in the window [s]; 0 if fewer
};

// The test above on a record (t, x) whose recent window starts at sample `window_start`;
// `cycles` is K (>= 1). Pure; exposed for tests. Throws std::invalid_argument as
// summarizeOscillation does for a bad record.
SettleCheck checkSettled(std::span<const double> t, std::span<const double> x,
                         std::size_t window_start, int cycles, double tolerance);

// Watches one run of `scene`: monitor() gives the hook for runScene; after the run,
// settled() says whether the run stopped because it settled. Throws std::invalid_argument
// when the scene names no observed coordinate (output.summary) or the rule is invalid.
class SettleWatch {
 public:
  SettleWatch(const io::Scene& scene, const SettleRule& rule);

  RunMonitor monitor();
  bool settled() const { return settled_; }

 private:
  bool check(const TrajectoryRecorder& trajectory);

  SettleRule rule_;
  int cycles_ = 3;
  std::size_t x_column_ = 0;
  double period_ = 0;  // the last check's estimate, 0 when unknown
  bool settled_ = false;
};

}  // namespace tribo::study
