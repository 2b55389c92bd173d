// Where a run's rows fall. Rows are recorded after whole steps, so an output interval that
// is not a whole multiple of the step would space them unevenly (1.498, 1.4992, 1.5, 1.5012
// s for 1.5 ms rows of 1.2 ms steps), and an FFT of the CSV would be wrong. The interval
// used is the whole multiple of the step nearest to the one asked for, with a warning when
// they differ. Not here: recording (study/trajectory_recorder.hpp), the run loop
// (study/scene_run.hpp).
#pragma once

#include <optional>
#include <string>

namespace tribo::study {

// Rows fall on steps. The steps between two rows: the whole multiple of the step `dt`
// nearest to the output interval asked for, at least 1 (so rows are evenly spaced).
long outputStride(double interval, double dt);
// The interval rows are recorded at: `dt` when `interval` is at most the step; `interval`
// itself when it is a whole multiple of `dt` (to 1e-9 relative); else outputStride * dt.
double outputInterval(double interval, double dt);
// The warning a run gives when an interval above the step is not a whole multiple of it,
// naming both and the interval used; none otherwise.
std::optional<std::string> outputStrideNote(double interval, double dt);

}  // namespace tribo::study
