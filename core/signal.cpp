#include "core/signal.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
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

// The running integral of a function signal at the ends of panels [k w, (k + 1) w].
struct Signal::IntegralPanels {
  double width = 0.0;
  std::mutex lock;
  std::vector<double> sums{0.0};  // sums[k] = int_0^{k w}
};

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
  s.cumulative_.assign(s.points_.size(), 0.0);
  for (std::size_t i = 1; i < s.points_.size(); ++i)
    s.cumulative_[i] = s.cumulative_[i - 1] + 0.5 * (s.points_[i].first - s.points_[i - 1].first) *
                                                  (s.points_[i].second + s.points_[i - 1].second);
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
  s.cumulative_.assign(s.points_.size(), 0.0);
  for (std::size_t i = 1; i < s.points_.size(); ++i)
    s.cumulative_[i] =
        s.cumulative_[i - 1] + splineIntegral(s.points_, s.curvatures_, i - 1, s.points_[i].first);
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
  s.panels_ = std::make_shared<IntegralPanels>();
  s.panels_->width = time_scale;
  return s;
}

namespace {

// The side a stencil of reach 4 h around t keeps to: 0 for the central formula, +1 to stay
// right of a breakpoint within (t - 2h, t + 2h] from it on, -1 to stay left of it before it.
int stencilSide(const std::vector<double>& breaks, double t, double h) {
  const auto near = std::upper_bound(breaks.begin(), breaks.end(), t - 2.0 * h);
  if (near == breaks.end() || *near > t + 2.0 * h) return 0;
  return t >= *near ? 1 : -1;
}

// f'(t) by the five-point formulas (header comment), central or one-sided.
double fivePointSlope(const std::function<double(double)>& fn, const std::vector<double>& breaks,
                      double t, double h) {
  const auto f = [&](int k) { return fn(t + k * h); };
  if (const int k = stencilSide(breaks, t, h); k != 0)
    return k * (-25.0 * f(0) + 48.0 * f(k) - 36.0 * f(2 * k) + 16.0 * f(3 * k) - 3.0 * f(4 * k)) /
           (12.0 * h);
  return (f(-2) - 8.0 * f(-1) + 8.0 * f(1) - f(2)) / (12.0 * h);
}

// f''(t) by the five-point second differences (header comment), central or one-sided.
double fivePointCurvature(const std::function<double(double)>& fn,
                          const std::vector<double>& breaks, double t, double h) {
  const auto f = [&](int k) { return fn(t + k * h); };
  if (const int k = stencilSide(breaks, t, h); k != 0)
    return (35.0 * f(0) - 104.0 * f(k) + 114.0 * f(2 * k) - 56.0 * f(3 * k) + 11.0 * f(4 * k)) /
           (12.0 * h * h);
  return (-f(-2) + 16.0 * f(-1) - 30.0 * f(0) + 16.0 * f(1) - f(2)) / (12.0 * h * h);
}

// Gauss-Kronrod 7-15 on [a, b] (QUADPACK's qk15 nodes and weights, Piessens et al. 1983),
// bisected while the Gauss and Kronrod sums differ by more than 1e-12 of the integral of
// |f|, down to 2^-6 of the interval (where rounding in f's argument, eps |t| |f'|, is above
// that tolerance, as for sin(w t) at w t ~ 1e5, more bisection would not help).
double kronrod(const std::function<double(double)>& f, double a, double b, int depth = 0) {
  static constexpr double x[8] = {
      0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
      0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
      0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
      0.207784955007898467600689403773245, 0.0};
  static constexpr double wk[8] = {
      0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
      0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
      0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
      0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
  // The 7-point Gauss weights, at x[1], x[3], x[5] and x[7].
  static constexpr double wg[4] = {
      0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
      0.381830050505118944950369775488975, 0.417959183673469387755102040816327};
  const double centre = 0.5 * (a + b), half = 0.5 * (b - a);
  const double fc = f(centre);
  double k15 = wk[7] * fc, g7 = wg[3] * fc, absolute = wk[7] * std::abs(fc);
  for (int i = 0; i < 7; ++i) {
    const double f1 = f(centre - half * x[i]), f2 = f(centre + half * x[i]);
    k15 += wk[i] * (f1 + f2);
    absolute += wk[i] * (std::abs(f1) + std::abs(f2));
    if (i % 2 == 1) g7 += wg[i / 2] * (f1 + f2);
  }
  if (std::abs(k15 - g7) <= 1e-12 * absolute || depth >= 6) return k15 * half;
  return kronrod(f, a, centre, depth + 1) + kronrod(f, centre, b, depth + 1);
}

}  // namespace

double Signal::numericDerivative(double t) const {
  return fivePointSlope(function_, breaks_, t, difference_step_);
}

double Signal::numericSecondDerivative(double t) const {
  if (function_derivative_)
    return fivePointSlope(function_derivative_, breaks_, t, difference_step_);
  return fivePointCurvature(function_, breaks_, t, 10.0 * difference_step_);
}

double Signal::functionIntegral(double a, double b) const {
  if (b < a) return -functionIntegral(b, a);
  double sum = 0.0, from = a;
  for (auto it = std::upper_bound(breaks_.begin(), breaks_.end(), a);
       it != breaks_.end() && *it < b; ++it) {
    sum += kronrod(function_, from, *it);
    from = *it;
  }
  return sum + (b > from ? kronrod(function_, from, b) : 0.0);
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

double Signal::secondDerivative(double t) const {
  switch (kind_) {
    case Kind::kConstant:
    case Kind::kStep:
    case Kind::kRamp:
    case Kind::kTable:
      return 0.0;
    case Kind::kSmoothStep: {
      if (t < a_ || t >= c_) return 0.0;
      const double width = c_ - a_;
      const double s = (t - a_) / width;
      return (d_ - b_) * 6.0 * (1.0 - 2.0 * s) / (width * width);
    }
    case Kind::kCubicTable:
      if (t < points_.front().first || t >= points_.back().first) return 0.0;
      return splineCurvature(points_, curvatures_, segment(points_, t), t);
    case Kind::kFunction:
      return numericSecondDerivative(t);
    case Kind::kSines: {
      double d = 0.0;
      for (const Sine& k : sines_) {
        const double w = 2.0 * std::numbers::pi * k.frequency;
        d -= k.amplitude * w * w * std::sin(w * t + k.phase);
      }
      return d;
    }
  }
  return 0.0;
}

double Signal::antiderivative(double t) const {
  switch (kind_) {
    case Kind::kConstant:
      return a_ * t;
    case Kind::kRamp: {
      const double after = std::max(0.0, t - b_);
      return c_ * t + 0.5 * a_ * after * after;
    }
    case Kind::kStep:
      return b_ * t + (c_ - b_) * std::max(0.0, t - a_);
    case Kind::kSmoothStep: {
      const double width = c_ - a_;
      double shape = 0.0;  // int of s^2 (3 - 2 s) from the start, in time
      if (t >= c_) {
        shape = 0.5 * width + (t - c_);
      } else if (t > a_) {
        const double s = (t - a_) / width;
        shape = width * s * s * s * (1.0 - 0.5 * s);
      }
      return b_ * t + (d_ - b_) * shape;
    }
    case Kind::kTable:
    case Kind::kCubicTable: {
      const auto& [t0, v0] = points_.front();
      const auto& [tn, vn] = points_.back();
      if (t <= t0) return v0 * (t - t0);
      if (t >= tn) return cumulative_.back() + vn * (t - tn);
      const std::size_t i = segment(points_, t);
      if (kind_ == Kind::kCubicTable)
        return cumulative_[i] + splineIntegral(points_, curvatures_, i, t);
      return cumulative_[i] + 0.5 * (t - points_[i].first) * (points_[i].second + value(t));
    }
    case Kind::kSines: {
      double v = 0.0;
      for (const Sine& k : sines_) {
        const double w = 2.0 * std::numbers::pi * k.frequency;
        v += k.offset * t + (w > 0.0 ? -k.amplitude * std::cos(w * t + k.phase) / w
                                     : k.amplitude * std::sin(k.phase) * t);
      }
      return v;
    }
    case Kind::kFunction:
      break;
  }
  return 0.0;
}

void Signal::reserveIntegral(double until) const {
  if (kind_ != Kind::kFunction || !(until > 0.0)) return;
  const double panels = std::min(std::ceil(until / panels_->width) + 2.0, 4194304.0);
  const std::lock_guard<std::mutex> hold(panels_->lock);
  panels_->sums.reserve(static_cast<std::size_t>(panels));
}

double Signal::integral(double t) const {
  if (kind_ != Kind::kFunction) return antiderivative(t) - antiderivative(0.0);
  if (t <= 0.0) return -functionIntegral(t, 0.0);
  IntegralPanels& p = *panels_;
  // Panels up to 2^24 (beyond: the rest is integrated panel by panel at each call).
  constexpr double kMostPanels = 16777216.0;
  const double whole = std::min(std::floor(t / p.width), kMostPanels);
  const auto k = static_cast<std::size_t>(whole);
  double sum = 0.0;
  {
    const std::lock_guard<std::mutex> hold(p.lock);
    while (p.sums.size() <= k) {
      const double j = static_cast<double>(p.sums.size() - 1);
      p.sums.push_back(p.sums.back() + functionIntegral(j * p.width, (j + 1.0) * p.width));
    }
    sum = p.sums[k];
  }
  double from = whole * p.width;
  for (; from + p.width < t; from += p.width) sum += functionIntegral(from, from + p.width);
  return sum + functionIntegral(from, t);
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
