// A scalar function of time for the inputs of a scene (applied loads, actuator targets, joint
// drives, surface velocities): its value, its first two derivatives, its integral from 0 and
// its breakpoints (the times where it or its derivative is not smooth).
//
//   constant     v(t) = c
//   ramp         v(t) = v0 for t < t0,  v0 + rate (t - t0) for t >= t0
//   step         v(t) = before for t < t_s,  after for t >= t_s  (derivative 0: the jump's
//                impulse is not represented)
//   smooth step  v(t) = h0 + (h1 - h0) s^2 (3 - 2 s),  s = (t - t0) / (t1 - t0) clipped to
//                [0, 1]: the cubic STEP function of MSC Adams (Adams Solver function
//                reference, "STEP"), continuous in value and slope
//   table        piecewise linear through (t_i, v_i), t_i strictly increasing, held at v_0
//                before t_0 and at v_n after t_n
//   cubic table  the natural cubic spline through (t_i, v_i) (core/cubic_spline.hpp: C2,
//                zero second derivative at both ends), held like the linear table outside
//   sines        v(t) = sum_k offset_k + A_k sin(2 pi f_k t + phi_k)   (f in Hz, phi in rad)
//   function     any callable v(t) (io/ builds one from an expression of t), with its
//                derivative when the caller has one, else the five-point central difference
//                f'(t) ~ (f(t-2h) - 8 f(t-h) + 8 f(t+h) - f(t+2h)) / (12 h), h = 1e-3 tau
//                (Abramowitz & Stegun, Handbook of Mathematical Functions, 25.3.6), whose
//                error is h^4 |f^(5)| / 30 plus rounding ~ 1.5 eps |f| / h + eps |t| |f'| / h.
//                For A sin(2 pi t / P) relative to its slope's amplitude that is
//                (2 pi h / P)^4 / 30 + 5e-17 P / h + 2e-16 |t| / h: 5e-11 at P = tau,
//                5e-7 at P = tau / 10. tau is the signal's time scale, default 1 ms: 1e-6 or
//                better for periods 1e-4 .. 1e3 s at |t| <= 1e3 s. Within 2 h of one of the
//                function's breakpoints the stencil is one-sided, of the same order (the
//                five-point forward or backward formula, A&S 25.3.6's companions), on the
//                side that keeps the derivative right-continuous.
// Derivatives at a breakpoint are right-continuous: the slope of what follows (a ramp's
// rate at t0, a table's next segment's slope at t_i, 0 at a table's last time).
// Second derivatives (a position drive's acceleration, core/joint_elements.hpp) are the
// kinds' closed forms (0 for constants, ramps, steps and linear tables; the smooth step's
// 6 (h1 - h0)(1 - 2 s) / (t1 - t0)^2; the spline's A M_i + B M_{i+1}; -A w^2 sin for sines),
// right-continuous like the first; a function's is the five-point difference of its
// derivative callable at h (as above), or without one the five-point second difference
//   f''(t) ~ (-f(t-2H) + 16 f(t-H) - 30 f(t) + 16 f(t+H) - f(t+2H)) / (12 H^2)
// at H = 1e-2 tau (A&S 25.3.24; one-sided near a breakpoint: (35 f0 - 104 f1 + 114 f2 -
// 56 f3 + 11 f4) / (12 H^2)), whose error relative to A w^2 for A sin(w t) is about
// (w H)^4 / 90 + eps (5 + w |t|) / (w H)^2: 2e-7 at a period of tau, 3e-8 (5 + w |t|) at
// 1000 tau (measured: 1.2e-7 at 1 ms, 2.2e-6 at 1 s over 10 s, default tau); a slow signal
// wants a longer tau, and a velocity drive needs none of it.
// Integrals from 0 to t (a velocity drive's position) are closed forms for every kind but
// the function, whose integral is adaptive Gauss-Kronrod (7-point Gauss, 15-point Kronrod:
// Piessens et al., QUADPACK, Springer 1983, ch. 2) on panels of width tau split at its
// breakpoints, each panel to 1e-12 of the integral of |f| over it (bisected at most 6 times:
// rounding in f's argument, eps |t| |f'|, bounds what more would give); the running sum at each
// panel's end is kept (shared by the signal's copies, behind a lock), so a run to time t
// evaluates f 15 t / tau times in all (up to 140 t / tau where rounding makes panels bisect:
// a sine of period tau over 25 s) and each call at most a panel's worth.
// A function signal is as thread-safe as its callable: Signal copies it (std::function),
// so a callable with mutable state must give each copy its own (io/time_expression.hpp).
// Not here: reading expressions or files (io/), honouring the breakpoints in the adaptive
// integrators (core/input_breakpoints.hpp, core/sundials_stepper.hpp; a fixed step steps over
// them), finding the kinks of a function by itself.
#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace tribo {

