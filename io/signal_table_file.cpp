#include "io/signal_table_file.hpp"

#include <cstddef>
#include <sstream>

#include "core/number_text.hpp"
#include "io/file_read.hpp"
#include "io/scene_parameters.hpp"

namespace tribo::io {

namespace {

struct Field {
  std::string text;
  int column = 1;  // 1-based character column of the field's first character
};

// The comma-separated fields of `line`, trimmed of spaces, tabs and '\r'.
std::vector<Field> fields(const std::string& line) {
  std::vector<Field> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string::npos ? line.size() : comma;
    std::size_t a = start, b = end;
    while (a < b && (line[a] == ' ' || line[a] == '\t')) ++a;
    while (b > a && (line[b - 1] == ' ' || line[b - 1] == '\t' || line[b - 1] == '\r')) --b;
    out.push_back({line.substr(a, b - a), static_cast<int>(a) + 1});
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

bool skipped(const std::string& line) {
  const std::size_t first = line.find_first_not_of(" \t\r");
  return first == std::string::npos || line[first] == '#';
}

}  // namespace

std::vector<std::pair<double, double>> parseSignalTable(const std::string& text,
                                                        const std::string& name,
                                                        const SignalTableColumn& column) {
  const auto fail = [&](int line, int col, const std::string& what) {
    throw SceneError({name, line, col}, "", what);
  };
  std::vector<std::pair<double, double>> points;
  std::size_t index = static_cast<std::size_t>(column.position) - 1;  // 0-based field
  int previous_line = 0, line_number = 0;
  bool first = true;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (skipped(line)) continue;
    const std::vector<Field> f = fields(line);
    if (first) {
      first = false;
      if (!parseNumber(f[0].text)) {  // a header
        if (!column.name.empty()) {
          std::size_t i = 1;
          while (i < f.size() && f[i].text != column.name) ++i;
          if (i == f.size())
            fail(line_number, 0,
                 "no column named '" + column.name + "' in the header '" + line + "'");
          index = i;
        } else if (index >= f.size()) {
          fail(line_number, 0,
               "no column " + std::to_string(column.position) + ": the header '" + line + "' has " +
                   std::to_string(f.size()));
        }
        continue;
      }
      if (!column.name.empty())
        fail(line_number, 0,
             "no column named '" + column.name +
                 "': the file has no header line (its first line is '" + line + "')");
    }
    if (index >= f.size())
      fail(line_number, 0,
           "expected at least " + std::to_string(index + 1) + " fields (the value column is " +
               (column.name.empty() ? std::to_string(index + 1) : "'" + column.name + "'") +
               "), found " + std::to_string(f.size()));
    const auto number = [&](const Field& x) {
      const auto v = parseNumber(x.text);
      if (!v) fail(line_number, x.column, "expected a number, found '" + x.text + "'");
      return *v;
    };
    const double t = number(f[0]);
    const double v = number(f[index]);
    if (!points.empty() && !(t > points.back().first))
      fail(line_number, f[0].column,
           "times must be strictly increasing: t = " + numberText(t) + " follows t = " +
               numberText(points.back().first) + " (line " + std::to_string(previous_line) + ")");
    points.emplace_back(t, v);
    previous_line = line_number;
  }
  if (points.empty()) fail(line_number, 0, "expected lines of 't, value', found no point");
  return points;
}

std::vector<std::pair<double, double>> readSignalTableFile(const std::string& path,
                                                           const SignalTableColumn& column) {
  std::string text;
  try {
    text = readFileBounded(path, "signal table file", kMaxTableBytes);
  } catch (const FileReadError& e) {
    throw SceneError(e.what());
  }
  return parseSignalTable(text, path, column);
}

}  // namespace tribo::io
