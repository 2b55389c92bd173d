// A measured friction curve mu(v) given as a table of points (scene name "tabulated"; the
// points come from a CSV file, io/friction_curve.hpp). Between points the curve is the
// monotone piecewise-cubic Hermite interpolant of Fritsch & Carlson, "Monotone Piecewise
// Cubic Interpolation", SIAM J. Numer. Anal. 17(2):238-246 (1980), with the slopes of
// Fritsch & Butland (1984): interior slopes are the weighted harmonic mean of the adjacent
// secants, zero where the data turn (a Stribeck peak), so the curve adds no wiggle and never
// overshoots the measured values; end slopes by the shape-preserving three-point formula.
// It is C1 between the first and the last point.
//
//   speeds:  0 <= v_0 < v_1 < ... < v_n (at least 2 points), coefficients mu_i >= 0, finite;
//   origin:  a table starting above v = 0 is joined to (0, 0), which becomes its first point
//            (a regularization whose transition speed is the first measured speed); a table
//            starting at v = 0 must have mu = 0 there (the law is odd and continuous);
//   beyond:  past the last point mu stays at its last value (slope 0): measure far enough;
//   odd:     mu(-v) = -mu(v).
// The stick speed (for stuck-fraction statistics) is the speed of the largest coefficient,
// or, when the curve rises to its last point, the first positive speed of the table.
// Not here: reading files (io/), fitting a law to noisy data (the table is taken as exact),
// extrapolation trends past the last point.
#pragma once

#include <string_view>
#include <vector>

#include "friction/friction_law.hpp"

namespace tribo::friction {

// A rule broken by one point of the table; `point` is its 0-based index in the table given.
class TabulatedPointError : public FrictionParameterError {
 public:
  TabulatedPointError(std::size_t point, const std::string& what)
      : FrictionParameterError(what), point(point) {}
  std::size_t point;
};

class TabulatedLaw final : public FrictionLaw {
 public:
  // Throws TabulatedPointError naming the point that breaks a rule above, and
  // FrictionParameterError for too few points.
  TabulatedLaw(std::vector<double> speeds, std::vector<double> coefficients);

  double coefficient(double v) const override;
  void coefficientsAt(std::span<const double> v, std::span<double> mu) const override;
  double slope(double v) const override;
  double maxCoefficient(double v_max) const override;
  double stickSpeed() const override { return stick_speed_; }
  std::vector<double> breakpoints() const override;
  std::string_view name() const override { return "tabulated"; }

  const std::vector<double>& speeds() const { return v_; }  // after joining the origin
  const std::vector<double>& coefficients() const { return mu_; }

 private:
  // mu and d mu / dv at v >= 0.
  void evaluate(double v, double& mu, double& dmu) const;

  std::vector<double> v_, mu_, slope_;  // points and Hermite slopes at them
  double stick_speed_ = 0.0;
};

}  // namespace tribo::friction