class Signal {
 public:
  enum class Kind { kConstant, kRamp, kStep, kSmoothStep, kTable, kCubicTable, kSines, kFunction };
  struct Sine {
    double amplitude = 0.0;  // A
    double frequency = 0.0;  // f [Hz]
    double phase = 0.0;      // phi [rad]
    double offset = 0.0;
  };

  Signal() = default;  // the constant 0
  // Each factory throws std::invalid_argument for a non-finite number, a smooth step whose
  // end is not after its start, a table with no point or with times not strictly increasing,
  // a negative frequency, a cubic table of fewer than 2 points, a function without a value
  // callable, with breakpoints not strictly increasing or a time scale that is not > 0.
  static Signal constant(double value);
  static Signal ramp(double rate, double start = 0.0, double initial = 0.0);
  static Signal step(double time, double before, double after);
  static Signal smoothStep(double start, double before, double end, double after);
  static Signal table(std::vector<std::pair<double, double>> points);
  static Signal cubicTable(std::vector<std::pair<double, double>> points);
  static Signal sines(std::vector<Sine> terms);
  // v(t) = value(t); derivative(t) when given, else the five-point difference with
  // h = 1e-3 time_scale (header comment). `breakpoints` are reported and keep the
  // difference on one side of them.
  static Signal function(std::function<double(double)> value,
                         std::function<double(double)> derivative = {},
                         std::vector<double> breakpoints = {}, double time_scale = 1e-3);

  Kind kind() const { return kind_; }
  // The terms of a sines signal (empty for the other kinds): what a forced orbit's period is
  // read from (study/orbit/forcing.hpp).
  const std::vector<Sine>& sineTerms() const { return sines_; }
  // True for the constant 0 (a load component that is not there).
  bool isZero() const { return kind_ == Kind::kConstant && a_ == 0.0; }
  double value(double t) const;
  double derivative(double t) const;
  double secondDerivative(double t) const;
  // int_0^t value(s) ds (negative for t < 0).
  double integral(double t) const;
  // Room for a function signal's running integral up to `until` (at most 2^22 panels), so
  // that integrals up to then do not allocate; nothing for the other kinds.
  void reserveIntegral(double until) const;
  // Times where the value or the derivative is not smooth, increasing (none for constants
  // and sines).
  std::vector<double> breakpoints() const;

 private:
  Kind kind_ = Kind::kConstant;
  // constant: a; ramp: a rate, b start, c initial; step: a time, b before, c after;
  // smooth step: a start, b before, c end, d after.
  double a_ = 0.0, b_ = 0.0, c_ = 0.0, d_ = 0.0;
  std::vector<std::pair<double, double>> points_;
  std::vector<double> curvatures_;  // cubic table: the spline's second derivative at each t_i
  std::vector<double> cumulative_;  // tables: int_{t_0}^{t_i} value
  std::vector<Sine> sines_;
  std::function<double(double)> function_, function_derivative_;
  std::vector<double> breaks_;    // function: its breakpoints
  double difference_step_ = 0.0;  // function: h of the five-point difference
  struct IntegralPanels;          // function: the running integral at each panel's end
  std::shared_ptr<IntegralPanels> panels_;

  double numericDerivative(double t) const;
  double numericSecondDerivative(double t) const;
  // int_a^b of the function, split at its breakpoints inside (a, b).
  double functionIntegral(double a, double b) const;
  double antiderivative(double t) const;  // closed kinds: some F with F' = value
};

// The largest magnitude(t) over [0, duration] at 1001 even samples and at the `breakpoints`
// inside it: the bound on an input's speed that the step estimate and the energy guard's
// scales use (a peak narrower than duration / 1000 between breakpoints may be missed).
template <class Magnitude>
double sampledBound(double duration, const std::vector<double>& breakpoints, Magnitude magnitude) {
  double bound = 0.0;
  for (int i = 0; i <= 1000; ++i) bound = std::max(bound, magnitude(duration * i / 1000.0));
  for (double t : breakpoints)
    if (t >= 0.0 && t <= duration) bound = std::max(bound, magnitude(t));
  return bound;
}

}  // namespace tribo
