#include "study/orbit_shape.hpp"

#include <algorithm>
#include <cmath>

namespace tribo::study {

namespace {

struct Family {
  double pp = 0, duration = 0, spread = 0;
};

// Means of the cycles i = first, first + step, ... < end, and their largest relative
// deviation from those means.
Family family(std::span<const Cycle> c, std::size_t first, std::size_t step) {
  Family f;
  int n = 0;
  for (std::size_t i = first; i < c.size(); i += step, ++n) {
    f.pp += c[i].peak_to_peak;
    f.duration += c[i].t_end - c[i].t_start;
  }
  f.pp /= n;
  f.duration /= n;
  for (std::size_t i = first; i < c.size(); i += step) {
    const double dp = f.pp > 0 ? std::abs(c[i].peak_to_peak - f.pp) / f.pp : 0.0;
    const double dt =
        f.duration > 0 ? std::abs(c[i].t_end - c[i].t_start - f.duration) / f.duration : 0.0;
    f.spread = std::max({f.spread, dp, dt});
  }
  return f;
}

}  // namespace

std::string_view orbitKindName(OrbitKind kind) {
  switch (kind) {
    case OrbitKind::kPeriod1:
      return "period_1";
    case OrbitKind::kPeriod2:
      return "period_2";
    case OrbitKind::kIrregular:
      return "irregular";
    case OrbitKind::kNone:
      break;
  }
  return "none";
}

OrbitShape classifyOrbit(std::span<const Cycle> cycles, double tolerance) {
  OrbitShape o;
  const std::size_t n = std::min<std::size_t>(cycles.size(), 8);
  o.examined = static_cast<int>(n);
  if (n < 2) return o;
  const std::span<const Cycle> last = cycles.last(n);
  const Family all = family(last, 0, 1);
  if (all.spread <= tolerance) {
    o.kind = OrbitKind::kPeriod1;
    o.peak_to_peak_a = o.peak_to_peak_b = all.pp;
    o.duration_a = o.duration_b = all.duration;
    o.spread = all.spread;
    return o;
  }
  o.kind = OrbitKind::kIrregular;
  o.spread = all.spread;
  if (n < 4) return o;
  const Family a = family(last, (n - 1) % 2, 2);  // the last cycle's family
  const Family b = family(last, n % 2, 2);
  if (std::max(a.spread, b.spread) <= tolerance) {
    o.kind = OrbitKind::kPeriod2;
    o.peak_to_peak_a = a.pp;
    o.peak_to_peak_b = b.pp;
    o.duration_a = a.duration;
    o.duration_b = b.duration;
    o.spread = std::max(a.spread, b.spread);
  }
  return o;
}

}  // namespace tribo::study
