// The events between a branch's consecutive points (detectBranchEvents, orbit_branch.hpp):
// folds and Hopf points from the parameter's turns (dp/ds changing sign where the points'
// parameters turn too), period doublings, tori and stability changes from the multipliers,
// grazing from the smallest slip speed.
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
  const std::size_t n = points.size();
  // Folds and Hopf points: turns of p(s). A turn shows in the points' parameters (they rise
  // to it and fall after it) and in dp/ds, the unit tangent's parameter component, changing
  // sign. The tangent comes from the finite-difference Jacobian, which is noisy near a kink
  // (a joint stop's fold: dp/ds flipped sign six times around one turn), so each turn of the
  // parameters is one fold, in the interval where the parabola through its three points has
  // its vertex, located by dp/ds's sign change there (or in the other interval beside the
  // turn) if there is one and it lies beyond the turning point's parameter, else at that
  // vertex; a sign change away from any turn is noise. At either end, where the parameters
  // cannot show a turn, a sign change of dp/ds is a fold.
  auto step = [&](std::size_t j) { return points[j + 1].parameter - points[j].parameter; };
  auto flips = [&](std::size_t i) { return points[i].dp_ds * points[i + 1].dp_ds < 0.0; };
  std::vector<bool> turned(n, false);  // a fold or Hopf point between i and i + 1
  auto turnAt = [&](std::size_t i, double parameter) {
    const BranchPoint &a = points[i], &b = points[i + 1];
    // Through a Hopf point the branch passes the steady state (amplitude zero) and p(s)
    // turns like at a fold: p - p_H ~ eps^2 for the orbit of amplitude eps, which the phase
    // condition also meets with -eps (the same orbit from its minimum). Told apart by the
    // amplitude: falling into the interval, rising after it, small against the branch's.
    double largest = 0.0;
    for (const BranchPoint& q : points) largest = std::max(largest, q.amplitude_pp);
    const bool falls = i > 0 && points[i - 1].amplitude_pp > a.amplitude_pp;
    const bool rises = i + 2 >= n || points[i + 2].amplitude_pp > b.amplitude_pp;
    const bool hopf = autonomous && falls && rises &&
                      std::min(a.amplitude_pp, b.amplitude_pp) < kHopfAmplitude * largest;
    events.push_back({hopf ? BranchEventKind::kHopf : BranchEventKind::kFold, i, i + 1, parameter});
    turned[i] = true;
  };
  // dp/ds linear in s between points i and i + 1: zero at sigma = a ds / (a - b) past point i,
  // where p(s), its integral, has its vertex p_i + a sigma / 2.
  auto interpolated = [&](std::size_t i) {
    const BranchPoint &a = points[i], &b = points[i + 1];
    const double sigma = a.dp_ds * (b.arclength - a.arclength) / (a.dp_ds - b.dp_ds);
    return a.parameter + 0.5 * a.dp_ds * sigma;
  };
  for (std::size_t j = 1; j + 1 < n; ++j) {
    if (!(step(j - 1) * step(j) < 0.0)) continue;
    const BranchPoint &l = points[j - 1], &m = points[j], &r = points[j + 1];
    const double h0 = m.arclength - l.arclength, h1 = r.arclength - m.arclength;
    const double d0 = step(j - 1) / h0, d1 = step(j) / h1;  // the secants' slopes
    const double curvature = (d1 - d0) / (h0 + h1);         // p(s) = p_j + b x + c x^2
    const double slope = d0 + curvature * h0;               // b, x = s - s_j
    const bool parabola = h0 > 0.0 && h1 > 0.0 && curvature != 0.0;
    const std::size_t at = parabola && -slope / (2.0 * curvature) < 0.0 ? j - 1 : j;
    const std::size_t other = at == j ? j - 1 : j;
    // The turn lies beyond the point where the parameters turn (above it at a maximum of
    // p, below at a minimum): a location from a noisy dp/ds that is not gives way to the
    // parabola's vertex.
    const double vertex = parabola ? m.parameter - slope * slope / (4.0 * curvature) : m.parameter;
    const double outward = step(j - 1) > 0.0 ? 1.0 : -1.0;
    auto located = [&](std::size_t i) {
      const double v = interpolated(i);
      return (v - m.parameter) * outward >= 0.0 ? v : vertex;
    };
    if (flips(at))
      turnAt(at, located(at));
    else if (flips(other))
      turnAt(other, located(other));
    else
      turnAt(at, vertex);
  }
  if (n >= 2 && !turned[0] && flips(0) && (n == 2 || points[0].dp_ds * step(1) < 0.0))
    turnAt(0, interpolated(0));
  if (n >= 3 && !turned[n - 2] && flips(n - 2) && points[n - 1].dp_ds * step(n - 3) < 0.0)
    turnAt(n - 2, interpolated(n - 2));
  // Multipliers crossing the unit circle (period doubling, torus, any change of stability)
  // between consecutive decided points: a point whose stability is undecided has a multiplier
  // on the circle within the flow's accuracy, and on which side it lies is rounding.
  std::size_t decided = n;  // the last decided point before i + 1
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const BranchPoint &a = points[i], &b = points[i + 1];
    if (!a.undecided) decided = i;
    if (decided < n && !b.undecided) {
      const BranchPoint& d = points[decided];
      bool explained = false;
      if (countOf(d, below_minus_one) != countOf(b, below_minus_one)) {
        events.push_back(
            {BranchEventKind::kPeriodDoubling, decided, i + 1,
             crossing(d, b, largestOf(d, real_negative), largestOf(b, real_negative))});
        explained = true;
      }
      if (countOf(d, complex_outside) != countOf(b, complex_outside)) {
        events.push_back({BranchEventKind::kTorus, decided, i + 1,
                          crossing(d, b, largestOf(d, complex_any), largestOf(b, complex_any))});
        explained = true;
      }
      if (d.stable != b.stable && !explained)
        events.push_back({BranchEventKind::kStabilityChange, decided, i + 1,
                          crossing(d, b, largestOf(d, any), largestOf(b, any))});
    }
    if (stick_speed > 0.0 && std::isfinite(a.min_slip) && std::isfinite(b.min_slip) &&
        (a.min_slip < stick_speed) != (b.min_slip < stick_speed))
      events.push_back({BranchEventKind::kGrazing, i, i + 1,
                        crossing(a, b, a.min_slip / stick_speed, b.min_slip / stick_speed)});
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const BranchEvent& x, const BranchEvent& y) { return x.before < y.before; });
  return events;
}

}  // namespace tribo::study
