// The ADAMS-style friction law (scene name "adams"): static coefficient mu_s reached at the
// static transition speed v_s, kinetic coefficient mu_k from the dynamic transition speed
// v_d on, joined by cubic STEP functions (MSC ADAMS/Solver reference, STEP function and the
// friction of joints; as in Roh & Yoo 2007). For v >= 0, odd in v:
//
//   0   <= v < v_s:  mu = step(v, 0,   0,    v_s, mu_s)
//   v_s <= v < v_d:  mu = step(v, v_s, mu_s, v_d, mu_k)
//   v_d <= v:        mu = mu_k
//
// step(x, x0, h0, x1, h1) = h0 + (h1 - h0) s^2 (3 - 2 s), s = (x - x0) / (x1 - x0) clamped to
// [0, 1]. Same shape as recurdyn_law.hpp with a cubic instead of a haversine blend.
// What it does not do: stick. mu -> 0 as v -> 0, so a loaded body creeps at low slip speed,
// and mu is flat beyond v_d, so it cannot drive stick-slip from a falling characteristic
// (Roh & Yoo 2007; see roh_yoo_law.hpp).
#pragma once

#include <string_view>
#include <vector>

#include "friction/friction_law.hpp"
#include "friction/smooth_step.hpp"

namespace tribo::friction {

struct AdamsParams {
  double mu_s = 0.0;  // static coefficient [-], > 0 and >= mu_k
  double mu_k = 0.0;  // kinetic coefficient [-], >= 0
  double v_s = 0.0;   // static transition speed [m/s], > 0
  double v_d = 0.0;   // dynamic transition speed [m/s], > v_s
};

class AdamsLaw final : public FrictionLaw {
 public:
  // Throws FrictionParameterError when a rule above is broken or a value is not finite.
  explicit AdamsLaw(const AdamsParams& params);

  double coefficient(double v) const override;
  double slope(double v) const override;  // continuous: both steps have zero end slopes
  double maxCoefficient(double v_max) const override;
  double stickSpeed() const override { return params_.v_s; }
  std::vector<double> breakpoints() const override { return {params_.v_s, params_.v_d}; }
  std::string_view name() const override { return "adams"; }

  const AdamsParams& params() const { return params_; }

 private:
  AdamsParams params_;
  CubicStep rise_;  // 0 -> mu_s over [0, v_s]
  CubicStep fall_;  // mu_s -> mu_k over [v_s, v_d]
};

}  // namespace tribo::friction
