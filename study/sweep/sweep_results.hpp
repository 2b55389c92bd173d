// The files of a sweep folder and how a sweep resumes from them:
//   DIR/sweep.json   what the sweep is (scene file and its content hash, fixed overrides,
//                    axes and values, settle rule, columns); written at the first start
//   DIR/results.csv  a header, then one line per finished point:
//                      point,<swept parameters...>,status,amplitude_pp,period,time_to_98,
//                      rise_time,stuck_fraction,mean,first_pp,cycles,simulated,settled,
//                      warnings,message
//                    or, for --analysis modes,
//                      point,<swept parameters...>,status,max_growth_rate,frequency,
//                      unstable_modes,warnings,message
//                    or, for --analysis orbit,
//                      point,<swept parameters...>,status,period,amplitude_pp,x_min,x_max,
//                      largest_multiplier,stable,iterations,residual,warnings,message
//                    (figures as study/sweep/sweep_point.hpp; numbers with 10 significant digits);
//                    status is complete, diverged or error; the figures are empty unless
//                    complete (never NaN); text fields are quoted as CSV needs.
// Lines are appended as points finish, in finishing order, each written whole and flushed,
// so a killed sweep leaves every finished point on disk. Opening the folder again with the
// same sweep.json reads back the complete, valid lines, drops the rest (a line cut off by
// the kill), and skips those points; a different sweep.json is refused. When the last point
// is in, finish() rewrites results.csv in point order, so an interrupted and resumed sweep
// ends with the same bytes as an uninterrupted one (rows hold no wall times).
// Rows that slices of the sweep left in DIR/rows/ (study/sweep/sweep_rows.hpp) count as done
// too: they are added to results.csv on opening, so a plain run completes a sliced sweep.
// A lock (study/dir_lock.hpp: flock on DIR/.lock) keeps a second sweep or run from writing
// the same folder.
// Not here: running points, distributing them.
#pragma once

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "study/dir_lock.hpp"
#include "study/sweep/sweep_grid.hpp"
#include "study/sweep/sweep_point.hpp"

namespace tribo::study {

// The output folder cannot be used: not writable, locked by another sweep, holding a
// different sweep, or a results file that is not one. what() names the path.
class SweepOutputError : public std::runtime_error {
 public:
  enum class Reason { kCannotWrite, kInUse, kOtherSweep };
  SweepOutputError(Reason reason, const std::string& what)
      : std::runtime_error(what), reason_(reason) {}
  Reason reason() const { return reason_; }

 private:
  Reason reason_;
};

// Header columns for a grid.
std::vector<std::string> sweepColumns(const SweepGrid& grid,
                                      SweepAnalysis analysis = SweepAnalysis::kRun);

// One results line (ending in '\n') for point `index` of `grid`.
std::string formatSweepRow(std::size_t index, const SweepGrid& grid, const PointOutcome& outcome,
                           SweepAnalysis analysis = SweepAnalysis::kRun);

// Fields of one CSV line (without its '\n'); quoted fields unquoted. Empty on a malformed
// line (an unclosed quote).
std::vector<std::string> splitCsvLine(const std::string& line);

// The point a results line (without its '\n') is the row of, when it is a whole row of this
// sweep: the columns' count, a point index in the grid, that point's values and a status.
std::optional<std::size_t> sweepRowPoint(const std::string& line, const SweepGrid& grid,
                                         SweepAnalysis analysis = SweepAnalysis::kRun);

class SweepResultsFile {
 public:
  // Creates `dir` if needed, takes its lock, and either starts a new sweep (writing
  // `manifest` to sweep.json and the header) or resumes the one there. Throws
  // SweepOutputError.
  SweepResultsFile(const std::filesystem::path& dir, const std::string& manifest,
                   const SweepGrid& grid, SweepAnalysis analysis = SweepAnalysis::kRun);
  ~SweepResultsFile();
  SweepResultsFile(const SweepResultsFile&) = delete;
  SweepResultsFile& operator=(const SweepResultsFile&) = delete;

  // Per point: already in the file.
  const std::vector<bool>& done() const { return done_; }
  std::size_t doneCount() const { return done_count_; }
  // The points not yet in the file, in point order.
  std::vector<std::size_t> pendingPoints() const {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < done_.size(); ++i)
      if (!done_[i]) out.push_back(i);
    return out;
  }
  // Lines dropped when resuming (cut off or not a row of this sweep).
  std::size_t droppedLines() const { return dropped_; }

  // Appends and flushes the line of point `index` (thread-safe). A point already done is
  // ignored. Throws SweepOutputError if the write fails.
  void append(std::size_t index, const std::string& line);
  // Rewrites results.csv in point order. Call once every point is done.
  void finish();

  const std::filesystem::path& resultsPath() const { return results_; }

 private:
  void rewrite(const std::vector<std::size_t>& order);

  std::filesystem::path dir_, results_;
  std::string header_;
  std::vector<bool> done_;
  std::vector<std::string> lines_;  // per point, the line as written
  std::vector<std::size_t> written_order_;
  std::size_t done_count_ = 0, dropped_ = 0;
  std::FILE* file_ = nullptr;
  std::optional<DirLock> lock_;
  std::mutex mutex_;
};

}  // namespace tribo::study
