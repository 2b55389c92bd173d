// The generalized Maxwell-slip law (scene name "gms"): N elastoplastic elements in parallel,
// after Al-Bender, Lampaert & Swevers, "The generalized Maxwell-slip model: a novel model for
// friction simulation and compensation", IEEE Trans. Automatic Control 50(11):1883-1887, 2005.
// Element i has stiffness k_i [1/m] and carries at most the fraction alpha_i of the Stribeck
// curve S(v) = mu_c + (mu_s - mu_c) exp(-|v / v_s|^delta); per unit normal force and in vector
// form in the tangent plane, with z_i the element's deflection:
//
//   sticking: dz_i/dt = s
//   sliding:  dz_i/dt = (C / k_i) (alpha_i s / |s| - k_i z_i / S(|s|))
//   F_t = -F_n (sum_i (k_i z_i + sigma1 (k_i / K) dz_i/dt) + sigma2 s),   K = sum_i k_i
//
// The paper's sliding equation dF_i/dt = sgn(v) C (alpha_i - F_i / s(v)) read per unit load.
// Switching rule (the state stays continuous; decided from it alone, no stored mode): element
// i slides when k_i |z_i| >= alpha_i S(|s|) (1 - 1e-12) and z_i . s > 0 (at its limit, to
// rounding, and pushed further), and sticks otherwise. The paper's hybrid rule keeps a sliding
// element sliding until the slip reverses; here an element whose limit rises above its force
// (deceleration along the Stribeck curve) sticks again, so the frictional lag during deceleration
// comes from the sticking rate k_i |s| rather than C. The rate is discontinuous where an element
// meets its limit at an angle to s (the state then follows the limit circle, to within a step).
// Steady state: every element at its limit along s, F = S(v) + sigma2 v (coefficient()),
// with sum alpha_i = 1. Presliding: the virgin curve is piecewise linear, stiffness K at
// rest, each element yielding at deflection alpha_i mu_s / k_i; reversals give Masing loops.
// Parameters: elements N (default 4, 1..8); stiffness K [1/m] (default 1e5, > 0) with equal
// k_i = K / N and alpha_i = 2 i / (N (N + 1)) (break-away deflections evenly spaced: a
// piecewise-linear parabolic virgin curve), or per element k_1..k_N [1/m] (> 0) and
// alpha_1..alpha_N (> 0, summing to 1); mu_c [-] (1, > 0), mu_s [-] (1.5, >= mu_c), v_s
// [m/s] (1e-3, > 0), delta [-] (2, > 0), attraction C [1/s] (default 20, > 0: a sliding
// element relaxes to its limit at rate C / S), sigma1 [s/m] micro-damping (default 0, >= 0),
// sigma2 [s/m] viscous (default 0, >= 0).
// Limits, honestly: the rate jumps at each switch, which implicit multistep methods do not
// survive (bdf stops with CVODE's step limit on the belt) and which costs every fixed-step
// method its order; the default stiffness and C are illustrative, not fitted; stableStep is
// exact at frozen slip for an element whose deflection is along s, and for others lets an
// element that reached its limit slide for the rest of the step; without sigma1 the
// presliding spring is undamped.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "friction/dynamic_law.hpp"
#include "friction/stribeck_curve.hpp"

namespace tribo::friction {

struct GmsParams {
  static constexpr int kMaxElements = 8;
  int elements = 4;           // N [-], 1..kMaxElements
  double stiffness = 1e5;     // total K [1/m], > 0 (used when k is empty)
  std::vector<double> k;      // per-element stiffness [1/m] (empty: K / N each)
  std::vector<double> alpha;  // per-element fraction [-] (empty: 2 i / (N (N + 1)))
  double mu_c = 1.0;          // Coulomb level [-], > 0
  double mu_s = 1.5;          // static level [-], >= mu_c
  double v_s = 1e-3;          // Stribeck speed [m/s], > 0
  double delta = 2.0;         // Stribeck shape [-], > 0
  double attraction = 20.0;   // C [1/s], > 0
  double sigma1 = 0.0;        // micro-damping [s/m], >= 0
  double sigma2 = 0.0;        // viscous coefficient [s/m], >= 0
};

class GmsLaw final : public DynamicFrictionLaw {
 public:
  // Throws FrictionParameterError when a rule above is broken or a value is not finite.
  explicit GmsLaw(const GmsParams& params);

  // Steady-state curve: sgn(v) S(|v|) + sigma2 v.
  double coefficient(double v) const override;
  void coefficientsAt(std::span<const double> v, std::span<double> mu) const override;
  double slope(double v) const override;
  // mu_s + sigma1 (v_max + C (1 + mu_s / mu_c) / K) + sigma2 v_max: |k_i z_i| <= alpha_i mu_s
  // for states reached from there.
  double maxCoefficient(double v_max) const override;
  double stickSpeed() const override { return params_.v_s; }
  std::vector<double> breakpoints() const override { return {}; }
  std::string_view name() const override { return "gms"; }

  int stateSize() const override { return 3 * elements(); }
  int tangentVectors() const override { return elements(); }
  std::string stateName(int i) const override;  // "z1.x" ... "zN.z"
  void initialState(double* z) const override;
  void rate(const double* z, const Eigen::Vector3d& slip, double fn, double* zdot) const override;
  Eigen::Vector3d force(const double* z, const double* zdot, const Eigen::Vector3d& slip, double fn,
                        double* mu_out) const override;
  // Per element: sticks (z_i += s t) until it reaches its limit moving forward, then the exact
  // sliding solution z_ss + (z_i - z_ss) exp(-C t / S) for the rest of the step.
  void stableStep(double* z, const Eigen::Vector3d& slip, double fn, double h) const override;
  // {K, sigma1}: all elements stuck.
  Presliding presliding() const override { return {total_stiffness_, params_.sigma1}; }
  // C / mu_c: the sliding elements' relaxation rate (sticking elements are not stiff).
  double stateStiffness(double v_max) const override;

  int elements() const { return static_cast<int>(k_.size()); }
  double elementStiffness(int i) const { return k_[i]; }
  double elementFraction(int i) const { return alpha_[i]; }
  // Whether element i (deflection zi) slides at slip s.
  bool sliding(int i, const Eigen::Vector3d& zi, const Eigen::Vector3d& slip) const;

 private:
  // The rule above from z_i . s, |z_i|^2 and S(|s|).
  bool slidingAt(int i, double z_dot_s, double z_squared, double stribeck) const;

  GmsParams params_;
  StribeckCurve s_;
  std::vector<double> k_;
  std::vector<double> alpha_;
  std::vector<double> attraction_over_k_;  // C / k_i [m]
  double total_stiffness_ = 0.0;
  double damping_per_stiffness_ = 0.0;  // sigma1 / K [s]
};

}  // namespace tribo::friction
