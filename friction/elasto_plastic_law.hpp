// The elasto-plastic law (scene name "elasto_plastic"): LuGre's bristle with a purely elastic
// range below a break-away deflection, after Dupont, Hayward, Armstrong & Altpeter, "Single
// state elastoplastic friction models", IEEE Trans. Automatic Control 47(5):787-792, 2002,
// written per unit normal force and in vector form in the tangent plane:
//
//   dz/dt = s - alpha(z, s) sigma0 |s| z / g(|s|),   g(v) = mu_c + (mu_s - mu_c) exp(-(v/v_s)^2)
//   F_t   = -F_n (sigma0 z + sigma1 dz/dt + sigma2 s)
//
//   alpha = 0                                              |z| <= z_ba or z . s <= 0
//         = (1 + sin(pi (|z| - (z_ss + z_ba) / 2) / (z_ss - z_ba))) / 2    z_ba < |z| < z_ss
//         = 1                                              |z| >= z_ss
//
// with z_ss = g(|s|) / sigma0 the steady deflection and z_ba = z_ba_fraction * mu_c / sigma0
// the break-away deflection (< z_ss at every speed). The paper's alpha(z, v) uses z and the
// sign of v; here |z| and the sign of z . s. Below break-away the contact is a spring: a load
// under sigma0 z_ba F_n, steady or oscillating, moves it elastically and it returns (no drift,
// unlike LuGre). Steady state as LuGre: g(v) + sigma2 v (coefficient()).
// Parameters (per unit normal force): sigma0 [1/m] (default 1e5, > 0), sigma1 [s/m] (default
// sqrt(1e5), >= 0), sigma2 [s/m] (default 0.4, >= 0), mu_c [-] (1, > 0), mu_s [-] (1.5,
// >= mu_c), v_s [m/s] (1e-3, > 0): LuGre's defaults; z_ba_fraction [-] (default 0.7, in (0, 1)).
// Limits, honestly: as in the paper, alpha's sine transition makes the state equation stiff
// near z_ss (slope pi / (2 (z_ss - z_ba)) of alpha); stableStep at frozen slip is exact in the
// elastic range and an exponential-midpoint update with substeps beyond it (second order,
// not exact); like LuGre, dissipative only for small enough sigma1; sideways (z . s <= 0) the
// bristle is elastic whatever |z|.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "friction/bristle_law.hpp"
#include "friction/stribeck_curve.hpp"

namespace tribo::friction {

struct ElastoPlasticParams {
  double sigma0 = 1e5;                 // bristle stiffness per unit normal force [1/m], > 0
  double sigma1 = 316.22776601683796;  // bristle damping [s/m], >= 0 (sqrt(1e5))
  double sigma2 = 0.4;                 // viscous coefficient [s/m], >= 0
  double mu_c = 1.0;                   // Coulomb level [-], > 0
  double mu_s = 1.5;                   // static level [-], >= mu_c
  double v_s = 1e-3;                   // Stribeck speed [m/s], > 0
  double z_ba_fraction = 0.7;          // break-away deflection / (mu_c / sigma0) [-], in (0, 1)
};

class ElastoPlasticLaw final : public BristleLaw {
 public:
  // Throws FrictionParameterError when a rule above is broken or a value is not finite.
  explicit ElastoPlasticLaw(const ElastoPlasticParams& params);

  // Steady-state curve: sgn(v) g(|v|) + sigma2 v.
  double coefficient(double v) const override;
  void coefficientsAt(std::span<const double> v, std::span<double> mu) const override;
  double slope(double v) const override;
  // mu_s + sigma1 (1 + mu_s / mu_c) v_max + sigma2 v_max: |z| <= mu_s / sigma0 and |dz/dt| <=
  // |s| (1 + mu_s / mu_c) for states reached from |z| <= mu_s / sigma0.
  double maxCoefficient(double v_max) const override;
  double stickSpeed() const override { return params_.v_s; }
  std::string_view name() const override { return "elasto_plastic"; }

  void rate(const double* z, const Eigen::Vector3d& slip, double fn, double* zdot) const override;
  Eigen::Vector3d force(const double* z, const double* zdot, const Eigen::Vector3d& slip, double fn,
                        double* mu_out) const override;
  // Exact while elastic (z moves with s until it leaves the break-away ball along s), then
  // exponential-midpoint substeps with alpha frozen over each (bounded: each substep is the
  // exact solution of a linear decay towards s / (alpha k)).
  void stableStep(double* z, const Eigen::Vector3d& slip, double fn, double h) const override;
  // {sigma0, sigma1 + sigma2}.
  Presliding presliding() const override {
    return {params_.sigma0, params_.sigma1 + params_.sigma2};
  }
  // sigma0 v_max (1 + pi / (2 (1 - z_ba_fraction))) / mu_c: the decay rate including alpha's
  // slope.
  double stateStiffness(double v_max) const override;

  const ElastoPlasticParams& params() const { return params_; }
  // alpha for a state z and slip s (vector form).
  double alpha(const Eigen::Vector3d& z, const Eigen::Vector3d& slip) const;
  double breakAwayDeflection() const { return z_ba_; }

 private:
  // alpha with g(|s|) already known.
  double alphaAt(const Eigen::Vector3d& z, const Eigen::Vector3d& slip, double g) const;
  // z over time t at frozen slip with alpha frozen: z e^(-a k t) + s (1 - e^(-a k t)) / (a k).
  static Eigen::Vector3d frozenAlpha(const Eigen::Vector3d& z, const Eigen::Vector3d& slip,
                                     double ak, double t);

  ElastoPlasticParams params_;
  StribeckCurve g_;
  double z_ba_;
};

}  // namespace tribo::friction
