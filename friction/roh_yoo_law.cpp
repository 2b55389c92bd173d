#include "friction/roh_yoo_law.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace tribo::friction {
namespace {

std::string num(double value) {
  std::ostringstream os;
  os.precision(15);
  os << value;
  return os.str();
}

[[noreturn]] void fail(const std::string& what) {
  throw FrictionParameterError("roh_yoo: " + what);
}

const RohYooParams& validated(const RohYooParams& p) {
  for (const auto& [key, value] :
       {std::pair{"mu_s", p.mu_s}, std::pair{"mu_k", p.mu_k}, std::pair{"v_s", p.v_s},
        std::pair{"a", p.a}, std::pair{"beta", p.beta}}) {
    if (!std::isfinite(value)) {
      fail(std::string(key) + " must be a finite number (got " + num(value) + ")");
    }
  }
  if (!(p.mu_k >= 0.0)) fail("mu_k must be >= 0 (got " + num(p.mu_k) + ")");
  if (!(p.mu_s > p.mu_k)) {
    fail(
        "mu_s must exceed mu_k for roh_yoo, since b = -ln(mu_s - mu_k) / ln(a) - v_s (got mu_s = " +
        num(p.mu_s) + ", mu_k = " + num(p.mu_k) + ")");
  }
  if (!(p.v_s > 0.0)) fail("v_s must be > 0 (got " + num(p.v_s) + ")");
  if (!(p.a > 1.0)) fail("a must be > 1 (got " + num(p.a) + ")");
  if (!(p.beta > 0.0)) fail("beta must be > 0 (got " + num(p.beta) + ")");
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
