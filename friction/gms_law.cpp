#include "friction/gms_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "friction/parameter_check.hpp"

namespace tribo::friction {

GmsLaw::GmsLaw(const GmsParams& p) : params_(p), s_{p.mu_c, p.mu_s, p.v_s, p.delta} {
  const ParameterCheck check("gms");
  check.finite({{"elements", static_cast<double>(p.elements)},
                {"stiffness", p.stiffness},
                {"mu_c", p.mu_c},
                {"mu_s", p.mu_s},
                {"v_s", p.v_s},
                {"delta", p.delta},
                {"attraction", p.attraction},
                {"sigma1", p.sigma1},
                {"sigma2", p.sigma2}});
  check.require(p.elements >= 1 && p.elements <= GmsParams::kMaxElements,
                "elements must be an integer in 1.." + std::to_string(GmsParams::kMaxElements),
                p.elements);
  check.require(p.stiffness > 0.0, "stiffness must be > 0 [1/m]", p.stiffness);
  check.require(p.mu_c > 0.0, "mu_c must be > 0", p.mu_c);
  check.require(p.mu_s >= p.mu_c, "mu_s must be >= mu_c", "mu_s", p.mu_s, "mu_c", p.mu_c);
  check.require(p.v_s > 0.0, "v_s must be > 0 [m/s]", p.v_s);
  check.require(p.delta > 0.0, "delta must be > 0", p.delta);
  check.require(p.attraction > 0.0, "attraction must be > 0 [1/s]", p.attraction);
  check.require(p.sigma1 >= 0.0, "sigma1 must be >= 0 [s/m]", p.sigma1);
  check.require(p.sigma2 >= 0.0, "sigma2 must be >= 0 [s/m]", p.sigma2);
  const int n = p.elements;
  const auto count = static_cast<std::size_t>(n);
  if (!p.k.empty() && p.k.size() != count)
    check.fail("give k_1..k_N for all N = " + std::to_string(n) + " elements (got " +
               std::to_string(p.k.size()) + ")");
  if (!p.alpha.empty() && p.alpha.size() != count)
    check.fail("give alpha_1..alpha_N for all N = " + std::to_string(n) + " elements (got " +
               std::to_string(p.alpha.size()) + ")");
  k_ = p.k.empty() ? std::vector<double>(count, p.stiffness / n) : p.k;
  alpha_ = p.alpha;
  if (alpha_.empty()) {
    for (int i = 1; i <= n; ++i) alpha_.push_back(2.0 * i / (n * (n + 1.0)));
  }
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const std::string k_key = "k_" + std::to_string(i + 1);
    const std::string a_key = "alpha_" + std::to_string(i + 1);
    check.require(std::isfinite(k_[i]), k_key + " must be a finite number", k_[i]);
    check.require(k_[i] > 0.0, k_key + " must be > 0 [1/m]", k_[i]);
    check.require(std::isfinite(alpha_[i]), a_key + " must be a finite number", alpha_[i]);
    check.require(alpha_[i] > 0.0, a_key + " must be > 0", alpha_[i]);
    sum += alpha_[i];
    total_stiffness_ += k_[i];
    attraction_over_k_.push_back(p.attraction / k_[i]);
  }
  check.require(std::abs(sum - 1.0) <= 1e-9, "alpha_1..alpha_N must sum to 1", sum);
  damping_per_stiffness_ = p.sigma1 / total_stiffness_;
}

double GmsLaw::coefficient(double v) const {
  if (std::isnan(v)) return v;
  const double steady = s_.value(v) + params_.sigma2 * std::abs(v);
  return v > 0.0 ? steady : v < 0.0 ? -steady : 0.0;
}

void GmsLaw::coefficientsAt(std::span<const double> v, std::span<double> mu) const {
  coefficientsOf(*this, v, mu);
}

double GmsLaw::slope(double v) const { return s_.derivative(std::abs(v)) + params_.sigma2; }

double GmsLaw::maxCoefficient(double v_max) const {
  const double v = std::abs(v_max);
  const double sliding_rate =
      params_.attraction * (1.0 + params_.mu_s / params_.mu_c) / total_stiffness_;
  return params_.mu_s + params_.sigma1 * (v + sliding_rate) + params_.sigma2 * v;
}

std::string GmsLaw::stateName(int i) const {
  static constexpr const char* kAxes[] = {".x", ".y", ".z"};
  const int clamped = std::clamp(i, 0, stateSize() - 1);
  std::string name(1, 'z');
  name.append(std::to_string(clamped / 3 + 1)).append(kAxes[clamped % 3]);
  return name;
}

