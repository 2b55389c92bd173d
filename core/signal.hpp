// A scalar function of time for applied loads (core/applied_load.hpp): its value, its
// derivative and its breakpoints (the times where it or its derivative is not smooth).
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
//   sines        v(t) = sum_k offset_k + A_k sin(2 pi f_k t + phi_k)   (f in Hz, phi in rad)
// Derivatives at a breakpoint are right-continuous: the slope of what follows (a ramp's
// rate at t0, a table's next segment's slope at t_i, 0 at a table's last time).
// Not here: expressions of t, tables read from files, splines; honouring the breakpoints in
// the adaptive integrators (a fixed step steps over them).
#pragma once

#include <utility>
#include <vector>

namespace tribo {

class Signal {
 public:
  enum class Kind { kConstant, kRamp, kStep, kSmoothStep, kTable, kSines };
  struct Sine {
    double amplitude = 0.0;  // A
    double frequency = 0.0;  // f [Hz]
    double phase = 0.0;      // phi [rad]
    double offset = 0.0;
  };

  Signal() = default;  // the constant 0
  // Each factory throws std::invalid_argument for a non-finite number, a smooth step whose
  // end is not after its start, a table with no point or with times not strictly increasing,
  // a negative frequency.
  static Signal constant(double value);
  static Signal ramp(double rate, double start = 0.0, double initial = 0.0);
  static Signal step(double time, double before, double after);
  static Signal smoothStep(double start, double before, double end, double after);
  static Signal table(std::vector<std::pair<double, double>> points);
  static Signal sines(std::vector<Sine> terms);

  Kind kind() const { return kind_; }
  // True for the constant 0 (a load component that is not there).
  bool isZero() const { return kind_ == Kind::kConstant && a_ == 0.0; }
  double value(double t) const;
  double derivative(double t) const;
  // Times where the value or the derivative is not smooth, increasing (none for constants
  // and sines).
  std::vector<double> breakpoints() const;

 private:
  Kind kind_ = Kind::kConstant;
  // constant: a; ramp: a rate, b start, c initial; step: a time, b before, c after;
  // smooth step: a start, b before, c end, d after.
  double a_ = 0.0, b_ = 0.0, c_ = 0.0, d_ = 0.0;
  std::vector<std::pair<double, double>> points_;
  std::vector<Sine> sines_;
};

}  // namespace tribo
