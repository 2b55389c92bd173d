// Runs a loaded scene from t = 0 to its duration, recording at the output interval, and
// analyses the observed coordinate (limit-cycle amplitude, period, time to 98% of the
// amplitude, stuck fraction). Before the run, the step is checked against the a-priori
// stability limit (core/stability.hpp); exceeding it is a warning carried in the result. The loop
// does no I/O. A diverged run stops at the failing step and is returned with complete = false and
// the simulator's message; what was recorded up to the last good step is kept. Not here: writing
// files (study/result_writer.hpp), argument parsing (apps/).
#pragma once

#include <functional>
#include <string>

#include "core/simulator.hpp"
#include "core/stability.hpp"
#include "io/scene_loader.hpp"
#include "study/oscillation_summary.hpp"
#include "study/trajectory_recorder.hpp"

namespace tribo::study {

struct RunResult {
  bool complete = false;
  std::string message;  // why the run stopped early, when !complete
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

RunResult runScene(const io::Scene& scene, const RunMonitor& monitor = {});

// The oscillation summary of a recorded trajectory for a summary spec.
OscillationSummary summarize(const TrajectoryRecorder& trajectory, const Model& model,
                             const io::SummarySpec& spec);

}  // namespace tribo::study
