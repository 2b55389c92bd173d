// Writes a run's results into an output folder:
//   trajectory.csv  header row, then one row per recorded sample (columns as recorded)
//   summary.json    status ("complete" or "diverged" with the message), the scene's
//                   parameters and speed/accuracy settings, the oscillation figures, run
//                   statistics (penetration, constraint drift) and speed
// Each file is written under a temporary name and renamed when complete, so a reader never
// sees a half-written file under the final name. Not here: running, analysis.
#pragma once

#include <filesystem>

#include "study/scene_run.hpp"

namespace tribo::study {

// Throws std::runtime_error naming the path when a file cannot be written.
void writeTrajectoryCsv(const std::filesystem::path& file, const TrajectoryRecorder& trajectory);
void writeSummaryJson(const std::filesystem::path& file, const io::Scene& scene,
                      const RunResult& result);
// Both files into `dir` (created if missing).
void writeResults(const std::filesystem::path& dir, const io::Scene& scene,
                  const RunResult& result);

}  // namespace tribo::study
