#include "friction/coulomb_law.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "friction/parameter_check.hpp"
#include "friction/vector_tanh.hpp"

namespace tribo::friction {
namespace {

const CoulombParams& validated(const CoulombParams& p) {
  const ParameterCheck check("coulomb");
  check.finite({{"mu", p.mu}, {"v_eps", p.v_eps}});
  check.require(p.mu >= 0.0, "mu must be >= 0", p.mu);
  check.require(p.v_eps > 0.0, "v_eps must be > 0", p.v_eps);
  return p;
}

// sign(v) with sign(0) = 0; NaN stays NaN.
double signOf(double v) { return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : v * 0.0); }

}  // namespace

std::string_view toString(CoulombRegularization regularization) {
  return kCoulombRegularizationNames.view(regularization);
}

CoulombLaw::CoulombLaw(const CoulombParams& params)
    : params_(validated(params)),
      inv_v_eps_(1.0 / params.v_eps),
      ramp_(0.0, 0.0, params.v_eps, params.mu) {}

double CoulombLaw::coefficient(double v) const {
  const double mu = params_.mu;
  switch (params_.regularization) {
    case CoulombRegularization::kNone:
      return mu * signOf(v);
    case CoulombRegularization::kLinear:
      return mu * std::clamp(v * inv_v_eps_, -1.0, 1.0);
    case CoulombRegularization::kTanh:
      return mu * tanhOf(v * inv_v_eps_);
    case CoulombRegularization::kHavsin:
      return std::copysign(ramp_.value(std::abs(v)), v);
  }
  return 0.0;
}

void CoulombLaw::coefficientsAt(std::span<const double> v, std::span<double> mu) const {
  if (params_.regularization != CoulombRegularization::kTanh) {
    coefficientsOf(*this, v, mu);
    return;
  }
  // tanh's arguments in mu, every tanh in one call (friction/vector_tanh.hpp: the same bits
  // as coefficient's tanhOf), then the coefficient: the arithmetic of coefficient, the same
  // bits, and 0 at zero speed as coefficientsAt promises.
  const std::size_t n = std::min(v.size(), mu.size());
  for (std::size_t i = 0; i < n; ++i) mu[i] = v[i] * inv_v_eps_;
  tanhEach(mu.first(n), mu.first(n));
  for (std::size_t i = 0; i < n; ++i) mu[i] = v[i] == 0.0 ? 0.0 : params_.mu * mu[i];
}

double CoulombLaw::slope(double v) const {
  if (std::isnan(v)) return v;
  const double mu = params_.mu;
  switch (params_.regularization) {
    case CoulombRegularization::kNone:
      return 0.0;
    case CoulombRegularization::kLinear:
      return std::abs(v) < params_.v_eps ? mu * inv_v_eps_ : 0.0;
    case CoulombRegularization::kTanh: {
      const double t = tanhOf(v * inv_v_eps_);
      return mu * inv_v_eps_ * (1.0 - t * t);
    }
    case CoulombRegularization::kHavsin:
      return ramp_.derivative(std::abs(v));
  }
  return 0.0;
}

double CoulombLaw::maxCoefficient(double v_max) const {
  // Every regularization is monotone in |v|, so the largest value is the one at v_max.
  return std::abs(coefficient(std::abs(v_max)));
}

std::vector<double> CoulombLaw::breakpoints() const {
  switch (params_.regularization) {
    case CoulombRegularization::kLinear:
    case CoulombRegularization::kHavsin:
      return {params_.v_eps};
    case CoulombRegularization::kNone:
    case CoulombRegularization::kTanh:
      break;
  }
  return {};
}

}  // namespace tribo::friction
