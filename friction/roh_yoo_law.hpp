// The friction law proposed by Roh & Yoo (2007), "Friction Model to Realize Self-excited
// Vibration of Multi-body Systems", Trans. KSNVE 17(6) (scene name "roh_yoo"). A power
// law up to the static peak mu_s at v_s, then an exponential decay towards mu_k:
//
//   |v| <= v_s:  mu = mu_s * sign(v) * (|v| / v_s)^beta
//   v > v_s:     mu = a^-(v + b) + mu_k,   b = -ln(mu_s - mu_k) / ln(a) - v_s
//   v < -v_s:    mu = -a^(v - b) - mu_k
//
// b makes mu continuous at v_s (a^-(v_s + b) = mu_s - mu_k); the exponential branch is
// evaluated as mu_k + (mu_s - mu_k) * a^-(|v| - v_s), the same function without the
// cancellation. Above v_s the slope is negative everywhere,
// mu'(v) = -ln(a) (mu_s - mu_k) a^-(v - v_s), which is what drives stick-slip.
// With beta < 1 the slope at v = 0 is infinite (slope(0) returns +infinity): the law pins a
// lightly loaded contact harder than haversine/STEP laws, but it still does not stick
// exactly (mu(0) = 0). The printed formula in the paper has typos; the form above is the
// continuous, odd one.
#pragma once

#include <string_view>
#include <vector>

#include "friction/friction_law.hpp"

namespace tribo::friction {

struct RohYooParams {
  double mu_s = 0.0;  // static (peak) coefficient [-], > mu_k
  double mu_k = 0.0;  // kinetic (asymptotic) coefficient [-], >= 0
  double v_s = 0.0;   // speed of the peak [m/s], > 0
  double a = 0.0;     // decay base [-], > 1 (decay rate ln(a) per m/s of slip speed)
  double beta = 0.0;  // exponent of the rise below v_s [-], > 0 (the paper uses 1/3)
};

class RohYooLaw final : public FrictionLaw {
 public:
  // Throws FrictionParameterError when a rule above is broken or a value is not finite.
  explicit RohYooLaw(const RohYooParams& params);

  double coefficient(double v) const override;
  void coefficientsAt(std::span<const double> v, std::span<double> mu) const override;
  // Left-hand slope mu_s beta / v_s at |v| = v_s (the law has a kink there); +infinity at
  // v = 0 for beta < 1, mu_s / v_s for beta = 1, 0 for beta > 1.
  double slope(double v) const override;
  double maxCoefficient(double v_max) const override;
  double stickSpeed() const override { return params_.v_s; }
  std::vector<double> breakpoints() const override { return {params_.v_s}; }
  std::string_view name() const override { return "roh_yoo"; }

  const RohYooParams& params() const { return params_; }
  // The continuity offset b = -ln(mu_s - mu_k) / ln(a) - v_s [m/s].
  double b() const { return b_; }

 private:
  RohYooParams params_;
  double inv_v_s_;     // 1 / v_s [s/m]
  double ln_a_;        // ln(a) [s/m]
  double drop_;        // mu_s - mu_k > 0
  double rise_slope_;  // mu_s * beta / v_s [s/m]
  double b_;
};

}  // namespace tribo::friction
