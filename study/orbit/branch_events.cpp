// The events between a branch's consecutive points (detectBranchEvents, orbit_branch.hpp):
// folds and Hopf points from the parameter's turns, period doublings, tori and stability
// changes from the multipliers, grazing from the smallest slip speed.
#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "study/orbit/orbit_branch.hpp"

namespace tribo::study {

namespace {

// A turn of the parameter where the amplitude has a minimum below this fraction of the
// branch's largest is a Hopf point, not a fold.
constexpr double kHopfAmplitude = 0.2;

// Modulus of the largest multiplier among the non-trivial ones that `pick` selects (0: none).
template <typename Pick>
double largestOf(const BranchPoint& p, Pick pick) {
  double m = 0.0;
  for (std::size_t i = 0; i < p.multipliers.size(); ++i)
    if (static_cast<int>(i) != p.trivial && pick(p.multipliers[i]))
      m = std::max(m, std::abs(p.multipliers[i]));
  return m;
}

bool isReal(std::complex<double> mu) {
  return std::abs(mu.imag()) <= 1e-9 * std::max(1.0, std::abs(mu));
}

template <typename Pick>
int countOf(const BranchPoint& p, Pick pick) {
  int count = 0;
  for (std::size_t i = 0; i < p.multipliers.size(); ++i)
    if (static_cast<int>(i) != p.trivial && pick(p.multipliers[i])) ++count;
  return count;
}

// Where g (a multiplier's modulus) crosses 1 between points a and b, by linear interpolation
// in the parameter (clamped to the interval).
double crossing(const BranchPoint& a, const BranchPoint& b, double ga, double gb) {
  double s = gb != ga ? (1.0 - ga) / (gb - ga) : 0.5;
  s = std::clamp(s, 0.0, 1.0);
  return a.parameter + s * (b.parameter - a.parameter);
}

}  // namespace

std::string branchEventName(BranchEventKind kind) {
  switch (kind) {
    case BranchEventKind::kFold:
      return "fold";
    case BranchEventKind::kPeriodDoubling:
      return "period_doubling";
    case BranchEventKind::kTorus:
      return "torus";
    case BranchEventKind::kStabilityChange:
      return "stability_change";
    case BranchEventKind::kGrazing:
      return "grazing";
    case BranchEventKind::kHopf:
      return "hopf";
  }
  return "unknown";
}

std::vector<BranchEvent> detectBranchEvents(const std::vector<BranchPoint>& points,
                                            double stick_speed, bool autonomous) {
  std::vector<BranchEvent> events;
  auto below_minus_one = [](std::complex<double> mu) { return isReal(mu) && mu.real() < -1.0; };
  auto real_negative = [](std::complex<double> mu) { return isReal(mu) && mu.real() < 0.0; };
  auto complex_outside = [](std::complex<double> mu) { return !isReal(mu) && std::abs(mu) > 1.0; };
  auto complex_any = [](std::complex<double> mu) { return !isReal(mu); };
  auto any = [](std::complex<double>) { return true; };
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const BranchPoint &a = points[i], &b = points[i + 1];
    if (a.dp_ds * b.dp_ds < 0.0) {
      // dp/ds linear in s between the points: zero at sigma = a ds / (a - b) past point i,
      // where p(s), its integral, has its vertex p_i + a sigma / 2.
      const double ds = b.arclength - a.arclength;
      const double sigma = a.dp_ds * ds / (a.dp_ds - b.dp_ds);
      // Through a Hopf point the branch passes the steady state (amplitude zero) and p(s)
      // turns like at a fold: p - p_H ~ eps^2 for the orbit of amplitude eps, which the phase
      // condition also meets with -eps (the same orbit from its minimum). Told apart by the
      // amplitude: falling into the interval, rising after it, small against the branch's.
      double largest = 0.0;
      for (const BranchPoint& q : points) largest = std::max(largest, q.amplitude_pp);
      const bool falls = i > 0 && points[i - 1].amplitude_pp > a.amplitude_pp;
      const bool rises = i + 2 >= points.size() || points[i + 2].amplitude_pp > b.amplitude_pp;
      const bool hopf = autonomous && falls && rises &&
                        std::min(a.amplitude_pp, b.amplitude_pp) < kHopfAmplitude * largest;
      events.push_back({hopf ? BranchEventKind::kHopf : BranchEventKind::kFold, i, i + 1,
                        a.parameter + 0.5 * a.dp_ds * sigma});
    }
    bool explained = false;
    if (countOf(a, below_minus_one) != countOf(b, below_minus_one)) {
      events.push_back({BranchEventKind::kPeriodDoubling, i, i + 1,
                        crossing(a, b, largestOf(a, real_negative), largestOf(b, real_negative))});
      explained = true;
    }
    if (countOf(a, complex_outside) != countOf(b, complex_outside)) {
      events.push_back({BranchEventKind::kTorus, i, i + 1,
                        crossing(a, b, largestOf(a, complex_any), largestOf(b, complex_any))});
      explained = true;
    }
    if (a.stable != b.stable && !explained)
      events.push_back({BranchEventKind::kStabilityChange, i, i + 1,
                        crossing(a, b, largestOf(a, any), largestOf(b, any))});
    if (stick_speed > 0.0 && std::isfinite(a.min_slip) && std::isfinite(b.min_slip) &&
        (a.min_slip < stick_speed) != (b.min_slip < stick_speed))
      events.push_back({BranchEventKind::kGrazing, i, i + 1,
                        crossing(a, b, a.min_slip / stick_speed, b.min_slip / stick_speed)});
  }
  return events;
}

}  // namespace tribo::study
