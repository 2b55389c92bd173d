#include "study/view/view_branch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/file_read.hpp"
#include "io/scene_parameters.hpp"
#include "study/csv_text.hpp"
#include "study/file_commit.hpp"
#include "study/view/page_template.hpp"
#include "study/view/view_assets.hpp"
#include "study/view/view_trajectory.hpp"

namespace tribo::study {

namespace {

std::string named(const std::filesystem::path& file) {
  return std::string("'").append(file.string()).append("'");
}

// branch.json: the continued parameter's name, the observed coordinate and the events must be
// there; the rest (scene, status, the Hopf start) is shown when it is.
nlohmann::json readManifest(const std::filesystem::path& file) {
  nlohmann::json manifest;
  try {
    manifest =
        nlohmann::json::parse(io::readFileBounded(file, "branch manifest", io::kMaxJsonBytes));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(named(file) + " is not JSON: " + e.what());
  }
  if (!manifest.is_object()) throw std::runtime_error(named(file) + " is not a JSON object");
  for (const char* key : {"parameter", "observed"})
    if (!manifest.contains(key) || !manifest[key].is_string() ||
        manifest[key].get<std::string>().empty())
      throw std::runtime_error(named(file) + " has no '" + key + "' (a name)");
  if (!manifest.contains("events") || !manifest["events"].is_array())
    throw std::runtime_error(named(file) + " has no 'events' list");
  return manifest;
}

// The events of branch.json, each checked: a kind, a parameter (null when it could not be
// interpolated) and the two points of branch.csv it lies between.
nlohmann::json eventsOf(const nlohmann::json& manifest, const std::filesystem::path& file,
                        std::size_t points) {
  nlohmann::json events = nlohmann::json::array();
  std::size_t k = 0;
  for (const nlohmann::json& e : manifest["events"]) {
    const std::string where = named(file) + " event " + std::to_string(k++);
    if (!e.is_object() || !e.contains("kind") || !e["kind"].is_string())
      throw std::runtime_error(where + " has no 'kind' (a name)");
    if (!e.contains("parameter") || !(e["parameter"].is_number() || e["parameter"].is_null()))
      throw std::runtime_error(where + " has no 'parameter' (a number)");
    const nlohmann::json between = e.value("between", nlohmann::json());
    if (!between.is_array() || between.size() != 2 || !between[0].is_number_unsigned() ||
        !between[1].is_number_unsigned() || between[0].get<std::size_t>() >= points ||
        between[1].get<std::size_t>() >= points)
      throw std::runtime_error(where + "'s 'between' is not two of branch.csv's points (0 to " +
                               std::to_string(points - 1) + ")");
    events.push_back({{"kind", e["kind"]}, {"parameter", e["parameter"]}, {"between", between}});
  }
  return events;
}

// The Hopf point a branch started from (`--from-hopf`), or null.
nlohmann::json hopfStartOf(const nlohmann::json& manifest) {
  if (manifest.value("start", "") != "hopf" || !manifest.contains("hopf") ||
      !manifest["hopf"].is_object())
    return nullptr;
  const nlohmann::json& h = manifest["hopf"];
  if (!h.contains("parameter") || !h["parameter"].is_number()) return nullptr;
  nlohmann::json start = {{"parameter", h["parameter"]}};
  for (const char* key : {"period", "omega", "amplitude"})
    if (h.contains(key) && h[key].is_number()) start[key] = h[key];
  return start;
}

struct BranchTable {
  nlohmann::json points = nlohmann::json::array();
  // The steady_growth_rate column is there with a value in some row (a forced branch leaves
  // it empty: it has no steady state).
  bool steady_growth = false;
};

// branch.csv: one object per row, its numbers checked (an empty optional field is null).
BranchTable readBranchTable(const std::filesystem::path& file) {
  const std::string text = io::readFileBounded(file, "branch table", io::kMaxTableBytes);
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    lines.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  if (lines.empty() || lines[0].empty()) throw std::runtime_error(named(file) + " is empty");
  const std::vector<std::string> header = csvFieldsOf(lines[0]);
  std::map<std::string, std::size_t> column;
  for (std::size_t c = 0; c < header.size(); ++c) column.emplace(header[c], c);
  const std::vector<std::string> required = {"index",        "parameter",          "period",
                                             "amplitude_pp", "largest_multiplier", "stable"};
  for (const std::string& name : required)
    if (!column.count(name)) throw std::runtime_error(named(file) + " has no column " + name);
  const std::vector<std::string> optional = {"stick_fraction", "min_slip", "x_min", "x_max",
                                             "steady_growth_rate"};
  BranchTable table;
  for (std::size_t l = 1; l < lines.size(); ++l) {
    if (lines[l].empty() || lines[l] == "\r") continue;
    const std::string where = named(file) + " line " + std::to_string(l + 1);
    const std::vector<std::string> fields = csvFieldsOf(lines[l]);
    if (fields.size() != header.size())
      throw std::runtime_error(where + " has " + std::to_string(fields.size()) +
                               " fields, the header " + std::to_string(header.size()));
    auto field = [&](const std::string& name) -> const std::string& {
      return fields[column.at(name)];
    };
    nlohmann::json point;
    for (const std::string& name : required) {
      if (name == "stable") continue;
      const auto v = io::parseNumber(field(name));
      if (!v)
        throw std::runtime_error(where + ": " + name + " '" + field(name) + "' is not a number");
      point[name] = *v;
    }
    const std::size_t expected = table.points.size();
    if (point["index"].get<double>() != static_cast<double>(expected))
      throw std::runtime_error(where + ": index '" + field("index") + "', expected " +
                               std::to_string(expected) + " (the rows in order from 0)");
    point["index"] = expected;
    if (field("stable") != "0" && field("stable") != "1")
      throw std::runtime_error(where + ": stable '" + field("stable") + "' is not 0 or 1");
    point["stable"] = field("stable") == "1";
    // `stability` (stable, unstable or undecided) came with the undecided points; older
    // files have none.
    point["undecided"] = column.count("stability") > 0 && field("stability") == "undecided";
    for (const std::string& name : optional) {
      point[name] = nullptr;
      if (!column.count(name) || field(name).empty()) continue;
      const auto v = io::parseNumber(field(name));
      if (!v)
        throw std::runtime_error(where + ": " + name + " '" + field(name) + "' is not a number");
      point[name] = *v;
    }
    point["event"] = column.count("event") ? field("event") : "";
    table.points.push_back(point);
  }
  if (table.points.empty())
    throw std::runtime_error(named(file) + " has no points (no rows after its header)");
  for (const nlohmann::json& point : table.points)
    table.steady_growth = table.steady_growth || !point["steady_growth_rate"].is_null();
  return table;
}

// branch_orbits.csv: each point's orbit over one period, decimated to `cap` samples a point
// (every stride-th sample, the last and the extremes of x kept). Read twice (check and count,
// then keep), so a long file never sits in memory whole.
struct BranchOrbits {
  std::vector<std::vector<double>> t, x;  // per point of branch.csv
  std::vector<std::size_t> rows, stride;  // per point
  std::size_t total_rows = 0, kept = 0;
};

BranchOrbits readBranchOrbits(const std::filesystem::path& file, const std::string& observed,
                              std::size_t points, std::size_t cap) {
  io::checkReadableFile(file, "branch orbits", std::numeric_limits<std::uintmax_t>::max());
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + named(file));
  std::string line;
  auto next = [&] { return io::getLineBounded(in, line, io::kMaxCsvLineBytes, file); };
  if (!next() || line.empty() || line == "\r") throw std::runtime_error(named(file) + " is empty");
  const std::vector<std::string> header = csvFieldsOf(line);
  if (header.size() != 3 || header[0] != "point" || header[1] != "t" || header[2].empty())
    throw std::runtime_error(named(file) + " has the header '" + line +
                             "', expected point,t,<the observed coordinate>");
  if (header[2] != observed)
    throw std::runtime_error(named(file) + " holds " + header[2] + ", branch.json observes " +
                             observed);
  std::size_t line_number = 1;
  std::size_t point = 0;
  double t = 0, x = 0;
  // One row checked into point, t and x; throws naming the line.
  auto parse = [&] {
    const std::string where = named(file) + " line " + std::to_string(line_number);
    const std::vector<std::string> fields = csvFieldsOf(line);
    if (fields.size() != 3)
      throw std::runtime_error(where + " has " + std::to_string(fields.size()) +
                               " fields, expected 3 (point,t," + observed + ")");
    const auto p = io::parseNumber(fields[0]);
    if (!p || *p < 0 || *p != std::floor(*p) || *p >= static_cast<double>(points))
      throw std::runtime_error(where + ": point '" + fields[0] +
                               "' is not one of branch.csv's points (0 to " +
                               std::to_string(points - 1) + ")");
    const auto tv = io::parseNumber(fields[1]);
    if (!tv) throw std::runtime_error(where + ": t '" + fields[1] + "' is not a number");
    const auto xv = io::parseNumber(fields[2]);
    if (!xv)
      throw std::runtime_error(where + ": " + observed + " '" + fields[2] + "' is not a number");
    point = static_cast<std::size_t>(*p);
    t = *tv;
    x = *xv;
  };
  BranchOrbits orbits;
  orbits.rows.assign(points, 0);
  std::vector<std::size_t> lowest(points, 0), highest(points, 0);
  std::vector<double> lo(points, std::numeric_limits<double>::infinity());
  std::vector<double> hi(points, -std::numeric_limits<double>::infinity());
  while (next()) {
    ++line_number;
    if (line.empty() || line == "\r") continue;
    parse();
    std::size_t& k = orbits.rows[point];
    if (x < lo[point]) {
      lo[point] = x;
      lowest[point] = k;
    }
    if (x > hi[point]) {
      hi[point] = x;
      highest[point] = k;
    }
    ++k;
    ++orbits.total_rows;
  }
  for (std::size_t p = 0; p < points; ++p)
    if (orbits.rows[p] == 0)
      throw std::runtime_error(named(file) + " has no rows for point " + std::to_string(p) +
                               " (branch.csv has " + std::to_string(points) + " points)");
  orbits.stride.resize(points);
  for (std::size_t p = 0; p < points; ++p) {
    const std::size_t n = orbits.rows[p];
    orbits.stride[p] = n <= cap ? 1 : (n + cap - 2) / (cap - 1);
  }
  orbits.t.assign(points, {});
  orbits.x.assign(points, {});
  std::vector<std::size_t> seen(points, 0);
  in.clear();
  in.seekg(0);
  next();
  line_number = 1;
  while (next()) {
    ++line_number;
    if (line.empty() || line == "\r") continue;
    parse();
    const std::size_t k = seen[point]++;
    if (k % orbits.stride[point] == 0 || k + 1 == orbits.rows[point] || k == lowest[point] ||
        k == highest[point]) {
      orbits.t[point].push_back(t);
      orbits.x[point].push_back(x);
      ++orbits.kept;
    }
  }
  return orbits;
}

void appendSeries(std::string& out, const std::vector<double>& values) {
  out.push_back('[');
  char buffer[40];
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) out.push_back(',');
    char* end = csvNumberTo(buffer, buffer + sizeof buffer, values[i], 10);
    out.append(buffer, end);
  }
  out.push_back(']');
}

}  // namespace

