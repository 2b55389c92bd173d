// scenes/incline.yaml and incline_slide.yaml: a block on a tilted plane (a rotated
// half-space, 3D contact on four corners).
// Below atan(mu_s): every memoryless law has mu(0) = 0, so the block creeps at the speed
// v* where mu(v*) = tan(theta) (quasi-static balance); v* is computed here from each law's
// formula by hand (README, SEED.md), not by the library. The stateful elastic_stick law
// must hold the block: under 1 um of creep in 10 s.
// Above atan(mu_s): the block slides with a = g (sin(theta) - mu(v) cos(theta)).
// docs/creep.md tabulates the measured creep (DISABLED_PrintCreepTable prints it).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

const std::string kDir = std::string(TRIBO_SOURCE_DIR) + "/scenes/";
constexpr double kG = 9.81, kMuS = 0.35, kMuK = 0.3, kVs = 0.01, kVd = 0.15;
constexpr double kK = 1e5;  // normal stiffness per corner (incline.yaml)

std::string set(const std::string& name, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return name + "=" + buf;
}

// Overrides placing the block at rest on a plane of slope tan(theta) = slope.
std::vector<std::string> onSlope(double slope, const std::string& law) {
  const double theta = std::atan(slope);
  const double c = 0.05 - 1.0 * kG * std::cos(theta) / (4 * kK);
  return {set("theta", theta), set("px", c * std::sin(theta)), set("pz", c * std::cos(theta)),
          "law=" + law};
}

double bisect(const std::function<double(double)>& f, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Creep speed v* with mu(v*) = r, from each curve's formula.
double creepSpeed(const std::string& law, const std::string& regularization, double r) {
  const double pi = std::numbers::pi;
  if (law == "coulomb") {
    const double x = r / kMuK;  // coulomb uses mu = mu_k, v_eps = v_s
    if (regularization == "linear") return kVs * x;
    if (regularization == "tanh") return kVs * std::atanh(x);
    if (regularization == "havsin") return 2 * kVs / pi * std::asin(std::sqrt(x));
  }
  const double x = r / kMuS;
  if (law == "recurdyn") return 2 * kVs / pi * std::asin(std::sqrt(x));
  if (law == "adams") return kVs * bisect([&](double s) { return s * s * (3 - 2 * s) - x; }, 0, 1);
  if (law == "roh_yoo") return kVs * std::pow(x, 3.0);  // beta = 1/3
  if (law == "stribeck")                                // v_st = v_d, v_eps = v_s, delta = 2
    return bisect(
        [&](double v) {
          return std::tanh(v / kVs) * (kMuK + (kMuS - kMuK) * std::exp(-std::pow(v / kVd, 2))) - r;
        },
        0, kVd);
  return NAN;
}

struct Creep {
  double total;  // displacement down the slope from t = 0 to 10 s [m]
  double creep;  // from t = 1 s to t = 11 s [m]
  double speed;  // at t = 11 s [m/s]
};

Creep measureCreep(double slope, const std::string& law, const std::string& regularization,
                   double dt = 1e-3) {
  auto overrides = onSlope(slope, law);
  overrides.push_back("regularization=" + regularization);
  overrides.push_back(set("dt", dt));
  const auto scene = io::loadScene(kDir + "incline.yaml", overrides);
  const double theta = std::atan(slope);
  const Vec3 down(std::cos(theta), 0, -std::sin(theta));
  Simulator sim(scene.model);
  const Vec3 start = sim.state().bodies[1].position;
  Vec3 at1 = start, at10 = start;
  const long steps = std::lround(11.0 / scene.model->options.time_step);
  for (long i = 1; i <= steps; ++i) {
    EXPECT_TRUE(sim.step().ok);
    if (i == steps / 11) at1 = sim.state().bodies[1].position;
    if (i == 10 * steps / 11) at10 = sim.state().bodies[1].position;
  }
  const BodyState& end = sim.state().bodies[1];
  return {(at10 - start).dot(down), (end.position - at1).dot(down), end.velocity.dot(down)};
}

TEST(InclineScene, MemorylessLawsCreepAtTheSpeedWhereMuEqualsTheSlope) {
  for (double slope : {0.25, 0.1}) {
    for (const auto& [law, reg] :
         std::vector<std::pair<std::string, std::string>>{{"coulomb", "linear"},
                                                          {"coulomb", "tanh"},
                                                          {"coulomb", "havsin"},
                                                          {"recurdyn", ""},
                                                          {"adams", ""},
                                                          {"roh_yoo", ""},
                                                          {"stribeck", ""}}) {
      // roh_yoo's slope is unbounded at 0 (beta = 1/3): at light load its creep speed sits
      // where mu' is steep, and RK4 needs a finer step there (see the next test).
      const double dt = (law == "roh_yoo" && slope < 0.2) ? 2.5e-4 : 1e-3;
      const Creep c = measureCreep(slope, law, reg.empty() ? "tanh" : reg, dt);
      const double expected = creepSpeed(law, reg, slope);
      EXPECT_NEAR(c.speed / expected, 1.0, 1e-3) << law << " " << reg << " slope " << slope;
      EXPECT_NEAR(c.creep / (10 * expected), 1.0, 1e-3) << law << " " << reg << " slope " << slope;
    }
  }
}

TEST(InclineScene, RohYooLightLoadCreepIsStepDependentAtOneMillisecond) {
  // At slope 0.1, v* = 2.3e-4 m/s and mu'(v*) = 142 s/m: the friction damping rate
  // g cos(theta) mu' = 1390 1/s puts RK4 at h = 1 ms into a spurious oscillation whose mean
  // creep is several times v*; at 0.25 ms it is gone. The speed/accuracy trade of the law.
  const double expected = creepSpeed("roh_yoo", "", 0.1);
  EXPECT_GT(measureCreep(0.1, "roh_yoo", "tanh", 1e-3).speed / expected, 2.0);
  EXPECT_NEAR(measureCreep(0.1, "roh_yoo", "tanh", 2.5e-4).speed / expected, 1.0, 1e-3);
}

TEST(InclineScene, ElasticStickHoldsTheBlock) {
  // Released at rest, the tangential springs take the load with an overshoot (damping ratio
  // 0.32 at c_t = 100 N s/m per corner), so slopes close to mu_s would break away at the
  // start; at up to 0.71 of mu_s the block must hold.
  for (double slope : {0.25, 0.1}) {
    const Creep c = measureCreep(slope, "elastic_stick", "tanh");
    EXPECT_LT(std::abs(c.creep), 1e-6) << "slope " << slope;
    // The anchors' elastic deflection m g sin(theta) / (4 k_t), plus the first step before
    // the anchors exist: micrometres.
    EXPECT_LT(std::abs(c.total), 5e-5) << "slope " << slope;
  }
}

TEST(InclineScene, ElasticStickRunRestartsBitForBitFromASavedState) {
  // The anchors are part of the state: a run resumed from a saved state must repeat the
  // original exactly (four loaded corner anchors, elongated by the slope).
  auto overrides = onSlope(0.25, "elastic_stick");
  const auto scene = io::loadScene(kDir + "incline.yaml", overrides);
  Simulator original(scene.model);
  for (int i = 0; i < 300; ++i) ASSERT_TRUE(original.step().ok);
  const State saved = original.state();
  ASSERT_FALSE(saved.stick_anchors.empty());
  for (int i = 0; i < 300; ++i) ASSERT_TRUE(original.step().ok);
  Simulator resumed(scene.model);
  resumed.setState(saved);
  for (int i = 0; i < 300; ++i) ASSERT_TRUE(resumed.step().ok);
  const BodyState& a = original.state().bodies[1];
  const BodyState& b = resumed.state().bodies[1];
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.orientation.coeffs(), b.orientation.coeffs());
  EXPECT_EQ(original.state().stick_anchors, resumed.state().stick_anchors);
}

