// Rate-and-state friction (scene name "rate_state"): the coefficient depends on the slip speed
// and on a state variable theta [s], the mean age of the contacting asperities, after
// Dieterich, "Modeling of rock friction 1. Experimental results and constitutive equations",
// J. Geophys. Res. 84(B5):2161-2168, 1979 (aging law) and Ruina, "Slip instability and state
// variable friction laws", J. Geophys. Res. 88(B12):10359-10370, 1983 (slip law), with the
// arcsinh regularization at zero slip of Rice & Ben-Zion, PNAS 93:3811-3818, 1996 and Lapusta,
// Rice, Ben-Zion & Zheng, J. Geophys. Res. 105(B10):23765-23789, 2000:
//
//   mu    = a asinh( |s| / (2 v0) exp((mu0 + b ln(v0 theta / d_c)) / a) )
//   aging:  dtheta/dt = 1 - |s| theta / d_c
//   slip:   dtheta/dt = -(|s| theta / d_c) ln(|s| theta / d_c)
//   F_t   = -F_n mu s / |s|
//
// For |s| >> 2 v0 exp(-mu0 / a) this is mu0 + a ln(|s| / v0) + b ln(v0 theta / d_c).
// State layout: one scalar, psi = ln(v0 theta / d_c) [-] (stateName "psi"), not theta: the
// evolution laws read
//   aging: dpsi/dt = (v0 exp(-psi) - |s|) / d_c,     slip: dpsi/dt = -(|s| / d_c)(psi + ln(|s| /
//   v0))
// so theta never over- or underflows (d_c down to 1e-7 m and below), x ln x needs no guard
// (the slip law is linear in psi; 0 at s = 0), and exp is only taken of psi's negative in the
// aging law (bounded by ln(v_max / v0)). The arcsinh is evaluated in logs (no overflow of the
// exponential for small a). Steady state: theta = d_c / |s| (psi = ln(v0 / |s|)):
//   mu_ss(v) = a asinh( (v / (2 v0)) exp(mu0 / a) (v0 / v)^(b / a) ) ~ mu0 + (a - b) ln(v / v0)
// (coefficient()). After a speed step V1 -> V2 the direct effect is a ln(V2 / V1) and the
// steady level moves by (a - b) ln(V2 / V1).
// Parameters: mu0 [-] (default 0.6, >= 0), a [-] (0.01, > 0), b [-] (0.015, >= 0), d_c [m]
// (1e-5, > 0), v0 [m/s] (1e-6, > 0), theta0 [s] the initial state (default d_c / v0, > 0),
// option evolution = aging (default) | slip. Defaults: typical laboratory values for rock
// (Marone, "Laboratory-derived friction laws and their application to seismic faulting",
// Annu. Rev. Earth Planet. Sci. 26:643-696, 1998).
// Limits, honestly: no static friction (mu = 0 at s = 0; a loaded contact creeps, if very
// slowly); with b > a the steady curve rises without bound as v -> 0 (slowly: (b - a) per
// e-fold); maxCoefficient bounds contacts up to kBoundAge old (theta <= theta0 + age for both
// evolution laws); stickSpeed() returns v0 (a scale for events and finite differences, not a
// stick threshold); a change of normal load does not change theta (no Linker-Dieterich term).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "friction/dynamic_law.hpp"

namespace tribo::friction {

enum class RateStateEvolution { kAging, kSlip };

struct RateStateParams {
  double mu0 = 0.6;     // reference coefficient at v0 and steady state [-], >= 0
  double a = 0.01;      // direct-effect coefficient [-], > 0
  double b = 0.015;     // evolution-effect coefficient [-], >= 0
  double d_c = 1e-5;    // characteristic slip distance [m], > 0
  double v0 = 1e-6;     // reference speed [m/s], > 0
  double theta0 = 0.0;  // initial state [s], > 0; 0 here means d_c / v0
  RateStateEvolution evolution = RateStateEvolution::kAging;
};

class RateStateLaw final : public DynamicFrictionLaw {
 public:
  static constexpr double kBoundAge = 1e8;  // contact age covered by maxCoefficient [s]

  // Throws FrictionParameterError when a rule above is broken or a value is not finite.
  explicit RateStateLaw(const RateStateParams& params);

  // Steady-state curve mu_ss(v) above, odd.
  double coefficient(double v) const override;
  void coefficientsAt(std::span<const double> v, std::span<double> mu) const override;
  // (a - b) / (v sqrt(1 + exp(-2 L))), L the log of the arcsinh's argument; at 0 the limit
  // from v > 0.
  double slope(double v) const override;
  // mu at v_max with psi <= ln(exp(psi0) + v0 kBoundAge / d_c): bounds every transient of a
  // contact younger than kBoundAge and the steady curve for |v| >= d_c / kBoundAge.
  double maxCoefficient(double v_max) const override;
  double stickSpeed() const override { return params_.v0; }
  std::vector<double> breakpoints() const override { return {}; }
  std::string_view name() const override { return "rate_state"; }

  int stateSize() const override { return 1; }
  int tangentVectors() const override { return 0; }
  std::string stateName(int) const override { return "psi"; }
  void initialState(double* z) const override { z[0] = psi0_; }
  void rate(const double* z, const Eigen::Vector3d& slip, double fn, double* zdot) const override;
  Eigen::Vector3d force(const double* z, const double* zdot, const Eigen::Vector3d& slip, double fn,
                        double* mu_out) const override;
  // Exact at frozen slip for both evolution laws: aging is linear in theta, slip linear in psi.
  void stableStep(double* z, const Eigen::Vector3d& slip, double fn, double h) const override;
  // No bristle: {0, 0}.
  Presliding presliding() const override { return {}; }
  // max(v0 exp(-psi0), v_max) / d_c (aging) or v_max / d_c (slip).
  double stateStiffness(double v_max) const override;
  // The direct effect at the steady state of speed v: a / (v sqrt(1 + exp(-2 L))) (L as in
  // slope()), about a / v; unbounded as v -> 0 (+infinity at 0 when b > 0).
  double directSlope(double v) const override;

  const RateStateParams& params() const { return params_; }
  // mu at slip speed v >= 0 and state psi.
  double mu(double v, double psi) const;
  // psi = ln(v0 theta / d_c) and back.
  double psiOf(double theta) const;
  double thetaOf(double psi) const;

 private:
  RateStateParams params_;
  double psi0_ = 0.0;
};

}  // namespace tribo::friction
