#include "study/output_budget.hpp"

#include <algorithm>
#include <string>

#include "core/number_text.hpp"
#include "study/output_stride.hpp"

namespace tribo::study {

namespace {

std::string bytesText(double bytes) {
  static const char* kUnits[] = {"B", "KB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000 && u < 6) {
    bytes /= 1000;
    ++u;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g %s", bytes, kUnits[u]);
  return buf;
}

std::string what(const io::Scene& scene, const OutputEstimate& e) {
  const SimulationOptions& o = scene.model->options;
  return "output.interval " + numberText(scene.output.interval) + " s (step " +
         numberText(o.time_step) + " s) over duration " + numberText(o.duration) +
         " s gives about " + numberText(e.rows) + " rows of " + numberText(e.columns) + " columns";
}

}  // namespace

OutputEstimate estimateOutput(const io::Scene& scene) {
  const SimulationOptions& o = scene.model->options;
  OutputEstimate e;
  e.rows = o.duration / outputInterval(scene.output.interval, o.time_step) + 2;
  e.columns = 1.0 + 8.0 * static_cast<double>(scene.model->bodies.size());
  e.csv_bytes = e.rows * (e.columns * kCsvBytesPerField + kSpillBytesPerRow);
  e.kept_bytes = e.rows * e.columns * 8.0;
  return e;
}

void checkOutputFitsDisk(const io::Scene& scene, const std::filesystem::path& dir) {
  const OutputEstimate e = estimateOutput(scene);
  std::filesystem::path existing = std::filesystem::absolute(dir);
  std::error_code ec;
  while (!std::filesystem::exists(existing, ec) && existing.has_parent_path() &&
         existing != existing.parent_path())
    existing = existing.parent_path();
  const auto space = std::filesystem::space(existing, ec);
  if (ec) return;  // unknown: the writes themselves will report a full disk
  const double free_bytes = static_cast<double>(space.available);
  if (e.csv_bytes > free_bytes)
    throw OutputTooLarge(what(scene, e) + ", up to " + bytesText(e.csv_bytes) +
                         " of trajectory.csv, more than the " + bytesText(free_bytes) +
                         " free in '" + existing.string() +
                         "' (raise output.interval or shorten duration)");
}

void checkOutputFitsMemory(const io::Scene& scene) {
  const OutputEstimate e = estimateOutput(scene);
  if (e.kept_bytes > kMaxKeptBytes)
    throw OutputTooLarge(what(scene, e) + ", " + bytesText(e.kept_bytes) +
                         " to keep in memory, more than the cap of " + bytesText(kMaxKeptBytes) +
                         " (raise output.interval or shorten duration)");
}

}  // namespace tribo::study
