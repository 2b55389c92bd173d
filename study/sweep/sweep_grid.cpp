#include "study/sweep/sweep_grid.hpp"

#include <charconv>
#include <set>

#include "io/scene_parameters.hpp"
#include "study/csv_text.hpp"

namespace tribo::study {

namespace {

// 12 significant digits: 0.1:0.3:3 gives "0.2", not "0.20000000000000001".
std::string gridText(double v) { return csvNumber(v, 12); }

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
  const std::string where = std::string(option) + " '" + std::string(spec) + "': ";
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
  const std::string where = "--grid '" + std::string(spec) + "': ";
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
  if (c.ec != std::errc() || c.ptr != fields[2].data() + fields[2].size() || count < 1 ||
      count > static_cast<long>(SweepGrid::kMaxPoints))
    throw SweepSpecError(where + "COUNT: expected a whole number from 1 to " +
                         std::to_string(SweepGrid::kMaxPoints) + ", found '" +
                         std::string(fields[2]) + "'");
  if (count == 1 && *start != *stop)
    throw SweepSpecError(where + "COUNT 1 needs START = STOP, found " + std::string(fields[0]) +
                         " and " + std::string(fields[1]));
  SweepAxis axis{name, {}};
  axis.values.reserve(static_cast<std::size_t>(count));
  for (long i = 0; i < count; ++i) {
    const double v = i + 1 == count ? *stop : *start + i * (*stop - *start) / (count - 1);
    axis.values.push_back(gridText(v));
  }
  requireDistinctNeighbours(axis, where);
  return axis;
}

SweepAxis parseListAxis(std::string_view spec) {
  auto [name, rest] = nameAndRest(spec, "--list", "NAME=V1,V2,...");
  const std::string where = "--list '" + std::string(spec) + "': ";
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
  for (const auto& a : axes_) {
    if (a.values.empty()) throw SweepSpecError("parameter '" + a.name + "' has no values");
    if (!names.insert(a.name).second)
      throw SweepSpecError("parameter '" + a.name +
                           "' is swept twice; give each parameter one --grid or --list");
    if (size_ > kMaxPoints / a.values.size())
      throw SweepSpecError("the grid spans more than " + std::to_string(kMaxPoints) + " points");
    size_ *= a.values.size();
  }
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
