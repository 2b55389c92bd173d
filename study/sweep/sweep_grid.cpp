#include "study/sweep/sweep_grid.hpp"

#include <charconv>
#include <cmath>
#include <set>

#include "io/scene_parameters.hpp"
#include "io/utf8_check.hpp"
#include "study/csv_text.hpp"

namespace tribo::study {

namespace {

// 12 significant digits: 0.1:0.3:3 gives "0.2", not "0.20000000000000001".
std::string gridText(double v) { return csvNumber(v, 12); }

// The shortest text that reads back as exactly `v`: for grids whose neighbours agree to 12
// digits (1:1.000000000001:5, or -1e308:1e308:1000001 near 0).
std::string exactText(double v) {
  char buf[40];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// "--grid 'SPEC': " with bytes that are not UTF-8 shown as \xNN; throws for such bytes.
std::string checkedWhere(std::string_view spec, const char* option) {
  const std::string where = std::string(option) + " '" + io::printableText(spec) + "': ";
  if (const std::size_t bad = io::firstBadUtf8(spec); bad != std::string::npos)
    throw SweepSpecError(where + "expected UTF-8 text, found " + io::badUtf8Reason(spec, bad) +
                         " at byte " + std::to_string(bad + 1));
  return where;
}

std::vector<std::string_view> split(std::string_view text, char sep) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = text.find(sep, start);
    parts.push_back(text.substr(start, end == std::string_view::npos ? end : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

// Splits "NAME=REST" and checks NAME; `option` and `form` are for messages.
std::pair<std::string, std::string_view> nameAndRest(std::string_view spec, const char* option,
                                                     const char* form) {
  const std::string where = checkedWhere(spec, option);
  const std::size_t eq = spec.find('=');
  if (eq == std::string_view::npos)
    throw SweepSpecError(where + "expected " + form + ", found no '='");
  const std::string name(spec.substr(0, eq));
  if (!io::isParameterName(name))
    throw SweepSpecError(where +
                         "expected a parameter name ([A-Za-z_][A-Za-z0-9_]*) before '=', "
                         "found '" +
                         name + "'");
  return {name, spec.substr(eq + 1)};
}

// A grid's values never decrease (or never increase) and their texts follow, so two equal
// texts are neighbours: one pass, no set of up to kMaxPoints strings (a --grid COUNT of
// millions took seconds, found by fuzz/cli_values_fuzzer).
void requireDistinctNeighbours(const SweepAxis& axis, const std::string& where) {
  for (std::size_t i = 1; i < axis.values.size(); ++i)
    if (axis.values[i] == axis.values[i - 1])
      throw SweepSpecError(where + "value '" + axis.values[i] +
                           "' appears twice; points must be distinct");
}

void requireDistinct(const SweepAxis& axis, const std::string& where) {
  std::set<std::string> seen;
  for (const auto& v : axis.values)
    if (!seen.insert(v).second)
      throw SweepSpecError(where + "value '" + v + "' appears twice; points must be distinct");
}

}  // namespace

SweepAxis parseGridAxis(std::string_view spec) {
  constexpr const char* kForm = "NAME=START:STOP:COUNT";
  auto [name, rest] = nameAndRest(spec, "--grid", kForm);
  const std::string where = checkedWhere(spec, "--grid");
  const auto fields = split(rest, ':');
  if (fields.size() != 3)
    throw SweepSpecError(where + "expected " + kForm + ", found " + std::to_string(fields.size()) +
                         " field" + (fields.size() == 1 ? "" : "s") + " after '='");
  const auto start = io::parseNumber(fields[0]);
  const auto stop = io::parseNumber(fields[1]);
  if (!start)
    throw SweepSpecError(where + "START: expected a number, found '" + std::string(fields[0]) +
                         "'");
  if (!stop)
    throw SweepSpecError(where + "STOP: expected a number, found '" + std::string(fields[1]) + "'");
  long count = 0;
  const auto c = std::from_chars(fields[2].data(), fields[2].data() + fields[2].size(), count);
  if (c.ec != std::errc() || c.ptr != fields[2].data() + fields[2].size() || count < 1)
    throw SweepSpecError(where + "COUNT: expected a whole number from 1 to " +
                         std::to_string(SweepGrid::kMaxPoints) + ", found '" +
                         std::string(fields[2]) + "'");
  // Sized before any value is made: a grid is at most kMaxPoints points.
  if (count > static_cast<long>(SweepGrid::kMaxPoints))
    throw SweepSpecError(where + "COUNT " + std::string(fields[2]) +
                         " is more points than a sweep may have (at most " +
                         std::to_string(SweepGrid::kMaxPoints) + ")");
  if (count == 1 && *start != *stop)
    throw SweepSpecError(where + "COUNT 1 needs START = STOP, found " + std::string(fields[0]) +
                         " and " + std::string(fields[1]));
  // std::lerp: exact at both ends, monotonic, and no overflow for ends of opposite sign near
  // the largest doubles (START + i (STOP - START) / (COUNT - 1) overflowed there).
  std::vector<double> numbers(static_cast<std::size_t>(count));
  for (long i = 0; i < count; ++i)
    numbers[static_cast<std::size_t>(i)] =
        i + 1 == count
            ? *stop
            : std::lerp(*start, *stop, static_cast<double>(i) / static_cast<double>(count - 1));
  for (std::size_t i = 1; i < numbers.size(); ++i)
    if (numbers[i] == numbers[i - 1])
      throw SweepSpecError(where + "values " + std::to_string(i) + " and " + std::to_string(i + 1) +
                           " are both " + exactText(numbers[i]) +
                           ": the step (STOP - START) / (COUNT - 1) is below the precision of "
                           "a double there; points must be distinct");
  SweepAxis axis{name, {}};
  axis.values.reserve(numbers.size());
  for (const double v : numbers) axis.values.push_back(gridText(v));
  // The ends are the numbers given, exactly (START and STOP typed with 17 digits).
  for (const std::size_t end : {std::size_t{0}, numbers.size() - 1})
    if (io::parseNumber(axis.values[end]) != numbers[end])
      axis.values[end] = exactText(numbers[end]);
  // Equal texts of distinct values are neighbours (a grid is monotonic): then every value
  // gets as many digits as it needs to read back exactly.
  for (std::size_t i = 1; i < axis.values.size(); ++i)
    if (axis.values[i] == axis.values[i - 1]) {
      for (std::size_t k = 0; k < numbers.size(); ++k) axis.values[k] = exactText(numbers[k]);
      break;
    }
  requireDistinctNeighbours(axis, where);
  return axis;
}

SweepAxis parseListAxis(std::string_view spec) {
  auto [name, rest] = nameAndRest(spec, "--list", "NAME=V1,V2,...");
  const std::string where = checkedWhere(spec, "--list");
  SweepAxis axis{name, {}};
  for (const auto v : split(rest, ',')) {
    if (v.empty()) throw SweepSpecError(where + "expected a value between commas, found none");
    axis.values.emplace_back(v);
  }
  requireDistinct(axis, where);
  return axis;
}

SweepGrid::SweepGrid(std::vector<SweepAxis> axes) : axes_(std::move(axes)) {
  if (axes_.empty()) throw SweepSpecError("expected at least one --grid or --list, found none");
  std::set<std::string> names;
  size_ = 1;
  double points = 1;  // the product, for the message when it is too large
  std::string shape;
  for (const auto& a : axes_) {
    if (a.values.empty()) throw SweepSpecError("parameter '" + a.name + "' has no values");
    if (!names.insert(a.name).second)
      throw SweepSpecError("parameter '" + a.name +
                           "' is swept twice; give each parameter one --grid or --list");
    points *= static_cast<double>(a.values.size());
    shape += (shape.empty() ? "" : " x ") + std::to_string(a.values.size()) + " " + a.name;
  }
  if (points > static_cast<double>(kMaxPoints))
    throw SweepSpecError("the grid spans " + csvNumber(points, 6) + " points (" + shape +
                         "); a sweep may have at most " + std::to_string(kMaxPoints));
  for (const auto& a : axes_) size_ *= a.values.size();
}

std::vector<std::string> SweepGrid::values(std::size_t i) const {
  if (i >= size_)
    throw std::out_of_range("sweep point " + std::to_string(i) + " of " + std::to_string(size_));
  std::vector<std::string> v(axes_.size());
  for (std::size_t a = axes_.size(); a-- > 0;) {
    const std::size_t n = axes_[a].values.size();
    v[a] = axes_[a].values[i % n];
    i /= n;
  }
  return v;
}

std::vector<std::string> SweepGrid::overrides(std::size_t i) const {
  auto v = values(i);
  for (std::size_t a = 0; a < v.size(); ++a) v[a] = axes_[a].name + "=" + v[a];
  return v;
}

}  // namespace tribo::study
