// Smooth steps shared by the regularized friction laws: the haversine step used by RecurDyn
// and the cubic STEP used by MSC ADAMS (as in Roh & Yoo 2007; RecurDyn "Friction" and ADAMS "STEP"
// function reference pages). Both go from h0 at x0 to h1 at x1 with zero slope at both ends:
//
//   havsin(x, x0, h0, x1, h1) = h0 + (h1 - h0) * (1 - cos(pi * (x - x0) / (x1 - x0))) / 2
//   step(x, x0, h0, x1, h1)   = h0 + (h1 - h0) * s^2 * (3 - 2 s),  s = (x - x0) / (x1 - x0)
//
// for x0 < x < x1, h0 for x <= x0 and h1 for x >= x1. Each comes with its derivative d/dx.
// The Haversine/CubicStep structs precompute the 1/(x1 - x0) scale for laws that evaluate the
// same step many times; the free functions are the same formula for one-off use.
//
// What it does not do: check x0 < x1 (callers validate their parameters; with x0 >= x1 the
// result is h0 for x <= x0 and h1 above it), or smooth beyond the first derivative (the cubic
// STEP has a jump in the second derivative at both ends, the haversine too).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tribo::friction {

// Haversine step from (x0, h0) to (x1, h1), x0 < x1. Evaluated as
// h0 + (h1 - h0) sin^2(pi (x - x0) / (2 (x1 - x0))), the same function as (1 - cos) / 2
// without the cancellation near x0.
struct Haversine {
  Haversine(double x0_in, double h0_in, double x1_in, double h1_in)
      : x0(x0_in),
        x1(x1_in),
        h0(h0_in),
        h1(h1_in),
        half_phase_per_x(0.5 * std::numbers::pi / (x1 - x0)) {}

  double value(double x) const {
    if (x <= x0) return h0;
    if (x >= x1) return h1;
    const double s = std::sin(half_phase_per_x * (x - x0));
    return h0 + (h1 - h0) * (s * s);
  }
  // d value / dx; 0 outside (x0, x1) and at both ends.
  double derivative(double x) const {
    if (x <= x0 || x >= x1) return 0.0;
    return (h1 - h0) * half_phase_per_x * std::sin(2.0 * half_phase_per_x * (x - x0));
  }

  double x0, x1, h0, h1;
  double half_phase_per_x;  // pi / (2 (x1 - x0)) [rad per unit x]
};

// Cubic STEP from (x0, h0) to (x1, h1), x0 < x1.
struct CubicStep {
  CubicStep(double x0_in, double h0_in, double x1_in, double h1_in)
      : x0(x0_in), x1(x1_in), h0(h0_in), h1(h1_in), inv_width(1.0 / (x1 - x0)) {}

  double value(double x) const {
    if (x <= x0) return h0;
    if (x >= x1) return h1;
    const double s = (x - x0) * inv_width;
    // The blend s^2 (3 - 2 s) can round to just above 1 near x1; keep it in [0, 1] so the
    // step never overshoots h1 (maxCoefficient relies on it).
    return h0 + (h1 - h0) * std::min(s * s * (3.0 - 2.0 * s), 1.0);
  }
  // d value / dx; 0 outside (x0, x1) and at both ends.
  double derivative(double x) const {
    if (x <= x0 || x >= x1) return 0.0;
    const double s = (x - x0) * inv_width;
    return (h1 - h0) * 6.0 * s * (1.0 - s) * inv_width;
  }

  double x0, x1, h0, h1;
  double inv_width;  // 1 / (x1 - x0)
};

inline double havsin(double x, double x0, double h0, double x1, double h1) {
  return Haversine(x0, h0, x1, h1).value(x);
}
inline double havsinDerivative(double x, double x0, double h0, double x1, double h1) {
  return Haversine(x0, h0, x1, h1).derivative(x);
}
inline double step(double x, double x0, double h0, double x1, double h1) {
  return CubicStep(x0, h0, x1, h1).value(x);
}
inline double stepDerivative(double x, double x0, double h0, double x1, double h1) {
  return CubicStep(x0, h0, x1, h1).derivative(x);
}

}  // namespace tribo::friction
