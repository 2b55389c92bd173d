#include "study/sweep/sweep_results.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "io/file_read.hpp"
#include "study/csv_text.hpp"
#include "study/file_commit.hpp"
#include "study/sweep/sweep_rows.hpp"

namespace tribo::study {

namespace fs = std::filesystem;
using Reason = SweepOutputError::Reason;

namespace {

constexpr const char* kFigureColumns[] = {
    "status",   "amplitude_pp", "period",    "time_to_98", "rise_time", "stuck_fraction", "mean",
    "first_pp", "cycles",       "simulated", "settled",    "warnings",  "message"};

constexpr const char* kModesColumns[] = {"status",         "max_growth_rate", "frequency",
                                         "unstable_modes", "warnings",        "message"};

constexpr const char* kOrbitColumns[] = {
    "status", "period",     "amplitude_pp", "x_min",    "x_max",  "largest_multiplier",
    "stable", "iterations", "residual",     "warnings", "message"};

std::string number(double v) { return csvNumber(v); }

std::string join(const std::vector<std::string>& fields) { return csvLine(fields); }

std::string slurp(const fs::path& p) {
  try {
    return io::readFileBounded(p, "sweep file", io::kMaxSweepResultsBytes);
  } catch (const io::FileReadError& e) {
    throw SweepOutputError(Reason::kOtherSweep, e.what());
  }
}

void writeWhole(const fs::path& file, const std::string& text) {
  try {
    writeFileWhole(file, text);
  } catch (const std::runtime_error& e) {
    throw SweepOutputError(Reason::kCannotWrite, e.what());
  }
}

bool isStatus(const std::string& s) { return kPointStatusNames.find(s).has_value(); }

}  // namespace

std::vector<std::string> sweepColumns(const SweepGrid& grid, SweepAnalysis analysis) {
  std::vector<std::string> c{"point"};
  for (const auto& a : grid.axes()) c.push_back(a.name);
  if (analysis == SweepAnalysis::kModes)
    c.insert(c.end(), std::begin(kModesColumns), std::end(kModesColumns));
  else if (analysis == SweepAnalysis::kOrbit)
    c.insert(c.end(), std::begin(kOrbitColumns), std::end(kOrbitColumns));
  else
    c.insert(c.end(), std::begin(kFigureColumns), std::end(kFigureColumns));
  return c;
}

std::string formatSweepRow(std::size_t index, const SweepGrid& grid, const PointOutcome& o,
                           SweepAnalysis analysis) {
  std::vector<std::string> f{std::to_string(index)};
  for (auto& v : grid.values(index)) f.push_back(std::move(v));
  f.emplace_back(pointStatusName(o.status));
  const bool ok = o.status == PointStatus::kComplete;
  if (analysis == SweepAnalysis::kModes) {
    f.push_back(ok ? number(o.max_growth_rate) : "");
    f.push_back(ok ? number(o.growth_frequency) : "");
    f.push_back(ok ? std::to_string(o.unstable_modes) : "");
  } else if (analysis == SweepAnalysis::kOrbit) {
    for (const double v : {o.period, o.amplitude_pp, o.x_min, o.x_max, o.largest_multiplier})
      f.push_back(ok ? number(v) : "");
    f.push_back(ok ? (o.stable ? "1" : "0") : "");
    f.push_back(ok ? std::to_string(o.iterations) : "");
    f.push_back(ok ? number(o.residual) : "");
  } else {
    for (const double v : {o.amplitude_pp, o.period, o.time_to_98, o.rise_time, o.stuck_fraction,
                           o.x_mean, o.first_pp})
      f.push_back(ok ? number(v) : "");
    f.push_back(ok ? std::to_string(o.cycles) : "");
    f.push_back(o.status == PointStatus::kError ? "" : number(o.simulated));
    f.push_back(ok ? (o.settled ? "1" : "0") : "");
  }
  std::string warnings;
  for (const auto& w : o.warnings) {
    if (!warnings.empty()) warnings += " | ";
    warnings += w;
  }
  f.push_back(warnings);
  f.push_back(o.message);
  return join(f);
}

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        out.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        out.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  if (quoted) return {};
  return out;
}

