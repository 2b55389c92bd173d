// study/modes on the pin-on-disc scene (scenes/pin_on_disc.yaml): a pad of mass m, edge 2h,
// pressed by its weight on a disc spinning at omega about z, held in the y-z plane by its
// holder and along y by a spring (k, c); its centre on the track x = R.
// Expectation, derived here by hand. Corner i of the pad sits at (x_i, y_i) = (R +- h, y +- h)
// and carries N_i = m g / 4 (the holder keeps the pad level). The disc under it moves at
// omega z x p = omega (-y_i, x_i), so the disc slides past the pad at
//   S_i = (-omega y_i, omega x_i - y'),   s_i = |S_i|,
// and drags it with mu(s_i) N_i S_i / s_i. The tangential force F(y, y') = sum N_i mu(s_i)
// S_iy / s_i; its derivatives at the steady state (y', y) = (0, y_eq), k y_eq = F(y_eq, 0):
//   -dF/dy' = sum N_i [mu'(s) S_y^2 / s^2 + mu(s) S_x^2 / s^3]        (slope + turning slip)
//   -dF/dy  = omega sum N_i S_x S_y [mu'(s) / s^2 - mu(s) / s^3]
// The vertical motion changes N_i but not y's equation back (the spring is level, the
// contact damping normal), so the tangential pair is that of
//   m y'' + c_e y' + k_e y = 0,   c_e = c - dF/dy',   k_e = k - dF/dy,
//   sigma = -c_e / (2 m),   f = sqrt(k_e / m - sigma^2) / (2 pi).
// For a small pad far from the axis c_e -> c + N mu'(R omega): the belt's closed form.
// mu and mu' come from the law built here from the scene's parameters. The oracle-free
// check: a run started beside y_eq grows (or decays) at sigma (envelope of its cycles).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "friction/friction_law.hpp"
#include "io/scene_loader.hpp"
#include "study/modes/modes.hpp"
#include "study/scene_run.hpp"

