#include "friction/dahl_law.hpp"

#include <algorithm>
#include <cmath>

#include "friction/parameter_check.hpp"

namespace tribo::friction {

DahlLaw::DahlLaw(const DahlParams& p) : params_(p) {
  const ParameterCheck check("dahl");
  check.finite({{"sigma0", p.sigma0}, {"mu_c", p.mu_c}, {"alpha", p.alpha}});
  check.require(p.sigma0 > 0.0, "sigma0 must be > 0 [1/m]", p.sigma0);
  check.require(p.mu_c > 0.0, "mu_c must be > 0", p.mu_c);
  check.require(p.alpha >= 1.0, "alpha must be >= 1", p.alpha);
}

double DahlLaw::coefficient(double v) const {
  if (std::isnan(v)) return v;
  return v > 0.0 ? params_.mu_c : v < 0.0 ? -params_.mu_c : 0.0;
}

void DahlLaw::coefficientsAt(std::span<const double> v, std::span<double> mu) const {
  coefficientsOf(*this, v, mu);
}

double DahlLaw::slope(double v) const { return std::isnan(v) ? v : 0.0; }

double DahlLaw::maxCoefficient(double) const { return params_.mu_c; }

void DahlLaw::rate(const double* z, const Eigen::Vector3d& slip, double, double* zdot) const {
  const double v = slip.norm();
  if (v == 0.0) {
    zdot[0] = zdot[1] = zdot[2] = 0.0;
    return;
  }
  const Eigen::Vector3d e =
      slip / v - (params_.sigma0 / params_.mu_c) * Eigen::Vector3d(z[0], z[1], z[2]);
  const double scale = params_.alpha == 1.0 ? v : v * std::pow(e.norm(), params_.alpha - 1.0);
  for (int i = 0; i < 3; ++i) zdot[i] = scale * e[i];
}

Eigen::Vector3d DahlLaw::force(const double* z, const double*, const Eigen::Vector3d&, double fn,
                               double* mu_out) const {
  const Eigen::Vector3d per_load = params_.sigma0 * Eigen::Vector3d(z[0], z[1], z[2]);
  if (mu_out != nullptr) *mu_out = fn > 0.0 ? per_load.norm() : 0.0;
  return -fn * per_load;
}

void DahlLaw::stableStep(double* z, const Eigen::Vector3d& slip, double, double h) const {
  const double v = slip.norm();
  if (v == 0.0 || h <= 0.0) return;  // dz/dt = 0 at rest
  const double to_e = params_.sigma0 / params_.mu_c;
  const Eigen::Vector3d direction = slip / v;
  const Eigen::Vector3d e = direction - to_e * Eigen::Vector3d(z[0], z[1], z[2]);
  const double x = to_e * v * h;  // k h
  double ratio = 0.0;             // |e(h)| / |e|
  if (params_.alpha == 1.0) {
    ratio = std::exp(-x);
  } else {
    // (1 + (alpha - 1) y)^(-1 / (alpha - 1)) through log1p: accurate as alpha -> 1.
    const double am1 = params_.alpha - 1.0;
    const double y = x * std::pow(e.norm(), am1);
    ratio = std::exp(-std::log1p(am1 * y) / am1);
  }
  const Eigen::Vector3d z_new = (direction - ratio * e) / to_e;
  for (int i = 0; i < 3; ++i) z[i] = z_new[i];
}

double DahlLaw::stateStiffness(double v_max) const {
  return params_.sigma0 * std::abs(v_max) * params_.alpha * std::pow(2.0, params_.alpha - 1.0) /
         params_.mu_c;
}

}  // namespace tribo::friction