// Prints the table of docs/creep.md (on demand: --gtest_also_run_disabled_tests).
// Coulomb "none" has no creep speed: it chatters about zero slip.
TEST(InclineScene, DISABLED_PrintCreepTable) {
  std::printf("| law | slope | dt [s] | creep 1-11 s [m] | 10 v* [m] | total 0-10 s [m] |\n");
  for (double slope : {0.25, 0.1}) {
    for (const auto& [law, reg] :
         std::vector<std::pair<std::string, std::string>>{{"coulomb", "none"},
                                                          {"coulomb", "linear"},
                                                          {"coulomb", "tanh"},
                                                          {"coulomb", "havsin"},
                                                          {"recurdyn", ""},
                                                          {"adams", ""},
                                                          {"roh_yoo", ""},
                                                          {"stribeck", ""},
                                                          {"elastic_stick", ""}}) {
      for (double dt : {1e-3, 2.5e-4}) {
        const Creep c = measureCreep(slope, law, reg.empty() ? "tanh" : reg, dt);
        std::printf("| %s %s | %.2f | %g | %.4g | %.4g | %.4g |\n", law.c_str(), reg.c_str(), slope,
                    dt, c.creep, 10 * creepSpeed(law, reg, slope), c.total);
      }
    }
  }
}

// Down-slope acceleration over [t0, t1] and the mean speed there.
std::pair<double, double> slide(const std::string& law, double t0, double t1) {
  const double slope = 0.5, theta = std::atan(slope);
  const auto scene = io::loadScene(kDir + "incline_slide.yaml", onSlope(slope, law));
  const Vec3 down(std::cos(theta), 0, -std::sin(theta));
  Simulator sim(scene.model);
  double v0 = 0, v1 = 0;
  const double dt = scene.model->options.time_step;
  while (sim.state().time < t1 - 0.5 * dt) {
    EXPECT_TRUE(sim.step().ok);
    if (std::abs(sim.state().time - t0) < 0.5 * dt) v0 = sim.state().bodies[1].velocity.dot(down);
  }
  v1 = sim.state().bodies[1].velocity.dot(down);
  return {(v1 - v0) / (t1 - t0), 0.5 * (v0 + v1)};
}

TEST(InclineSlideScene, SlidesWithTheKineticAcceleration) {
  const double theta = std::atan(0.5);
  const double a = kG * (std::sin(theta) - kMuK * std::cos(theta));
  for (const std::string law : {"elastic_stick", "recurdyn", "adams", "stribeck", "coulomb"}) {
    const auto [measured, speed] = slide(law, 1.0, 2.0);
    EXPECT_GT(speed, 10 * kVd) << law;  // far past every transition speed
    EXPECT_NEAR(measured / a, 1.0, 1e-4) << law;
  }
  // roh_yoo approaches mu_k only slowly (a^-(v - v_s)): over a short window the acceleration
  // follows its coefficient at the window's mean speed.
  const auto [measured, speed] = slide("roh_yoo", 1.5, 1.6);
  const double b = -std::log(kMuS - kMuK) / std::log(1.5) - kVs;
  const double mu = std::pow(1.5, -(speed + b)) + kMuK;
  EXPECT_NEAR(measured / (kG * (std::sin(theta) - mu * std::cos(theta))), 1.0, 1e-3);
}

}  // namespace
}  // namespace tribo
