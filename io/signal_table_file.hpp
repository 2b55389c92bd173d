// Reads the points of a table signal (`{table: {file: forces.csv, column: fx}}`,
// io/scene_signal.hpp) from a CSV file: the first column is the time [s], one other column
// the value. Fields are separated by commas (spaces around them allowed, no quoting); lines
// starting with '#' and blank lines are skipped; the first other line is a header when its
// first field is not a number (e.g. "t, fx, fy"). The value column is chosen by its header
// name or by its position counted from 1 as in gnuplot's `using 1:3` (the time column is
// 1; the default is 2); only the time and the chosen column of each line are read.
// Errors are SceneErrors located in the CSV file ("forces.csv:LINE:COLUMN: ..."): a field
// that is not a number, a line without the chosen column, a column name the header does not
// have (or no header), a position past the header, times not strictly increasing (naming
// both lines), no point at all.
// Not here: the scene's location (the caller adds it), the number of points a kind needs
// and the interpolation (core/signal.hpp), quoted fields, other separators.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace tribo::io {

struct SignalTableColumn {
  std::string name;  // by header name when not empty
  int position = 2;  // else by position, 2 or more
};

std::vector<std::pair<double, double>> readSignalTableFile(const std::string& path,
                                                           const SignalTableColumn& column);
// The same from the file's text; `name` stands for the file in messages.
std::vector<std::pair<double, double>> parseSignalTable(const std::string& text,
                                                        const std::string& name,
                                                        const SignalTableColumn& column);

}  // namespace tribo::io
