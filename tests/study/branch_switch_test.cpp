// Branch switching (study/orbit/orbit_branch.hpp, BranchSpec::switch_at), against
// references computed in the test from the pendulums' own equations, never from the engine:
// - the parametric pendulum (scenes/parametric_pendulum.yaml, pivot shaken up and down):
//   hanging straight down is an orbit of the shaking's period; it loses stability where the
//   damped Mathieu equation I_O th'' + c th' + m L (g + a(t)) th = 0 has a Floquet multiplier
//   -1 (found here by the test's own RK4 and bisection). The switch must locate that
//   frequency, and the branch it follows must be orbits of twice the period: each one, taken
//   from its start state and integrated by the test over 2 P of the full nonlinear equation,
//   closes on itself, and over one P it does not (the swing reverses). Near the bifurcation
//   the swing's square grows linearly with the distance to it (a period doubling's normal
//   form), and the pendulum, whose restoring torque softens with the swing, swings there at
//   lower shaking frequencies (supercritical as the frequency falls: stable). Two pendulums,
//   1 kg on 1 m and 50 g on 0.25 m.
// - the forced pendulum (scenes/forced_pendulum.yaml, a harmonic torque at the pivot) at
//   c = 1.566 N m s, f = 0.33231 Hz: its swing symmetric under th(t + P/2) = -th(t) loses
//   stability to an asymmetric pair at a branch point, a real multiplier through +1 without
//   a fold, which the test finds by its own 2-D shooting and bisection in M0. The branch
//   switched to is asymmetric (th(t + P/2) != -th(t)), and each of its orbits closes under the
//   test's integration. Further on, the asymmetric swing (found by a settling run where it is
//   stable) doubles its period where the test's own shooting of it has a multiplier -1.
// - a branch with no period doubling (the forced linear oscillator) ends as asked with no
//   switch and says so.
#include "study/orbit/branch_switch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include "study/csv_text.hpp"
#include "study/orbit/orbit_branch.hpp"

