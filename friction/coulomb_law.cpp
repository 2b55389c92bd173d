#include "friction/coulomb_law.hpp"

#include <algorithm>
#include <array>
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
  // coefficientsOf's rule (askedAt: 0 at zero speed; a speed equal to the one before it takes
  // its coefficient: a resting box's corners, a translating body's points), with the tanh of
  // the speeds asked gathered and taken in one call (friction/vector_tanh.hpp: the same bits
  // as coefficient's tanhOf), a chunk at a time; then the coefficient as coefficient forms it.
  const std::size_t n = std::min(v.size(), mu.size());
  constexpr std::size_t kChunk = 256;
  std::array<double, kChunk> t;
  for (std::size_t begin = 0; begin < n; begin += kChunk) {
    const std::size_t end = std::min(n, begin + kChunk);
    std::size_t count = 0;
    for (std::size_t i = begin; i < end; ++i)
      if (askedAt(v, i)) t[count++] = v[i] * inv_v_eps_;
    tanhEach(std::span<const double>(t.data(), count), std::span<double>(t.data(), count));
    if (count == end - begin) {  // every speed asked (a granular scene's points)
      for (std::size_t i = begin; i < end; ++i) mu[i] = params_.mu * t[i - begin];
      continue;
    }
    count = 0;
    for (std::size_t i = begin; i < end; ++i)
      mu[i] = askedAt(v, i) ? params_.mu * t[count++] : v[i] == 0.0 ? 0.0 : mu[i - 1];
  }
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
