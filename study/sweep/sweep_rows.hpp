// The per-point rows of a sweep run in slices (tribo sweep --slice I/N: several processes,
// on one machine or on several sharing the folder, writing one sweep folder at once):
// DIR/rows/<point>.csv holds the results line of one finished point (the line results.csv
// would hold, study/sweep/sweep_results.hpp), written under a temporary name unique to the
// process and renamed (study/file_commit.hpp), so a reader sees a point's row whole or not
// at all and no two processes ever write one file. <point> is zero-padded to the width of
// the largest point index, so the files list in point order.
// Not here: which points a slice runs, results.csv, sweep.json
// (study/sweep/sweep_shared_folder.hpp).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "study/sweep/sweep_grid.hpp"
#include "study/sweep/sweep_point.hpp"

namespace tribo::study {

// DIR/rows.
std::filesystem::path rowsDir(const std::filesystem::path& dir);

// Writes the row of point `index` of a sweep of `points` points (`line` ends in '\n').
// DIR/rows must exist. Throws SweepOutputError (kCannotWrite) naming the file.
void writePointRow(const std::filesystem::path& dir, std::size_t index, std::size_t points,
                   const std::string& line);

// Reads back every row file of DIR/rows that is a whole row of this sweep (its name's point
// and its line's point agree, sweepRowPoint accepts it): `lines` (grid.size() entries) gets
// each point's line with its '\n'; other entries are left as they are. Other files (the
// temporary ones of a process still writing or killed) are skipped. Returns the count read.
// No DIR/rows: none. Throws SweepOutputError (kCannotWrite) when the folder cannot be read.
std::size_t readPointRows(const std::filesystem::path& dir, const SweepGrid& grid,
                          SweepAnalysis analysis, std::vector<std::string>& lines);

}  // namespace tribo::study
