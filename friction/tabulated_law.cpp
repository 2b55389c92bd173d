#include "friction/tabulated_law.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tribo::friction {

namespace {

[[noreturn]] void fail(const std::string& what) {
  throw FrictionParameterError("tabulated: " + what);
}

[[noreturn]] void failAt(std::size_t i, double v, double mu, const std::string& what) {
  std::ostringstream s;
  s << "tabulated: point " << i + 1 << " (v = " << v << ", mu = " << mu << "): " << what;
  throw TabulatedPointError(i, s.str());
}

bool sameSign(double a, double b) { return (a > 0.0 && b > 0.0) || (a < 0.0 && b < 0.0); }

// Shape-preserving end slope from the first two secants d0 (at the end) and d1.
double endSlope(double h0, double h1, double d0, double d1) {
  double m = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
  if (!sameSign(m, d0))
    m = 0.0;
  else if (!sameSign(d0, d1) && std::abs(m) > 3.0 * std::abs(d0))
    m = 3.0 * d0;
  return m;
}

}  // namespace

TabulatedLaw::TabulatedLaw(std::vector<double> speeds, std::vector<double> coefficients)
    : v_(std::move(speeds)), mu_(std::move(coefficients)) {
  if (v_.size() != mu_.size())
    fail("as many speeds as coefficients expected, found " + std::to_string(v_.size()) + " and " +
         std::to_string(mu_.size()));
  if (v_.size() < 2) fail("at least 2 points expected, found " + std::to_string(v_.size()));
  for (std::size_t i = 0; i < v_.size(); ++i) {
    if (!std::isfinite(v_[i]) || !std::isfinite(mu_[i]))
      failAt(i, v_[i], mu_[i], "expected finite numbers");
    if (v_[i] < 0.0) failAt(i, v_[i], mu_[i], "speeds must be >= 0");
    if (mu_[i] < 0.0) failAt(i, v_[i], mu_[i], "coefficients must be >= 0");
    if (i > 0 && !(v_[i] > v_[i - 1])) failAt(i, v_[i], mu_[i], "speeds must increase strictly");
  }
  if (v_[0] == 0.0 && mu_[0] != 0.0)
    failAt(0, v_[0], mu_[0], "at v = 0 the coefficient must be 0 (the law is odd)");
  if (v_[0] > 0.0) {  // join the origin
    v_.insert(v_.begin(), 0.0);
    mu_.insert(mu_.begin(), 0.0);
  }
  const std::size_t n = v_.size();
  std::vector<double> h(n - 1), d(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    h[k] = v_[k + 1] - v_[k];
    d[k] = (mu_[k + 1] - mu_[k]) / h[k];
  }
  slope_.assign(n, 0.0);
  if (n == 2) {
    slope_[0] = slope_[1] = d[0];
  } else {
    for (std::size_t k = 1; k + 1 < n; ++k) {
      if (!sameSign(d[k - 1], d[k])) continue;  // a turn or a flat: slope 0
      const double w1 = 2.0 * h[k] + h[k - 1], w2 = h[k] + 2.0 * h[k - 1];
      slope_[k] = (w1 + w2) / (w1 / d[k - 1] + w2 / d[k]);
    }
    slope_[0] = endSlope(h[0], h[1], d[0], d[1]);
    slope_[n - 1] = endSlope(h[n - 2], h[n - 3], d[n - 2], d[n - 3]);
  }
  const auto peak = std::max_element(mu_.begin(), mu_.end()) - mu_.begin();
  stick_speed_ = static_cast<std::size_t>(peak) + 1 == n ? v_[1] : v_[peak];
}

void TabulatedLaw::evaluate(double v, double& mu, double& dmu) const {
  if (v >= v_.back()) {
    mu = mu_.back();
    dmu = 0.0;
    return;
  }
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(v_.begin(), v_.end(), v) - v_.begin()) - 1;
  const double h = v_[k + 1] - v_[k], t = (v - v_[k]) / h;
  const double t2 = t * t, t3 = t2 * t;
  mu = (2 * t3 - 3 * t2 + 1) * mu_[k] + (t3 - 2 * t2 + t) * h * slope_[k] +
       (-2 * t3 + 3 * t2) * mu_[k + 1] + (t3 - t2) * h * slope_[k + 1];
  dmu = ((6 * t2 - 6 * t) * mu_[k] + (-6 * t2 + 6 * t) * mu_[k + 1]) / h +
        (3 * t2 - 4 * t + 1) * slope_[k] + (3 * t2 - 2 * t) * slope_[k + 1];
}

double TabulatedLaw::coefficient(double v) const {
  double mu = 0.0, dmu = 0.0;
  evaluate(std::abs(v), mu, dmu);
  return v < 0.0 ? -mu : mu;
}

void TabulatedLaw::coefficientsAt(std::span<const double> v, std::span<double> mu) const {
  coefficientsOf(*this, v, mu);
}

double TabulatedLaw::slope(double v) const {
  double mu = 0.0, dmu = 0.0;
  evaluate(std::abs(v), mu, dmu);
  return dmu;  // the derivative of an odd function is even
}

double TabulatedLaw::maxCoefficient(double v_max) const {
  // The interpolant stays within the range of each interval's end values (monotone), so
  // the largest value up to v_max is at a point or at v_max itself.
  const double limit = std::abs(v_max);
  double best = std::abs(coefficient(limit));
  for (std::size_t i = 0; i < v_.size() && v_[i] <= limit; ++i) best = std::max(best, mu_[i]);
  return best;
}

std::vector<double> TabulatedLaw::breakpoints() const {
  return std::vector<double>(v_.begin() + 1, v_.end());
}

}  // namespace tribo::friction
