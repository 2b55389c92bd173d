// Runs a loaded scene from t = 0 to its duration, recording at the output interval, and
// analyses the observed coordinate (limit-cycle amplitude, period, time to 98% of the
// amplitude, stuck fraction). Before the run, the step is checked against the a-priori
// stability limit (core/stability.hpp); exceeding it is a warning carried in the result. A
// diverged run stops at the failing step and is returned with complete = false and the
// simulator's message; what was recorded up to the last good step is kept.
// Recording either keeps every row in memory (the default: sweeps, the tradeoff read the
// columns; capped by study/output_budget.hpp) or streams them (RunOptions::sink, e.g.
// trajectory.csv written as the run goes): then memory does not grow with the duration, and
// the summary is computed from its three columns spilled to scratch files
// (study/series_spill.hpp), with the same figures as from memory. The simulator's step does
// no I/O; a streamed row is a buffered write between steps.
// A run may be stopped from outside (RunOptions::stop, e.g. set by a signal handler): it
// stops at once (between steps, or inside a step of the adaptive integrators, which check
// the flag at every force evaluation) and goes back to the state of the last output row,
// so the trajectory ends at the state the result reports and its rows are those of an
// uninterrupted run; it returns with interrupted = true. The step counts in `stats` include
// the steps after that row that were given up.
// Not here: opening files (study/result_writer.hpp), argument parsing, signals (apps/).
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "core/simulator.hpp"
#include "core/stability.hpp"
#include "io/scene_loader.hpp"
#include "study/oscillation_summary.hpp"
#include "study/trajectory_recorder.hpp"

namespace tribo::study {

struct RunResult {
  bool complete = false;
  bool interrupted = false;  // stopped by RunOptions::stop (complete is false)
  std::string message;       // why the run stopped early, when !complete
  StepStats stats;
  double wall_seconds = 0.0;  // time spent stepping (analysis excluded)
  double simulated_seconds = 0.0;
  TrajectoryRecorder trajectory;
  OscillationSummary summary;         // of output.summary's body and coordinate
  StabilityReport stability;          // a-priori step limit of the model
  std::vector<std::string> warnings;  // e.g. the step exceeds the stability limit
  StepStatus stop;                    // when !complete: the failed step's time, body and quantity
};

// An optional watch over a run: every `interval` simulated seconds (> 0) `stop` sees the
// recording so far; returning true ends the run there, complete (e.g. a sweep point whose
// oscillation has settled, study/sweep/sweep_settle.hpp). Empty `stop`: the run lasts its duration.
struct RunMonitor {
  double interval = 0.0;  // [s]
  std::function<bool(const TrajectoryRecorder&)> stop;
};

// How a run records and who may stop it. The defaults keep every row and run to the end.
struct RunOptions {
  RunMonitor monitor;  // needs the rows kept (no sink)
  // Streaming: every row goes to `sink` and none is kept; the summary's scratch files go
  // into `spill_dir` (the temporary folder when empty).
  RowSink* sink = nullptr;
  std::filesystem::path spill_dir;
  // Set by someone else: stop now, back at the last output row (interrupted).
  const std::atomic<bool>* stop = nullptr;
  // Called about every `progress_interval` wall seconds with the simulated time [s].
  std::function<void(double)> progress;
  double progress_interval = 0.25;
  // Time each stage of the step into RunResult::stats.profile (core/stage_profile.hpp).
  bool profile = false;
  // A controller outside the model: called before the first row and then before every step
  // that starts at or after the next multiple of `control_interval` (every step when 0),
  // with the simulator, to command its actuators (Simulator::setActuatorCommand; held over
  // the steps until the next call). A non-empty return stops the run there, not complete,
  // with that message as its status and every row so far kept.
  std::function<std::string(Simulator&)> controller;
  double control_interval = 0.0;  // [s]
};

// Throws OutputTooLarge (study/output_budget.hpp) when rows are kept and would not fit the
// memory cap, std::invalid_argument for a monitor on a streamed run, std::runtime_error
// when a scratch file cannot be written.
RunResult runScene(const io::Scene& scene, const RunOptions& options);
RunResult runScene(const io::Scene& scene, const RunMonitor& monitor = {});
// A run's status in one word: complete, interrupted (the stop request), stopped (its
// controller said so, RunOptions::controller) or diverged (a failed step).
inline const char* runStatusName(const RunResult& r) {
  if (r.complete) return "complete";
  if (r.interrupted) return "interrupted";
  return r.stop.quantity == "controller" ? "stopped" : "diverged";
}

// The oscillation summary of a recorded trajectory for a summary spec.
OscillationSummary summarize(const TrajectoryRecorder& trajectory, const Model& model,
                             const io::SummarySpec& spec);

}  // namespace tribo::study
