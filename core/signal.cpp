#include "core/signal.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/cubic_spline.hpp"
#include "core/number_text.hpp"

namespace tribo {

namespace {

void checkFinite(const char* kind, const char* what, double x) {
  if (!std::isfinite(x))
    throw std::invalid_argument(std::string(kind) + ": " + what + " must be finite (got " +
                                numberText(x) + ")");
}

void checkIncreasing(const char* kind, const std::vector<std::pair<double, double>>& points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    checkFinite(kind, "time", points[i].first);
    checkFinite(kind, "value", points[i].second);
    if (i > 0 && !(points[i].first > points[i - 1].first))
      throw std::invalid_argument(std::string(kind) +
                                  ": times must be strictly increasing (point " +
                                  std::to_string(i) + " at t = " + numberText(points[i].first) +
                                  " follows t = " + numberText(points[i - 1].first) + ")");
  }
}

// The interval [t_i, t_{i+1}) holding t, for t_0 < t < t_n: i.
std::size_t segment(const std::vector<std::pair<double, double>>& points, double t) {
  const auto next = std::upper_bound(points.begin(), points.end(), t,
                                     [](double x, const auto& p) { return x < p.first; });
  return static_cast<std::size_t>(next - points.begin()) - 1;
}

}  // namespace

Signal Signal::constant(double value) {
  checkFinite("constant", "value", value);
  Signal s;
  s.a_ = value;
  return s;
}

Signal Signal::ramp(double rate, double start, double initial) {
  checkFinite("ramp", "rate", rate);
  checkFinite("ramp", "start", start);
  checkFinite("ramp", "initial", initial);
  Signal s;
  s.kind_ = Kind::kRamp;
  s.a_ = rate;
  s.b_ = start;
  s.c_ = initial;
  return s;
}

Signal Signal::step(double time, double before, double after) {
  checkFinite("step", "time", time);
  checkFinite("step", "before", before);
  checkFinite("step", "after", after);
  Signal s;
  s.kind_ = Kind::kStep;
  s.a_ = time;
  s.b_ = before;
  s.c_ = after;
  return s;
}

Signal Signal::smoothStep(double start, double before, double end, double after) {
  checkFinite("smooth_step", "start", start);
  checkFinite("smooth_step", "before", before);
  checkFinite("smooth_step", "end", end);
  checkFinite("smooth_step", "after", after);
  if (!(end > start))
    throw std::invalid_argument("smooth_step: end (" + numberText(end) + ") must be after start (" +
                                numberText(start) + ")");
  Signal s;
  s.kind_ = Kind::kSmoothStep;
  s.a_ = start;
  s.b_ = before;
  s.c_ = end;
  s.d_ = after;
  return s;
}

Signal Signal::table(std::vector<std::pair<double, double>> points) {
  if (points.empty()) throw std::invalid_argument("table: needs at least one [t, v] point");
  checkIncreasing("table", points);
  Signal s;
  s.kind_ = Kind::kTable;
  s.points_ = std::move(points);
  return s;
}

Signal Signal::cubicTable(std::vector<std::pair<double, double>> points) {
  if (points.size() < 2)
    throw std::invalid_argument("cubic table: needs at least 2 points, found " +
                                std::to_string(points.size()));
  checkIncreasing("cubic table", points);
  Signal s;
  s.kind_ = Kind::kCubicTable;
  s.curvatures_ = naturalSplineCurvatures(points);
  s.points_ = std::move(points);
  return s;
}

Signal Signal::function(std::function<double(double)> value,
                        std::function<double(double)> derivative, std::vector<double> breakpoints,
                        double time_scale) {
  if (!value) throw std::invalid_argument("function: needs a value callable");
  checkFinite("function", "time scale", time_scale);
  if (!(time_scale > 0.0))
    throw std::invalid_argument("function: time scale must be > 0 (got " + numberText(time_scale) +
                                ")");
  for (std::size_t i = 0; i < breakpoints.size(); ++i) {
    checkFinite("function", "breakpoint", breakpoints[i]);
    if (i > 0 && !(breakpoints[i] > breakpoints[i - 1]))
      throw std::invalid_argument("function: breakpoints must be strictly increasing");
  }
  Signal s;
  s.kind_ = Kind::kFunction;
  s.function_ = std::move(value);
  s.function_derivative_ = std::move(derivative);
  s.breaks_ = std::move(breakpoints);
  s.difference_step_ = 1e-3 * time_scale;
  return s;
}

