// The LuGre law (scene name "lugre"): bristles whose mean deflection z is the internal state,
// after Canudas de Wit, Olsson, Astrom & Lischinsky, "A new model for control of systems
// with friction", IEEE Trans. Automatic Control 40(3):419-425, 1995, eqs. (2)-(4), written
// per unit normal force for contacts and in vector form in the tangent plane:
//
//   dz/dt = s - sigma0 |s| z / g(|s|),   g(v) = mu_c + (mu_s - mu_c) exp(-(v / v_s)^2)
//   F_t   = -F_n (sigma0 z + sigma1 dz/dt + sigma2 s)
//
// s: slip velocity of B relative to A [m/s]; z [m]; sigma0 [1/m] bristle stiffness per unit
// normal force, sigma1 [s/m] bristle damping, sigma2 [s/m] viscous coefficient (all per unit
// normal force). Steady sliding at speed v: z = g(v) s / (sigma0 v), so the steady-state
// coefficient is g(v) + sigma2 v (coefficient() below). Presliding: under a slowly rising
// force the displacement is x = -(mu_s / sigma0) ln(1 - F / (mu_s F_n)) (the paper's
// Property 1 region); small motions about a stuck state have stiffness sigma0 F_n and
// damping (sigma1 + sigma2) F_n.
// Defaults: the paper's Table I (sigma0 = 1e5 N/m, sigma1 = sqrt(1e5) N s/m, sigma2 = 0.4
// N s/m, F_c = 1 N, F_s = 1.5 N, v_s = 1e-3 m/s) read per newton of normal force.
// Limits, honestly: with sigma1 > 0 the model is dissipative only for sigma1 small enough
// (Olsson's condition; Barabanov & Ortega 2000); a stuck contact drifts under an oscillating
// sub-break-away load (z ratchets each cycle, the law's known flaw: use elasto_plastic), while
// under a held one it comes to rest (tests/scenes/exact_break_away_test.cpp: 2e-12 m in 80 s).
// |z| stays within mu_s / sigma0 when it starts there. Not a normal law: contact stiffness is
// contact/'s.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "friction/bristle_law.hpp"

namespace tribo::friction {

struct LuGreParams {
  double sigma0 = 1e5;                 // bristle stiffness per unit normal force [1/m], > 0
  double sigma1 = 316.22776601683796;  // bristle damping [s/m], >= 0 (sqrt(1e5))
  double sigma2 = 0.4;                 // viscous coefficient [s/m], >= 0
  double mu_c = 1.0;                   // Coulomb level [-], > 0
  double mu_s = 1.5;                   // static level [-], >= mu_c
  double v_s = 1e-3;                   // Stribeck speed [m/s], > 0
};

class LuGreLaw final : public BristleLaw {
 public:
  // Throws FrictionParameterError when a rule above is broken or a value is not finite.
  explicit LuGreLaw(const LuGreParams& params);

  // Steady-state curve: sgn(v) g(|v|) + sigma2 v.
  double coefficient(double v) const override;
  void coefficientsAt(std::span<const double> v, std::span<double> mu) const override;
  double slope(double v) const override;
  // Bounds the transient too: mu_s + (2 sigma1 + sigma2) v_max (|dz/dt| <= 2 |s| while
  // |z| <= mu_s / sigma0).
  double maxCoefficient(double v_max) const override;
  double stickSpeed() const override { return params_.v_s; }
  std::string_view name() const override { return "lugre"; }

  void rate(const double* z, const Eigen::Vector3d& slip, double fn, double* zdot) const override;
  Eigen::Vector3d force(const double* z, const double* zdot, const Eigen::Vector3d& slip, double fn,
                        double* mu_out) const override;
  // Exact at frozen slip: z(h) = z_ss + (z - z_ss) exp(-sigma0 |s| h / g(|s|)).
  void stableStep(double* z, const Eigen::Vector3d& slip, double fn, double h) const override;
  // {sigma0, sigma1 + sigma2}.
  Presliding presliding() const override {
    return {params_.sigma0, params_.sigma1 + params_.sigma2};
  }
  // sigma0 v_max / min(mu_c, g): the decay rate of z at speed v_max.
  double stateStiffness(double v_max) const override;

  const LuGreParams& params() const { return params_; }
  // g(v) for v >= 0.
  double g(double v) const;

 private:
  LuGreParams params_;
};

}  // namespace tribo::friction