namespace tribo {
namespace {

using study::BranchPoint;
using study::BranchSwitch;

constexpr double kG = 9.81;
constexpr double kPi = std::numbers::pi;
const std::string kParametric = std::string(TRIBO_SOURCE_DIR) + "/scenes/parametric_pendulum.yaml";
const std::string kForced = std::string(TRIBO_SOURCE_DIR) + "/scenes/forced_pendulum.yaml";
const std::string kOscillator = std::string(TRIBO_SOURCE_DIR) + "/scenes/forced_oscillator.yaml";

using Vec2 = std::array<double, 2>;
using Rhs = std::function<Vec2(double, const Vec2&)>;

// Classical RK4 over [0, T] in `steps` steps: the test's own integrator.
Vec2 integrate(const Rhs& f, Vec2 y, double T, int steps) {
  const double h = T / steps;
  for (int i = 0; i < steps; ++i) {
    const double t = i * h;
    const Vec2 k1 = f(t, y);
    const Vec2 k2 = f(t + h / 2, {y[0] + h / 2 * k1[0], y[1] + h / 2 * k1[1]});
    const Vec2 k3 = f(t + h / 2, {y[0] + h / 2 * k2[0], y[1] + h / 2 * k2[1]});
    const Vec2 k4 = f(t + h, {y[0] + h * k3[0], y[1] + h * k3[1]});
    for (int j = 0; j < 2; ++j) y[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
  }
  return y;
}

// The 2x2 monodromy's eigenvalues (real parts; NaN imaginary parts mean a complex pair) of
// the map y -> integrate(y) linearised by central differences around y0 (or exactly, for a
// linear f, from the unit vectors).
struct Eigen2 {
  bool real = false;
  double low = NAN, high = NAN, modulus = NAN;
};
Eigen2 eigenvalues(double a, double b, double c, double d) {
  const double tr = a + d, det = a * d - b * c, disc = tr * tr / 4 - det;
  Eigen2 e;
  e.modulus = std::sqrt(std::abs(det));
  if (disc < 0) return e;
  e.real = true;
  e.low = tr / 2 - std::sqrt(disc);
  e.high = tr / 2 + std::sqrt(disc);
  return e;
}

struct Pendulum {  // the bob on a massless arm: I_O = i_bob + m L^2
  double m, L, i_bob, c;
  double inertia() const { return i_bob + m * L * L; }
};

// The parametric pendulum, pivot velocity V sin(2 pi f t) along z.
struct Parametric : Pendulum {
  double V;
  Rhs rhs(double f, bool linear) const {
    return [=, *this](double t, const Vec2& y) -> Vec2 {
      const double a = 2 * kPi * f * V * std::cos(2 * kPi * f * t);
      const double s = linear ? y[0] : std::sin(y[0]);
      return {y[1], -(c * y[1] + m * L * (kG + a) * s) / inertia()};
    };
  }
  // g(f) = -mu_low - 1 of the hanging orbit's linearisation (> 0: unstable by a multiplier
  // below -1); the modulus - 1 while the pair is complex.
  double g(double f) const {
    const Rhs r = rhs(f, true);
    const Vec2 a = integrate(r, {1, 0}, 1 / f, 4000), b = integrate(r, {0, 1}, 1 / f, 4000);
    const Eigen2 e = eigenvalues(a[0], b[0], a[1], b[1]);
    return e.real ? -e.low - 1 : e.modulus - 1;
  }
  // The period doubling between lo (stable) and hi (unstable) by bisection.
  double periodDoubling(double lo, double hi) const {
    EXPECT_LT(g(lo) * g(hi), 0.0);
    const bool rising = g(hi) > 0;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      ((g(mid) > 0) == rising ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  }
  std::vector<std::string> overrides() const {
    return {"m=" + study::csvNumber(m, 17), "L=" + study::csvNumber(L, 17),
            "i_bob=" + study::csvNumber(i_bob, 17), "c=" + study::csvNumber(c, 17),
            "V=" + study::csvNumber(V, 17)};
  }
};

// The swing angle and its rate from a point's start state: the bob relative to `pivot` (a
// body name, or empty for a pivot fixed at the origin).
Vec2 swing(const study::BranchResult& r, const BranchPoint& p, const std::string& pivot, double L) {
  auto entry = [&](const std::string& name) -> double {
    const auto it = std::find(r.coordinates.begin(), r.coordinates.end(), name);
    if (it == r.coordinates.end()) {
      ADD_FAILURE() << "no coordinate " << name;
      return NAN;
    }
    return p.start[it - r.coordinates.begin()];
  };
  auto rel = [&](const std::string& axis) {
    return entry("bob." + axis) - (pivot.empty() ? 0.0 : entry(pivot + "." + axis));
  };
  const double th = std::atan2(rel("x"), -rel("z"));
  return {th, (rel("vx") * std::cos(th) + rel("vz") * std::sin(th)) / L};
}

double angleGap(const Vec2& a, const Vec2& b) {
  return std::hypot(std::remainder(a[0] - b[0], 2 * kPi), a[1] - b[1]);
}

study::BranchSpec switchSpec(const std::string& parameter, double from, double to, int max_points,
                             BranchSwitch at) {
  study::BranchSpec spec;
  spec.parameter = parameter;
  spec.from = from;
  spec.to = to;
  spec.max_points = max_points;
  spec.norm = study::ArclengthNorm::kScaled;
  spec.switch_at = at;
  return spec;
}

struct ParametricCase {
  const char* name;
  Parametric pendulum;
  double from, to;  // the continuation in f, down through the tongue's upper edge
  double lo, hi;    // a bracket of the period doubling for the reference's bisection
};

// Its name, for ctest's test name (gtest_discover_tests puts the printed value in place of
// the index).
void PrintTo(const ParametricCase& c, std::ostream* os) { *os << c.name; }

class ParametricPendulum : public ::testing::TestWithParam<ParametricCase> {};

TEST_P(ParametricPendulum, SwitchesAtTheMathieuPeriodDoublingToOrbitsOfTwiceThePeriod) {
  const ParametricCase& k = GetParam();
  const Parametric& pend = k.pendulum;
  const double f_pd = pend.periodDoubling(k.lo, k.hi);
  const study::BranchResult r =
      study::continueOrbit(kParametric, pend.overrides(),
                           switchSpec("f", k.from, k.to, 9, BranchSwitch::kPeriodDoubling));
  ASSERT_TRUE(r.switched.found) << r.stop_reason;
  EXPECT_FALSE(r.lost) << r.stop_reason;
  // The primary: the hanging orbit (no swing), stable before the period doubling, the last
  // point past it; its events are that period doubling.
  ASSERT_GE(r.primary.size(), 2u);
  for (const BranchPoint& p : r.primary) EXPECT_LT(p.amplitude_pp, 1e-12) << p.parameter;
  EXPECT_TRUE(r.primary.front().stable);
  EXPECT_FALSE(r.primary.back().stable);
  ASSERT_FALSE(r.primary_events.empty());
  EXPECT_EQ(r.primary_events.back().kind, study::BranchEventKind::kPeriodDoubling);
  // Located (measured: 1.2e-8 and 7.3e-8 of the reference; RK4 at 5 ms against the test's
  // 4000 steps a period), its multiplier -1 to the locating tolerance.
  EXPECT_NEAR(r.switched.parameter / f_pd, 1.0, 1e-6);
  EXPECT_NEAR(r.switched.multiplier.real(), -1.0, 1e-8);
  EXPECT_LT(r.switched.residual, 1e-8);
  // The secondary branch: twice the period, the swing growing as f falls below f_pd.
  ASSERT_GE(r.points.size(), 6u) << r.stop_reason;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const BranchPoint& p = r.points[i];
    SCOPED_TRACE("point " + std::to_string(i) + " f " + study::csvNumber(p.parameter, 10));
    EXPECT_NEAR(p.period * p.parameter, 2.0, 1e-9);
    EXPECT_LT(p.parameter, f_pd);
    if (i > 0) {
      EXPECT_GT(p.amplitude_pp, r.points[i - 1].amplitude_pp);
    }
    EXPECT_TRUE(p.stable);
    const Vec2 y0 = swing(r, p, "shaker", pend.L);
    const Rhs at = pend.rhs(p.parameter, false);
    const double P = 1.0 / p.parameter;
    const Vec2 once = integrate(at, y0, P, 8000), twice = integrate(at, y0, 2 * P, 16000);
    // Closes over 2 P (measured within 2.7e-6 of the swing's scale: the engine's RK4 at 5 ms
    // against the test's 8000 steps a period), not over P (there it is 2.1 and 4.5 scales
    // off: the swing reverses).
    const double scale = std::max(std::abs(y0[0]), 1e-3);
    EXPECT_LT(angleGap(twice, y0), 2e-5 * scale) << "theta0 " << y0[0];
    EXPECT_GT(angleGap(once, y0), 0.5 * scale) << "theta0 " << y0[0];
  }
  // The normal form of a period doubling: the swing^2 linear in f_pd - f near it. Between
  // the second and third points (swings of a few degrees) the ratio holds within 10%.
  auto ratio = [&](const BranchPoint& p) {
    return p.amplitude_pp * p.amplitude_pp / (f_pd - p.parameter);
  };
  EXPECT_NEAR(ratio(r.points[2]) / ratio(r.points[1]), 1.0, 0.1);
}

INSTANTIATE_TEST_SUITE_P(
    Pendulums, ParametricPendulum,
    ::testing::Values(
        ParametricCase{"one_kg_one_metre", {{1.0, 1.0, 1e-4, 0.1}, 0.5}, 1.2, 0.85, 1.06, 1.12},
        ParametricCase{
            "fifty_grams_quarter_metre", {{0.05, 0.25, 1e-4, 0.002}, 0.3}, 2.4, 1.7, 2.0, 2.4}));

// The forced pendulum with a torque M0 sin(2 pi f t) about +y at its fixed pivot, th the
// swing with the bob at x = L sin th (the torque about +y turns it towards -x):
//   I_O th'' = -M0 sin(2 pi f t) - c th' - m g L sin th.
struct Forced : Pendulum {
  double f;
  Rhs rhs(double M0) const {
    return [=, *this](double t, const Vec2& y) -> Vec2 {
      return {y[1], (-M0 * std::sin(2 * kPi * f * t) - c * y[1] - m * kG * L * std::sin(y[0])) /
                        inertia()};
    };
  }
  Vec2 flow(double M0, const Vec2& y) const { return integrate(rhs(M0), y, 1 / f, 3000); }
  // The orbit of period 1/f near y by Newton's method on the test's flow.
  Vec2 orbit(double M0, Vec2 y) const {
    for (int it = 0; it < 40; ++it) {
      const Vec2 F = flow(M0, y);
      const Vec2 res{F[0] - y[0], F[1] - y[1]};
      if (std::hypot(res[0], res[1]) < 1e-12) break;
      const auto J = jacobian(M0, y);
      const double a = J[0] - 1, b = J[1], c2 = J[2], d = J[3] - 1, det = a * d - b * c2;
      y[0] += (-res[0] * d + res[1] * b) / det;
      y[1] += (-a * res[1] + c2 * res[0]) / det;
    }
    return y;
  }
  std::array<double, 4> jacobian(double M0, const Vec2& y) const {  // row-major
    std::array<double, 4> J{};
    for (int j = 0; j < 2; ++j) {
      const double d = 1e-6;
      Vec2 up = y, down = y;
      up[j] += d;
      down[j] -= d;
      const Vec2 a = flow(M0, up), b = flow(M0, down);
      J[j] = (a[0] - b[0]) / (2 * d);
      J[2 + j] = (a[1] - b[1]) / (2 * d);
    }
    return J;
  }
  double largestMultiplier(double M0, const Vec2& y) const {
    const auto J = jacobian(M0, y);
    const Eigen2 e = eigenvalues(J[0], J[1], J[2], J[3]);
    return e.real ? e.high : e.modulus;
  }
  // Where `margin(M0, orbit)` turns from negative to positive in [lo, hi], by bisection, the
  // orbit followed from y (the orbit at lo) on the negative side.
  template <typename Margin>
  double bisect(double lo, double hi, Vec2 y, Margin margin) const {
    for (int i = 0; i < 30; ++i) {
      const double mid = 0.5 * (lo + hi);
      const Vec2 ym = orbit(mid, y);
      if (margin(mid, ym) < 0.0) {
        lo = mid;
        y = ym;
      } else {
        hi = mid;
      }
    }
    return 0.5 * (lo + hi);
  }
  // -mu_low - 1 (> 0: a multiplier below -1), the modulus - 1 while the pair is complex.
  double doublingMargin(double M0, const Vec2& y) const {
    const auto J = jacobian(M0, y);
    const Eigen2 e = eigenvalues(J[0], J[1], J[2], J[3]);
    return e.real ? -e.low - 1 : e.modulus - 1;
  }
};

TEST(BranchSwitch, TheForcedPendulumsSymmetricSwingBranchesToAnAsymmetricPair) {
  const Forced pend{{1.0, 1.0, 1e-4, 1.566}, 0.33231};
  // The reference: the symmetric orbit followed in M0 from 5 N m (settled from rest) to 9.7,
  // then the multiplier through +1 bisected (measured at M0 = 9.8517875).
  Vec2 y{0, 0};
  for (int i = 0; i < 40; ++i) y = pend.flow(5.0, y);
  y = pend.orbit(5.0, y);
  for (double M0 = 5.25; M0 <= 9.7; M0 += 0.25) y = pend.orbit(M0, y);
  const double m_bp = pend.bisect(9.7, 10.0, y, [&](double M0, const Vec2& ym) {
    return pend.largestMultiplier(M0, ym) - 1.0;
  });

  study::BranchSpec spec = switchSpec("M0", 9.0, 12.0, 8, BranchSwitch::kBranchPoint);
  spec.norm = study::ArclengthNorm::kSi;
  spec.step = 0.25;
  const study::BranchResult r = study::continueOrbit(kForced, {"c=1.566", "f=0.33231"}, spec);
  ASSERT_TRUE(r.switched.found) << r.stop_reason;
  EXPECT_EQ(r.switched.kind, study::BranchEventKind::kStabilityChange);
  // Located (measured 7e-8 of the reference, |mu| - 1 = 3.6e-7): at a branch point the orbit
  // at fixed M0 is solved against a Jacobian singular there, so |mu| - 1 does not reach the
  // period doubling's 1e-9 in the locator's 12 orbits.
  EXPECT_NEAR(r.switched.parameter / m_bp, 1.0, 1e-6);
  EXPECT_NEAR(r.switched.multiplier.real(), 1.0, 1e-5);
  // The symmetric primary: th(t + P/2) = -th(t) on each of its orbits (the bob's x is
  // L sin th, odd in th), so x(t + P/2) = -x(t).
  // x at t + P/2 by linear interpolation between the samples (a step apart: within
  // h^2 |x''| / 8, about 2e-5 at 5 ms).
  auto asymmetry = [](const BranchPoint& p) {
    const double half = 0.5 * p.period;
    double worst = 0.0;
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.t.size() && p.t[i] + half <= p.t.back(); ++i) {
      const double t = p.t[i] + half;
      while (k + 1 < p.t.size() && p.t[k + 1] < t) ++k;
      const double s = (t - p.t[k]) / (p.t[k + 1] - p.t[k]);
      worst = std::max(worst, std::abs(p.x[i] + p.x[k] + s * (p.x[k + 1] - p.x[k])));
    }
    return worst;
  };
  for (const BranchPoint& p : r.primary) EXPECT_LT(asymmetry(p), 1e-4) << p.parameter;  // 3e-5
  // No fold on the way: the bifurcation itself, between the secondary's first two points, is
  // the switch's (the first orbit is a off it, with dp/ds 0 to O(a)).
  for (const study::BranchEvent& e : r.events) EXPECT_NE(e.kind, study::BranchEventKind::kFold);
  // The secondary: the period stays 1/f, the orbits close under the test's integration, and
  // past the first one they are asymmetric.
  ASSERT_GE(r.points.size(), 4u) << r.stop_reason;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const BranchPoint& p = r.points[i];
    SCOPED_TRACE("point " + std::to_string(i) + " M0 " + study::csvNumber(p.parameter, 10));
    EXPECT_NEAR(p.period * 0.33231, 1.0, 1e-9);
    const Vec2 y0 = swing(r, p, "", 1.0);
    EXPECT_LT(angleGap(pend.flow(p.parameter, y0), y0), 2e-5);  // measured 0.9-2.5e-6 rad
    if (i > 0) {
      EXPECT_GT(asymmetry(p), 1e-2);  // measured 0.48 to 1.7 from the second point
    }
  }
}

TEST(BranchSwitch, TheForcedPendulumsAsymmetricSwingDoublesItsPeriod) {
  // Past the branch point the asymmetric swing is stable, so a settling run at M0 = 10.2
  // finds it; its branch loses stability by a period doubling, the first of the cascade.
  const Forced pend{{1.0, 1.0, 1e-4, 1.566}, 0.33231};
  study::BranchSpec spec = switchSpec("M0", 10.2, 11.0, 6, BranchSwitch::kPeriodDoubling);
  spec.norm = study::ArclengthNorm::kSi;
  spec.step = 0.1;
  const study::BranchResult r =
      study::continueOrbit(kForced, {"c=1.566", "f=0.33231", "M0=10.2"}, spec);
  ASSERT_TRUE(r.switched.found) << r.stop_reason;
  // The reference: the test's own shooting from the primary's first orbit (its start state),
  // followed in M0 to the bracket the primary gives and bisected on mu = -1.
  double lo = r.primary[r.switched.before].parameter, hi = r.primary[r.switched.after].parameter;
  Vec2 y = pend.orbit(10.2, swing(r, r.primary.front(), "", 1.0));
  for (double M0 = 10.2; M0 < lo; M0 = std::min(M0 + 0.05, lo)) y = pend.orbit(M0, y);
  y = pend.orbit(lo, y);
  ASSERT_LT(pend.doublingMargin(lo, y), 0.0);
  const double m_pd = pend.bisect(
      lo, hi, y, [&](double M0, const Vec2& ym) { return pend.doublingMargin(M0, ym); });
  // Located (measured 4.3e-8 of the reference's 10.460496), the multiplier -1 to 3e-8 (the
  // locator's 12 orbits; the shaken pendulum's reach 1e-9).
  EXPECT_NEAR(r.switched.parameter / m_pd, 1.0, 1e-6) << r.switched.parameter << " " << m_pd;
  EXPECT_NEAR(r.switched.multiplier.real(), -1.0, 1e-7);
  // The new orbits span two forcing periods and close under the test's integration over
  // them, not over one.
  ASSERT_GE(r.points.size(), 3u) << r.stop_reason;
  for (const BranchPoint& p : r.points) {
    SCOPED_TRACE("M0 " + study::csvNumber(p.parameter, 10));
    EXPECT_NEAR(p.period * 0.33231, 2.0, 1e-9);
    const Vec2 y0 = swing(r, p, "", 1.0);
    const Vec2 once = pend.flow(p.parameter, y0), twice = pend.flow(p.parameter, once);
    EXPECT_LT(angleGap(twice, y0), 2e-5);
  }
  EXPECT_GT(angleGap(pend.flow(r.points.back().parameter, swing(r, r.points.back(), "", 1.0)),
                     swing(r, r.points.back(), "", 1.0)),
            1e-3);
}

TEST(BranchSwitch, ABranchWithoutThePeriodDoublingEndsAsAskedAndSaysSo) {
  // The forced linear oscillator: every multiplier inside the unit circle at any frequency.
  study::BranchSpec spec = switchSpec("f", 0.8, 2.5, 40, BranchSwitch::kPeriodDoubling);
  spec.step = 0.3;
  const study::BranchResult r = study::continueOrbit(kOscillator, {}, spec);
  EXPECT_TRUE(r.reached_end) << r.stop_reason;
  EXPECT_FALSE(r.switched.found);
  EXPECT_TRUE(r.primary.empty());
  EXPECT_GE(r.points.size(), 4u);
  EXPECT_NE(r.stop_reason.find("no period doubling"), std::string::npos) << r.stop_reason;
}

// The critical mode of a monodromy built from known eigenpairs: M = V diag(mu) V^-1.
Eigen::MatrixXd withEigenpairs(const Eigen::Matrix3d& V, const Eigen::Vector3d& mu) {
  return V * mu.asDiagonal() * V.inverse();
}

TEST(CriticalMode, PicksTheMultiplierNearestMinusOrPlusOneAndItsEigenvector) {
  Eigen::Matrix3d V;
  V << 1, 0.3, 0.2,  //
      0.5, 1, -0.4,  //
      -0.2, 0.6, 1;
  // A period doubling: -1.03 is the one nearest -1 with a negative real part (not -0.2).
  const study::CriticalMode pd =
      study::criticalMode(withEigenpairs(V, {-0.2, -1.03, 0.9}), Eigen::Vector3d::Zero(),
                          BranchSwitch::kPeriodDoubling, false);
  ASSERT_TRUE(pd.ok);
  EXPECT_NEAR(pd.mu.real(), -1.03, 1e-12);
  EXPECT_NEAR(std::abs(pd.v.normalized().dot(V.col(1).normalized())), 1.0, 1e-12);
  // A branch point of an autonomous orbit: 1 and 1.02 are both near +1; the trivial one's
  // eigenvector is the flow's direction (column 0), so 1.02 is the critical one.
  const study::CriticalMode bp = study::criticalMode(withEigenpairs(V, {1.0, 1.02, 0.3}), V.col(0),
                                                     BranchSwitch::kBranchPoint, true);
  ASSERT_TRUE(bp.ok);
  EXPECT_NEAR(bp.mu.real(), 1.02, 1e-12);
  EXPECT_NEAR(std::abs(bp.v.normalized().dot(V.col(1).normalized())), 1.0, 1e-12);
  // The same with the flow along column 1: then 1.0 (column 0) is the critical one.
  const study::CriticalMode other = study::criticalMode(withEigenpairs(V, {1.0, 1.02, 0.3}),
                                                        V.col(1), BranchSwitch::kBranchPoint, true);
  EXPECT_NEAR(other.mu.real(), 1.0, 1e-12);
  // None with a negative real part: no period doubling to follow.
  EXPECT_FALSE(study::criticalMode(withEigenpairs(V, {0.2, 0.5, 0.9}), Eigen::Vector3d::Zero(),
                                   BranchSwitch::kPeriodDoubling, false)
                   .ok);
}

TEST(SwitchEvent, APeriodDoublingOrAStabilityChangeNoFoldExplains) {
  using study::BranchEvent;
  using study::BranchEventKind;
  const std::vector<BranchEvent> events{{BranchEventKind::kFold, 1, 2, 0.5},
                                        {BranchEventKind::kStabilityChange, 1, 2, 0.5},
                                        {BranchEventKind::kStabilityChange, 4, 5, 0.8},
                                        {BranchEventKind::kPeriodDoubling, 6, 7, 0.9}};
  const auto bp = study::switchEvent(events, BranchSwitch::kBranchPoint);
  ASSERT_TRUE(bp);
  EXPECT_EQ(bp->after, 5u);  // the first one is a fold's
  const auto pd = study::switchEvent(events, BranchSwitch::kPeriodDoubling);
  ASSERT_TRUE(pd);
  EXPECT_EQ(pd->after, 7u);
  EXPECT_FALSE(study::switchEvent({events[0], events[1]}, BranchSwitch::kBranchPoint));
}

}  // namespace
}  // namespace tribo
