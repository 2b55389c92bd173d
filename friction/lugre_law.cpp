#include "friction/lugre_law.hpp"

#include <algorithm>
#include <cmath>

#include "friction/parameter_check.hpp"

namespace tribo::friction {

LuGreLaw::LuGreLaw(const LuGreParams& p) : params_(p) {
  ParameterCheck("lugre").bristle(p.sigma0, p.sigma1, p.sigma2, p.mu_c, p.mu_s, p.v_s);
}

double LuGreLaw::g(double v) const {
  const double r = v / params_.v_s;
  if (r * r > 745.0) return params_.mu_c;  // exp underflows to 0 (and glibc is slow there)
  return params_.mu_c + (params_.mu_s - params_.mu_c) * std::exp(-r * r);
}

double LuGreLaw::coefficient(double v) const {
  const double steady = g(std::abs(v)) + params_.sigma2 * std::abs(v);
  return v > 0.0 ? steady : v < 0.0 ? -steady : 0.0;
}

void LuGreLaw::coefficientsAt(std::span<const double> v, std::span<double> mu) const {
  coefficientsOf(*this, v, mu);
}

double LuGreLaw::slope(double v) const {
  const double r = std::abs(v) / params_.v_s;
  const double dg = -(params_.mu_s - params_.mu_c) * 2.0 * r / params_.v_s * std::exp(-r * r);
  return dg + params_.sigma2;
}

double LuGreLaw::maxCoefficient(double v_max) const {
  return params_.mu_s + (2.0 * params_.sigma1 + params_.sigma2) * v_max;
}

void LuGreLaw::rate(const double* z, const Eigen::Vector3d& slip, double, double* zdot) const {
  const double v = slip.norm();
  const double k = params_.sigma0 * v / g(v);
  for (int i = 0; i < 3; ++i) zdot[i] = slip[i] - k * z[i];
}

Eigen::Vector3d LuGreLaw::force(const double* z, const double* zdot, const Eigen::Vector3d& slip,
                                double fn, double* mu_out) const {
  const Eigen::Vector3d per_load = params_.sigma0 * Eigen::Vector3d(z[0], z[1], z[2]) +
                                   params_.sigma1 * Eigen::Vector3d(zdot[0], zdot[1], zdot[2]) +
                                   params_.sigma2 * slip;
  if (mu_out != nullptr) *mu_out = fn > 0.0 ? per_load.norm() : 0.0;  // |F_t| / fn, 0 unloaded
  return -fn * per_load;
}

void LuGreLaw::stableStep(double* z, const Eigen::Vector3d& slip, double, double h) const {
  const double v = slip.norm();
  if (v == 0.0) return;  // dz/dt = 0 at rest
  const double k = params_.sigma0 * v / g(v);
  // z + (z_ss - z)(1 - exp(-k h)), z_ss = slip / k; expm1 keeps small k h accurate.
  const double fraction = -std::expm1(-k * h);
  for (int i = 0; i < 3; ++i) z[i] += (slip[i] / k - z[i]) * fraction;
}

double LuGreLaw::stateStiffness(double v_max) const {
  return params_.sigma0 * v_max / std::min(params_.mu_c, params_.mu_s);
}

}  // namespace tribo::friction
