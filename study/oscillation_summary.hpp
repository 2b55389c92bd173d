// Oscillation analysis for run summaries: turns a recorded time series x(t) of one body
// coordinate (e.g. the box displacement on the belt) into the figures the seed paper reports:
// peak-to-peak amplitude of the limit cycle, its period, the time to reach it, the share of
// time spent stuck, and the exponential growth rate of the envelope.
//
//   cycle k         = [t of maximum k, t of maximum k+1] (successive maxima of x)
//   peak_to_peak_k  = max(x over cycle k) - min(x over cycle k)
//   sigma           = least-squares slope of ln(peak_to_peak_k) vs cycle mid-time [1/s]
//                     (for x = A e^(sigma t) sin(w t) this recovers sigma exactly)
//
// Extrema are found with hysteresis: a maximum counts only once x has dropped below it by
// more than the prominence threshold, and a minimum likewise, so numerical ripple and the
// almost linear stick phases of a stick-slip sawtooth make no spurious cycles. Each extremum
// is refined between samples: with a parabola through the three samples around it where x
// is smooth, or, at a kink (the corner where stick turns into slip), by intersecting
// polynomials extrapolated from each side.
//
// A record too long for memory is read through SampleSeries (e.g. a column spilled to a
// file, study/series_spill.hpp): the analysis then holds only the extrema, the cycles and
// one running integral per 1024 samples, and gives the same bits as from memory.
//
// What it is not: a spectral analysis (no FFT, one dominant oscillation is assumed), a noise
// filter (noise larger than the threshold makes cycles), or a detector of when a transient
// has settled (the figures average the last cycles of the record; the caller chooses the
// record). Pure functions of their inputs; no other Tribo dependency.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace tribo::study {

// One max-to-max cycle of x.
struct Cycle {
  double t_start = 0;       // time of the maximum that opens the cycle [s]
  double t_end = 0;         // time of the next maximum, which closes it [s]
  double peak_to_peak = 0;  // max - min of x within [t_start, t_end] [unit of x]
  double mean = 0;          // time average of x over [t_start, t_end] [unit of x]
};

struct OscillationOptions {
  // Number of final cycles averaged for amplitude_pp, period and x_mean (>= 1).
  int last_cycles = 3;
  // A sample counts as stuck when |slip speed| < stick_speed [m/s] (>= 0).
  double stick_speed = 1e-3;
  // Hysteresis: an extremum must stand out from the next opposite extremum by more than
  // max(min_relative_prominence * (max x - min x), min_prominence) (both >= 0).
  double min_relative_prominence = 1e-3;
  // Absolute floor of the hysteresis [unit of x]; motions smaller than this are ripple.
  // Needed because a relative threshold alone would turn ripple on a constant into cycles.
  double min_prominence = 1e-6;
};

struct OscillationSummary {
  bool oscillating = false;   // cycles_used >= 1 and amplitude_pp > 0
  int cycles_used = 0;        // cycles averaged: min(last_cycles, number of cycles found)
  double amplitude_pp = 0;    // mean peak_to_peak of the cycles used [unit of x]; with no
                              // cycle: max - min of x over the last half of the record
  double period = 0;          // mean duration of the cycles used [s]; 0 with no cycle
  double time_to_98 = 0;      // t_end of the first cycle whose peak_to_peak reaches
                              // 0.98 * amplitude_pp [s]; 0 with no cycle
  double stuck_fraction = 0;  // share of the record's duration with |slip speed| <
                              // stick_speed (samples weighted by their time interval);
                              // 0 when no slip speed is given
  double x_mean = 0;          // time average of x over the cycles used [unit of x]; with no
                              // cycle: over the last half of the record
  std::vector<Cycle> cycles;  // every detected cycle, in time order
};

// Analyses x(t). t must be finite and strictly increasing (uniform sampling not required),
// x the same size, slip_speed the same size or empty; at least 3 samples. Throws
// std::invalid_argument naming the problem otherwise (also for out-of-range options).
OscillationSummary summarizeOscillation(std::span<const double> t, std::span<const double> x,
                                        std::span<const double> slip_speed,
                                        const OscillationOptions& options = {});

// Samples read by index from wherever they are kept. The analysis reads them mostly in
// order (a few passes, binary searches, and neighbours of each extremum).
class SampleSeries {
 public:
  virtual ~SampleSeries() = default;
  virtual std::size_t size() const = 0;
  virtual double at(std::size_t i) const = 0;
};

// The same analysis of samples read through SampleSeries; `slip_speed` may be null.
OscillationSummary summarizeOscillation(const SampleSeries& t, const SampleSeries& x,
                                        const SampleSeries* slip_speed,
                                        const OscillationOptions& options = {});

// Exponential growth rate sigma [1/s] of the envelope: least-squares slope of
// ln(peak_to_peak) against the mid-time (t_start + t_end) / 2 of the cycles whose mid-time
// lies in [t0, t1]. Negative for a decaying oscillation. Throws std::invalid_argument if
// t0 > t1 or fewer than two such cycles have peak_to_peak > 0.
double envelopeGrowthRate(const std::vector<Cycle>& cycles, double t0, double t1);

}  // namespace tribo::study
