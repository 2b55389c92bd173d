// A regularized Stribeck law with optional viscous term (scene name "stribeck"): the
// coefficient falls from the static value mu_s to the kinetic value mu_k over the Stribeck
// speed v_st, is regularized by tanh near zero slip, and grows with a viscous coefficient:
//
//   mu(v) = tanh(v / v_eps) * (mu_k + (mu_s - mu_k) * exp(-(|v| / v_st)^delta)) + viscous * v
//
// The Stribeck curve as usually written (Armstrong-Helouvry 1991; Andersson, Soderberg &
// Bjorklund 2007, "Friction models for sliding dry, boundary and mixed lubricated contacts")
// with a tanh regularization in place of sign(v). `viscous` is a coefficient per unit speed
// [s/m], so viscous * v is dimensionless like mu and the force stays proportional to F_n.
// What it does not do: stick (mu(0) = 0, a loaded body creeps below ~v_eps), hysteresis or
// any memory (no frictional lag; see bristle models for that).
#pragma once

#include <string_view>
#include <vector>

#include "friction/friction_law.hpp"

namespace tribo::friction {

struct StribeckParams {
  double mu_s = 0.0;     // static coefficient [-], >= mu_k (required in scenes)
  double mu_k = 0.0;     // kinetic coefficient [-], >= 0 (required in scenes)
  double v_st = 0.0;     // Stribeck speed [m/s], > 0 (required in scenes)
  double delta = 2.0;    // shape exponent [-], > 0 (2: Gaussian decay)
  double viscous = 0.0;  // viscous coefficient [s/m], >= 0
  double v_eps = 1e-4;   // regularization speed [m/s], > 0
};

class StribeckLaw final : public FrictionLaw {
 public:
  // Throws FrictionParameterError when a rule above is broken or a value is not finite.
  explicit StribeckLaw(const StribeckParams& params);

  double coefficient(double v) const override;
  void coefficientsAt(std::span<const double> v, std::span<double> mu) const override;
  double slope(double v) const override;
  // No closed form: a rigorous upper bound, found by interval bisection, within 1e-6 relative
  // of the true maximum (mu_s-ish near the peak, or mu_k + viscous * v_max at large v_max).
  // Allocates; meant for setup, not for the step loop.
  double maxCoefficient(double v_max) const override;
  double stickSpeed() const override { return params_.v_eps; }
  std::vector<double> breakpoints() const override { return {}; }  // smooth
  std::string_view name() const override { return "stribeck"; }

  const StribeckParams& params() const { return params_; }

 private:
  // (|v| / v_st)^delta, with a fast path for the default delta = 2.
  double shapePower(double u) const;
  // mu_k + (mu_s - mu_k) exp(-(u / v_st)^delta) for u = |v| >= 0.
  double decay(double u) const;
  // Largest coefficient over [0, w], w finite and > 0 (see maxCoefficient).
  double maxOver(double w) const;

  StribeckParams params_;
  double inv_v_eps_;  // 1 / v_eps [s/m]
  double inv_v_st_;   // 1 / v_st [s/m]
  double drop_;       // mu_s - mu_k >= 0
  bool delta_is_two_;
};

}  // namespace tribo::friction
