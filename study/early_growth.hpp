// The early growth rate a run measures, to set beside `tribo modes`' prediction: the
// least-squares slope of ln(peak_to_peak) of the first cycles against their mid-times
// (study/oscillation_summary.hpp's envelopeGrowthRate), while the oscillation is still small
// enough to be linear. For x = x_eq + A e^(sigma t) cos(w t + phi) every max-to-max cycle's
// peak-to-peak is a fixed multiple of e^(sigma t_k), so the slope is sigma exactly, without
// knowing x_eq.
// Which cycles: from cycle `skip` (the first holds the start's transient: the contact
// settling, a second mode decaying) on, at most `max_cycles` of them, and only while their
// peak-to-peak stays within a factor `max_change` of the first one used (beyond it a growing
// oscillation is meeting its nonlinearity, e.g. stick-slip, or a decaying one the noise).
// At least `min_cycles`, else nothing is measured.
// Not here: the linear prediction (study/modes/modes.hpp), the cycles themselves, a run whose
// start is far from the steady state (its first cycles are then not the linear regime: the
// figure is what the run shows, not sigma).
#pragma once

#include <vector>

#include "study/oscillation_summary.hpp"

namespace tribo::study {

struct EarlyGrowthOptions {
  int skip = 1;
  int max_cycles = 20;
  double max_change = 10.0;
  int min_cycles = 3;
};

struct EarlyGrowth {
  bool measured = false;
  double rate = 0.0;  // [1/s]
  int first_cycle = 0, cycles = 0;
  double t_start = 0.0, t_end = 0.0;  // [s], of the cycles used
};

EarlyGrowth earlyGrowth(const std::vector<Cycle>& cycles, const EarlyGrowthOptions& options = {});

}  // namespace tribo::study