void GmsLaw::initialState(double* z) const { std::fill(z, z + stateSize(), 0.0); }

bool GmsLaw::sliding(int i, const Eigen::Vector3d& zi, const Eigen::Vector3d& slip) const {
  return slidingAt(i, zi.dot(slip), zi.squaredNorm(), s_.value(slip.norm()));
}

bool GmsLaw::slidingAt(int i, double z_dot_s, double z_squared, double stribeck) const {
  // |k z| >= alpha S (1 - 1e-12), compared squared (no square root per element). The 1e-12
  // band keeps an element settled on its limit sliding whichever way rounding put it (else
  // sigma1 would see its rate flip between 0 and s).
  const double limit = alpha_[i] * stribeck;
  return z_dot_s > 0.0 && k_[i] * k_[i] * z_squared >= limit * limit * (1.0 - 2e-12);
}

void GmsLaw::rate(const double* z, const Eigen::Vector3d& slip, double, double* zdot) const {
  const double v = slip.norm();
  const double stribeck = s_.value(v);
  // A sliding element's rate (C / k_i) (alpha_i s / |s| - k_i z_i / S) written as
  // (C alpha_i / (k_i |s|)) s - (C / S) z_i: one division per call, none per element.
  const double relax = params_.attraction / stribeck;
  const double inv_v = 1.0 / v;  // used only by a sliding element, which needs z . s > 0
  for (int i = 0; i < elements(); ++i) {
    const Eigen::Map<const Eigen::Vector3d> zi(z + 3 * i);
    Eigen::Map<Eigen::Vector3d> rate_i(zdot + 3 * i);
    if (slidingAt(i, zi.dot(slip), zi.squaredNorm(), stribeck)) {
      rate_i = (attraction_over_k_[i] * alpha_[i] * inv_v) * slip - relax * zi;
    } else {
      rate_i = slip;
    }
  }
}

Eigen::Vector3d GmsLaw::force(const double* z, const double* zdot, const Eigen::Vector3d& slip,
                              double fn, double* mu_out) const {
  // sum_i k_i z_i + (sigma1 / K) sum_i k_i dz_i/dt + sigma2 s
  Eigen::Vector3d elastic = Eigen::Vector3d::Zero();
  Eigen::Vector3d rate = Eigen::Vector3d::Zero();
  for (int i = 0; i < elements(); ++i) {
    elastic += k_[i] * Eigen::Map<const Eigen::Vector3d>(z + 3 * i);
    rate += k_[i] * Eigen::Map<const Eigen::Vector3d>(zdot + 3 * i);
  }
  const Eigen::Vector3d per_load = elastic + damping_per_stiffness_ * rate + params_.sigma2 * slip;
  if (mu_out != nullptr) *mu_out = fn > 0.0 ? per_load.norm() : 0.0;
  return -fn * per_load;
}

void GmsLaw::stableStep(double* z, const Eigen::Vector3d& slip, double, double h) const {
  const double v = slip.norm();
  if (v == 0.0 || !(h > 0.0)) return;  // every element sticks at rest
  const double stribeck = s_.value(v);
  const double decay = -std::expm1(-params_.attraction / stribeck * h);  // 1 - e^(-C h / S)
  const double v2 = v * v;
  for (int i = 0; i < elements(); ++i) {
    Eigen::Vector3d zi(z[3 * i], z[3 * i + 1], z[3 * i + 2]);
    // Sticking until z_i . s > 0 and |z_i| >= r (as in elasto_plastic's elastic range).
    const double r = alpha_[i] * stribeck / k_[i];
    const double zs = zi.dot(slip);
    const double t0 = -zs / v2;
    const double disc = zs * zs - v2 * (zi.squaredNorm() - r * r);
    const double t_limit =
        disc >= 0.0 ? (-zs + std::sqrt(disc)) / v2 : -std::numeric_limits<double>::infinity();
    const double t_stick = std::max({0.0, t0, t_limit});
    if (t_stick >= h) {
      zi += h * slip;
    } else {
      zi += t_stick * slip;
      const Eigen::Vector3d steady = (r / v) * slip;
      const double d =
          t_stick == 0.0 ? decay : -std::expm1(-params_.attraction / stribeck * (h - t_stick));
      zi += (steady - zi) * d;
    }
    for (int j = 0; j < 3; ++j) z[3 * i + j] = zi[j];
  }
}

double GmsLaw::stateStiffness(double) const { return params_.attraction / params_.mu_c; }

}  // namespace tribo::friction
