// The Dahl law (scene name "dahl"): a rate-independent bristle whose deflection z is the
// internal state, after P. R. Dahl, "A solid friction model", The Aerospace Corporation,
// TOR-0158(3107-18)-1, 1968 (and "Solid friction damping of mechanical vibrations", AIAA J.
// 14(12):1675-1682, 1976): in one dimension, with F = F_n sigma0 z,
//
//   dF/dx = sigma0 F_n |1 - (F / F_c) sgn v|^alpha sgn(1 - (F / F_c) sgn v),  F_c = mu_c F_n
//
// written per unit normal force and in vector form in the tangent plane:
//
//   e     = s / |s| - sigma0 z / mu_c                  (0 at steady sliding)
//   dz/dt = |s| |e|^(alpha - 1) e                      (dz/dt = 0 at s = 0)
//   F_t   = -F_n sigma0 z
//
// In one dimension e = sgn(v) (1 - (F / F_c) sgn v), so this is Dahl's equation; with
// alpha = 1 it is LuGre (friction/lugre_law.hpp) with g = mu_c and sigma1 = sigma2 = 0.
// Steady state: z = mu_c s / (sigma0 |s|), a Coulomb curve mu_c sgn(v) (coefficient()).
// Cyclic motion x = +-X (alpha = 1) dissipates 4 F_c X - (4 F_c^2 / (sigma0 F_n)) tanh(sigma0
// X / mu_c) per cycle (hysteresis loops closed-form; tests/friction/dynamic_law_values_test).
// Parameters: sigma0 [1/m] stiffness per unit normal force (default 1e5, > 0), mu_c [-]
// (default 1, > 0), alpha [-] shape (default 1, >= 1: below 1 the state equation's stiffness
// is unbounded at steady sliding).
// Limits, honestly: rate-independent (no Stribeck peak, no static level above mu_c: use lugre or
// elasto_plastic); a stuck contact drifts under an oscillating sub-Coulomb load (the
// bristle relaxes whenever it moves); no damping of the presliding spring (stiffness sigma0
// F_n, damping 0), so the contact's own mode rings; there is no speed scale, so stickSpeed()
// is a nominal 1e-6 m/s used only for event location and finite differences.
// |z| stays within mu_c / sigma0 when it starts there.
#pragma once

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "friction/bristle_law.hpp"

namespace tribo::friction {

struct DahlParams {
  double sigma0 = 1e5;  // stiffness per unit normal force [1/m], > 0
  double mu_c = 1.0;    // Coulomb level [-], > 0
  double alpha = 1.0;   // shape exponent [-], >= 1
};

class DahlLaw final : public BristleLaw {
 public:
  static constexpr double kStickSpeed = 1e-6;  // nominal [m/s]: the law has no speed scale

  // Throws FrictionParameterError when a rule above is broken or a value is not finite.
  explicit DahlLaw(const DahlParams& params);

  // Steady-state curve: mu_c sgn(v); slope 0 (one-sided at 0).
  double coefficient(double v) const override;
  void coefficientsAt(std::span<const double> v, std::span<double> mu) const override;
  double slope(double v) const override;
  // mu_c: |sigma0 z| <= mu_c for every state reached from |z| <= mu_c / sigma0.
  double maxCoefficient(double v_max) const override;
  double stickSpeed() const override { return kStickSpeed; }
  std::string_view name() const override { return "dahl"; }

  void rate(const double* z, const Eigen::Vector3d& slip, double fn, double* zdot) const override;
  Eigen::Vector3d force(const double* z, const double* zdot, const Eigen::Vector3d& slip, double fn,
                        double* mu_out) const override;
  // Exact at frozen slip: e keeps its direction and d|e|/dt = -k |e|^alpha, k = sigma0 |s| /
  // mu_c, so |e(h)| = |e| exp(-k h) (alpha = 1) or |e| (1 + (alpha - 1) k h |e|^(alpha - 1))^(-1
  // / (alpha - 1)).
  void stableStep(double* z, const Eigen::Vector3d& slip, double fn, double h) const override;
  // {2^alpha sigma0, 0}: the steepest dF/dx = sigma0 F_n |1 - (F / F_c) sgn v|^alpha (Dahl's
  // equation above) over the stuck states |F| <= F_c, reached unloading a bristle loaded to
  // F_c; sigma0 F_n at z = 0. A body held at 0.8 F_c rings on the unloading side at 1.8 sigma0
  // F_n, past the RK4 limit taken at sigma0 (measured: diverged at 0.9 of that estimate).
  Presliding presliding() const override {
    return {params_.sigma0 * std::pow(2.0, params_.alpha), 0.0};
  }
  // sigma0 v_max alpha 2^(alpha - 1) / mu_c (|e| <= 2 while |z| <= mu_c / sigma0).
  double stateStiffness(double v_max) const override;

  const DahlParams& params() const { return params_; }

 private:
  DahlParams params_;
};

}  // namespace tribo::friction
