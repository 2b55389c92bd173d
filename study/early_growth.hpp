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
// Trust: the slope is the linear growth rate only when the cycles used are one mode growing
// or decaying exponentially. Two checks say when they are not: the scatter of
// ln(peak_to_peak) about the fitted line (RMS; two modes beating, a contact opening or a
// stick phase in the window make it large) and the spread of the cycles' periods (max
// |T_k - T_mean| / T_mean; a second frequency, or a cycle that sticks, make it large). Above
// `max_scatter` or `max_period_spread` the figure is still given, marked not trustworthy with
// the reason, so no one reads it as sigma.
// Not here: the linear prediction (study/modes/modes.hpp), the cycles themselves, a run whose
// start is far from the steady state (its first cycles are then not the linear regime: the
// figure is what the run shows, not sigma).
#pragma once

#include <string>
#include <vector>

#include "study/oscillation_summary.hpp"

namespace tribo::study {

struct EarlyGrowthOptions {
  int skip = 1;
  int max_cycles = 20;
  double max_change = 10.0;
  int min_cycles = 3;
  double max_scatter = 0.02;        // RMS of ln(pp) about the fit, ~2% in amplitude
  double max_period_spread = 0.02;  // relative
};

struct EarlyGrowth {
  bool measured = false;
  double rate = 0.0;  // [1/s]
  int first_cycle = 0, cycles = 0;
  double t_start = 0.0, t_end = 0.0;  // [s], of the cycles used
  double scatter = 0.0;               // RMS residual of ln(pp) about the fitted line
  double period_spread = 0.0;         // max |T_k - T_mean| / T_mean over the cycles used
  bool trustworthy = false;           // both within the options' bounds
  std::string doubt;                  // why not, when not: a phrase for messages
};

EarlyGrowth earlyGrowth(const std::vector<Cycle>& cycles, const EarlyGrowthOptions& options = {});

}  // namespace tribo::study
