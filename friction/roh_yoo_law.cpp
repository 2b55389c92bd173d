#include "friction/roh_yoo_law.hpp"

#include <algorithm>
#include <cmath>

#include "friction/parameter_check.hpp"

namespace tribo::friction {
namespace {

const RohYooParams& validated(const RohYooParams& p) {
  const ParameterCheck check("roh_yoo");
  check.finite({{"mu_s", p.mu_s}, {"mu_k", p.mu_k}, {"v_s", p.v_s}, {"a", p.a}, {"beta", p.beta}});
  check.require(p.mu_k >= 0.0, "mu_k must be >= 0", p.mu_k);
  check.require(p.mu_s > p.mu_k,
                "mu_s must exceed mu_k for roh_yoo, since b = -ln(mu_s - mu_k) / ln(a) - v_s",
                "mu_s", p.mu_s, "mu_k", p.mu_k);
  check.require(p.v_s > 0.0, "v_s must be > 0", p.v_s);
  check.require(p.a > 1.0, "a must be > 1", p.a);
  check.require(p.beta > 0.0, "beta must be > 0", p.beta);
  return p;
}

}  // namespace

RohYooLaw::RohYooLaw(const RohYooParams& params)
    : params_(validated(params)),
      inv_v_s_(1.0 / params.v_s),
      ln_a_(std::log(params.a)),
      drop_(params.mu_s - params.mu_k),
      rise_slope_(params.mu_s * params.beta / params.v_s),
      b_(-std::log(params.mu_s - params.mu_k) / std::log(params.a) - params.v_s) {}

double RohYooLaw::coefficient(double v) const {
  const double u = std::abs(v);
  double mu;
  if (u <= params_.v_s) {
    // min: u / v_s can round to just above 1 at u = v_s.
    mu = params_.mu_s * std::pow(std::min(u * inv_v_s_, 1.0), params_.beta);
  } else {
    mu = params_.mu_k + drop_ * std::exp(-ln_a_ * (u - params_.v_s));  // NaN lands here
  }
  return std::copysign(mu, v);
}

void RohYooLaw::coefficientsAt(std::span<const double> v, std::span<double> mu) const {
  coefficientsOf(*this, v, mu);
}

double RohYooLaw::slope(double v) const {
  const double u = std::abs(v);
  if (u <= params_.v_s) return rise_slope_ * std::pow(u * inv_v_s_, params_.beta - 1.0);
  return -ln_a_ * drop_ * std::exp(-ln_a_ * (u - params_.v_s));  // NaN lands here
}

double RohYooLaw::maxCoefficient(double v_max) const {
  // Rises to mu_s at v_s, then decays towards mu_k < mu_s.
  return std::abs(coefficient(std::min(std::abs(v_max), params_.v_s)));
}

}  // namespace tribo::friction