std::optional<std::size_t> sweepRowPoint(const std::string& line, const SweepGrid& grid,
                                         SweepAnalysis analysis) {
  const auto f = splitCsvLine(line);
  const std::size_t n_axes = grid.axes().size();
  if (f.size() != sweepColumns(grid, analysis).size() || f[0].empty()) return std::nullopt;
  std::size_t index = 0;
  const auto r = std::from_chars(f[0].data(), f[0].data() + f[0].size(), index);
  if (r.ec != std::errc() || r.ptr != f[0].data() + f[0].size() || index >= grid.size() ||
      !isStatus(f[1 + n_axes]))
    return std::nullopt;
  const auto values = grid.values(index);
  for (std::size_t a = 0; a < n_axes; ++a)
    if (f[1 + a] != values[a]) return std::nullopt;
  return index;
}

SweepResultsFile::SweepResultsFile(const fs::path& dir, const std::string& manifest,
                                   const SweepGrid& grid, SweepAnalysis analysis)
    : dir_(dir), results_(dir / "results.csv"), done_(grid.size(), false), lines_(grid.size()) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec)
    throw SweepOutputError(Reason::kCannotWrite,
                           "cannot create '" + dir.string() + "': " + ec.message());
  try {
    lock_.emplace(dir);
  } catch (const DirLockedError& e) {
    throw SweepOutputError(Reason::kInUse, e.what());
  } catch (const std::runtime_error& e) {
    throw SweepOutputError(Reason::kCannotWrite, e.what());
  }
  header_ = join(sweepColumns(grid, analysis));
  const fs::path manifest_file = dir / "sweep.json";
  const bool have_results = fs::exists(results_);
  if (fs::exists(manifest_file)) {
    if (slurp(manifest_file) != manifest)
      throw SweepOutputError(Reason::kOtherSweep,
                             "'" + dir.string() +
                                 "' holds a different sweep (its sweep.json differs from this "
                                 "one's scene, parameters, values or settings); use another --out "
                                 "or remove the folder");
  } else if (have_results) {
    throw SweepOutputError(
        Reason::kOtherSweep,
        "'" + results_.string() + "' exists without sweep.json; not resuming an unknown sweep");
  } else {
    writeWhole(manifest_file, manifest);
  }

  if (have_results) {
    const std::string text = slurp(results_);
    if (text.compare(0, header_.size(), header_) != 0)
      throw SweepOutputError(Reason::kOtherSweep,
                             "'" + results_.string() +
                                 "' does not start with this sweep's header; remove it to restart");
    std::size_t pos = header_.size();
    while (pos < text.size()) {
      const std::size_t end = text.find('\n', pos);
      if (end == std::string::npos) {  // cut off by a kill: no line end
        ++dropped_;
        break;
      }
      const std::string line = text.substr(pos, end - pos);
      pos = end + 1;
      const auto index = sweepRowPoint(line, grid, analysis);
      if (!index || done_[*index]) {
        ++dropped_;
        continue;
      }
      done_[*index] = true;
      lines_[*index] = line + '\n';
      written_order_.push_back(*index);
      ++done_count_;
    }
  }
  // Rows of slices of this sweep (tribo sweep --slice) not yet in results.csv.
  bool added = false;
  std::vector<std::string> rows(grid.size());
  readPointRows(dir, grid, analysis, rows);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].empty() || done_[i]) continue;
    done_[i] = true;
    lines_[i] = std::move(rows[i]);
    written_order_.push_back(i);
    ++done_count_;
    added = true;
  }
  // Start from a file holding exactly the header and the kept lines, then append.
  if (!have_results || dropped_ > 0 || added) rewrite(written_order_);
  file_ = std::fopen(results_.c_str(), "ab");
  if (!file_)
    throw SweepOutputError(Reason::kCannotWrite,
                           "cannot open '" + results_.string() + "' for appending");
}

SweepResultsFile::~SweepResultsFile() {
  if (file_) std::fclose(file_);
}

void SweepResultsFile::rewrite(const std::vector<std::size_t>& order) {
  std::string text = header_;
  for (const std::size_t i : order) text += lines_[i];
  writeWhole(results_, text);
}

void SweepResultsFile::append(std::size_t index, const std::string& line) {
  std::lock_guard lock(mutex_);
  if (index >= done_.size() || done_[index]) return;
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size() || std::fflush(file_) != 0)
    throw SweepOutputError(Reason::kCannotWrite, "cannot append to '" + results_.string() + "'");
  done_[index] = true;
  lines_[index] = line;
  written_order_.push_back(index);
  ++done_count_;
}

void SweepResultsFile::finish() {
  std::lock_guard lock(mutex_);
  if (file_) std::fclose(file_);
  file_ = nullptr;
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < done_.size(); ++i)
    if (done_[i]) order.push_back(i);
  rewrite(order);
}

}  // namespace tribo::study
