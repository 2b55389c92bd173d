#include "contact/normal_law.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "friction/name_table.hpp"

namespace tribo::contact {

namespace {

// g(z) = z - ln(1 + z), the energy-like integral of the Hunt-Crossley impact in u = alpha d'.
// A series near 0 avoids the cancellation of z - log1p(z) ~ z^2 / 2.
double g(double z) {
  if (std::abs(z) > 1e-2) return z - std::log1p(z);
  double sum = 0.0, power = z;
  for (int k = 2; k <= 14; ++k) {
    power *= z;
    sum += ((k % 2 == 0) ? power : -power) / k;
  }
  return sum;
}

}  // namespace

double NormalLaw::powerEnergy(double depth) const {
  const double p = elasticExponent();
  return stiffness * std::pow(depth, p + 1.0) / (p + 1.0);
}

void NormalLaw::validate() const {
  const std::string law = normalLawName(type);
  auto fail = [&](const std::string& what, double got) {
    throw std::invalid_argument("normal law: " + what + " (got " + std::to_string(got) + ", law " +
                                law + ")");
  };
  if (!std::isfinite(stiffness) || stiffness <= 0.0) fail("stiffness must be > 0", stiffness);
  if (!std::isfinite(damping) || damping < 0.0) fail("damping must be >= 0", damping);
  if (type == NormalLawType::kHertz && damping != 0.0)
    fail("damping must be 0 (Hertz is elastic; use hunt_crossley for a damped Hertz contact)",
         damping);
  if ((type == NormalLawType::kHuntCrossley || type == NormalLawType::kRecurDyn) &&
      (!std::isfinite(exponent) || exponent < 1.0))
    fail("exponent must be >= 1", exponent);
  if (type == NormalLawType::kRecurDyn && (!std::isfinite(max_depth) || max_depth <= 0.0))
    fail("max_depth must be > 0", max_depth);
}

namespace {

constexpr NameTable<NormalLawType, 4> kNormalLawNames{
    "normal law",
    {{{NormalLawType::kLinear, "linear"},
      {NormalLawType::kHertz, "hertz"},
      {NormalLawType::kHuntCrossley, "hunt_crossley"},
      {NormalLawType::kRecurDyn, "recurdyn"}}}};

}  // namespace

NormalLawType normalLawFromName(const std::string& name) { return kNormalLawNames.fromName(name); }

std::string normalLawName(NormalLawType type) { return kNormalLawNames.name(type); }

double huntCrossleyRestitution(double u) {
  if (!(u > 0.0)) return 1.0;
  // Solve g(z) = g(u) for z in (-1, 0): g decreases there from +inf to 0. Bisection on
  // e = -z / u in (0, min(1, 1/u)); the exit speed never exceeds the entry speed.
  const double target = g(u);
  double lo = 0.0, hi = std::min(1.0, 1.0 / u);  // e
  for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(-mid * u) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double huntCrossleyDamping(double e, double v_in) {
  if (!(e > 0.0 && e <= 1.0))
    throw std::invalid_argument("hunt_crossley: restitution must be in (0, 1] (got " +
                                std::to_string(e) + ")");
  if (!(v_in > 0.0) || !std::isfinite(v_in))
    throw std::invalid_argument("hunt_crossley: impact speed must be > 0 (got " +
                                std::to_string(v_in) + ")");
  if (e == 1.0) return 0.0;
  // Restitution decreases monotonically in u = alpha v_in: bracket, then bisect.
  double lo = 0.0, hi = 1.0;
  while (huntCrossleyRestitution(hi) > e) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (huntCrossleyRestitution(mid) > e ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi) / v_in;
}

double hertzStiffness(double e1, double nu1, double e2, double nu2, double r1, double r2) {
  const double inv_e = (1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2;
  const double inv_r = (std::isinf(r1) ? 0.0 : 1.0 / r1) + (std::isinf(r2) ? 0.0 : 1.0 / r2);
  if (!(inv_e > 0.0) || !(inv_r > 0.0) || !std::isfinite(inv_e) || !std::isfinite(inv_r))
    throw std::invalid_argument(
        "hertz stiffness: moduli must be > 0, Poisson ratios in (-1, 0.5] and at least one "
        "radius finite and > 0");
  return 4.0 / 3.0 * std::sqrt(1.0 / inv_r) / inv_e;
}

}  // namespace tribo::contact