bool isBranchDir(const std::filesystem::path& dir) {
  return std::filesystem::exists(dir / "branch.json");
}

BranchViewInfo writeBranchView(const std::filesystem::path& dir, const ViewOptions& options) {
  const std::filesystem::path manifest_file = dir / "branch.json";
  const nlohmann::json manifest = readManifest(manifest_file);
  const std::string observed = manifest["observed"].get<std::string>();
  const BranchTable table = readBranchTable(dir / "branch.csv");
  const std::size_t points = table.points.size();
  if (manifest.contains("points") && manifest["points"].is_number_unsigned() &&
      manifest["points"].get<std::size_t>() != points)
    throw std::runtime_error(
        named(manifest_file) + " counts " + std::to_string(manifest["points"].get<std::size_t>()) +
        " points, " + named(dir / "branch.csv") + " has " + std::to_string(points) + " rows");
  const nlohmann::json events = eventsOf(manifest, manifest_file, points);
  // Samples a point at most: the frame cap, and the value budget shared by every orbit (t and x).
  const std::size_t by_budget = options.value_budget / (2 * points);
  const std::size_t cap = std::max<std::size_t>(2, std::min(options.frame_cap, by_budget));
  const BranchOrbits orbits = readBranchOrbits(dir / "branch_orbits.csv", observed, points, cap);

  // After a branch switch (`--switch`): the branch it left, drawn beside this one, and where.
  nlohmann::json primary = nlohmann::json::array();
  nlohmann::json switched;
  if (std::filesystem::exists(dir / "primary_branch.csv")) {
    primary = readBranchTable(dir / "primary_branch.csv").points;
    if (manifest.contains("switch") && manifest["switch"].is_object())
      switched = manifest["switch"];
  }

  nlohmann::json strides = nlohmann::json::array();
  for (std::size_t p = 0; p < points; ++p) strides.push_back(orbits.stride[p]);
  const nlohmann::json meta = {
      {"kind", "branch"},
      {"scene", manifest.value("scene", "")},
      {"parameter", manifest["parameter"]},
      {"observed", observed},
      {"from", manifest.contains("from") ? manifest["from"] : nlohmann::json()},
      {"to", manifest.contains("to") ? manifest["to"] : nlohmann::json()},
      {"status", manifest.value("status", "")},
      {"stop_reason", manifest.value("stop_reason", "")},
      {"start", manifest.value("start", "orbit")},
      {"hopf", hopfStartOf(manifest)},
      {"steady_growth", table.steady_growth},
      {"orbit_rows", orbits.total_rows},
      {"orbit_samples", orbits.kept},
      {"orbit_cap", cap},
      {"orbit_strides", strides},
      {"switch", switched}};
  std::string data = "{\"meta\":" + meta.dump() + ",\"points\":" + table.points.dump() +
                     ",\"primary\":" + primary.dump() + ",\"events\":" + events.dump() +
                     ",\"orbits\":[";
  for (std::size_t p = 0; p < points; ++p) {
    if (p) data += ",\n";
    data += "{\"t\":";
    appendSeries(data, orbits.t[p]);
    data += ",\"x\":";
    appendSeries(data, orbits.x[p]);
    data += "}";
  }
  data += "]}";

  std::string page(view_assets::kBranchHtml);
  replaceMarker(page, "/*TRIBO_CSS*/", std::string(view_assets::kPageCss), "branch");
  replaceMarker(page, "/*TRIBO_ERRORS*/", std::string(view_assets::kErrorsScript), "branch");
  replaceMarker(page, "/*TRIBO_DATA*/", "window.TRIBO_DATA = " + scriptSafe(data) + ";", "branch");
  replaceMarker(page, "/*TRIBO_JS*/",
                scriptSafe(std::string(view_assets::kPlotScript) + "\n" +
                           std::string(view_assets::kBranchScript)),
                "branch");
  BranchViewInfo info;
  info.file = dir / "view.html";
  writeFileWhole(info.file, page);
  info.bytes = page.size();
  info.points = points;
  info.events = events.size();
  info.orbit_rows = orbits.total_rows;
  info.orbit_samples = orbits.kept;
  info.steady_growth = table.steady_growth;
  info.primary_points = primary.size();
  return info;
}

}  // namespace tribo::study
