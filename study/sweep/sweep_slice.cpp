#include "study/sweep/sweep_slice.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "io/file_read.hpp"
#include "io/utf8_check.hpp"
#include "study/sweep/sweep_manifest.hpp"
#include "study/sweep/sweep_progress.hpp"
#include "study/sweep/sweep_results.hpp"
#include "study/sweep/sweep_shared_folder.hpp"

namespace tribo::study {

namespace fs = std::filesystem;

namespace {

// A whole number written with digits only.
std::optional<std::size_t> wholeNumber(std::string_view text) {
  std::size_t v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size())
    return std::nullopt;
  return v;
}

}  // namespace

SweepSlice parseSweepSlice(std::string_view text) {
  const std::string found = "found '" + io::printableText(text) + "'";
  const std::string expected =
      "--slice: expected I/N, two whole numbers with 1 <= I <= N <= " + std::to_string(kMaxSlices) +
      " (e.g. 2/8), ";
  const std::size_t slash = text.find('/');
  if (slash == std::string_view::npos) throw std::invalid_argument(expected + found);
  const auto i = wholeNumber(text.substr(0, slash));
  const auto n = wholeNumber(text.substr(slash + 1));
  if (!i || !n) throw std::invalid_argument(expected + found);
  if (*n < 1 || *n > kMaxSlices)
    throw std::invalid_argument(expected + found + " (N = " + std::to_string(*n) + ")");
  if (*i < 1 || *i > *n)
    throw std::invalid_argument(expected + found + " (I = " + std::to_string(*i) +
                                (*i < 1 ? ", below 1)" : ", above N)"));
  return {*i, *n};
}

std::vector<std::size_t> slicePoints(std::size_t points, SweepSlice slice) {
  std::vector<std::size_t> out;
  for (std::size_t k = slice.index - 1; k < points; k += slice.count) out.push_back(k);
  return out;
}

SliceReport runSweepSlice(const SweepPlan& plan, const fs::path& out, SweepSlice slice,
                          const LocalRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SharedSweepFolder folder(out, plan.manifest, plan.grid, plan.setup.analysis);
  SliceReport report;
  report.sweep_points = plan.grid.size();
  std::vector<std::size_t> pending;
  for (const std::size_t p : slicePoints(plan.grid.size(), slice)) {
    ++report.slice.points;
    if (folder.isDone(p))
      ++report.slice.resumed;
    else
      pending.push_back(p);
  }

  std::atomic<std::size_t> cursor{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;  // guards report, folder and the first write error
  std::optional<SweepOutputError> write_error;
  SweepProgress progress(options.progress, report.slice.points, report.slice.resumed);
  const unsigned jobs = static_cast<unsigned>(std::min<std::size_t>(
      options.jobs ? options.jobs : defaultJobs(), std::max<std::size_t>(1, pending.size())));
  if (!pending.empty())
    runPointsOnThreads(
        plan, out, jobs,
        [&]() -> std::optional<std::size_t> {
          if (stop) return std::nullopt;
          const std::size_t k = cursor++;
          if (k >= pending.size()) return std::nullopt;
          return pending[k];
        },
        [&](const FinishedPoint& p) {
          std::lock_guard lock(mutex);
          if (stop) return;
          try {
            folder.record(p.index, p.line);
          } catch (const SweepOutputError& e) {
            write_error = e;
            stop = true;
            return;
          }
          ++report.slice.ran;
          report.slice.failed += p.failed;
          report.slice.unsettled += p.unsettled;
          progress.pointDone(p.failed);
          if (options.stop_after && report.slice.ran >= options.stop_after) stop = true;
        });
  progress.finish();
  if (write_error) throw *write_error;
  report.slice.complete = report.slice.resumed + report.slice.ran == report.slice.points;
  folder.rescan();  // the rows the other slices wrote meanwhile
  report.sweep_done = folder.doneCount();
  report.results_written = folder.writeResultsIfComplete();
  report.slice.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

MergeReport mergeSweep(const fs::path& dir) {
  const fs::path manifest_file = dir / "sweep.json";
  std::error_code ec;
  if (!fs::is_regular_file(manifest_file, ec))
    throw SweepOutputError(
        SweepOutputError::Reason::kOtherSweep,
        "'" + dir.string() + "' holds no sweep (no " + manifest_file.string() + ")");
  std::string manifest;
  try {
    manifest = io::readFileBounded(manifest_file, "sweep file", io::kMaxJsonBytes);
  } catch (const io::FileReadError& e) {
    throw SweepOutputError(SweepOutputError::Reason::kCannotWrite, e.what());
  }
  const ManifestGrid sweep = readManifestGrid(manifest, manifest_file.string());
  SharedSweepFolder folder(dir, manifest, sweep.grid, sweep.analysis);
  MergeReport report;
  report.points = sweep.grid.size();
  for (const auto& a : sweep.grid.axes()) report.axis_names.push_back(a.name);
  report.missing = folder.missingPoints();
  for (std::size_t k = 0; k < std::min(report.missing.size(), kMissingNamed); ++k)
    report.missing_values.push_back(sweep.grid.values(report.missing[k]));
  report.written = folder.writeResultsIfComplete();
  return report;
}

}  // namespace tribo::study
