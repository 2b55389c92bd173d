#include "friction/rate_state_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "friction/parameter_check.hpp"

namespace tribo::friction {
namespace {

// asinh(exp(L)) without overflow: ln(2 y) + 1 / (4 y^2) for y = exp(L); beyond L = 20 the
// second term (< 1.1e-18) is below the rounding of L itself (>= 20 * 1.1e-16) and is dropped.
double asinhExp(double log_y) {
  if (log_y > 20.0) return log_y + std::numbers::ln2;
  return std::asinh(std::exp(log_y));
}

// ln(exp(x) + exp(y)).
double logAddExp(double x, double y) {
  const double hi = std::max(x, y);
  if (hi == -std::numeric_limits<double>::infinity()) return hi;
  return hi + std::log1p(std::exp(std::min(x, y) - hi));
}

}  // namespace

RateStateLaw::RateStateLaw(const RateStateParams& p) : params_(p) {
  const ParameterCheck check("rate_state");
  check.finite(
      {{"mu0", p.mu0}, {"a", p.a}, {"b", p.b}, {"d_c", p.d_c}, {"v0", p.v0}, {"theta0", p.theta0}});
  check.require(p.mu0 >= 0.0, "mu0 must be >= 0", p.mu0);
  check.require(p.a > 0.0, "a must be > 0", p.a);
  check.require(p.b >= 0.0, "b must be >= 0", p.b);
  check.require(p.d_c > 0.0, "d_c must be > 0 [m]", p.d_c);
  check.require(p.v0 > 0.0, "v0 must be > 0 [m/s]", p.v0);
  check.require(p.theta0 >= 0.0, "theta0 must be > 0 [s] (0: the default d_c / v0)", p.theta0);
  psi0_ = p.theta0 == 0.0 ? 0.0 : psiOf(p.theta0);
  check.require(std::isfinite(psi0_), "theta0 must give a finite ln(v0 theta0 / d_c)", p.theta0);
}

double RateStateLaw::psiOf(double theta) const {
  return std::log(params_.v0 / params_.d_c) + std::log(theta);
}

double RateStateLaw::thetaOf(double psi) const {
  return std::exp(psi + std::log(params_.d_c / params_.v0));
}

double RateStateLaw::mu(double v, double psi) const {
  if (!(v > 0.0)) return std::isnan(v) ? v : 0.0;
  const double log_y =
      std::log(v / (2.0 * params_.v0)) + (params_.mu0 + params_.b * psi) / params_.a;
  return params_.a * asinhExp(log_y);
}

double RateStateLaw::coefficient(double v) const {
  const double m = mu(std::abs(v), std::log(params_.v0) - std::log(std::abs(v)));
  return v < 0.0 ? -m : m;
}

void RateStateLaw::coefficientsAt(std::span<const double> v, std::span<double> mu) const {
  coefficientsOf(*this, v, mu);
}

double RateStateLaw::slope(double v) const {
  const double speed = std::abs(v);
  const double a = params_.a;
  const double b = params_.b;
  if (std::isnan(v)) return v;
  if (speed == 0.0) {  // limit from v > 0
    if (b > a) return -std::numeric_limits<double>::infinity();
    if (b == a) return 0.0;
    if (b > 0.0) return std::numeric_limits<double>::infinity();
    return a * std::exp(params_.mu0 / a) / (2.0 * params_.v0);
  }
  // L = mu0 / a - ln 2 + (1 - b / a) ln(v / v0); d asinh(e^L) / dL = 1 / sqrt(1 + e^(-2 L)).
  const double log_y =
      params_.mu0 / a - std::log(2.0) + (1.0 - b / a) * std::log(speed / params_.v0);
  return (a - b) / (speed * std::sqrt(1.0 + std::exp(-2.0 * log_y)));
}

double RateStateLaw::directSlope(double v) const {
  const double speed = std::abs(v);
  const double a = params_.a;
  const double b = params_.b;
  if (std::isnan(v)) return v;
  if (speed == 0.0) {
    return b > 0.0 ? std::numeric_limits<double>::infinity()
                   : a * std::exp(params_.mu0 / a) / (2.0 * params_.v0);
  }
  // At psi = ln(v0 / v) the arcsinh's argument has the log L of slope(); d asinh(e^L) / dv at
  // frozen psi is (1 / v) / sqrt(1 + e^(-2 L)).
  const double log_y =
      params_.mu0 / a - std::log(2.0) + (1.0 - b / a) * std::log(speed / params_.v0);
  return a / (speed * std::sqrt(1.0 + std::exp(-2.0 * log_y)));
}

double RateStateLaw::maxCoefficient(double v_max) const {
  const double psi_max = logAddExp(psi0_, std::log(params_.v0 * kBoundAge / params_.d_c));
  return mu(std::abs(v_max), psi_max);
}

void RateStateLaw::rate(const double* z, const Eigen::Vector3d& slip, double, double* zdot) const {
  const double v = slip.norm();
  const double psi = z[0];
  if (params_.evolution == RateStateEvolution::kAging) {
    zdot[0] = (params_.v0 * std::exp(-psi) - v) / params_.d_c;
  } else {
    zdot[0] = v == 0.0 ? 0.0 : -(v / params_.d_c) * (psi + std::log(v / params_.v0));
  }
}

Eigen::Vector3d RateStateLaw::force(const double* z, const double*, const Eigen::Vector3d& slip,
                                    double fn, double* mu_out) const {
  const double v = slip.norm();
  const double m = mu(v, z[0]);
  if (mu_out != nullptr) *mu_out = fn > 0.0 ? m : 0.0;
  if (v == 0.0) return Eigen::Vector3d::Zero();
  return (-fn * m / v) * slip;
}

void RateStateLaw::stableStep(double* z, const Eigen::Vector3d& slip, double, double h) const {
  if (!(h > 0.0)) return;
  const double v = slip.norm();
  const double x = v * h / params_.d_c;  // slip over the step in units of d_c
  double& psi = z[0];
  if (params_.evolution == RateStateEvolution::kAging) {
    // theta(h) = theta e^-x + (d_c / v)(1 - e^-x), or theta + h at rest; in psi:
    // v0 theta(h) / d_c = e^(psi - x) + (v0 / v)(1 - e^-x).
    if (v == 0.0) {
      psi = logAddExp(psi, std::log(params_.v0 * h / params_.d_c));
    } else {
      psi = logAddExp(psi - x, std::log(params_.v0 / v) + std::log(-std::expm1(-x)));
    }
  } else if (v > 0.0) {
    const double steady = std::log(params_.v0 / v);
    psi = steady + (psi - steady) * std::exp(-x);
  }
}

double RateStateLaw::stateStiffness(double v_max) const {
  const double v = std::abs(v_max);
  if (params_.evolution == RateStateEvolution::kSlip) return v / params_.d_c;
  return std::max(params_.v0 * std::exp(-psi0_), v) / params_.d_c;
}

}  // namespace tribo::friction