namespace tribo::study {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/pin_on_disc.yaml";
constexpr double kGravity = 9.81;

struct Case {
  std::string law;
  double m, k, c, R, omega, pad;
};

std::string text(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

std::vector<std::string> overrides(const Case& p) {
  return {"friction=" + p.law, "m=" + text(p.m),         "k=" + text(p.k),    "c=" + text(p.c),
          "R=" + text(p.R),    "omega=" + text(p.omega), "pad=" + text(p.pad)};
}

// The scene's law `name` at its default parameters.
std::unique_ptr<const friction::FrictionLaw> law(const std::string& name) {
  friction::LawSpec spec{name, {{"mu_s", 0.35}, {"mu_k", 0.3}}, {}};
  if (name == "roh_yoo") spec.values.insert({{"v_s", 0.01}, {"a", 1.5}, {"beta", 1.0 / 3.0}});
  if (name == "stribeck") spec.values.insert({{"v_st", 0.15}, {"v_eps", 0.01}});
  if (name == "coulomb")
    spec = {name, {{"mu", 0.3}, {"v_eps", 0.01}}, {{"regularization", "tanh"}}};
  return friction::makeFrictionLaw(spec);
}

struct Expected {
  double y_eq, sigma, frequency;
};

Expected expected(const Case& p) {
  const auto mu = law(p.law);
  const double h = p.pad / 2, n = p.m * kGravity / 4, w = p.omega;
  // Sums over the four corners at the pad position y (pad at rest).
  struct Sums {
    double force = 0, damping = 0, stiffness = 0;
  };
  auto sums = [&](double y) {
    Sums out;
    for (const double dx : {-h, h})
      for (const double dy : {-h, h}) {
        const double sx = -w * (y + dy), sy = w * (p.R + dx), s = std::hypot(sx, sy);
        const double f = mu->coefficient(s), df = mu->slope(s);
        out.force += n * f * sy / s;
        out.damping += n * (df * sy * sy / (s * s) + f * sx * sx / (s * s * s));
        out.stiffness += w * n * sx * sy * (df / (s * s) - f / (s * s * s));
      }
    return out;
  };
  double y = 0;  // k y = F(y): a contraction, |dF/dy| << k
  for (int i = 0; i < 200; ++i) y = sums(y).force / p.k;
  const Sums at = sums(y);
  const double ce = p.c + at.damping, ke = p.k + at.stiffness;
  const double sigma = -ce / (2 * p.m);
  return {y, sigma, std::sqrt(ke / p.m - sigma * sigma) / (2 * std::numbers::pi)};
}

// The mode that moves pad.y most (the other one is the vertical contact mode).
const Mode& tangential(const ModesResult& r) {
  for (const Mode& m : r.modes)
    if (m.dominant.rfind("pad.y", 0) == 0) return m;
  ADD_FAILURE() << "no mode moves pad.y most";
  return r.modes.front();
}

class PinOnDisc : public ::testing::TestWithParam<Case> {};

TEST_P(PinOnDisc, TangentialPairMatchesTheCornerSum) {
  const Case& p = GetParam();
  const ModesResult r = analyzeModes(io::loadScene(kScene, overrides(p)));
  const Expected e = expected(p);
  ASSERT_EQ(r.coordinates, 2);  // the holder: y and z
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  EXPECT_NEAR(r.steady.state.bodies[1].position.y(), e.y_eq, 1e-9 + 1e-7 * std::abs(e.y_eq));
  const Mode& m = tangential(r);
  EXPECT_NEAR(m.growth_rate, e.sigma, 1e-6 * std::abs(e.sigma) + 1e-9);
  EXPECT_NEAR(m.frequency, e.frequency, 1e-7 * e.frequency);
  EXPECT_EQ(m.unstable, e.sigma > 0);
  EXPECT_EQ(r.unstable_count, e.sigma > 0 ? 1 : 0);
}

// Falling branches at several radii, speeds, masses and stiffnesses (unstable), a pad close
// to the axis (slip up to 45 degrees off the tangent at its inner corners: the turning-slip
// term is a large share), and coulomb with a damped spring (stable: no slope, only c and
// the turning slip damp).
INSTANTIATE_TEST_SUITE_P(Cases, PinOnDisc,
                         ::testing::Values(Case{"roh_yoo", 0.5, 2000, 0, 0.1, 15, 0.02},
                                           Case{"roh_yoo", 1.0, 500, 0, 0.05, 10, 0.03},
                                           Case{"roh_yoo", 0.5, 2000, 0, 0.02, 50, 0.02},
                                           Case{"stribeck", 0.2, 5000, 0, 0.08, 1.0, 0.01},
                                           Case{"coulomb", 0.5, 1000, 0.5, 0.12, 20, 0.02}),
                         [](const auto& info) { return "case" + std::to_string(info.index); });

TEST(PinOnDisc, FarFromTheAxisTheBeltClosedFormHolds) {
  // A 2 mm pad on a 10 m track: the corners' slip turns off the tangent by
  // theta ~ (y_eq +- h) / R ~ 1e-4 rad, and the turning-slip damping N mu sin^2(theta) / s is
  // 3e-7 of the slope's N |mu'|, so sigma -> -N mu'(R omega) / (2 m) to well within 1e-5.
  const Case p{"roh_yoo", 0.5, 2000, 0, 10.0, 0.15, 0.002};
  const ModesResult r = analyzeModes(io::loadScene(kScene, overrides(p)));
  const double belt = -p.m * kGravity * law(p.law)->slope(p.R * p.omega) / (2 * p.m);
  EXPECT_NEAR(tangential(r).growth_rate, belt, 1e-5 * belt);
}

TEST(PinOnDisc, SimulationGrowsAndDecaysAtThePredictedRate) {
  for (const Case& p : {Case{"roh_yoo", 0.5, 2000, 0, 0.1, 15, 0.02},
                        Case{"coulomb", 0.5, 1000, 0.5, 0.12, 20, 0.02}}) {
    const Expected e = expected(p);
    const double predicted =
        tangential(analyzeModes(io::loadScene(kScene, overrides(p)))).growth_rate;
    std::vector<std::string> run = overrides(p);
    run.push_back("y0=" + text(e.y_eq + 1e-4));
    const RunResult result = runScene(io::loadScene(kScene, run));
    ASSERT_TRUE(result.complete) << result.message;
    // Skip the first second (the vertical contact mode's transient, gone at -400 1/s).
    const double measured = envelopeGrowthRate(result.summary.cycles, 1.0, 30.0);
    std::printf("pin on disc %s: growth rate expected %.7g, tribo modes %.7g, simulated %.7g 1/s\n",
                p.law.c_str(), e.sigma, predicted, measured);
    EXPECT_NEAR(measured, predicted, 0.01 * std::abs(predicted)) << p.law;
  }
}

}  // namespace
}  // namespace tribo::study
