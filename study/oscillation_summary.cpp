#include "study/oscillation_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

namespace tribo::study {
namespace {

// Every helper reads its samples through S: std::span<const double> (in memory) or
// SeriesRef (a SampleSeries, e.g. a spilled column), with the same arithmetic in the same
// order, so both give the same bits.
struct SeriesRef {
  const SampleSeries* series;  // null: empty
  std::size_t size() const { return series ? series->size() : 0; }
  bool empty() const { return size() == 0; }
  double operator[](std::size_t i) const { return series->at(i); }
};

// An extremum of x: sample index, kind, and the refined time and value.
struct Extremum {
  std::size_t index = 0;
  bool is_max = false;
  double t = 0;
  double x = 0;
};

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("summarizeOscillation: " + what);
}

template <class S>
void validate(const S& t, const S& x, const S& slip, const OscillationOptions& o) {
  if (x.size() != t.size()) {
    fail("t and x differ in size (" + std::to_string(t.size()) + " vs " + std::to_string(x.size()) +
         ")");
  }
  if (!slip.empty() && slip.size() != t.size()) {
    fail("slip_speed must be empty or the size of t (" + std::to_string(slip.size()) + " vs " +
         std::to_string(t.size()) + ")");
  }
  if (t.size() < 3) fail("need at least 3 samples (got " + std::to_string(t.size()) + ")");
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i]) || !std::isfinite(x[i]) || (!slip.empty() && !std::isfinite(slip[i])))
      fail("non-finite sample at index " + std::to_string(i));
    if (i > 0 && !(t[i] > t[i - 1])) {
      fail("t must be strictly increasing (t[" + std::to_string(i) + "] = " + std::to_string(t[i]) +
           " <= t[" + std::to_string(i - 1) + "] = " + std::to_string(t[i - 1]) + ")");
    }
  }
  if (o.last_cycles < 1) fail("options.last_cycles must be >= 1");
  if (!(o.stick_speed >= 0) || !std::isfinite(o.stick_speed))
    fail("options.stick_speed must be finite and >= 0");
  if (!(o.min_relative_prominence >= 0) || !std::isfinite(o.min_relative_prominence))
    fail("options.min_relative_prominence must be finite and >= 0");
  if (!(o.min_prominence >= 0) || !std::isfinite(o.min_prominence))
    fail("options.min_prominence must be finite and >= 0");
}

// Alternating maxima and minima found with hysteresis `delta`: an extremum is accepted once
// x has moved away from it by more than delta. An extremum at the first sample is dropped
// (the record may begin mid-slope); the last one is never confirmed.
template <class S>
std::vector<Extremum> findExtrema(const S& x, double delta) {
  enum class Seek { kEither, kMax, kMin };
  Seek seek = Seek::kEither;
  std::size_t hi = 0;
  std::size_t lo = 0;
  std::vector<Extremum> out;
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (seek != Seek::kMin && x[i] > x[hi]) hi = i;
    if (seek != Seek::kMax && x[i] < x[lo]) lo = i;
    if (seek != Seek::kMin && x[i] < x[hi] - delta) {
      out.push_back({hi, true, 0, 0});
      seek = Seek::kMin;
      lo = i;
    } else if (seek != Seek::kMax && x[i] > x[lo] + delta) {
      out.push_back({lo, false, 0, 0});
      seek = Seek::kMax;
      hi = i;
    }
  }
  if (!out.empty() && out.front().index == 0) out.erase(out.begin());
  return out;
}

// c0 + c1 u + c2 u^2 in u = t - t_ref.
struct Poly2 {
  double c0 = 0, c1 = 0, c2 = 0;
  double operator()(double u) const { return c0 + u * (c1 + u * c2); }
  double slope(double u) const { return c1 + 2 * c2 * u; }
};

