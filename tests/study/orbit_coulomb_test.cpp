// A Coulomb stick-slip orbit against the exact piecewise solution, derived and solved here.
// The belt reduced to its sliding coordinate with a wall damper c and ideal dry friction,
// static mu_s and kinetic mu_k:
//   stick: x' = v_b while k x + c v_b <= mu_s m g; it breaks away at x_s = (mu_s m g - c v_b)/k;
//   slip:  m x'' + c x' + k x = mu_k m g from x(0) = x_s, x'(0) = v_b: with u = x - mu_k m g/k,
//          u = exp(-zeta w_n t) (A cos w_d t + B sin w_d t), A = u(0), B = (v_b + zeta w_n A)/w_d,
//          until x' returns to v_b (time t_1, place x_1): it sticks again;
//   the period t_1 + (x_s - x_1) / v_b, the amplitude the slip's largest minus smallest x.
// The scene's smooth Stribeck law, mu = tanh(v / v_eps)(mu_k + (mu_s - mu_k) exp(-(v/v_st)^2)),
// tends to that ideal law as v_st and v_eps shrink (each with a step that resolves it): the
// orbit's period and amplitude must approach the piecewise ones, and its multipliers
// {1, 0, ...} (the stick phase forgets where it started).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "study/orbit/periodic_orbit.hpp"

