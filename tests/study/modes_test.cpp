// study/modes on the belt scene (scenes/belt.yaml): a box of mass m on a belt at v_b, held
// by a horizontal spring (k, c). Reduced by hand to its one in-plane coordinate x about the
// steady state x_eq = mu(v_b) m g / k (the box at rest, sliding at v_b):
//   m x'' + (c + N mu'(v_b)) x' + k x = 0,   N = m g,
// so the in-plane pair is  sigma = -(c + N mu'(v_b)) / (2 m),  f = sqrt(k/m - sigma^2) / (2 pi),
// with mu' the law's analytic slope (built here from the same parameters, not taken from the
// engine). The vertical contact mode (4 corners of k_c, c_c) is
//   sigma_z = -4 c_c / (2 m),  omega_z = sqrt(4 k_c / m - sigma_z^2),
// and must come out stable. The oracle-free check: a run started 1 mm beside x_eq, whose
// growth (or decay) rate is fitted to the logarithm of its first peaks.
#include "study/modes/modes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <tuple>

#include "friction/friction_law.hpp"
#include "study/early_growth.hpp"
#include "study/scene_run.hpp"
#include "study/sweep/sweep_results.hpp"
#include "study/sweep/sweep_runner.hpp"
#include "support/scene_text.hpp"

