// scenes/belt.yaml with each law that carries an internal state (--set friction=lugre, dahl,
// elasto_plastic, gms, rate_state), at a belt speed where the box sticks and slips
// (v_b = 0.1 m/s), against a reference computed here, outside the engine: the box's
// one-degree-of-freedom equations
//   m x'' = -k x - m g mu(z, x' - v_b),   z' = f(z, x' - v_b)
// with the law's own rate and force (each law is held to its closed forms in tests/friction),
// integrated by classical RK4 at 1e-5 s (the fastest state rate, sigma0 |s| / mu ~ 3e3 1/s
// for the bristles and v / d_c ~ 1e3 1/s for rate-and-state, times 1e-5 s is 0.03). The
// engine's box rests on four corners under penalty contact, each corner with its own state
// under a quarter of the load, and a planar joint keeps it level: the sum is the reference's.
// Compared: the limit cycle's peak-to-peak amplitude and period (study/oscillation_summary,
// the same analysis for both). Semi-implicit Euler (the exact state update at frozen slip)
// is first order: its error at the finer step is estimated by the difference between two
// steps (1e-4, 5e-5 s), and the engine must lie within twice that estimate plus twice the
// reference's own error (bounded by comparing it at 1e-5 and 2e-5 s), and within 1% (gms,
// whose rate jumps when an element switches, within 1% only: see the test).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/simulator.hpp"
#include "friction/dynamic_law.hpp"
#include "friction/friction_law.hpp"
#include "io/scene_loader.hpp"
#include "study/oscillation_summary.hpp"
#include "support/restart_check.hpp"
#include "support/scene_text.hpp"

