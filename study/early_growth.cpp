#include "study/early_growth.hpp"

#include <cstddef>

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
  return out;
}

}  // namespace tribo::study