// Polynomial through samples first .. first+count-1 (count 2: line, count 3: parabola).
template <class S>
Poly2 through(const S& t, const S& x, std::size_t first, std::size_t count, double t_ref) {
  const double u0 = t[first] - t_ref, u1 = t[first + 1] - t_ref;
  const double f01 = (x[first + 1] - x[first]) / (u1 - u0);
  double f012 = 0;
  if (count == 3) {
    const double u2 = t[first + 2] - t_ref;
    const double f12 = (x[first + 2] - x[first + 1]) / (u2 - u1);
    f012 = (f12 - f01) / (u2 - u0);
  }
  return {x[first] - f01 * u0 + f012 * u0 * u1, f01 - f012 * (u0 + u1), f012};
}

// Second divided difference at sample j (an estimate of x'' there).
template <class S>
double curvature(const S& t, const S& x, std::size_t j) {
  const double s_left = (x[j] - x[j - 1]) / (t[j] - t[j - 1]);
  const double s_right = (x[j + 1] - x[j]) / (t[j + 1] - t[j]);
  return 2 * (s_right - s_left) / (t[j + 1] - t[j - 1]);
}

// Smooth extremum at k: the curvature at both neighbours is within a factor 2 of that at k.
// A kink puts all the curvature on one or two samples. Undecidable near the ends: smooth.
template <class S>
bool looksSmooth(const S& t, const S& x, std::size_t k) {
  if (k < 2 || k + 2 >= x.size()) return true;
  const double c = curvature(t, x, k);
  if (c == 0) return false;
  for (const std::size_t j : {k - 1, k + 1}) {
    const double r = curvature(t, x, j) / c;
    if (!(r >= 0.5 && r <= 2.0)) return false;
  }
  return true;
}

// Vertex of the parabola through samples k-1, k, k+1, kept within [t[k-1], t[k+1]].
template <class S>
Extremum refineSmooth(const S& t, const S& x, std::size_t k, bool is_max) {
  const Poly2 p = through(t, x, k - 1, 3, t[k]);
  if (p.c2 == 0 || (p.c2 < 0) != is_max) return {k, is_max, t[k], x[k]};
  const double u = std::clamp(-p.c1 / (2 * p.c2), t[k - 1] - t[k], t[k + 1] - t[k]);
  return {k, is_max, t[k] + u, p(u)};
}

// Corner between the branch ending at sample k-1 and the branch starting at k+1: the crossing
// in [t[k-1], t[k+1]] of polynomials of degree `count`-1 extrapolated from each side. Empty
// if the crossing is missing or implausible (not beyond x[k], or beyond what the slopes allow).
template <class S>
std::optional<Extremum> refineKink(const S& t, const S& x, std::size_t k, bool is_max,
                                   std::size_t count) {
  if (k < count || k + count >= x.size()) return std::nullopt;
  const Poly2 left = through(t, x, k - count, count, t[k]);
  const Poly2 right = through(t, x, k + 1, count, t[k]);
  const double a = left.c2 - right.c2, b = left.c1 - right.c1, c = left.c0 - right.c0;
  const double u_lo = t[k - 1] - t[k], u_hi = t[k + 1] - t[k];
  double roots[2];
  int n_roots = 0;
  if (std::abs(a) * (u_hi - u_lo) <= 1e-12 * std::abs(b)) {
    if (b != 0) roots[n_roots++] = -c / b;
  } else {
    const double disc = b * b - 4 * a * c;
    if (disc >= 0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      if (q != 0) roots[n_roots++] = c / q;
      roots[n_roots++] = q / a;
    }
  }
  std::optional<Extremum> best;
  for (int r = 0; r < n_roots; ++r) {
    const double u = roots[r];
    if (!(u >= u_lo && u <= u_hi)) continue;
    // Left branch rises into a maximum faster than the right one (mirrored for a minimum).
    if ((left.slope(u) - right.slope(u) > 0) != is_max) continue;
    const double value = left(u);
    const double gain = is_max ? value - x[k] : x[k] - value;
    const double max_slope = std::max({std::abs(left.slope(u)), std::abs(right.slope(u)),
                                       std::abs((x[k] - x[k - 1]) / (t[k] - t[k - 1])),
                                       std::abs((x[k + 1] - x[k]) / (t[k + 1] - t[k]))});
    if (gain < 0 || gain > 2 * max_slope * std::abs(u)) continue;
    if (!best || std::abs(u) < std::abs(best->t - t[k]))
      best = Extremum{k, is_max, t[k] + u, value};
  }
  return best;
}

