// Which kind of orbit the last cycles of a run trace (study/oscillation_summary.hpp's
// max-to-max cycles), so that the summary's averages are not read as a limit cycle that is
// not there:
//   period_1   every examined cycle has the same peak-to-peak and duration, within
//              `tolerance` of their means (relative);
//   period_2   they alternate: the even-numbered cycles agree among themselves and the odd
//              ones among themselves (within tolerance), but the two families differ; the
//              orbit closes every two cycles (a period-doubled stick-slip);
//   irregular  neither (a transient still settling, a longer period, chaos);
//   none       fewer than 2 cycles (4 are needed to tell period 2).
// The last `examined` cycles (at most 8) are used; for period 2, figures are given per
// family, `a` being the family of the last cycle.
// Not here: longer periods (3, 4...), spectral analysis, deciding when a transient ends.
#pragma once

#include <span>
#include <string_view>

#include "study/oscillation_summary.hpp"

namespace tribo::study {

enum class OrbitKind { kNone, kPeriod1, kPeriod2, kIrregular };
std::string_view orbitKindName(OrbitKind kind);  // "none", "period_1", "period_2", "irregular"

struct OrbitShape {
  OrbitKind kind = OrbitKind::kNone;
  int examined = 0;           // cycles examined (the last ones)
  double peak_to_peak_a = 0;  // period 1: the mean; period 2: the last cycle's family [x]
  double peak_to_peak_b = 0;  // period 2: the other family (period 1: = a)
  double duration_a = 0;      // the same for the cycles' durations [s]
  double duration_b = 0;
  double spread = 0;  // largest relative deviation found within the families
};

OrbitShape classifyOrbit(std::span<const Cycle> cycles, double tolerance = 0.01);

}  // namespace tribo::study
