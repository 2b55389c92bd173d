// A run's trajectory.csv read for the replay page (study/view/view_page.hpp): the header, and
// every stride-th row (plus the last) so that the page holds at most `frame_cap` frames and
// at most `value_budget` numbers in all. Two passes over the file (count, then keep), so a
// long run never sits in memory whole. Not here: writing the page, the scene's geometry.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace tribo::study {

struct ViewTrajectory {
  std::vector<std::string> columns;         // header, "t" first
  std::vector<std::vector<double>> values;  // per column, the kept rows (NaN for empty)
  std::size_t rows = 0;                     // rows in the file
  std::size_t stride = 1;                   // every stride-th row kept (and the last)
  std::size_t frames() const { return values.empty() ? 0 : values[0].size(); }
  // Index of column `name`, or -1.
  int column(const std::string& name) const;
};

// The fields of one CSV line (RFC 4180 quotes; the result files' own form).
std::vector<std::string> csvFieldsOf(const std::string& line);

// Throws std::runtime_error naming the file when it cannot be read, has no "t" column first
// or a row of the wrong width.
ViewTrajectory readViewTrajectory(const std::filesystem::path& csv, std::size_t frame_cap,
                                  std::size_t value_budget);

}  // namespace tribo::study
