#include "friction/adams_law.hpp"

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

[[noreturn]] void fail(const std::string& what) { throw FrictionParameterError("adams: " + what); }

const AdamsParams& validated(const AdamsParams& p) {
  for (const auto& [key, value] : {std::pair{"mu_s", p.mu_s}, std::pair{"mu_k", p.mu_k},
                                   std::pair{"v_s", p.v_s}, std::pair{"v_d", p.v_d}}) {
    if (!std::isfinite(value))
      fail(std::string(key) + " must be a finite number (got " + num(value) + ")");
  }
  if (!(p.mu_k >= 0.0)) fail("mu_k must be >= 0 (got " + num(p.mu_k) + ")");
  if (!(p.mu_s > 0.0)) fail("mu_s must be > 0 (got " + num(p.mu_s) + ")");
  if (!(p.mu_s >= p.mu_k)) {
    fail("mu_s must be >= mu_k (got mu_s = " + num(p.mu_s) + ", mu_k = " + num(p.mu_k) + ")");
  }
  if (!(p.v_s > 0.0)) fail("v_s must be > 0 (got " + num(p.v_s) + ")");
  if (!(p.v_d > p.v_s)) {
    fail("v_d must be > v_s (got v_s = " + num(p.v_s) + ", v_d = " + num(p.v_d) + ")");
  }
  return p;
}

}  // namespace

AdamsLaw::AdamsLaw(const AdamsParams& params)
    : params_(validated(params)),
      rise_(0.0, 0.0, params.v_s, params.mu_s),
      fall_(params.v_s, params.mu_s, params.v_d, params.mu_k) {}

double AdamsLaw::coefficient(double v) const {
  const double u = std::abs(v);
  double mu;
  if (u >= params_.v_d) {
    mu = params_.mu_k;
  } else if (u >= params_.v_s) {
    mu = fall_.value(u);
  } else {
    mu = rise_.value(u);  // also where a NaN goes, so it propagates
  }
  return std::copysign(mu, v);
}

double AdamsLaw::slope(double v) const {
  const double u = std::abs(v);
  if (u >= params_.v_d) return 0.0;
  if (u >= params_.v_s) return fall_.derivative(u);
  return rise_.derivative(u);
}

double AdamsLaw::maxCoefficient(double v_max) const {
  // Rises to mu_s at v_s, then falls to mu_k <= mu_s.
  return std::abs(coefficient(std::min(std::abs(v_max), params_.v_s)));
}

}  // namespace tribo::friction