namespace tribo {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";
constexpr double kM = 10.0, kK = 300.0, kG = 9.81, kVb = 0.1, kDuration = 20.0;
constexpr double kSample = 1e-3;  // output interval of both series [s]

// The laws as scenes/belt.yaml's friction_laws section builds them from its parameters
// (mu_s 0.35, mu_k 0.3, v_s 0.01, sigma0 1e4, sigma1 30, d_c 1e-4), with the belt at v_b.
friction::LawSpec specOf(const std::string& name) {
  if (name == "lugre" || name == "elasto_plastic")
    return {name,
            {{"sigma0", 1e4},
             {"sigma1", 30.0},
             {"sigma2", 0.0},
             {"mu_c", 0.3},
             {"mu_s", 0.35},
             {"v_s", 0.01}},
            {}};
  if (name == "dahl") return {name, {{"sigma0", 1e4}, {"mu_c", 0.3}}, {}};
  if (name == "gms")
    return {name, {{"stiffness", 1e4}, {"mu_c", 0.3}, {"mu_s", 0.35}, {"v_s", 0.01}}, {}};
  return {name, {{"mu0", 0.3}, {"a", 0.01}, {"b", 0.015}, {"d_c", 1e-4}, {"v0", kVb}}, {}};
}

struct Series {
  std::vector<double> t, x, slip;
};

study::OscillationSummary summaryOf(const Series& s) {
  study::OscillationOptions options;
  options.stick_speed = 0.01;
  return study::summarizeOscillation(s.t, s.x, s.slip, options);
}

Series reference(const std::string& name, double h) {
  const auto owner = friction::makeFrictionLaw(specOf(name));
  const friction::DynamicFrictionLaw& law = *owner->dynamic();
  const int n = law.stateSize();
  const double fn = kM * kG;
  // y = (x, v, z...); f(y) as the equations above.
  using Y = std::vector<double>;
  Y zdot(static_cast<std::size_t>(n));
  auto f = [&](const Y& y, Y& dy) {
    const Eigen::Vector3d slip(y[1] - kVb, 0, 0);
    law.rate(y.data() + 2, slip, fn, zdot.data());
    const Eigen::Vector3d force = law.force(y.data() + 2, zdot.data(), slip, fn, nullptr);
    dy[0] = y[1];
    dy[1] = (-kK * y[0] + force.x()) / kM;
    for (int i = 0; i < n; ++i) dy[2 + i] = zdot[i];
  };
  const std::size_t size = 2 + static_cast<std::size_t>(n);
  Y y(size, 0.0), k1(size), k2(size), k3(size), k4(size), tmp(size);
  law.initialState(y.data() + 2);
  auto axpy = [&](const Y& k, double a) {
    for (std::size_t i = 0; i < size; ++i) tmp[i] = y[i] + a * k[i];
    return tmp;
  };
  Series out;
  const long per_sample = std::lround(kSample / h);
  const long samples = std::lround(kDuration / kSample);
  for (long s = 0; s <= samples; ++s) {
    out.t.push_back(s * kSample);
    out.x.push_back(y[0]);
    out.slip.push_back(y[1] - kVb);
    if (s == samples) break;
    for (long i = 0; i < per_sample; ++i) {
      f(y, k1);
      f(axpy(k1, h / 2), k2);
      f(axpy(k2, h / 2), k3);
      f(axpy(k3, h), k4);
      for (std::size_t j = 0; j < size; ++j)
        y[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    }
  }
  return out;
}

Series engine(const std::string& name, const std::string& dt) {
  const io::Scene scene = io::loadScene(
      kScene,
      {"friction=" + name, "v_b=0.1", "integrator=semi_implicit_euler", "dt=" + dt, "duration=20"});
  Simulator sim(scene.model);
  const int box = scene.model->findBody("box")->value;
  Series out;
  const long samples = std::lround(kDuration / kSample);
  for (long s = 0; s <= samples; ++s) {
    while (sim.state().time < s * kSample - 1e-9) {
      const StepStatus status = sim.step();
      EXPECT_TRUE(status.ok) << status.message;
      if (!status.ok) return out;
    }
    const BodyState& b = sim.state().bodies[box];
    out.t.push_back(sim.state().time);
    out.x.push_back(b.position.x());
    out.slip.push_back(b.velocity.x() - kVb);
  }
  return out;
}

class BeltDynamicLaw : public testing::TestWithParam<std::string> {};

TEST_P(BeltDynamicLaw, LimitCycleConvergesToTheOneDegreeOfFreedomReference) {
  const std::string& name = GetParam();
  const auto ref = summaryOf(reference(name, 1e-5));
  const auto ref_coarse = summaryOf(reference(name, 2e-5));
  ASSERT_TRUE(ref.oscillating) << name;
  // The box sticks: slip reaches zero in each cycle (the reference is a stick-slip cycle, not
  // a harmonic one), and the cycle is period 1 with more than a few cycles settled.
  ASSERT_GT(ref.stuck_fraction, 0.05) << name;
  const Series coarse = engine(name, "1e-4");
  const Series fine = engine(name, "5e-5");
  ASSERT_EQ(fine.t.size(), coarse.t.size());
  const auto a = summaryOf(coarse), b = summaryOf(fine);
  const double ref_error = std::abs(ref.amplitude_pp - ref_coarse.amplitude_pp);
  const double estimate = std::abs(a.amplitude_pp - b.amplitude_pp);  // ~ error at 5e-5
  const double error = std::abs(b.amplitude_pp - ref.amplitude_pp);
  std::printf(
      "%s: amplitude p-p reference %.7g m (%.2g at 2e-5), engine %.7g (1e-4 s) %.7g (5e-5 s): "
      "error %.2g m, first-order estimate %.2g m; period %.6g s against %.6g s\n",
      name.c_str(), ref.amplitude_pp, ref_error, a.amplitude_pp, b.amplitude_pp, error, estimate,
      b.period, ref.period);
  // Within the 1% that a speed-against-accuracy study asks for, every law.
  EXPECT_LT(error, 0.01 * ref.amplitude_pp) << name;
  EXPECT_LT(std::abs(b.period - ref.period), 0.01 * ref.period) << name;
  // gms's rate jumps where an element meets or leaves its limit: a fixed step misplaces each
  // switch by up to a step, an O(h) error of no fixed sign, so the error does not fall
  // steadily with the step (engine p-p 5.8455, 5.8477, 5.8446, 5.8431 cm at 1e-4, 5e-5,
  // 2.5e-5, 1.25e-5 s against 5.8413 cm; RK4 at 1e-5 s: 5.8412 cm). The other laws' rates are
  // continuous along the cycle, and there the first-order estimate bounds the error.
  if (name == "gms") return;
  EXPECT_LT(error, 2.0 * estimate + 2.0 * ref_error + 1e-6) << name;
  const double period_estimate = std::abs(a.period - b.period);
  EXPECT_LT(std::abs(b.period - ref.period),
            2.0 * period_estimate + 2.0 * std::abs(ref.period - ref_coarse.period) + 1e-5)
      << name;
}

// Fixed-step methods: a State is all a run needs. Mid-cycle (1.3 s: slipping back after the
// first stick), a copy of the state continues bit for bit like the run it came from.
TEST_P(BeltDynamicLaw, RestartFromASavedStateContinuesBitForBit) {
  for (const char* method : {"rk4", "semi_implicit_euler"}) {
    const io::Scene scene =
        io::loadScene(kScene, {"friction=" + GetParam(), "v_b=0.1", "duration=3", "dt=5e-5",
                               std::string("integrator=") + method});
    // Four corners, four records.
    test::expectRestartContinuesBitForBit(scene.model, 1.3, 400, GetParam() + " " + method, 4);
  }
}

// A second box on the same belt, 1 m aside, with its own wall spring and its own start
// (x0 = 0.03 m): each box must move as it does alone on the belt. A state read or written
// under the other box's contact key would change one of them.
TEST_P(BeltDynamicLaw, TheStateOfOneBoxDoesNotLeakIntoTheOther) {
  std::ifstream in(kScene);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = test::replaced(text.str(), "  - name: box\n", R"(  - name: other
    mass: $m
    position: [0.03, 1, $z0]
    geometry:
      - {name: other_shape, shape: box, size: [0.2, 0.2, 0.1]}
  - name: box
)");
  yaml = test::replaced(yaml, "joints:\n", R"(joints:
  - {name: other_on_belt, type: planar_translation, parent: world, child: other,
     anchor: [0.03, 1, $z0], axis: [0, 1, 0]}
)");
  yaml = test::replaced(yaml, "springs:\n", R"(springs:
  - {name: other_spring, a: world, point_a: [-100, 1, $z0], b: other, point_b: [0.03, 1, $z0],
     stiffness: $k, damping: 0, rest_length: 100}
)");
  yaml = test::replaced(yaml, "contacts:\n", R"(contacts:
  - {a: belt_surface, b: other_shape, material: belt_box}
)");
  const std::vector<std::string> common = {"friction=" + GetParam(), "v_b=0.1", "dt=1e-4",
                                           "integrator=semi_implicit_euler"};
  const io::Scene both = io::loadSceneFromString(yaml, kScene, common);
  std::vector<std::string> moved = common;
  moved.push_back("x0=0.03");
  const io::Scene alone = io::loadScene(kScene, common);
  const io::Scene alone_moved = io::loadScene(kScene, moved);
  Simulator sim(both.model), a(alone.model), b(alone_moved.model);
  const int box = both.model->findBody("box")->value;
  const int other = both.model->findBody("other")->value;
  const int alone_box = alone.model->findBody("box")->value;
  double worst = 0.0;
  while (sim.state().time < 3.0) {
    ASSERT_TRUE(sim.step().ok);
    ASSERT_TRUE(a.step().ok);
    ASSERT_TRUE(b.step().ok);
    worst = std::max(
        {worst,
         std::abs(sim.state().bodies[box].position.x() - a.state().bodies[alone_box].position.x()),
         std::abs(sim.state().bodies[other].position.x() -
                  b.state().bodies[alone_box].position.x())});
  }
  ASSERT_EQ(sim.state().friction_states.size(), 8u);
  // The two boxes' motions differ by centimetres (different starts); each agrees with its
  // run alone to round-off.
  EXPECT_GT(std::abs(sim.state().bodies[box].position.x() - sim.state().bodies[other].position.x()),
            1e-4);
  EXPECT_LT(worst, 1e-12) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(EveryDynamicLaw, BeltDynamicLaw,
                         testing::ValuesIn(friction::knownDynamicFrictionLaws()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace tribo
