// The friction-coefficient shape shared by the RecurDyn and ADAMS laws: static
// coefficient mu_s reached at the static transition speed v_s, kinetic coefficient mu_k
// from the dynamic transition speed v_d on, joined by two smooth steps. For v >= 0, odd in v:
//
//   0   <= v < v_s:  mu = step(v, 0,   0,    v_s, mu_s)
//   v_s <= v < v_d:  mu = step(v, v_s, mu_s, v_d, mu_k)
//   v_d <= v:        mu = mu_k
//
// `Step` is the blend (smooth_step.hpp): Haversine for recurdyn_law.hpp, CubicStep for
// adams_law.hpp. Both blends have zero slope at their ends, so the slope is continuous.
// What it does not do: stick. mu -> 0 as v -> 0, so a loaded body creeps at low slip speed,
// and mu is flat beyond v_d, so it cannot drive stick-slip from a falling characteristic
// (Roh & Yoo 2007; see roh_yoo_law.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "friction/friction_law.hpp"
#include "friction/parameter_check.hpp"
#include "friction/smooth_step.hpp"

namespace tribo::friction {

struct TwoStepParams {
  double mu_s = 0.0;  // static coefficient [-], > 0 and >= mu_k
  double mu_k = 0.0;  // kinetic coefficient [-], >= 0
  double v_s = 0.0;   // static transition speed [m/s], > 0
  double v_d = 0.0;   // dynamic transition speed [m/s], > v_s
};

template <typename Step>
class TwoStepLaw final : public FrictionLaw {
 public:
  // Throws FrictionParameterError ("NAME: RULE (got ...)") when a rule above is broken or a
  // value is not finite. `name` is the scene name, e.g. "recurdyn".
  TwoStepLaw(std::string_view name, const TwoStepParams& params)
      : name_(name),
        params_(validated(name, params)),
        rise_(0.0, 0.0, params.v_s, params.mu_s),
        fall_(params.v_s, params.mu_s, params.v_d, params.mu_k) {}

  double coefficient(double v) const override {
    const double u = std::abs(v);
    double mu;
    if (u >= params_.v_d) {
      mu = params_.mu_k;
    } else if (u >= params_.v_s) {
      mu = fall_.value(u);
    } else {
      mu = rise_.value(u);  // also where a NaN goes, so it propagates
    }
    return std::copysign(mu, v);
  }
  void coefficientsAt(std::span<const double> v, std::span<double> mu) const override {
    coefficientsOf(*this, v, mu);
  }
  double slope(double v) const override {
    const double u = std::abs(v);
    if (u >= params_.v_d) return 0.0;
    if (u >= params_.v_s) return fall_.derivative(u);
    return rise_.derivative(u);
  }
  // Rises to mu_s at v_s, then falls to mu_k <= mu_s.
  double maxCoefficient(double v_max) const override {
    return std::abs(coefficient(std::min(std::abs(v_max), params_.v_s)));
  }
  double stickSpeed() const override { return params_.v_s; }
  std::vector<double> breakpoints() const override { return {params_.v_s, params_.v_d}; }
  std::string_view name() const override { return name_; }

  const TwoStepParams& params() const { return params_; }

 private:
  static const TwoStepParams& validated(std::string_view name, const TwoStepParams& p) {
    const ParameterCheck check(name);
    check.finite({{"mu_s", p.mu_s}, {"mu_k", p.mu_k}, {"v_s", p.v_s}, {"v_d", p.v_d}});
    check.require(p.mu_k >= 0.0, "mu_k must be >= 0", p.mu_k);
    check.require(p.mu_s > 0.0, "mu_s must be > 0", p.mu_s);
    check.require(p.mu_s >= p.mu_k, "mu_s must be >= mu_k", "mu_s", p.mu_s, "mu_k", p.mu_k);
    check.require(p.v_s > 0.0, "v_s must be > 0", p.v_s);
    check.require(p.v_d > p.v_s, "v_d must be > v_s", "v_s", p.v_s, "v_d", p.v_d);
    return p;
  }

  std::string name_;
  TwoStepParams params_;
  Step rise_;  // 0 -> mu_s over [0, v_s]
  Step fall_;  // mu_s -> mu_k over [v_s, v_d]
};

}  // namespace tribo::friction
