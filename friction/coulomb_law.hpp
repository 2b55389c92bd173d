// Coulomb friction with a choice of regularization near zero slip speed (scene name
// "coulomb"). With mu the friction coefficient and v_eps the regularization speed [m/s]:
//
//   none:    mu(v) = mu * sign(v)                     (mu(0) = 0; discontinuous at 0)
//   linear:  mu(v) = mu * clamp(v / v_eps, -1, 1)
//   tanh:    mu(v) = mu * tanh(v / v_eps)             (default)
//   havsin:  mu(v) = sign(v) * havsin(|v|, 0, 0, v_eps, mu)   (haversine step, smooth_step.hpp)
//
// tanh is friction/vector_tanh.hpp's (glibc's vector tanh where there is one: within 2.2 ulp of
// the exact tanh, as std::tanh is within 2.1), so that a batch of speeds costs a few
// instructions a speed.
// Textbook Coulomb law; the regularizations are the usual ones of multibody codes (the
// haversine ramp is RecurDyn's static-transition step with mu_s = mu_k = mu).
// What it does not do: model stiction (mu_s > mu_k) or a Stribeck dip (see stribeck_law.hpp,
// roh_yoo_law.hpp); with regularization a body under load creeps at speeds below v_eps.
#pragma once

#include <string_view>
#include <vector>

#include "friction/friction_law.hpp"
#include "friction/name_table.hpp"
#include "friction/smooth_step.hpp"

namespace tribo::friction {

enum class CoulombRegularization { kNone, kLinear, kTanh, kHavsin };

// Scene spelling of a regularization ("none", "linear", "tanh", "havsin").
inline constexpr NameTable<CoulombRegularization, 4> kCoulombRegularizationNames{
    "regularization",
    {{{CoulombRegularization::kNone, "none"},
      {CoulombRegularization::kLinear, "linear"},
      {CoulombRegularization::kTanh, "tanh"},
      {CoulombRegularization::kHavsin, "havsin"}}}};
std::string_view toString(CoulombRegularization regularization);

struct CoulombParams {
  double mu = 0.0;      // friction coefficient [-], >= 0 (required in scenes)
  double v_eps = 1e-4;  // regularization speed [m/s], > 0
  CoulombRegularization regularization = CoulombRegularization::kTanh;
};

class CoulombLaw final : public FrictionLaw {
 public:
  // Throws FrictionParameterError for mu < 0, v_eps <= 0 or non-finite values.
  explicit CoulombLaw(const CoulombParams& params);

  double coefficient(double v) const override;
  void coefficientsAt(std::span<const double> v, std::span<double> mu) const override;
  // "none": 0 everywhere (the jump at v = 0 has no derivative; 0 is returned there too).
  // "linear": mu / v_eps for |v| < v_eps, else 0 (the right-hand value at the kink).
  double slope(double v) const override;
  double maxCoefficient(double v_max) const override;
  double stickSpeed() const override { return params_.v_eps; }
  // {v_eps} for "linear" and "havsin"; none for "tanh" and "none" (whose jump is at 0).
  std::vector<double> breakpoints() const override;
  std::string_view name() const override { return "coulomb"; }

  const CoulombParams& params() const { return params_; }

 private:
  CoulombParams params_;
  double inv_v_eps_;  // 1 / v_eps [s/m]
  Haversine ramp_;    // havsin(., 0, 0, v_eps, mu)
};

}  // namespace tribo::friction
