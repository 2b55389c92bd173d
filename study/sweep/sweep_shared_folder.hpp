// A sweep folder written by several processes at once: the slices of one sweep
// (tribo sweep --slice I/N), on one machine or on several sharing the folder, and the merge
// (tribo sweep --merge DIR). Opening it creates DIR (DIR/rows comes with the first row),
// takes the folder's lock shared (study/dir_lock.hpp: slices and merges run together; a
// one-process sweep or a run holding it is refused, and keeps them out), and publishes
// sweep.json race-free: the first process creates it whole (study/file_commit.hpp,
// createFileOnce), every other one reads it and refuses a different sweep, naming what
// differs (scene, axes, settings). Each finished point is a row file of its own
// (study/sweep/sweep_rows.hpp); a point counts as done when its row is in DIR/rows or in a
// results.csv of this sweep (one left by a one-process run). Once every point is done,
// results.csv is written whole in point order (header, then one line a point, the same
// bytes a one-process sweep ends with); any process may do it, and all write the same
// bytes, replaced atomically, so it does not matter which does it last.
// Not here: running points (study/sweep/sweep_slice.hpp), which points a slice runs.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "study/dir_lock.hpp"
#include "study/sweep/sweep_grid.hpp"
#include "study/sweep/sweep_point.hpp"

namespace tribo::study {

class SharedSweepFolder {
 public:
  // Opens `dir` for the sweep described by `manifest` (the text of its sweep.json), reading
  // what is done. Throws SweepOutputError: kCannotWrite (cannot create or read), kInUse
  // (a one-process sweep or run holds the folder), kOtherSweep (a different sweep.json, or
  // a results.csv without one).
  SharedSweepFolder(const std::filesystem::path& dir, const std::string& manifest,
                    const SweepGrid& grid, SweepAnalysis analysis);

  // Reads the folder again (the rows other processes wrote since).
  void rescan();
  bool isDone(std::size_t point) const { return !lines_[point].empty(); }
  std::size_t doneCount() const;
  // The points not done, in point order.
  std::vector<std::size_t> missingPoints() const;

  // Records point `index`'s row (`line` ends in '\n'). Not thread-safe: one call at a time.
  // Throws SweepOutputError (kCannotWrite).
  void record(std::size_t index, const std::string& line);

  // When every point is done: writes results.csv in point order and returns true; else
  // false, writing nothing. Throws SweepOutputError (kCannotWrite).
  bool writeResultsIfComplete();

  const std::filesystem::path& resultsPath() const { return results_; }

 private:
  std::filesystem::path dir_, results_;
  const SweepGrid& grid_;
  SweepAnalysis analysis_;
  std::string header_;
  std::vector<std::string> lines_;  // per point, its row with '\n'; empty when not done
  std::optional<DirLock> lock_;
  bool have_rows_dir_ = false;  // DIR/rows made (by the first record)
};

}  // namespace tribo::study