namespace tribo {
namespace {

struct PiecewiseCycle {
  double period = NAN, amplitude_pp = NAN;
};

// The exact stick-slip cycle above (m 10 kg, k 300 N/m, g 9.81, mu_s 0.35, mu_k 0.3: the belt
// scene's values); NaN when the slip never returns to the belt's speed (no stick-slip).
PiecewiseCycle coulombCycle(double v_b, double c) {
  const double m = 10.0, k = 300.0, g = 9.81, mu_s = 0.35, mu_k = 0.3;
  const double wn = std::sqrt(k / m), zeta = c / (2 * m * wn), wd = wn * std::sqrt(1 - zeta * zeta);
  const double x_s = (mu_s * m * g - c * v_b) / k, x_e = mu_k * m * g / k;
  const double A = x_s - x_e, B = (v_b + zeta * wn * A) / wd;
  auto x = [&](double t) {
    return x_e + std::exp(-zeta * wn * t) * (A * std::cos(wd * t) + B * std::sin(wd * t));
  };
  auto v = [&](double t) {
    return std::exp(-zeta * wn * t) * ((wd * B - zeta * wn * A) * std::cos(wd * t) -
                                       (wd * A + zeta * wn * B) * std::sin(wd * t));
  };
  // The first return of x' to v_b from below, bracketed on a fine grid, then bisected.
  const double h = 1e-5;
  double lo_x = x_s, hi_x = x_s;
  for (double t = h; t < 3 * 2 * std::numbers::pi / wd; t += h) {
    lo_x = std::min(lo_x, x(t));
    hi_x = std::max(hi_x, x(t));
    if (v(t) < v_b && v(t + h) >= v_b) {
      double a = t, b = t + h;
      for (int i = 0; i < 60; ++i) ((v(0.5 * (a + b)) < v_b) ? a : b) = 0.5 * (a + b);
      const double t1 = 0.5 * (a + b);
      return {t1 + (x_s - x(t1)) / v_b, hi_x - lo_x};
    }
  }
  return {};
}

TEST(OrbitCoulomb, TheStickSlipOrbitTendsToThePiecewiseSolutionAsTheLawSharpens) {
  const double v_b = 0.15, c = 1.5;
  const PiecewiseCycle exact = coulombCycle(v_b, c);
  ASSERT_TRUE(std::isfinite(exact.period));
  struct Sharpness {
    const char *v_st, *v_eps, *dt;
  };
  std::vector<double> period_error, amplitude_error;
  for (const Sharpness& s :
       {Sharpness{"0.01", "0.001", "2e-4"}, Sharpness{"0.003", "3e-4", "1e-4"}}) {
    SCOPED_TRACE(std::string("v_st ") + s.v_st);
    const io::Scene scene = io::loadScene(
        std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml",
        {"friction=stribeck", std::string("v_d=") + s.v_st, std::string("v_s=") + s.v_eps,
         std::string("dt=") + s.dt, "duration=30", "v_b=0.15", "springs[wall_spring].damping=1.5"});
    const study::OrbitResult r = study::findPeriodicOrbit(scene);
    period_error.push_back(std::abs(r.period / exact.period - 1));
    amplitude_error.push_back(std::abs(r.amplitude_pp / exact.amplitude_pp - 1));
    // Multipliers {1, 0, ...}: the trivial one, and the stick phase collapses every other
    // direction (measured 2.3e-6 and 2.9e-7 from 1; the others at most 1.2e-5).
    ASSERT_GE(r.trivial, 0);
    EXPECT_LT(r.trivial_error, 1e-4);
    EXPECT_LT(r.largest_multiplier, 1e-3);
    EXPECT_TRUE(r.stable);
  }
  // Measured: period 1.1e-2 then 2.4e-3 off the piecewise 1.16077 s, amplitude 5.1e-2 then
  // 1.2e-2 off its 0.06119 m: each error shrinks about as v_st does (by 3.3 here).
  EXPECT_LT(period_error[1], period_error[0] / 3) << period_error[0] << " " << period_error[1];
  EXPECT_LT(amplitude_error[1], amplitude_error[0] / 3)
      << amplitude_error[0] << " " << amplitude_error[1];
  EXPECT_LT(period_error[1], 4e-3);
  EXPECT_LT(amplitude_error[1], 2e-2);
}

// The belt speed above which the ideal law's stick-slip cannot exist: the slip started at
// (x_s, v_b) no longer brings the box back to the belt's speed. Bisected on coulombCycle's
// "returns" between speeds where it does and where it does not.
double piecewiseDisappearanceSpeed(double c, double lo, double hi) {
  EXPECT_TRUE(std::isfinite(coulombCycle(lo, c).period)) << c;
  EXPECT_FALSE(std::isfinite(coulombCycle(hi, c).period)) << c;
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::isfinite(coulombCycle(mid, c).period) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// scenes/belt.yaml with the law that truly sticks (friction/elastic_stick_law.hpp: anchored
// corners up to mu_s F_n, then mu_k; no creep, no Stribeck hump), a wall damper c, at v_b.
io::Scene stickingBelt(double v_b, double c) {
  std::ifstream in(std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::string laws = "friction_laws:\n";
  const std::size_t at = yaml.find(laws);
  EXPECT_NE(at, std::string::npos);
  // Per corner 1e6 N/m and 1000 N s/m: a stuck box creeps on its anchors at k v_b / 4e6 (the
  // wall spring's force grows), under 2e-5 m/s here, and its ringing (630 rad/s) is damped
  // to a third of critical.
  yaml.insert(at + laws.size(),
              "  elastic_stick: {mu_s: $mu_s, mu_k: $mu_k, stiffness: 1.0e6, damping: 1000, "
              "stick_speed: 1.0e-5}\n");
  char v[64], d[64];
  std::snprintf(v, sizeof v, "v_b=%.17g", v_b);
  std::snprintf(d, sizeof d, "springs[wall_spring].damping=%.17g", c);
  return io::loadSceneFromString(yaml, "belt.yaml with elastic_stick",
                                 {"friction=elastic_stick", v, d, "dt=1e-4", "duration=5"});
}

// True when the box, started at rest, sticks to the belt a second time: the first slip
// brings it up to the belt's speed (it starts far below the break-away point), it sticks,
// breaks away at x_s with the belt's speed, and what that slip does is the question. Stuck:
// within 1e-4 m/s of v_b for 0.03 s on end. A slip that passes close to v_b without sticking
// stays that close for 2 sqrt(2e-4 / a2) at most, 0.012 to 0.023 s here (a2 the speed's
// curvature at its peak, w_n^2 times the swing's speed: 1.5 to 6 m/s^3); near the boundary a
// stick lasts (x_s - x_1) / v_b, x_1 = (mu_k m g - c v_b) / k where the speed peaks: 0.08 s
// at 1.5 N s/m, 0.25 s at 10 N s/m.
bool sticksAgain(double v_b, double c) {
  const io::Scene scene = stickingBelt(v_b, c);
  Simulator sim(scene.model);
  const std::size_t box = scene.model->findBody("box")->value;
  const double h = scene.model->options.time_step, hold = 0.03;
  int sticks = 0;
  bool stuck = false;
  double near_since = -1, broke_away = -1;
  for (long k = 0; k < std::lround(scene.model->options.duration / h); ++k) {
    EXPECT_TRUE(sim.step().ok);
    const double t = sim.state().time, rel = v_b - sim.state().bodies[box].velocity.x();
    if (std::abs(rel) < 1e-4) {
      if (near_since < 0) near_since = t;
      if (!stuck && t - near_since >= hold) {
        stuck = true;
        if (++sticks == 2) return true;
      }
    } else {
      if (stuck) broke_away = t;
      near_since = -1;
      stuck = false;
      // A slip that has not brought the box back within a swing (2 pi / w_n = 1.15 s) never
      // will: its swing only shrinks.
      if (broke_away >= 0 && t - broke_away > 1.5) return false;
    }
  }
  ADD_FAILURE() << "undecided at v_b " << v_b;
  return false;
}

// The disappearance condition needs a law that sticks: the regularized laws keep stick-slip
// past it (docs/orbits.md, the Coulomb orbit), the elastic anchors break away at mu_s F_n
// exactly and slide at mu_k, the piecewise law's two branches.
TEST(OrbitCoulomb, StickSlipDisappearsWhereTheSlipNoLongerReturnsToTheBeltSpeed) {
  for (const double c : {1.5, 5.0, 10.0}) {
    SCOPED_TRACE("damper " + std::to_string(c));
    const double exact = piecewiseDisappearanceSpeed(c, 0.01, 0.6);
    // The engine's boundary, bisected from 20% either side of the exact one to 2e-4 of it.
    double lo = 0.8 * exact, hi = 1.2 * exact;
    ASSERT_TRUE(sticksAgain(lo, c));
    ASSERT_FALSE(sticksAgain(hi, c));
    while (hi - lo > 2e-4 * exact) {
      const double mid = 0.5 * (lo + hi);
      (sticksAgain(mid, c) ? lo : hi) = mid;
    }
    const double engine = 0.5 * (lo + hi);
    std::printf("damper %.1f N s/m: stick-slip ends at v_b = %.6f m/s (piecewise %.6f, %.2e)\n", c,
                engine, exact, engine / exact - 1);
    // Measured -4.4e-4, 1.5e-4 and 1.5e-4 (bisected to 1e-4). The law's re-stick speed
    // (1e-5 m/s here) sets it: the slip's closest approach to v_b falls through it a little
    // past the boundary; at the law's default 1e-4 m/s the boundary came out 1.3%, 0.9% and
    // 0.6% high.
    EXPECT_NEAR(engine / exact, 1.0, 2e-3);
  }
}

TEST(OrbitCoulomb, ThePiecewiseCycleIsTheUndampedStickSlipOfThePaper) {
  // A check of the solution above on its own: without the damper the slip is a harmonic swing
  // of u = x - x_e on the circle u^2 + (x'/w_n)^2 = u0^2 + (v_b/w_n)^2 (u0 = x_s - x_e) from
  // (u0, v_b) round to (-u0, v_b): w_n t = 2 pi - 2 atan2(w_n u0, v_b); it then sticks over
  // 2 u0 at v_b, and its amplitude is the circle's diameter.
  const double wn = std::sqrt(30.0), u0 = (0.35 - 0.3) * 10 * 9.81 / 300.0;
  for (const double v_b : {0.5, 1.0, 1.5}) {
    const PiecewiseCycle p = coulombCycle(v_b, 0.0);
    const double slip = (2 * std::numbers::pi - 2 * std::atan2(wn * u0, v_b)) / wn;
    EXPECT_NEAR(p.period, slip + 2 * u0 / v_b, 1e-9) << v_b;
    // The largest and smallest x come from the 1e-5 s grid: within (w_n 1e-5)^2 / 8 of R.
    EXPECT_NEAR(p.amplitude_pp, 2 * std::hypot(u0, v_b / wn), 1e-8) << v_b;
  }
}

}  // namespace
}  // namespace tribo