template <class S>
Extremum refine(const S& t, const S& x, std::size_t k, bool is_max) {
  if (looksSmooth(t, x, k)) return refineSmooth(t, x, k, is_max);
  for (const std::size_t count : {3u, 2u}) {
    if (auto e = refineKink(t, x, k, is_max, count)) return *e;
  }
  return {k, is_max, t[k], x[k]};
}

// First index i at which `before(t[i])` turns false (std::partition_point by index, for
// series that are read by index rather than iterated).
template <class S, class Before>
std::size_t partitionPoint(const S& t, Before before) {
  std::size_t lo = 0, n = t.size();
  while (n > 0) {
    const std::size_t half = n / 2;
    if (before(t[lo + half])) {
      lo += half + 1;
      n -= half + 1;
    } else {
      n = half;
    }
  }
  return lo;
}

// First index i with t[i] > a (std::upper_bound by index).
template <class S>
std::size_t upperBound(const S& t, double a) {
  return partitionPoint(t, [a](double v) { return !(a < v); });
}

// First index i with t[i] >= a (std::lower_bound by index).
template <class S>
std::size_t lowerBound(const S& t, double a) {
  return partitionPoint(t, [a](double v) { return v < a; });
}

// Integral of the piecewise linear x(t) from t[0]: cumulative trapezoids plus interpolation.
// The running sum is kept at every kStride-th sample and resumed from there, term by term in
// the same order, so memory stays small for a long record and the sums are exact repeats.
template <class S>
class Integral {
 public:
  static constexpr std::size_t kStride = 1024;
  Integral(const S& t, const S& x) : t_(t), x_(x) {
    double c = 0.0;
    checkpoints_.push_back(c);
    for (std::size_t i = 1; i < t.size(); ++i) {
      c = c + term(i);
      if (i % kStride == 0) checkpoints_.push_back(c);
    }
  }
  double upTo(double a) const {
    const std::size_t above = upperBound(t_, a);
    const std::size_t j = std::min<std::size_t>(above == 0 ? 0 : above - 1, t_.size() - 2);
    const double xa = x_[j] + (x_[j + 1] - x_[j]) * (a - t_[j]) / (t_[j + 1] - t_[j]);
    return cumulative(j) + 0.5 * (a - t_[j]) * (x_[j] + xa);
  }
  double mean(double a, double b) const { return (upTo(b) - upTo(a)) / (b - a); }

 private:
  double term(std::size_t i) const { return 0.5 * (t_[i] - t_[i - 1]) * (x_[i] + x_[i - 1]); }
  double cumulative(std::size_t j) const {
    double c = checkpoints_[j / kStride];
    for (std::size_t i = j / kStride * kStride + 1; i <= j; ++i) c = c + term(i);
    return c;
  }

  const S& t_;
  const S& x_;
  std::vector<double> checkpoints_;
};

// Smallest and largest of x[first..].
template <class S>
std::pair<double, double> minMax(const S& x, std::size_t first) {
  double lo = x[first], hi = x[first];
  for (std::size_t i = first + 1; i < x.size(); ++i) {
    lo = std::min(lo, x[i]);
    hi = std::max(hi, x[i]);
  }
  return {lo, hi};
}

template <class S>
double stuckFraction(const S& t, const S& slip, double stick_speed) {
  if (slip.empty()) return 0;
  const std::size_t n = t.size();
  double stuck = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = 0.5 * (t[std::min(i + 1, n - 1)] - t[i == 0 ? 0 : i - 1]);
    if (std::abs(slip[i]) < stick_speed) stuck += w;
  }
  return stuck / (t[n - 1] - t[0]);
}

