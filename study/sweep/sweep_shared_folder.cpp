#include "study/sweep/sweep_shared_folder.hpp"

#include <stdexcept>

#include "io/file_read.hpp"
#include "study/csv_text.hpp"
#include "study/file_commit.hpp"
#include "study/sweep/sweep_manifest.hpp"
#include "study/sweep/sweep_results.hpp"
#include "study/sweep/sweep_rows.hpp"

namespace tribo::study {

namespace fs = std::filesystem;
using Reason = SweepOutputError::Reason;

namespace {

std::string readWhole(const fs::path& p, std::uintmax_t limit) {
  try {
    return io::readFileBounded(p, "sweep file", limit);
  } catch (const io::FileReadError& e) {
    throw SweepOutputError(Reason::kCannotWrite, e.what());
  }
}

}  // namespace

SharedSweepFolder::SharedSweepFolder(const fs::path& dir, const std::string& manifest,
                                     const SweepGrid& grid, SweepAnalysis analysis)
    : dir_(dir),
      results_(dir / "results.csv"),
      grid_(grid),
      analysis_(analysis),
      header_(csvLine(sweepColumns(grid, analysis))),
      lines_(grid.size()) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec)
    throw SweepOutputError(Reason::kCannotWrite,
                           "cannot create '" + dir.string() + "': " + ec.message());
  try {
    lock_.emplace(dir, DirLock::Mode::kShared);
  } catch (const DirLockedError& e) {
    throw SweepOutputError(Reason::kInUse, e.what());
  } catch (const std::runtime_error& e) {
    throw SweepOutputError(Reason::kCannotWrite, e.what());
  }
  const fs::path manifest_file = dir / "sweep.json";
  // results.csv first: one written by tribo had its sweep.json before it, so a results.csv
  // seen here and no sweep.json seen after it is one tribo did not write.
  const bool have_results = fs::exists(results_);
  if (have_results && !fs::exists(manifest_file))
    throw SweepOutputError(
        Reason::kOtherSweep,
        "'" + results_.string() + "' exists without sweep.json; not resuming an unknown sweep");
  bool created = false;
  try {
    created = createFileOnce(manifest_file, manifest);
  } catch (const std::runtime_error& e) {
    throw SweepOutputError(Reason::kCannotWrite, e.what());
  }
  if (!created) {
    const std::string there = readWhole(manifest_file, io::kMaxJsonBytes);
    if (there != manifest)
      throw SweepOutputError(Reason::kOtherSweep,
                             "'" + dir.string() +
                                 "' holds a different sweep: its sweep.json differs from this "
                                 "one's in " +
                                 manifestDifferences(there, manifest) +
                                 "; give every slice the same scene, parameters, values and "
                                 "settings, or use another --out");
  }
  rescan();
}

void SharedSweepFolder::rescan() {
  if (fs::exists(results_)) {
    const std::string text = readWhole(results_, io::kMaxSweepResultsBytes);
    if (text.compare(0, header_.size(), header_) != 0)
      throw SweepOutputError(Reason::kOtherSweep,
                             "'" + results_.string() +
                                 "' does not start with this sweep's header; remove it to restart");
    std::size_t pos = header_.size();
    while (pos < text.size()) {
      const std::size_t end = text.find('\n', pos);
      if (end == std::string::npos) break;  // a line cut off by a kill
      const std::string line = text.substr(pos, end - pos + 1);
      pos = end + 1;
      const auto index = sweepRowPoint(line.substr(0, line.size() - 1), grid_, analysis_);
      if (index && lines_[*index].empty()) lines_[*index] = line;
    }
  }
  readPointRows(dir_, grid_, analysis_, lines_);
}

std::size_t SharedSweepFolder::doneCount() const {
  std::size_t n = 0;
  for (const auto& l : lines_) n += !l.empty();
  return n;
}

std::vector<std::size_t> SharedSweepFolder::missingPoints() const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < lines_.size(); ++i)
    if (lines_[i].empty()) out.push_back(i);
  return out;
}

void SharedSweepFolder::record(std::size_t index, const std::string& line) {
  if (!have_rows_dir_) {
    std::error_code ec;
    fs::create_directories(rowsDir(dir_), ec);
    if (ec)
      throw SweepOutputError(Reason::kCannotWrite,
                             "cannot create '" + rowsDir(dir_).string() + "': " + ec.message());
    have_rows_dir_ = true;
  }
  writePointRow(dir_, index, grid_.size(), line);
  lines_[index] = line;
}

bool SharedSweepFolder::writeResultsIfComplete() {
  std::string text = header_;
  for (const auto& l : lines_) {
    if (l.empty()) return false;
    text += l;
  }
  try {
    replaceFileWhole(results_, text);
  } catch (const std::runtime_error& e) {
    throw SweepOutputError(Reason::kCannotWrite, e.what());
  }
  return true;
}

}  // namespace tribo::study
