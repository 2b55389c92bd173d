#include "friction/stribeck_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "friction/parameter_check.hpp"

namespace tribo::friction {
namespace {

const StribeckParams& validated(const StribeckParams& p) {
  const ParameterCheck check("stribeck");
  check.finite({{"mu_s", p.mu_s},
                {"mu_k", p.mu_k},
                {"v_st", p.v_st},
                {"delta", p.delta},
                {"viscous", p.viscous},
                {"v_eps", p.v_eps}});
  check.staticAtLeastKinetic(p.mu_s, p.mu_k);
  check.require(p.v_st > 0.0, "v_st must be > 0", p.v_st);
  check.require(p.delta > 0.0, "delta must be > 0", p.delta);
  check.require(p.viscous >= 0.0, "viscous must be >= 0", p.viscous);
  check.require(p.v_eps > 0.0, "v_eps must be > 0", p.v_eps);
  return p;
}

}  // namespace

StribeckLaw::StribeckLaw(const StribeckParams& params)
    : params_(validated(params)),
      inv_v_eps_(1.0 / params.v_eps),
      inv_v_st_(1.0 / params.v_st),
      drop_(params.mu_s - params.mu_k),
      delta_is_two_(params.delta == 2.0) {}

double StribeckLaw::shapePower(double u) const {
  const double x = u * inv_v_st_;
  return delta_is_two_ ? x * x : std::pow(x, params_.delta);
}

double StribeckLaw::decay(double u) const {
  return params_.mu_k + drop_ * std::exp(-shapePower(u));
}

double StribeckLaw::coefficient(double v) const {
  return std::tanh(v * inv_v_eps_) * decay(std::abs(v)) + params_.viscous * v;
}

void StribeckLaw::coefficientsAt(std::span<const double> v, std::span<double> mu) const {
  coefficientsOf(*this, v, mu);
}

double StribeckLaw::slope(double v) const {
  // d/dv [tanh(v/v_eps) g(|v|)] = g / v_eps (1 - tanh^2) + tanh(|v|/v_eps) g'(|v|), with
  // g'(u) = -(mu_s - mu_k) e^{-p} delta p / u, p = (u/v_st)^delta. tanh(u/v_eps)/u -> 1/v_eps
  // as u -> 0, so the second term vanishes there for any delta > 0.
  const double u = std::abs(v);
  const double t = std::tanh(u * inv_v_eps_);
  const double p = shapePower(u);
  const double e = std::exp(-p);
  const double g = params_.mu_k + drop_ * e;
  const double t_over_u = u > 0.0 ? t / u : inv_v_eps_;
  return inv_v_eps_ * (1.0 - t * t) * g - drop_ * e * params_.delta * p * t_over_u +
         params_.viscous;
}

double StribeckLaw::maxOver(double w) const {
  // On [p, q] (0 <= p <= q) tanh rises, the decay g falls and the viscous term rises, so
  // h(v) <= tanh(q / v_eps) g(p) + viscous q. Bisect the intervals whose bound exceeds the
  // best value found until every bound is within the tolerance of it.
  constexpr double kRelTol = 1e-6;
  constexpr int kInitial = 64;
  constexpr std::size_t kMaxIntervals = 1 << 14;
  const auto h = [this](double v) { return coefficient(v); };
  const auto bound = [this](double p, double q) {
    return std::tanh(q * inv_v_eps_) * decay(p) + params_.viscous * q;
  };

  std::vector<std::pair<double, double>> open;
  const double lo = std::min(w, 1e-3 * std::min(params_.v_eps, params_.v_st));
  double best = h(lo);
  open.emplace_back(0.0, lo);
  double prev = lo;
  for (int k = 1; k <= kInitial && lo < w; ++k) {
    const double next = k == kInitial ? w : lo * std::pow(w / lo, double(k) / kInitial);
    best = std::max(best, h(next));
    open.emplace_back(prev, next);
    prev = next;
  }

  double settled = 0.0;  // largest bound among intervals already within the tolerance
  std::vector<std::pair<double, double>> split;
  while (!open.empty()) {
    split.clear();
    for (const auto& [p, q] : open) {
      const double ub = bound(p, q);
      if (ub <= best * (1.0 + kRelTol) ||
          !(q - p > 4.0 * std::numeric_limits<double>::epsilon() * q)) {
        settled = std::max(settled, ub);
        continue;
      }
      const double mid = 0.5 * (p + q);
      best = std::max(best, h(mid));
      split.emplace_back(p, mid);
      split.emplace_back(mid, q);
    }
    open.swap(split);
    if (open.size() > kMaxIntervals) break;  // unreachable for sane parameters; stay rigorous
  }
  for (const auto& [p, q] : open) settled = std::max(settled, bound(p, q));
  return std::max(best, settled);
}

double StribeckLaw::maxCoefficient(double v_max) const {
  const double w = std::abs(v_max);
  if (!(w > 0.0)) return w;  // 0, or NaN passed through
  if (std::isinf(w)) {
    if (params_.viscous > 0.0) return w;
    // Beyond cut, |mu| <= g(cut) <= mu_k + (mu_s - mu_k) e^-40.
    const double cut =
        std::max(40.0 * params_.v_eps, params_.v_st * std::pow(40.0, 1.0 / params_.delta));
    return std::max(maxOver(cut), decay(cut));
  }
  return maxOver(w);
}

}  // namespace tribo::friction
