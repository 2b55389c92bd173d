#include "study/early_growth.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <sstream>

namespace tribo::study {

EarlyGrowth earlyGrowth(const std::vector<Cycle>& cycles, const EarlyGrowthOptions& options) {
  EarlyGrowth out;
  const std::size_t first = static_cast<std::size_t>(options.skip);
  if (cycles.size() <= first || !(cycles[first].peak_to_peak > 0)) return out;
  const double reference = cycles[first].peak_to_peak;
  std::size_t last = first;
  while (last + 1 < cycles.size() && static_cast<int>(last + 1 - first) < options.max_cycles) {
    const double pp = cycles[last + 1].peak_to_peak;
    if (!(pp > reference / options.max_change && pp < reference * options.max_change)) break;
    ++last;
  }
  const int used = static_cast<int>(last - first + 1);
  if (used < options.min_cycles) return out;
  auto mid = [&](std::size_t k) { return 0.5 * (cycles[k].t_start + cycles[k].t_end); };
  out.rate = envelopeGrowthRate(cycles, mid(first), mid(last));
  out.measured = true;
  out.first_cycle = static_cast<int>(first);
  out.cycles = used;
  out.t_start = cycles[first].t_start;
  out.t_end = cycles[last].t_end;
  // The fit's quality: ln(pp) about the line through its centroid, and the periods.
  double t_bar = 0.0, y_bar = 0.0, period_bar = 0.0;
  for (std::size_t k = first; k <= last; ++k) {
    t_bar += mid(k) / used;
    y_bar += std::log(cycles[k].peak_to_peak) / used;
    period_bar += (cycles[k].t_end - cycles[k].t_start) / used;
  }
  double squares = 0.0;
  for (std::size_t k = first; k <= last; ++k) {
    const double r = std::log(cycles[k].peak_to_peak) - (y_bar + out.rate * (mid(k) - t_bar));
    squares += r * r;
    const double period = cycles[k].t_end - cycles[k].t_start;
    out.period_spread = std::max(out.period_spread, std::abs(period - period_bar) / period_bar);
  }
  out.scatter = std::sqrt(squares / used);
  std::ostringstream doubt;
  if (!(out.scatter <= options.max_scatter))
    doubt << "the amplitude scatters " << std::setprecision(2) << 100.0 * out.scatter
          << "% about the exponential fit";
  if (!(out.period_spread <= options.max_period_spread))
    doubt << (doubt.tellp() > 0 ? " and " : "") << "the periods differ by up to "
          << std::setprecision(2) << 100.0 * out.period_spread << "%";
  out.doubt = doubt.str();
  if (!out.doubt.empty())
    out.doubt += ": not one mode growing exponentially, so not the linear growth rate";
  out.trustworthy = out.doubt.empty();
  return out;
}

}  // namespace tribo::study
