// The RecurDyn friction law (scene name "recurdyn"): static coefficient mu_s reached at the
// static transition speed v_s, kinetic coefficient mu_k from the dynamic transition speed
// v_d on, joined by haversine steps (RecurDyn Solver Theory, "Friction"; as in Roh & Yoo 2007). For
// v >= 0, odd in v:
//
//   0   <= v < v_s:  mu = havsin(v, 0,   0,    v_s, mu_s)
//   v_s <= v < v_d:  mu = havsin(v, v_s, mu_s, v_d, mu_k)
//   v_d <= v:        mu = mu_k
//
// What it does not do: stick. mu -> 0 as v -> 0, so a loaded body creeps at low slip speed,
// and mu is flat beyond v_d, so it cannot drive stick-slip from a falling characteristic
// (Roh & Yoo 2007; see roh_yoo_law.hpp).
#pragma once

#include <string_view>
#include <vector>

#include "friction/friction_law.hpp"
#include "friction/smooth_step.hpp"

namespace tribo::friction {

struct RecurDynParams {
  double mu_s = 0.0;  // static coefficient [-], > 0 and >= mu_k
  double mu_k = 0.0;  // kinetic coefficient [-], >= 0
  double v_s = 0.0;   // static transition speed [m/s], > 0
  double v_d = 0.0;   // dynamic transition speed [m/s], > v_s
};

class RecurDynLaw final : public FrictionLaw {
 public:
  // Throws FrictionParameterError when a rule above is broken or a value is not finite.
  explicit RecurDynLaw(const RecurDynParams& params);

  double coefficient(double v) const override;
  double slope(double v) const override;  // continuous: both steps have zero end slopes
  double maxCoefficient(double v_max) const override;
  double stickSpeed() const override { return params_.v_s; }
  std::vector<double> breakpoints() const override { return {params_.v_s, params_.v_d}; }
  std::string_view name() const override { return "recurdyn"; }

  const RecurDynParams& params() const { return params_; }

 private:
  RecurDynParams params_;
  Haversine rise_;  // 0 -> mu_s over [0, v_s]
  Haversine fall_;  // mu_s -> mu_k over [v_s, v_d]
};

}  // namespace tribo::friction
