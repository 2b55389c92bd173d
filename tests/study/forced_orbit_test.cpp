// Forced periodic orbits (study/orbit/periodic_orbit.hpp, a scene whose inputs vary in time)
// against closed forms computed here, never against the engine's own runs: the forced linear
// oscillator's steady response (amplitude, phase and waveform) and its Floquet multipliers
// exp(-c T / 2m) at several masses, stiffnesses, dampings and frequencies, below and above
// resonance; a subharmonic request (two forcing periods) giving the same response; Den
// Hartog's forced oscillator with Coulomb friction (continuous sliding) against its exact
// piecewise solution, solved here; the same with stops (stick-slip under forcing) against an
// event-by-event integration of the ideal Coulomb law done here; and the forced scenes it
// must refuse, by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <fstream>
#include <numbers>
#include <sstream>
#include <vector>

#include "io/scene_loader.hpp"
#include "study/orbit/orbit_branch.hpp"
#include "study/orbit/periodic_orbit.hpp"

namespace tribo {
namespace {

const std::string kForced = std::string(TRIBO_SOURCE_DIR) + "/scenes/forced_oscillator.yaml";
constexpr double kPi = std::numbers::pi;

std::string set(const std::string& name, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return name + "=" + buf;
}

struct Oscillator {
  double m, k, c, F0, f;
};

// A test name per case: "m1_k100_c2_f1p2" (gtest names allow letters, digits and '_').
std::string caseName(const Oscillator& o, double friction = -1) {
  auto text = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    std::string s(buf);
    for (char& ch : s)
      if (ch == '.') ch = 'p';
    return s;
  };
  std::string name = std::string("m").append(text(o.m)).append("_k").append(text(o.k));
  name.append("_c").append(text(o.c)).append("_f").append(text(o.f));
  if (friction >= 0) name.append("_muN").append(text(friction));
  return name;
}

std::vector<std::string> overrides(const Oscillator& o) {
  return {set("m", o.m), set("k", o.k), set("c", o.c), set("F0", o.F0), set("f", o.f)};
}

class LinearForcedOrbit : public ::testing::TestWithParam<Oscillator> {};

TEST_P(LinearForcedOrbit, IsTheClosedFormSteadyResponse) {
  const Oscillator o = GetParam();
  const study::OrbitResult r = study::findPeriodicOrbit(io::loadScene(kForced, overrides(o)));
  // m x'' + c x' + k x = F0 sin(w t): x = X sin(w t - phi), X = F0 / |k - m w^2 + i c w|.
  const double w = 2 * kPi * o.f;
  const double X = o.F0 / std::hypot(o.k - o.m * w * w, o.c * w);
  const double phi = std::atan2(o.c * w, o.k - o.m * w * w);
  EXPECT_TRUE(r.forced);
  EXPECT_EQ(r.trivial, -1);
  EXPECT_NEAR(r.forcing_period * o.f, 1.0, 1e-12);
  EXPECT_NEAR(r.period, r.forcing_period, 1e-15);
  EXPECT_LE(r.residual, 1e-9);
  // RK4 at 1 ms: its error per period is (w_n h)^4 / 120 relative, below 1e-8 for these.
  EXPECT_NEAR(r.amplitude_pp / (2 * X), 1.0, 1e-6) << r.amplitude_pp << " vs " << 2 * X;
  // The waveform with its phase: the orbit starts at a whole number of forcing periods.
  double worst = 0.0;
  for (std::size_t i = 0; i < r.t.size(); ++i)
    worst = std::max(worst, std::abs(r.x[i] - X * std::sin(w * r.t[i] - phi)));
  EXPECT_LT(worst, 1e-6 * X);
  // The free motion decays like exp(-c t / 2m): the slide's two multipliers have that
  // modulus over one period; the joint's constrained directions decay faster.
  const double slide = std::exp(-o.c * r.period / (2 * o.m));
  ASSERT_FALSE(r.multipliers.empty());
  EXPECT_NEAR(std::abs(r.multipliers[0]) / slide, 1.0, 1e-6);
  EXPECT_NEAR(std::abs(r.multipliers[1]) / slide, 1.0, 1e-6);
  EXPECT_TRUE(r.stable);
}

INSTANTIATE_TEST_SUITE_P(
    MassesStiffnessesAndFrequencies, LinearForcedOrbit,
    ::testing::Values(Oscillator{1.0, 100.0, 2.0, 10.0, 1.2},       // below resonance
                      Oscillator{5.0, 2000.0, 10.0, 50.0, 3.3},     // near it (w / w_n = 1.04)
                      Oscillator{0.2, 50.0, 0.4, 1.0, 4.0},         // above it
                      Oscillator{20.0, 8.0e4, 200.0, 400.0, 7.5}),  // heavy and stiff
    [](const auto& info) { return caseName(info.param); });

TEST(ForcedOrbit, TwoForcingPeriodsGiveTheSameResponseWithSquaredMultipliers) {
  const Oscillator o{1.0, 100.0, 2.0, 10.0, 1.2};
  io::Scene scene = io::loadScene(kForced, overrides(o));
  study::OrbitSpec two;
  two.periods = 2;
  const study::OrbitResult r1 = study::findPeriodicOrbit(scene);
  const study::OrbitResult r2 = study::findPeriodicOrbit(scene, two);
  EXPECT_EQ(r2.periods, 2);
  EXPECT_NEAR(r2.period, 2 / o.f, 1e-12);
  EXPECT_NEAR(r2.amplitude_pp / r1.amplitude_pp, 1.0, 1e-7);
  EXPECT_NEAR(std::abs(r2.multipliers[0]), std::exp(-o.c * r2.period / (2 * o.m)), 1e-6);
}

// Den Hartog's oscillator m x'' + c x' + k x + F sign(x') = F0 sin(w t) sliding without
// stops: on a half period from the turning point x = -X (v = 0) at t_a, friction is -F and
// x = x_p(t) - F / k + e^{-zeta w_n s} (A cos w_d s + B sin w_d s), s = t - t_a, x_p the
// linear response; the orbit's symmetry x(t + T/2) = -x(t) asks x = X, v = 0 at s = T/2.
// Newton on (X, t_a), with a central-difference Jacobian.
struct DenHartog {
  double X = 0, t_a = 0;
  bool continuous = true;  // v > 0 over the half period (no stop)
};

DenHartog denHartog(const Oscillator& o, double F) {
  const double w = 2 * kPi * o.f, wn = std::sqrt(o.k / o.m),
               zeta = o.c / (2 * std::sqrt(o.k * o.m));
  const double wd = wn * std::sqrt(1 - zeta * zeta);
  const double Xp = o.F0 / std::hypot(o.k - o.m * w * w, o.c * w);
  const double phi = std::atan2(o.c * w, o.k - o.m * w * w);
  auto motion = [&](double X, double t_a, double s, double& x, double& v) {
    const double xp0 = Xp * std::sin(w * t_a - phi), vp0 = Xp * w * std::cos(w * t_a - phi);
    const double A = -X - xp0 + F / o.k, B = (zeta * wn * A - vp0) / wd;
    const double e = std::exp(-zeta * wn * s), cs = std::cos(wd * s), sn = std::sin(wd * s);
    x = Xp * std::sin(w * (t_a + s) - phi) - F / o.k + e * (A * cs + B * sn);
    v = Xp * w * std::cos(w * (t_a + s) - phi) +
        e * ((-zeta * wn * A + wd * B) * cs + (-zeta * wn * B - wd * A) * sn);
  };
  const double half = 0.5 / o.f;
  auto residual = [&](double X, double t_a) {
    double x, v;
    motion(X, t_a, half, x, v);
    return std::array<double, 2>{x - X, v};
  };
  DenHartog d{Xp, (phi - kPi / 2) / w};
  for (int it = 0; it < 50; ++it) {
    const auto F0 = residual(d.X, d.t_a);
    if (std::hypot(F0[0], F0[1] / w) < 1e-15 * Xp) break;
    const double hX = 1e-7 * Xp, ht = 1e-7 / w;
    const auto xp = residual(d.X + hX, d.t_a), xm = residual(d.X - hX, d.t_a);
    const auto tp = residual(d.X, d.t_a + ht), tm = residual(d.X, d.t_a - ht);
    const double a = (xp[0] - xm[0]) / (2 * hX), b = (tp[0] - tm[0]) / (2 * ht);
    const double c = (xp[1] - xm[1]) / (2 * hX), e = (tp[1] - tm[1]) / (2 * ht);
    const double det = a * e - b * c;
    d.X -= (e * F0[0] - b * F0[1]) / det;
    d.t_a -= (-c * F0[0] + a * F0[1]) / det;
  }
  for (int i = 1; i < 1000; ++i) {
    double x, v;
    motion(d.X, d.t_a, half * i / 1000.0, x, v);
    if (v <= 0.0) d.continuous = false;
  }
  return d;
}

struct FrictionCase {
  Oscillator o;
  double F;  // mu N [N]
};

class DenHartogOrbit : public ::testing::TestWithParam<FrictionCase> {};

TEST_P(DenHartogOrbit, IsTheExactPiecewiseSolution) {
  const FrictionCase fc = GetParam();
  const DenHartog ref = denHartog(fc.o, fc.F);
  ASSERT_TRUE(ref.continuous) << "the case must slide without stops";
  std::vector<std::string> set_all = overrides(fc.o);
  set_all.push_back(set("mu_N", fc.F));
  set_all.push_back("v_eps=1e-4");
  set_all.push_back("dt=1e-4");
  const study::OrbitResult r = study::findPeriodicOrbit(io::loadScene(kForced, set_all));
  EXPECT_TRUE(r.stable);
  // The law is Coulomb's regularized by tanh(v / 1e-4 m/s): it differs from the sign only
  // while the block turns, symmetrically about v = 0 (measured -3.4e-6, -2.9e-5 and -5.6e-6
  // for the three cases; at mu N = 4 N the error falls from 7.8e-5 to 4e-6 as v_eps goes from
  // 1e-4 to 1e-5 m/s at a 5 us step, towards this reference).
  EXPECT_NEAR(r.amplitude_pp / (2 * ref.X), 1.0, 1e-4) << r.amplitude_pp << " vs " << 2 * ref.X;
  // The turning point's time within the period.
  const double T = 1 / fc.o.f;
  const auto lowest = std::min_element(r.x.begin(), r.x.end()) - r.x.begin();
  const double t_min = r.t[static_cast<std::size_t>(lowest)];
  const double t_ref = ref.t_a - std::floor(ref.t_a / T) * T;
  EXPECT_NEAR(std::remainder(t_min - t_ref, T), 0.0, 2e-4);
}

INSTANTIATE_TEST_SUITE_P(LoadsAndMasses, DenHartogOrbit,
                         ::testing::Values(FrictionCase{{1.0, 100.0, 2.0, 10.0, 1.2}, 1.0},
                                           FrictionCase{{1.0, 100.0, 2.0, 10.0, 1.2}, 3.0},
                                           FrictionCase{{4.0, 400.0, 2.0, 40.0, 1.8}, 6.0}),
                         [](const auto& info) { return caseName(info.param.o, info.param.F); });

// The same oscillator with ideal Coulomb friction F and stops, integrated here event by event:
// RK4 at h while it slides (friction -F sign(v)); where v changes sign within a step, the
// crossing by linear interpolation and a substep to it, then stuck (v = 0) while the force on
// the block |F0 sin(w t) - k x| stays at or below F, sliding again the other way when it
// exceeds it (checked at each step). The last of `periods` forcing periods gives the
// peak-to-peak amplitude.
double coulombWithStops(const Oscillator& o, double F, double h, int periods) {
  const double w = 2 * kPi * o.f, T = 1 / o.f;
  auto acc = [&](double t, double x, double v, double s) {
    return (o.F0 * std::sin(w * t) - o.k * x - o.c * v - s * F) / o.m;
  };
  auto rk4 = [&](double t, double& x, double& v, double s, double dt) {
    const double k1x = v, k1v = acc(t, x, v, s);
    const double k2x = v + dt / 2 * k1v,
                 k2v = acc(t + dt / 2, x + dt / 2 * k1x, v + dt / 2 * k1v, s);
    const double k3x = v + dt / 2 * k2v,
                 k3v = acc(t + dt / 2, x + dt / 2 * k2x, v + dt / 2 * k2v, s);
    const double k4x = v + dt * k3v, k4v = acc(t + dt, x + dt * k3x, v + dt * k3v, s);
    x += dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  };
  double t = 0, x = 0, v = 0, s = 0, lo = 1e300, hi = -1e300;
  bool stuck = true;
  const long steps = std::lround(periods * T / h);
  for (long i = 0; i < steps; ++i) {
    if (stuck) {
      const double net = o.F0 * std::sin(w * t) - o.k * x;
      if (std::abs(net) > F) stuck = false, s = net > 0 ? 1.0 : -1.0;
    }
    if (!stuck) {
      double xn = x, vn = v;
      rk4(t, xn, vn, s, h);
      if (vn * s < 0) {
        const double share = v / (v - vn);
        rk4(t, x, v, s, share * h);
        v = 0;
        stuck = true;
      } else {
        x = xn, v = vn;
      }
    }
    t = static_cast<double>(i + 1) * h;
    if (t > (periods - 1) * T) lo = std::min(lo, x), hi = std::max(hi, x);
  }
  return hi - lo;
}

TEST(ForcedOrbit, StickSlipUnderForcingConvergesToTheCoulombOscillatorWithStops) {
  // mu N = 7 N against F0 = 10 N: the block stops twice a period. The scene's law is
  // Coulomb's regularized by tanh(v / v_eps), which creeps while the block should stick, so
  // the orbit approaches the ideal law's as v_eps shrinks (measured -2.0e-3 at 1e-4 m/s and
  // -1.9e-4 at 1e-5 m/s, each at a step of v_eps seconds).
  const Oscillator o{1.0, 100.0, 2.0, 10.0, 1.2};
  const double reference = coulombWithStops(o, 7.0, 2e-6, 12);
  std::vector<double> error;
  for (const char* v_eps : {"1e-4", "1e-5"}) {
    std::vector<std::string> set_all = overrides(o);
    set_all.insert(set_all.end(), {"mu_N=7", std::string("v_eps=") + v_eps,
                                   std::string("dt=") + v_eps, "duration=10"});
    const study::OrbitResult r = study::findPeriodicOrbit(io::loadScene(kForced, set_all));
    EXPECT_TRUE(r.stable);
    error.push_back(std::abs(r.amplitude_pp / reference - 1.0));
  }
  EXPECT_LT(error[0], 3e-3) << error[0];
  EXPECT_LT(error[1], 3e-4) << error[1];
}

TEST(ForcedOrbit, RefusesWhatHasNoPeriodNamingTheInput) {
  auto refused = [](const io::Scene& scene, const study::OrbitSpec& spec,
                    const std::string& words) {
    try {
      study::findPeriodicOrbit(scene, spec);
      ADD_FAILURE() << "no error for " << words;
    } catch (const study::OrbitError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  std::ifstream in(kForced);
  std::stringstream text;
  text << in.rdbuf();
  const std::string yaml = text.str();
  // A ramp load: no period, and a period given does not make it repeat.
  std::string ramp = yaml;
  const std::string sines = "{sines: [{amplitude: $F0, frequency: $f}]}";
  ramp.replace(ramp.find(sines), sines.size(), "{ramp: {rate: 1}}");
  const io::Scene ramped = io::loadSceneFromString(ramp, "ramp.yaml");
  refused(ramped, {}, "load 'shaker' force x varies in time with no period known");
  study::OrbitSpec given;
  given.period = 1.0;
  refused(ramped, given, "does not repeat with --period");
  // A period that is not a whole number of the forcing's (1 / 1.2 s).
  given.period = 0.5;
  refused(io::loadScene(kForced), given, "not a whole number of load 'shaker' force x");
  // Two incommensurate tones.
  std::string two = yaml;
  two.replace(two.find(sines), sines.size(),
              "{sines: [{amplitude: 1, frequency: 1}, {amplitude: 1, frequency: 3.14159265}]}");
  refused(io::loadSceneFromString(two, "two.yaml"), {}, "no common period");
  // An autonomous scene takes no forcing period.
  refused(io::loadScene(std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml"), given,
          "apply to forced scenes");
}

TEST(ForcedOrbit, ContinuationRefusesAHopfStartForAForcedSceneNamingItsInput) {
  // A forced scene's branch starts from its forced orbit (tests/study/forced_branch_test.cpp);
  // steady sliding's Hopf point is a start for autonomous orbits only.
  study::BranchSpec b;
  b.parameter = "f";
  b.from = 1.2;
  b.to = 1.5;
  b.from_hopf = true;
  try {
    study::continueOrbit(kForced, {}, b);
    ADD_FAILURE() << "a forced scene was continued from a Hopf point";
  } catch (const study::OrbitError& e) {
    EXPECT_NE(std::string(e.what()).find("load 'shaker' force x varies in time"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("without --from-hopf"), std::string::npos) << e.what();
  }
}

TEST(ForcedOrbit, CommensurateTonesShareTheirCommonPeriod) {
  // 2 Hz and 3 Hz repeat together every second; the response is the sum of the two linear
  // responses, so its peak-to-peak comes from the closed form sampled finely here.
  std::ifstream in(kForced);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::string sines = "{sines: [{amplitude: $F0, frequency: $f}]}";
  yaml.replace(yaml.find(sines), sines.size(),
               "{sines: [{amplitude: 10, frequency: 2}, {amplitude: 5, frequency: 3, phase: 1}]}");
  const study::OrbitResult r =
      study::findPeriodicOrbit(io::loadSceneFromString(yaml, "two_tones.yaml"));
  EXPECT_NEAR(r.forcing_period, 1.0, 1e-12);
  const double m = 1, k = 100, c = 2;
  double lo = 1e300, hi = -1e300;
  for (int i = 0; i < 200000; ++i) {
    const double t = i / 200000.0;
    double x = 0;
    for (auto [F, f, p] : {std::array<double, 3>{10, 2, 0}, std::array<double, 3>{5, 3, 1}}) {
      const double w = 2 * kPi * f;
      x += F / std::hypot(k - m * w * w, c * w) *
           std::sin(w * t + p - std::atan2(c * w, k - m * w * w));
    }
    lo = std::min(lo, x), hi = std::max(hi, x);
  }
  EXPECT_NEAR(r.amplitude_pp / (hi - lo), 1.0, 1e-6);
}

}  // namespace
}  // namespace tribo
