// Writes a run's results into an output folder:
//   trajectory.csv  header row, then one row per recorded sample (columns as recorded),
//                   either from a recorder's kept rows or row by row as the run goes
//                   (TrajectoryCsvFile, a RowSink: nothing of it stays in memory)
//   summary.json    status ("complete", "diverged" with the message, or "interrupted"), the scene's
//                   parameters and speed/accuracy settings, the oscillation figures, run
//                   statistics (penetration, constraint drift) and speed
// Each file is written under a temporary name and renamed when complete, so a reader never
// sees a half-written file under the final name. Not here: running, analysis.
#pragma once

#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "study/scene_run.hpp"

namespace tribo::study {

// trajectory.csv written while the run goes: the header at once, each row as recorded,
// all under partialPath(file) until commit() renames it. Destroyed without commit(), it
// leaves the .partial file behind and the final name untouched.
class TrajectoryCsvFile : public RowSink {
 public:
  // Numbers to `digits` significant digits (17: every double exactly). Throws
  // std::runtime_error naming the path when it cannot be opened.
  TrajectoryCsvFile(const std::filesystem::path& file, const std::vector<std::string>& columns,
                    int digits = 10);
  ~TrajectoryCsvFile() override;
  TrajectoryCsvFile(const TrajectoryCsvFile&) = delete;
  TrajectoryCsvFile& operator=(const TrajectoryCsvFile&) = delete;

  void row(std::span<const double> values) override;
  // Flushes, closes and renames to the final name. Throws std::runtime_error naming the
  // path if any write failed (e.g. the disk filled up during the run).
  void commit();

 private:
  std::filesystem::path file_;
  std::FILE* f_ = nullptr;
  int digits_ = 10;
  std::vector<char> line_;  // a row's text, written with one call
};

// Throws std::runtime_error naming the path when a file cannot be written. The recorder must
// keep its rows.
void writeTrajectoryCsv(const std::filesystem::path& file, const TrajectoryRecorder& trajectory,
                        int digits = 10);
void writeSummaryJson(const std::filesystem::path& file, const io::Scene& scene,
                      const RunResult& result);
// The text writeSummaryJson writes (without its final newline), e.g. for the Python module.
std::string summaryJsonText(const io::Scene& scene, const RunResult& result);
// The run statistics of summary.json's "run" block (steps, penetration, constraint drift,
// evaluations, ...) as a JSON object's text: also the Python Simulator's stats dict.
std::string stepStatsJsonText(const StepStats& stats);
// Both files into `dir` (created if missing), from a recorder that keeps its rows.
void writeResults(const std::filesystem::path& dir, const io::Scene& scene,
                  const RunResult& result);

}  // namespace tribo::study