namespace tribo::study {
namespace {

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";
constexpr double kMass = 10.0, kSpring = 300.0, kGravity = 9.81;
constexpr double kCornerStiffness = 2.5e5, kCornerDamping = 1.5e3;

std::string beltText(double spring_damping) {
  std::ifstream in(kBelt);
  std::stringstream s;
  s << in.rdbuf();
  std::ostringstream c;
  c << "damping: " << spring_damping << ", rest_length";
  return test::replaced(s.str(), "damping: 0, rest_length", c.str());
}

// The law of the scene's friction_laws section for `name`, at Table 1's parameters.
std::unique_ptr<const friction::FrictionLaw> law(const std::string& name) {
  friction::LawSpec spec{name, {{"mu_s", 0.35}, {"mu_k", 0.3}}, {}};
  if (name == "roh_yoo") spec.values.insert({{"v_s", 0.01}, {"a", 1.5}, {"beta", 1.0 / 3.0}});
  if (name == "recurdyn" || name == "adams") spec.values.insert({{"v_s", 0.01}, {"v_d", 0.15}});
  if (name == "stribeck") spec.values.insert({{"v_st", 0.15}, {"v_eps", 0.01}});
  if (name == "coulomb")
    spec = {name, {{"mu", 0.3}, {"v_eps", 0.01}}, {{"regularization", "tanh"}}};
  return friction::makeFrictionLaw(spec);
}

struct Expected {
  double sigma, frequency, x_eq;
};

Expected expected(const std::string& name, double v_b, double c) {
  const auto mu = law(name);
  const double n = kMass * kGravity;
  const double sigma = -(c + n * mu->slope(v_b)) / (2 * kMass);
  return {sigma, std::sqrt(kSpring / kMass - sigma * sigma) / (2 * std::numbers::pi),
          mu->coefficient(v_b) * n / kSpring};
}

std::vector<std::string> overrides(const std::string& name, double v_b) {
  std::ostringstream v;
  v << "v_b=" << v_b;
  return {"friction=" + name, v.str()};
}

// The mode that moves box.x most, of those slower than the contact mode.
const Mode& inPlane(const ModesResult& r) {
  const Mode* best = nullptr;
  for (const Mode& m : r.modes)
    if (m.dominant.rfind("box.x", 0) == 0 && (!best || m.frequency < best->frequency)) best = &m;
  EXPECT_NE(best, nullptr);
  return best ? *best : r.modes.front();
}

struct Case {
  std::string law;
  double v_b;
};

class BeltModes : public ::testing::TestWithParam<Case> {};

TEST_P(BeltModes, InPlanePairMatchesTheClosedForm) {
  const Case& c = GetParam();
  const io::Scene scene = io::loadScene(kBelt, overrides(c.law, c.v_b));
  const ModesResult r = analyzeModes(scene);
  const Expected e = expected(c.law, c.v_b, 0.0);
  ASSERT_EQ(r.coordinates, 2);  // planar_translation: x and z
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  const Mode& m = inPlane(r);
  EXPECT_NEAR(m.growth_rate, e.sigma, 1e-6 * std::abs(e.sigma) + 1e-9) << c.law << " " << c.v_b;
  EXPECT_NEAR(m.frequency, e.frequency, 1e-7 * e.frequency);
  EXPECT_EQ(m.unstable, e.sigma > 0);
  EXPECT_NEAR(r.steady.state.bodies[1].position.x(), e.x_eq, 1e-9);
  // The vertical contact mode: stable, at its closed form.
  const double sz = -4 * kCornerDamping / (2 * kMass);
  const double wz = std::sqrt(4 * kCornerStiffness / kMass - sz * sz);
  const Mode& z = r.modes.back();
  EXPECT_NEAR(z.growth_rate, sz, 1e-6 * std::abs(sz));
  EXPECT_NEAR(z.frequency, wz / (2 * std::numbers::pi), 1e-6 * wz);
  EXPECT_EQ(r.unstable_count, e.sigma > 0 ? 1 : 0);
}

// Falling branches (unstable) of four laws at several belt speeds, and rising ones (stable:
// the stick branch below v_s, where the growth is a decay faster than the spring).
INSTANTIATE_TEST_SUITE_P(
    Laws, BeltModes,
    ::testing::Values(Case{"roh_yoo", 0.5}, Case{"roh_yoo", 1.5}, Case{"roh_yoo", 3.0},
                      Case{"stribeck", 0.05}, Case{"stribeck", 0.15}, Case{"recurdyn", 0.05},
                      Case{"recurdyn", 0.12}, Case{"adams", 0.08}, Case{"roh_yoo", 0.02}),
    [](const auto& info) {
      std::string v = std::to_string(static_cast<int>(std::lround(info.param.v_b * 1000)));
      return info.param.law + "_" + v + "mm_s";
    });

TEST(BeltModes, RisingSlopeAndSpringDampingAreStable) {
  // Stick branch of roh_yoo (v_b < v_s): positive slope, strongly damped; coulomb (no slope)
  // with a damped spring: decays at c / 2m.
  for (const auto& [name, v_b, c] : {std::tuple{"roh_yoo", 0.005, 0.0}, {"coulomb", 1.5, 2.0}}) {
    const io::Scene scene = io::loadSceneFromString(beltText(c), kBelt, overrides(name, v_b));
    const ModesResult r = analyzeModes(scene);
    EXPECT_EQ(r.unstable_count, 0) << name;
    const Expected e = expected(name, v_b, c);
    EXPECT_LT(r.leading().growth_rate, 0.0);
    if (e.sigma * e.sigma < kSpring / kMass) {
      EXPECT_NEAR(inPlane(r).growth_rate, e.sigma, 1e-6 * std::abs(e.sigma)) << name;
    } else {  // overdamped: two real roots -sigma +- sqrt(sigma^2 - k/m)... of x alone
      const double root = std::sqrt(e.sigma * e.sigma - kSpring / kMass);
      EXPECT_NEAR(r.leading().growth_rate, e.sigma + root, 1e-6 * std::abs(e.sigma)) << name;
    }
  }
}

// Growth rate of x - x_eq from the logarithm of its successive maxima (parabola through the
// three samples around each), least squares over the peaks in [0, t_end].
double measuredGrowth(const TrajectoryRecorder& tr, double x_eq) {
  const auto t = tr.column(tr.columnIndex("t"));
  const auto x = tr.column(tr.columnIndex("box.x"));
  std::vector<double> tp, lp;
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    const double a = x[i - 1] - x_eq, b = x[i] - x_eq, c = x[i + 1] - x_eq;
    if (!(b > a && b >= c && b > 0)) continue;
    const double d = 0.5 * (a - c) / (a - 2 * b + c);  // vertex offset in samples
    tp.push_back(t[i] + d * (t[i + 1] - t[i]));
    lp.push_back(std::log(b - 0.25 * (a - c) * d));
  }
  EXPECT_GE(tp.size(), 8u);
  const double n = static_cast<double>(tp.size());
  double st = 0, sl = 0, stt = 0, stl = 0;
  for (std::size_t i = 0; i < tp.size(); ++i) {
    st += tp[i];
    sl += lp[i];
    stt += tp[i] * tp[i];
    stl += tp[i] * lp[i];
  }
  return (n * stl - st * sl) / (n * stt - st * st);
}

TEST(BeltModes, SimulationGrowsAndDecaysAtThePredictedRate) {
  for (const double c : {0.0, 2.0}) {  // growing (roh_yoo's falling slope), then decaying
    const Expected e = expected("roh_yoo", 1.5, c);
    const ModesResult r =
        analyzeModes(io::loadSceneFromString(beltText(c), kBelt, overrides("roh_yoo", 1.5)));
    const double predicted = inPlane(r).growth_rate;
    std::ostringstream x0;
    x0.precision(17);
    x0 << "x0=" << e.x_eq + 1e-3;
    const io::Scene run =
        io::loadSceneFromString(beltText(c), kBelt, {"friction=roh_yoo", x0.str(), "duration=25"});
    const RunResult result = runScene(run);
    ASSERT_TRUE(result.complete) << result.message;
    const double measured = measuredGrowth(result.trajectory, e.x_eq);
    std::printf("belt c = %g: growth rate closed form %.7g, predicted %.7g, simulated %.7g 1/s\n",
                c, e.sigma, predicted, measured);
    EXPECT_NEAR(measured, predicted, 0.01 * std::abs(predicted)) << "c = " << c;
    EXPECT_NEAR(predicted, e.sigma, 1e-6 * std::abs(e.sigma));
  }
}

// What `tribo run` reports as its early growth (study/early_growth.hpp, from the run's own
// cycles) against tribo modes, within 1%: growing and decaying, at two speeds and masses.
TEST(BeltModes, RunsEarlyGrowthAgreesWithTheModes) {
  for (const auto& [c, v_b, m] : {std::tuple{0.0, 1.5, 10.0}, {2.0, 1.5, 10.0}, {0.0, 0.5, 4.0}}) {
    std::ostringstream set_m, set_v, set_z;
    set_m << "m=" << m;
    set_v << "v_b=" << v_b;
    set_z.precision(17);
    set_z << "z0=" << 0.05 - m * kGravity / (4 * kCornerStiffness);
    std::vector<std::string> set{"friction=roh_yoo", set_m.str(), set_v.str(), set_z.str()};
    const ModesResult r = analyzeModes(io::loadSceneFromString(beltText(c), kBelt, set));
    const double x_eq = r.steady.state.bodies[1].position.x();
    std::ostringstream x0;
    x0.precision(17);
    x0 << "x0=" << x_eq + 1e-3;
    set.push_back(x0.str());
    set.push_back("duration=25");
    const RunResult run = runScene(io::loadSceneFromString(beltText(c), kBelt, set));
    ASSERT_TRUE(run.complete) << run.message;
    const EarlyGrowth g = earlyGrowth(run.summary.cycles);
    ASSERT_TRUE(g.measured);
    const double predicted = inPlane(r).growth_rate;
    std::printf("belt c=%g v_b=%g m=%g: tribo modes %.7g, tribo run's early growth %.7g 1/s\n", c,
                v_b, m, predicted, g.rate);
    EXPECT_NEAR(g.rate, predicted, 0.01 * std::abs(predicted));
    // A small single-mode start: the run says its figure can be trusted.
    EXPECT_TRUE(g.trustworthy) << g.doubt << " (scatter " << g.scatter << ", period spread "
                               << g.period_spread << ")";
  }
}

TEST(BeltModes, SweepPointsGiveTheLeadingModeAndCount) {
  SweepSpec spec;
  spec.scene_path = kBelt;
  spec.axes = {parseListAxis("v_b=0.005,1.5")};
  spec.analysis = SweepAnalysis::kModes;
  const SweepPlan plan = planSweep(spec);
  const std::vector<std::string> columns = sweepColumns(plan.grid, SweepAnalysis::kModes);
  EXPECT_EQ(columns,
            (std::vector<std::string>{"point", "v_b", "status", "max_growth_rate", "frequency",
                                      "unstable_modes", "warnings", "message"}));
  for (std::size_t i = 0; i < 2; ++i) {
    const PointOutcome o = runPoint(plan.setup, plan.grid.overrides(i));
    ASSERT_EQ(o.status, PointStatus::kComplete) << o.message;
    const double v_b = i == 0 ? 0.005 : 1.5;
    const Expected e = expected("roh_yoo", v_b, 0.0);
    if (i == 1) {  // unstable pair
      EXPECT_NEAR(o.max_growth_rate, e.sigma, 1e-6 * e.sigma);
      EXPECT_NEAR(o.growth_frequency, e.frequency, 1e-6 * e.frequency);
      EXPECT_EQ(o.unstable_modes, 1);
    } else {  // overdamped stick branch: the slower real root leads
      EXPECT_NEAR(o.max_growth_rate, e.sigma + std::sqrt(e.sigma * e.sigma - kSpring / kMass),
                  1e-6 * std::abs(e.sigma));
      EXPECT_EQ(o.unstable_modes, 0);
    }
  }
}

TEST(BeltModes, FreeBoxHasTheJointedBoxsPairAndStableRocking) {
  // scenes/belt_free_box.yaml: the same box without its planar joint (six coordinates).
  const io::Scene scene =
      io::loadScene(std::string(TRIBO_SOURCE_DIR) + "/scenes/belt_free_box.yaml");
  const ModesResult r = analyzeModes(scene);
  EXPECT_EQ(r.coordinates, 6);
  const Expected e = expected("roh_yoo", 1.5, 0.0);
  EXPECT_EQ(r.unstable_count, 1);
  EXPECT_EQ(r.leading().dominant, "box.x");
  EXPECT_NEAR(r.leading().growth_rate, e.sigma, 1e-6 * e.sigma);
  EXPECT_NEAR(r.leading().frequency, e.frequency, 1e-6 * e.frequency);
}

TEST(Modes, RefusesWhatItCannotAnalyse) {
  // A box on the belt with no spring: friction drags it along, nothing holds it.
  const std::string text = test::replaced(beltText(0.0), "stiffness: $k,", "stiffness: 0,");
  EXPECT_THROW(analyzeModes(io::loadSceneFromString(text, kBelt, {})), NoSteadyState);
  try {
    analyzeModes(io::loadSceneFromString(text, kBelt, {}));
  } catch (const NoSteadyState& e) {
    EXPECT_NE(std::string(e.what()).find("box.x"), std::string::npos) << e.what();
  }
  // Nothing dynamic: a belt alone.
  const std::string kinematic =
      "bodies:\n"
      "  - {name: belt, kind: kinematic, surface_velocity: [1, 0, 0],\n"
      "     geometry: [{name: surface, shape: halfspace}]}\n";
  EXPECT_THROW(analyzeModes(io::loadSceneFromString(kinematic, "belt_only.yaml", {})), ModesError);
}

}  // namespace
}  // namespace tribo::study
