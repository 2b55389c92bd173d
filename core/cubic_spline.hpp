// The natural cubic spline through points (t_i, v_i), t_i strictly increasing, n >= 2: the
// C2 piecewise cubic with zero second derivative at t_0 and t_n, for the cubic table signal
// (core/signal.hpp). On [t_i, t_{i+1}], h = t_{i+1} - t_i, A = (t_{i+1} - t) / h, B = 1 - A:
//   s(t)  = A v_i + B v_{i+1} + ((A^3 - A) M_i + (B^3 - B) M_{i+1}) h^2 / 6
//   s'(t) = (v_{i+1} - v_i) / h - (3 A^2 - 1) h M_i / 6 + (3 B^2 - 1) h M_{i+1} / 6
//   s''(t) = A M_i + B M_{i+1}
//   int_{t_i}^t s = h ((1 - A^2) v_i + B^2 v_{i+1}) / 2
//                   + h^3 (M_i ((1 - A^4) / 4 - (1 - A^2) / 2) + M_{i+1} (B^4 / 4 - B^2 / 2)) / 6
//   (over the whole interval: h (v_i + v_{i+1}) / 2 - h^3 (M_i + M_{i+1}) / 24)
// with the second derivatives M_i solving, for 0 < i < n,
//   h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1}
//       = 6 ((v_{i+1} - v_i) / h_i - (v_i - v_{i-1}) / h_{i-1}),   M_0 = M_n = 0
// (Press et al., Numerical Recipes, 3rd ed., section 3.3; Burden & Faires, Numerical
// Analysis, algorithm 3.4), a diagonally dominant tridiagonal system solved by the Thomas
// algorithm. It reproduces a linear function exactly (all M_i = 0), not a general cubic
// (whose second derivative is not zero at the ends). Two points give the straight line.
// Not here: other end conditions (clamped, not-a-knot), monotonicity (it may overshoot
// between points), extrapolation (the signal holds the end values).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace tribo {

// M_i for each point (see above); points as described, not checked here.
std::vector<double> naturalSplineCurvatures(const std::vector<std::pair<double, double>>& points);

// s(t) and s'(t) on the interval [t_i, t_{i+1}] (i + 1 < points.size()).
double splineValue(const std::vector<std::pair<double, double>>& points,
                   const std::vector<double>& curvatures, std::size_t i, double t);
double splineSlope(const std::vector<std::pair<double, double>>& points,
                   const std::vector<double>& curvatures, std::size_t i, double t);
// s''(t) and int_{t_i}^t s on the same interval.
double splineCurvature(const std::vector<std::pair<double, double>>& points,
                       const std::vector<double>& curvatures, std::size_t i, double t);
double splineIntegral(const std::vector<std::pair<double, double>>& points,
                      const std::vector<double>& curvatures, std::size_t i, double t);

}  // namespace tribo
