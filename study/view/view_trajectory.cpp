#include "study/view/view_trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "io/file_read.hpp"

namespace tribo::study {

std::vector<std::string> csvFieldsOf(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.push_back(field);
      field.clear();
    } else if (c != '\r') {
      field.push_back(c);
    }
  }
  fields.push_back(field);
  return fields;
}

namespace {

double parseNumber(const std::string& text) {
  if (text.empty()) return std::numeric_limits<double>::quiet_NaN();
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return end == text.c_str() ? std::numeric_limits<double>::quiet_NaN() : v;
}

}  // namespace

int ViewTrajectory::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
}

ViewTrajectory readViewTrajectory(const std::filesystem::path& csv, std::size_t frame_cap,
                                  std::size_t value_budget) {
  // Streamed, so its size is not bounded; a device or FIFO (endless) is refused, and so is a
  // line longer than io::kMaxCsvLineBytes.
  io::checkReadableFile(csv, "trajectory", std::numeric_limits<std::uintmax_t>::max());
  std::ifstream in(csv);
  if (!in) throw std::runtime_error("cannot read '" + csv.string() + "'");
  ViewTrajectory v;
  std::string line;
  auto next = [&] { return io::getLineBounded(in, line, io::kMaxCsvLineBytes, csv); };
  if (!next()) throw std::runtime_error("'" + csv.string() + "' is empty");
  v.columns = csvFieldsOf(line);
  if (v.columns.empty() || v.columns[0] != "t")
    throw std::runtime_error("'" + csv.string() + "' has no column t first");
  while (next())
    if (!line.empty()) ++v.rows;
  const std::size_t by_budget = std::max<std::size_t>(2, value_budget / v.columns.size());
  const std::size_t cap = std::max<std::size_t>(2, std::min(frame_cap, by_budget));
  v.stride = v.rows <= cap ? 1 : (v.rows + cap - 2) / (cap - 1);
  v.values.assign(v.columns.size(), {});
  in.clear();
  in.seekg(0);
  next();
  std::size_t row = 0;
  while (next()) {
    if (line.empty()) continue;
    const bool last = row + 1 == v.rows;
    if (row % v.stride == 0 || last) {
      const std::vector<std::string> fields = csvFieldsOf(line);
      if (fields.size() != v.columns.size())
        throw std::runtime_error("'" + csv.string() + "' row " + std::to_string(row + 1) + " has " +
                                 std::to_string(fields.size()) + " fields, the header " +
                                 std::to_string(v.columns.size()));
      for (std::size_t c = 0; c < fields.size(); ++c) v.values[c].push_back(parseNumber(fields[c]));
    }
    ++row;
  }
  return v;
}

}  // namespace tribo::study
