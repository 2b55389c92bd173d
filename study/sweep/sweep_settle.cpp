#include "study/sweep/sweep_settle.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "study/oscillation_summary.hpp"

namespace tribo::study {

namespace {

double range(std::span<const double> x) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  return *hi - *lo;
}

}  // namespace

SettleCheck checkSettled(std::span<const double> t, std::span<const double> x,
                         std::size_t window_start, int cycles, double tolerance) {
  if (cycles < 1) throw std::invalid_argument("checkSettled: cycles must be >= 1");
  if (window_start + 3 > t.size()) window_start = 0;
  const auto tw = t.subspan(window_start), xw = x.subspan(window_start);
  OscillationOptions options;
  options.last_cycles = cycles;
  const OscillationSummary s = summarizeOscillation(tw, xw, {}, options);
  const auto k = static_cast<std::size_t>(cycles);
  SettleCheck out;
  const auto& c = s.cycles;
  if (c.size() >= k) out.period = (c.back().t_end - c[c.size() - k].t_start) / cycles;
  if (c.size() >= 2 * k) {
    double last = 0, previous = 0;
    for (std::size_t i = 0; i < k; ++i) {
      last += c[c.size() - 1 - i].peak_to_peak;
      previous += c[c.size() - 1 - k - i].peak_to_peak;
    }
    out.settled = std::abs(last - previous) <= tolerance * last;
  } else if (c.empty()) {
    // No cycle in the window: settled if x stands still there, relative to the whole motion.
    const double whole = range(x);
    out.settled = whole == 0 || range(xw) <= tolerance * whole;
  }
  return out;
}

SettleWatch::SettleWatch(const io::Scene& scene, const SettleRule& rule) : rule_(rule) {
  if (!(rule.tolerance > 0) || !std::isfinite(rule.tolerance))
    throw std::invalid_argument("settle tolerance must be a positive number");
  if (!(rule.check_interval > 0) || !std::isfinite(rule.check_interval))
    throw std::invalid_argument("settle check interval must be a positive number of seconds");
  const io::SummarySpec& spec = scene.output.summary;
  const auto body = spec.body.empty() ? std::nullopt : scene.model->findBody(spec.body);
  if (!body || body->isWorld())
    throw std::invalid_argument(scene.path +
                                ": output.summary names no body to observe; settling needs one");
  static const char* kAxis[] = {".x", ".y", ".z"};
  const TrajectoryRecorder probe(*scene.model);
  x_column_ = probe.columnIndex(scene.model->bodies[body->value].name + kAxis[spec.coordinate]);
  cycles_ = spec.last_cycles;
}

RunMonitor SettleWatch::monitor() {
  return {rule_.check_interval,
          [this](const TrajectoryRecorder& trajectory) { return check(trajectory); }};
}

bool SettleWatch::check(const TrajectoryRecorder& trajectory) {
  const auto t = trajectory.column(0);
  const auto x = trajectory.column(x_column_);
  if (t.size() < 3) return false;
  // The recent window: 2K cycles and a margin once the period is known, else everything.
  std::size_t start = 0;
  if (period_ > 0) {
    const double t0 = t.back() - (2 * cycles_ + 2) * period_;
    start = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), t0) - t.begin());
  }
  const SettleCheck c = checkSettled(t, x, start, cycles_, rule_.tolerance);
  period_ = c.period;
  settled_ = c.settled;
  return settled_;
}

}  // namespace tribo::study