template <class S>
OscillationSummary summarize(const S& t, const S& x, const S& slip_speed,
                             const OscillationOptions& options) {
  validate(t, x, slip_speed, options);
  OscillationSummary s;
  s.stuck_fraction = stuckFraction(t, slip_speed, options.stick_speed);

  const auto [x_lo, x_hi] = minMax(x, 0);
  const double delta =
      std::max(options.min_relative_prominence * (x_hi - x_lo), options.min_prominence);
  std::vector<Extremum> extrema = findExtrema(x, delta);
  for (Extremum& e : extrema) e = refine(t, x, e.index, e.is_max);

  const Integral<S> integral(t, x);
  for (std::size_t i = 0; i + 2 < extrema.size(); ++i) {
    const Extremum &a = extrema[i], &m = extrema[i + 1], &b = extrema[i + 2];
    if (!a.is_max) continue;  // extrema alternate, so m is a minimum and b a maximum
    s.cycles.push_back({a.t, b.t, std::max(a.x, b.x) - m.x, integral.mean(a.t, b.t)});
  }

  const std::size_t n_cycles = s.cycles.size();
  const std::size_t used = std::min<std::size_t>(options.last_cycles, n_cycles);
  s.cycles_used = static_cast<int>(used);
  if (used == 0) {
    const double t_back = t[t.size() - 1];
    const double t_half = 0.5 * (t[0] + t_back);
    const auto [lo, hi] = minMax(x, lowerBound(t, t_half));
    s.amplitude_pp = hi - lo;
    s.x_mean = integral.mean(t_half, t_back);
    return s;  // oscillating = false, period = time_to_98 = 0
  }
  const Cycle& first_used = s.cycles[n_cycles - used];
  const Cycle& last_used = s.cycles.back();
  double pp_sum = 0;
  for (std::size_t i = n_cycles - used; i < n_cycles; ++i) pp_sum += s.cycles[i].peak_to_peak;
  s.amplitude_pp = pp_sum / static_cast<double>(used);
  s.period = (last_used.t_end - first_used.t_start) / static_cast<double>(used);
  s.x_mean = integral.mean(first_used.t_start, last_used.t_end);
  for (const Cycle& c : s.cycles) {
    if (c.peak_to_peak >= 0.98 * s.amplitude_pp) {
      s.time_to_98 = c.t_end;
      break;
    }
  }
  s.oscillating = s.amplitude_pp > 0;
  return s;
}

}  // namespace

OscillationSummary summarizeOscillation(std::span<const double> t, std::span<const double> x,
                                        std::span<const double> slip_speed,
                                        const OscillationOptions& options) {
  return summarize(t, x, slip_speed, options);
}

OscillationSummary summarizeOscillation(const SampleSeries& t, const SampleSeries& x,
                                        const SampleSeries* slip_speed,
                                        const OscillationOptions& options) {
  return summarize(SeriesRef{&t}, SeriesRef{&x}, SeriesRef{slip_speed}, options);
}

double envelopeGrowthRate(const std::vector<Cycle>& cycles, double t0, double t1) {
  if (!(t0 <= t1)) throw std::invalid_argument("envelopeGrowthRate: need t0 <= t1");
  // Centered sums for a well-conditioned slope.
  double n = 0, sum_t = 0, sum_y = 0;
  for (const Cycle& c : cycles) {
    const double tm = 0.5 * (c.t_start + c.t_end);
    if (tm >= t0 && tm <= t1 && c.peak_to_peak > 0) {
      n += 1;
      sum_t += tm;
      sum_y += std::log(c.peak_to_peak);
    }
  }
  if (n < 2) {
    throw std::invalid_argument("envelopeGrowthRate: fewer than two cycles with mid-time in [" +
                                std::to_string(t0) + ", " + std::to_string(t1) + "]");
  }
  const double t_bar = sum_t / n, y_bar = sum_y / n;
  double stt = 0, sty = 0;
  for (const Cycle& c : cycles) {
    const double tm = 0.5 * (c.t_start + c.t_end);
    if (tm >= t0 && tm <= t1 && c.peak_to_peak > 0) {
      stt += (tm - t_bar) * (tm - t_bar);
      sty += (tm - t_bar) * (std::log(c.peak_to_peak) - y_bar);
    }
  }
  return sty / stt;
}

}  // namespace tribo::study
