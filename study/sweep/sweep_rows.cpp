#include "study/sweep/sweep_rows.hpp"

#include <charconv>
#include <stdexcept>

#include "io/file_read.hpp"
#include "study/file_commit.hpp"
#include "study/sweep/sweep_results.hpp"

namespace tribo::study {

namespace fs = std::filesystem;
using Reason = SweepOutputError::Reason;

namespace {

std::string rowName(std::size_t index, std::size_t points) {
  const std::size_t width = std::to_string(points > 0 ? points - 1 : 0).size();
  std::string name = std::to_string(index);
  if (name.size() < width) name.insert(0, width - name.size(), '0');
  return name + ".csv";
}

// The point a file name <digits>.csv names; false for any other name.
bool pointOfName(const std::string& name, std::size_t& index) {
  const std::string ext = ".csv";
  if (name.size() <= ext.size() || name.compare(name.size() - ext.size(), ext.size(), ext) != 0)
    return false;
  const char* first = name.data();
  const char* last = name.data() + name.size() - ext.size();
  const auto r = std::from_chars(first, last, index);
  return r.ec == std::errc() && r.ptr == last;
}

}  // namespace

fs::path rowsDir(const fs::path& dir) { return dir / "rows"; }

void writePointRow(const fs::path& dir, std::size_t index, std::size_t points,
                   const std::string& line) {
  try {
    replaceFileWhole(rowsDir(dir) / rowName(index, points), line);
  } catch (const std::runtime_error& e) {
    throw SweepOutputError(Reason::kCannotWrite, e.what());
  }
}

std::size_t readPointRows(const fs::path& dir, const SweepGrid& grid, SweepAnalysis analysis,
                          std::vector<std::string>& lines) {
  const fs::path rows = rowsDir(dir);
  std::error_code ec;
  if (!fs::is_directory(rows, ec)) return 0;
  fs::directory_iterator it(rows, ec);
  if (ec)
    throw SweepOutputError(Reason::kCannotWrite,
                           "cannot read '" + rows.string() + "': " + ec.message());
  std::size_t count = 0;
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) break;
    std::size_t index = 0;
    if (!pointOfName(it->path().filename().string(), index) || index >= grid.size()) continue;
    std::string text;
    try {
      // One row: its length is bounded by the results file's own limit.
      text = io::readFileBounded(it->path(), "sweep row file", io::kMaxSweepResultsBytes);
    } catch (const io::FileReadError&) {
      continue;  // not a regular file, or gone: not a row
    }
    if (text.empty() || text.back() != '\n' || text.find('\n') != text.size() - 1) continue;
    const auto point = sweepRowPoint(text.substr(0, text.size() - 1), grid, analysis);
    if (!point || *point != index) continue;
    if (lines[index].empty()) ++count;
    lines[index] = std::move(text);
  }
  if (ec)
    throw SweepOutputError(Reason::kCannotWrite,
                           "cannot read '" + rows.string() + "': " + ec.message());
  return count;
}

}  // namespace tribo::study
