// A stateful friction law that truly sticks: an elastic anchor (a tangential spring-damper
// between the two material points that met when the contact stuck) holds the contact up to
// the static limit, beyond which it slides with kinetic friction (scene name
// "elastic_stick"). With u the spring's elongation in the tangent plane, s the slip velocity
// and F_n the normal load:
//
//   stuck:    F = -k u - c s              while |F| <= mu_s F_n   (else it breaks away:
//                                          F = mu_k F_n along -k u - c s)
//   sliding:  F = -mu_k F_n s / |s|
//
// After each step (advance): a stuck contact whose |-k u - c s| exceeds mu_s F_n starts
// sliding; a sliding contact re-sticks when its slip speed falls below `stick_speed` or its
// slip turns against the spring (it stopped within the step), holding the kinetic force;
// while sliding the anchor is dragged along so that k |u| = mu_k F_n. This is the
// Cundall-Strack tangential spring of discrete-element contact (Cundall & Strack 1979,
// "A discrete numerical model for granular assemblies", Geotechnique 29(1):47-65) with
// separate static and kinetic coefficients. Unlike every memoryless law, a contact loaded
// below mu_s F_n does not creep: its anchored points stay put.
// What it does not do: a Stribeck curve or rate dependence when sliding (mu_k is constant),
// pre-sliding hysteresis beyond the linear spring (see LuGre), rolling resistance.
#pragma once

#include <string_view>
#include <vector>

#include "friction/friction_law.hpp"

namespace tribo::friction {

struct ElasticStickParams {
  double mu_s = 0.0;          // static coefficient [-], >= mu_k
  double mu_k = 0.0;          // kinetic coefficient [-], >= 0
  double stiffness = 0.0;     // k, tangential stiffness per contact point [N/m], > 0
  double damping = 0.0;       // c, tangential damping per contact point [N s/m], >= 0
  double stick_speed = 1e-4;  // slip speed below which a sliding contact re-sticks [m/s], > 0
};

class ElasticStickLaw final : public FrictionLaw {
 public:
  // Throws FrictionParameterError when a rule above is broken or a value is not finite.
  explicit ElasticStickLaw(const ElasticStickParams& params);

  // The sliding branch as a memoryless curve: mu_k sign(v) (what a sliding contact feels).
  double coefficient(double v) const override;
  double slope(double) const override { return 0.0; }
  double maxCoefficient(double) const override { return params_.mu_s; }
  double stickSpeed() const override { return params_.stick_speed; }
  std::vector<double> breakpoints() const override { return {}; }
  std::string_view name() const override { return "elastic_stick"; }

  bool stateful() const override { return true; }
  Eigen::Vector3d stickForce(const Eigen::Vector3d& slip, double fn, const StickView& view,
                             double* mu_out) const override;
  StickUpdate advance(const Eigen::Vector3d& slip, double fn, const StickView& view) const override;

  const ElasticStickParams& params() const { return params_; }

 private:
  ElasticStickParams params_;
};

}  // namespace tribo::friction
