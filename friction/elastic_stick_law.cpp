#include "friction/elastic_stick_law.hpp"

#include "friction/parameter_check.hpp"

namespace tribo::friction {
namespace {

const ElasticStickParams& validated(const ElasticStickParams& p) {
  const ParameterCheck check("elastic_stick");
  check.finite({{"mu_s", p.mu_s},
                {"mu_k", p.mu_k},
                {"stiffness", p.stiffness},
                {"damping", p.damping},
                {"stick_speed", p.stick_speed}});
  check.staticAtLeastKinetic(p.mu_s, p.mu_k);
  check.require(p.stiffness > 0.0, "stiffness must be > 0", p.stiffness);
  check.require(p.damping >= 0.0, "damping must be >= 0", p.damping);
  check.require(p.stick_speed > 0.0, "stick_speed must be > 0", p.stick_speed);
  return p;
}

}  // namespace

ElasticStickLaw::ElasticStickLaw(const ElasticStickParams& params) : params_(validated(params)) {}

double ElasticStickLaw::coefficient(double v) const {
  return v > 0.0 ? params_.mu_k : (v < 0.0 ? -params_.mu_k : 0.0);
}

Eigen::Vector3d ElasticStickLaw::stickForce(const Eigen::Vector3d& slip, double fn,
                                            const StickView& view, double* mu_out) const {
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  if (fn > 0.0) {
    // A sliding contact whose slip has turned against the direction it was sliding in at the
    // step's start (its dragged anchor u) has stopped within the step: it feels its anchored
    // spring, as the stuck contact advance() will make of it. Without this, the stages of a
    // multi-stage step that straddle the stop see opposite kinetic forces that cancel, and the
    // contact can slide on at a constant small speed for ever (RK4: measured 0.7 mm/s 3 s
    // after a box was launched at 0.5 m/s).
    const bool stopped = view.sliding && slip.dot(view.elongation) < 0.0;
    if (view.sliding && !stopped) {
      const double speed = slip.norm();
      if (speed > 0.0) f = (-params_.mu_k * fn / speed) * slip;
    } else {
      f = -params_.stiffness * view.elongation - params_.damping * slip;
      const double magnitude = f.norm();
      if (magnitude > params_.mu_s * fn) f *= params_.mu_k * fn / magnitude;  // breaks away
    }
  }
  if (mu_out != nullptr) *mu_out = fn > 0.0 ? f.norm() / fn : 0.0;
  return f;
}

StickUpdate ElasticStickLaw::advance(const Eigen::Vector3d& slip, double fn,
                                     const StickView& view) const {
  if (!(fn > 0.0)) return {};  // unloaded: nothing to hold, start over stuck and relaxed
  const double hold = params_.mu_k * fn / params_.stiffness;  // elongation at kinetic force
  const double speed = slip.norm();
  const Eigen::Vector3d& u = view.elongation;
  if (view.sliding) {
    if (speed < params_.stick_speed || slip.dot(u) < 0.0) {
      const double length = u.norm();
      return {false, length > hold ? Eigen::Vector3d(u * (hold / length)) : u};
    }
    return {true, (hold / speed) * slip};
  }
  const Eigen::Vector3d trial = -params_.stiffness * u - params_.damping * slip;
  const double magnitude = trial.norm();
  if (magnitude <= params_.mu_s * fn) return {false, u};
  const Eigen::Vector3d direction =
      speed > 0.0 ? Eigen::Vector3d(slip / speed) : Eigen::Vector3d(-trial / magnitude);
  return {true, hold * direction};
}

}  // namespace tribo::friction
