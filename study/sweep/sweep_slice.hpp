// A sweep cut into N slices run as separate processes (tribo sweep --slice I/N: a job array
// of Slurm or HTCondor, GNU parallel, several machines sharing a file system), each writing
// its points into the same folder (study/sweep/sweep_shared_folder.hpp), and the merge that
// completes results.csv once all are done (tribo sweep --merge DIR).
// Slices are numbered 1 to N (1 <= I <= N), as job arrays number their tasks. Point k of
// the grid belongs to slice (k mod N) + 1: interleaved, not in blocks, because neighbouring
// points cost alike (a slow corner of the grid, e.g. points that take long to settle, is
// shared by every slice instead of landing on one), and because the split needs nothing but
// I and N (there is no cost estimate of a point before it runs). A slice run again skips
// its points already done, so a killed slice resumes like a one-process sweep.
// Not here: the points themselves (study/sweep/sweep_runner.hpp), argument parsing.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "study/sweep/sweep_runner.hpp"

namespace tribo::study {

struct SweepSlice {
  std::size_t index = 1;  // I, 1 <= I <= count
  std::size_t count = 1;  // N
  bool contains(std::size_t point) const { return point % count == index - 1; }
};

// Most slices a sweep may be cut into (as many as it may have points).
inline constexpr std::size_t kMaxSlices = SweepGrid::kMaxPoints;

// "I/N" (the text after --slice), two whole numbers with 1 <= I <= N <= kMaxSlices. Throws
// std::invalid_argument naming --slice, what is expected and what was found.
SweepSlice parseSweepSlice(std::string_view text);

// The points of `slice` in a grid of `points` points, in point order.
std::vector<std::size_t> slicePoints(std::size_t points, SweepSlice slice);

struct SliceReport {
  SweepReport slice;             // points of this slice: in it, resumed, run now, failed
  std::size_t sweep_points = 0;  // of the whole sweep
  std::size_t sweep_done = 0;    // done in the folder when this slice ended
  bool results_written = false;  // every point was done: results.csv written
};

// Runs the points of `slice` not yet done in `out` on `options.jobs` threads, a row file
// each as it finishes; then, when every point of the sweep is done, writes results.csv.
// Throws SweepOutputError (the folder; a different sweep there names what differs).
SliceReport runSweepSlice(const SweepPlan& plan, const std::filesystem::path& out, SweepSlice slice,
                          const LocalRunOptions& options);

// How many missing points a merge names with their values.
inline constexpr std::size_t kMissingNamed = 20;

struct MergeReport {
  std::size_t points = 0;                                // of the sweep
  std::vector<std::size_t> missing;                      // points without a row, in point order
  std::vector<std::vector<std::string>> missing_values;  // the first kMissingNamed's values
  std::vector<std::string> axis_names;
  bool written = false;  // none missing: results.csv written
};

// Completes DIR/results.csv from the rows of DIR (the sweep read from DIR/sweep.json), or
// says which points are missing. Throws SweepOutputError (no sweep.json, not readable).
MergeReport mergeSweep(const std::filesystem::path& dir);

}  // namespace tribo::study
