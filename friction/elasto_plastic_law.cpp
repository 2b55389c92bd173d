#include "friction/elasto_plastic_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "friction/parameter_check.hpp"

namespace tribo::friction {

ElastoPlasticLaw::ElastoPlasticLaw(const ElastoPlasticParams& p)
    : params_(p), g_{p.mu_c, p.mu_s, p.v_s, 2.0}, z_ba_(p.z_ba_fraction * p.mu_c / p.sigma0) {
  const ParameterCheck check("elasto_plastic");
  check.bristle(p.sigma0, p.sigma1, p.sigma2, p.mu_c, p.mu_s, p.v_s);
  check.finite({{"z_ba_fraction", p.z_ba_fraction}});
  check.require(p.z_ba_fraction > 0.0 && p.z_ba_fraction < 1.0,
                "z_ba_fraction must be in (0, 1) (break-away below the Coulomb deflection)",
                p.z_ba_fraction);
}

double ElastoPlasticLaw::coefficient(double v) const {
  if (std::isnan(v)) return v;
  const double steady = g_.value(v) + params_.sigma2 * std::abs(v);
  return v > 0.0 ? steady : v < 0.0 ? -steady : 0.0;
}

void ElastoPlasticLaw::coefficientsAt(std::span<const double> v, std::span<double> mu) const {
  coefficientsOf(*this, v, mu);
}

double ElastoPlasticLaw::slope(double v) const {
  return g_.derivative(std::abs(v)) + params_.sigma2;  // even; NaN stays NaN
}

double ElastoPlasticLaw::maxCoefficient(double v_max) const {
  const double v = std::abs(v_max);
  return params_.mu_s + params_.sigma1 * (1.0 + params_.mu_s / params_.mu_c) * v +
         params_.sigma2 * v;
}

double ElastoPlasticLaw::alpha(const Eigen::Vector3d& z, const Eigen::Vector3d& slip) const {
  return alphaAt(z, slip, g_.value(slip.norm()));
}

double ElastoPlasticLaw::alphaAt(const Eigen::Vector3d& z, const Eigen::Vector3d& slip,
                                 double g) const {
  if (!(z.dot(slip) > 0.0)) return 0.0;
  const double n = z.norm();
  if (n <= z_ba_) return 0.0;
  const double z_ss = g / params_.sigma0;
  if (n >= z_ss) return 1.0;
  return 0.5 + 0.5 * std::sin(std::numbers::pi * (n - 0.5 * (z_ss + z_ba_)) / (z_ss - z_ba_));
}

void ElastoPlasticLaw::rate(const double* z, const Eigen::Vector3d& slip, double,
                            double* zdot) const {
  const Eigen::Vector3d zv(z[0], z[1], z[2]);
  const double v = slip.norm();
  const double g = g_.value(v);
  const double a = alphaAt(zv, slip, g);
  const double k = a == 0.0 ? 0.0 : a * params_.sigma0 * v / g;
  for (int i = 0; i < 3; ++i) zdot[i] = slip[i] - k * z[i];
}

Eigen::Vector3d ElastoPlasticLaw::force(const double* z, const double* zdot,
                                        const Eigen::Vector3d& slip, double fn,
                                        double* mu_out) const {
  const Eigen::Vector3d per_load = params_.sigma0 * Eigen::Vector3d(z[0], z[1], z[2]) +
                                   params_.sigma1 * Eigen::Vector3d(zdot[0], zdot[1], zdot[2]) +
                                   params_.sigma2 * slip;
  if (mu_out != nullptr) *mu_out = fn > 0.0 ? per_load.norm() : 0.0;
  return -fn * per_load;
}

Eigen::Vector3d ElastoPlasticLaw::frozenAlpha(const Eigen::Vector3d& z, const Eigen::Vector3d& slip,
                                              double ak, double t) {
  const double x = ak * t;
  if (x == 0.0) return z + t * slip;
  // (1 - e^-x) / (a k) = t (1 - e^-x) / x, through expm1 for small x.
  return std::exp(-x) * z + (t * (-std::expm1(-x)) / x) * slip;
}

void ElastoPlasticLaw::stableStep(double* z, const Eigen::Vector3d& slip, double, double h) const {
  const double v = slip.norm();
  if (v == 0.0 || !(h > 0.0)) return;  // dz/dt = 0 at rest
  Eigen::Vector3d zv(z[0], z[1], z[2]);
  // Elastic phase: z + s t stays elastic until z . s > 0 and |z| > z_ba both hold: t > t0
  // (z . s crosses 0) and t > t_exit (the later root of |z + s t| = z_ba, if any).
  const double v2 = v * v;
  const double zs = zv.dot(slip);
  const double t0 = -zs / v2;
  const double disc = zs * zs - v2 * (zv.squaredNorm() - z_ba_ * z_ba_);
  const double t_exit =
      disc >= 0.0 ? (-zs + std::sqrt(disc)) / v2 : -std::numeric_limits<double>::infinity();
  const double t_elastic = std::max({0.0, t0, t_exit});
  if (t_elastic >= h) {
    zv += h * slip;
  } else {
    zv += t_elastic * slip;
    const double rest = h - t_elastic;
    const double g = g_.value(v);
    const double k = params_.sigma0 * v / g;
    // Fully plastic already (the usual case in steady sliding): with the component p along s
    // at or beyond z_ss = g / sigma0, alpha = 1 holds for the rest of the step (p relaxes
    // monotonically to z_ss from above, and |z| >= p), so the update at alpha = 1 is exact.
    // Within 1e-6 of the transition's width below z_ss (where a loading from below settles),
    // 1 - alpha < (pi^2 / 4) 1e-12 and p only rises towards z_ss: alpha = 1 to that error.
    const double z_ss = g / params_.sigma0;
    if (zv.dot(slip) >= v * (z_ss - 1e-6 * (z_ss - z_ba_))) {
      zv = frozenAlpha(zv, slip, k, rest);
      for (int i = 0; i < 3; ++i) z[i] = zv[i];
      return;
    }
    // Substeps short enough for alpha's transition (z_ss - z_ba wide) to be resolved where z
    // moves with the slip; at most 64 (beyond that the relaxation is over and alpha = 1).
    const double width = z_ss - z_ba_;
    const double wanted = std::ceil(v * rest / (0.05 * width));
    const int n = static_cast<int>(std::clamp(wanted, 1.0, 64.0));
    const double dt = rest / n;
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d mid = frozenAlpha(zv, slip, alphaAt(zv, slip, g) * k, 0.5 * dt);
      zv = frozenAlpha(zv, slip, alphaAt(mid, slip, g) * k, dt);
    }
  }
  for (int i = 0; i < 3; ++i) z[i] = zv[i];
}

double ElastoPlasticLaw::stateStiffness(double v_max) const {
  return params_.sigma0 * std::abs(v_max) *
         (1.0 + std::numbers::pi / (2.0 * (1.0 - params_.z_ba_fraction))) / params_.mu_c;
}

}  // namespace tribo::friction