double Signal::numericDerivative(double t) const {
  const double h = difference_step_;
  const auto f = [&](int k) { return function_(t + k * h); };
  // The breakpoint nearest t within (t - 2h, t + 2h], if any: stay on its right from it on
  // (forward formula), on its left before it (backward formula).
  const auto near = std::upper_bound(breaks_.begin(), breaks_.end(), t - 2.0 * h);
  if (near != breaks_.end() && *near <= t + 2.0 * h) {
    const double sign = t >= *near ? 1.0 : -1.0;
    const int k = t >= *near ? 1 : -1;
    return sign *
           (-25.0 * f(0) + 48.0 * f(k) - 36.0 * f(2 * k) + 16.0 * f(3 * k) - 3.0 * f(4 * k)) /
           (12.0 * h);
  }
  return (f(-2) - 8.0 * f(-1) + 8.0 * f(1) - f(2)) / (12.0 * h);
}

Signal Signal::sines(std::vector<Sine> terms) {
  for (const Sine& k : terms) {
    checkFinite("sines", "amplitude", k.amplitude);
    checkFinite("sines", "frequency", k.frequency);
    checkFinite("sines", "phase", k.phase);
    checkFinite("sines", "offset", k.offset);
    if (k.frequency < 0.0)
      throw std::invalid_argument("sines: frequency must be >= 0 (got " + numberText(k.frequency) +
                                  ")");
  }
  Signal s;
  s.kind_ = Kind::kSines;
  s.sines_ = std::move(terms);
  return s;
}

double Signal::value(double t) const {
  switch (kind_) {
    case Kind::kConstant:
      return a_;
    case Kind::kRamp:
      return t < b_ ? c_ : c_ + a_ * (t - b_);
    case Kind::kStep:
      return t < a_ ? b_ : c_;
    case Kind::kSmoothStep: {
      if (t <= a_) return b_;
      if (t >= c_) return d_;
      const double s = (t - a_) / (c_ - a_);
      return b_ + (d_ - b_) * s * s * (3.0 - 2.0 * s);
    }
    case Kind::kTable: {
      if (t <= points_.front().first) return points_.front().second;
      if (t >= points_.back().first) return points_.back().second;
      // First point after t: t lies in [p[i-1], p[i]).
      const auto next = std::upper_bound(points_.begin(), points_.end(), t,
                                         [](double x, const auto& p) { return x < p.first; });
      const auto& [t1, v1] = *next;
      const auto& [t0, v0] = *(next - 1);
      return v0 + (v1 - v0) * ((t - t0) / (t1 - t0));
    }
    case Kind::kCubicTable:
      if (t <= points_.front().first) return points_.front().second;
      if (t >= points_.back().first) return points_.back().second;
      return splineValue(points_, curvatures_, segment(points_, t), t);
    case Kind::kFunction:
      return function_(t);
    case Kind::kSines: {
      double v = 0.0;
      for (const Sine& k : sines_)
        v += k.offset + k.amplitude * std::sin(2.0 * std::numbers::pi * k.frequency * t + k.phase);
      return v;
    }
  }
  return 0.0;
}

double Signal::derivative(double t) const {
  switch (kind_) {
    case Kind::kConstant:
    case Kind::kStep:
      return 0.0;
    case Kind::kRamp:
      return t < b_ ? 0.0 : a_;
    case Kind::kSmoothStep: {
      if (t < a_ || t >= c_) return 0.0;
      const double width = c_ - a_;
      const double s = (t - a_) / width;
      return (d_ - b_) * 6.0 * s * (1.0 - s) / width;
    }
    case Kind::kTable: {
      if (t < points_.front().first || t >= points_.back().first) return 0.0;
      const auto next = std::upper_bound(points_.begin(), points_.end(), t,
                                         [](double x, const auto& p) { return x < p.first; });
      const auto& [t1, v1] = *next;
      const auto& [t0, v0] = *(next - 1);
      return (v1 - v0) / (t1 - t0);
    }
    case Kind::kCubicTable:
      if (t < points_.front().first || t >= points_.back().first) return 0.0;
      return splineSlope(points_, curvatures_, segment(points_, t), t);
    case Kind::kFunction:
      return function_derivative_ ? function_derivative_(t) : numericDerivative(t);
    case Kind::kSines: {
      double d = 0.0;
      for (const Sine& k : sines_) {
        const double w = 2.0 * std::numbers::pi * k.frequency;
        d += k.amplitude * w * std::cos(w * t + k.phase);
      }
      return d;
    }
  }
  return 0.0;
}

std::vector<double> Signal::breakpoints() const {
  switch (kind_) {
    case Kind::kRamp:
      return {b_};
    case Kind::kStep:
      return {a_};
    case Kind::kSmoothStep:
      return {a_, c_};
    case Kind::kFunction:
      return breaks_;
    case Kind::kTable:
    case Kind::kCubicTable: {
      std::vector<double> times;
      for (const auto& p : points_) times.push_back(p.first);
      return times;
    }
    case Kind::kConstant:
    case Kind::kSines:
      return {};
  }
  return {};
}

}  // namespace tribo
