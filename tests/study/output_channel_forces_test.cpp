// The force and state channels (io/output_channels.hpp: pairs, joints' friction,
// friction_states) against values known without the engine:
//   a stack of five boxes at rest (scenes/box_stack.yaml, automatic contacts): the pair
//   between box k and the one below carries the weight of the boxes above, (6 - k) m g, for
//   two masses three orders of magnitude apart, pairs not touching carry nothing, and the
//   stack's friction forces vanish;
//   the belt's box sliding under LuGre (scenes/belt.yaml, always slipping: the belt at
//   1.5 m/s outruns the box's 0.54 m/s swing): the bristle deflection settles at
//   z = g(v) / sigma0 along the slip, g = mu_k far above v_s, so the pair's z.x is
//   -mu_k / sigma0 and its friction force mu_k m g; the same box on a prismatic joint with
//   the joint's friction (scenes/belt_joint_friction.yaml, coulomb and lugre) reports the
//   same friction force mu_k m g on its coordinate and, with lugre, the same state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "io/scene_loader.hpp"
#include "study/scene_run.hpp"
#include "support/recorded_run.hpp"
#include "support/scene_text.hpp"

namespace tribo::study {
namespace {

using Recorded = test::RecordedRun;

const std::string kScenes = std::string(TRIBO_SOURCE_DIR) + "/scenes/";
constexpr double kG = 9.81;

std::string textOf(const std::string& file) { return test::fileText(kScenes + file); }

Recorded record(const std::string& yaml, const std::string& file,
                const std::vector<std::string>& overrides) {
  return test::recordRun(yaml, kScenes + file, overrides);
}

// The column of pair "a/b" or "b/a" (the builder orders a pair's geometries).
std::span<const double> pairColumn(const TrajectoryRecorder& tr, const std::string& a,
                                   const std::string& b, const std::string& what) {
  for (const std::string& name : {a + "/" + b + "." + what, b + "/" + a + "." + what}) {
    const auto& c = tr.columns();
    if (std::find(c.begin(), c.end(), name) != c.end()) return tr.column(tr.columnIndex(name));
  }
  ADD_FAILURE() << "no column for the pair " << a << ", " << b << ": " << what;
  return {};
}

TEST(OutputChannelForces, StackedBoxesPairsCarryTheWeightAbove) {
  const std::string yaml = test::replaced(textOf("box_stack.yaml"), "  interval: 0.01\n",
                                          "  interval: 0.01\n  channels: [position, pairs]\n");
  for (const double m : {0.05, 1.0, 50.0}) {
    // The normal stiffness scales with the load so that every stack sinks as much.
    const std::string k = "k=" + std::to_string(1e5 * m), c = "c=" + std::to_string(100 * m);
    const Recorded run =
        record(yaml, "box_stack.yaml", {"m=" + std::to_string(m), k, c, "duration=2"});
    const TrajectoryRecorder& tr = run.result.trajectory;
    ASSERT_GT(tr.rows(), 100u);
    const std::size_t last = tr.rows() - 1;
    const std::vector<std::string> shapes = {"floor",      "box1_shape", "box2_shape",
                                             "box3_shape", "box4_shape", "box5_shape"};
    for (int k_box = 1; k_box <= 5; ++k_box) {
      const double weight_above = (6 - k_box) * m * kG;
      const auto normal = pairColumn(tr, shapes[k_box - 1], shapes[k_box], "normal_force");
      ASSERT_FALSE(normal.empty());
      // At rest after 2 s (contact modes damped at 0.16 of critical decay within 0.1 s).
      EXPECT_NEAR(normal[last], weight_above, 1e-6 * weight_above) << "m " << m << " box " << k_box;
      EXPECT_LT(pairColumn(tr, shapes[k_box - 1], shapes[k_box], "friction_force")[last],
                1e-6 * weight_above);
      EXPECT_LT(pairColumn(tr, shapes[k_box - 1], shapes[k_box], "slip")[last], 1e-6);
    }
    // Boxes two apart never touch.
    EXPECT_EQ(pairColumn(tr, "box1_shape", "box3_shape", "normal_force")[last], 0.0);
    EXPECT_EQ(pairColumn(tr, "floor", "box5_shape", "normal_force")[last], 0.0);
  }
}

TEST(OutputChannelForces, LugreBristleOnTheBeltSettlesAtMuKOverSigma0) {
  const double m = 10.0, mu_k = 0.3, sigma0 = 1e4;
  const std::string yaml =
      test::replaced(textOf("belt.yaml"), "  interval: $output_interval\n",
                     "  interval: $output_interval\n"
                     "  channels: [position, velocity, pairs, friction_states]\n");
  const Recorded run =
      record(yaml, "belt.yaml",
             {"friction=lugre", "integrator=semi_implicit_euler", "dt=1e-4", "duration=3"});
  const TrajectoryRecorder& tr = run.result.trajectory;
  const auto t = tr.column(0);
  const auto zx = pairColumn(tr, "belt_surface", "box_shape", "z.x");
  const auto zy = pairColumn(tr, "belt_surface", "box_shape", "z.y");
  const auto normal = pairColumn(tr, "belt_surface", "box_shape", "normal_force");
  const auto friction = pairColumn(tr, "belt_surface", "box_shape", "friction_force");
  const auto vx = tr.column(tr.columnIndex("box.vx"));
  int checked = 0;
  for (std::size_t i = 0; i < tr.rows(); ++i) {
    if (t[i] < 0.5) continue;  // the box's start from rest on the belt
    ASSERT_LT(vx[i], 1.4);     // slipping backwards on the belt throughout
    EXPECT_NEAR(zx[i], -mu_k / sigma0, 1e-9 * mu_k / sigma0) << t[i];
    EXPECT_LT(std::abs(zy[i]), 1e-15);
    EXPECT_NEAR(normal[i], m * kG, 1e-6 * m * kG) << t[i];
    EXPECT_NEAR(friction[i], mu_k * m * kG, 1e-6 * m * kG) << t[i];
    ++checked;
  }
  EXPECT_GT(checked, 2000);
}

TEST(OutputChannelForces, JointFrictionIsMuKTimesTheReactionLoad) {
  const double m = 10.0, mu_k = 0.3, sigma0 = 1e4;
  std::string yaml = test::replaced(textOf("belt_joint_friction.yaml"), "output:\n",
                                    "output:\n  channels: [position, joints, friction_states]\n");
  yaml = test::replaced(yaml, "  coulomb: {",
                        "  lugre: {sigma0: 1.0e4, sigma1: 30, sigma2: 0, mu_c: $mu_k, "
                        "mu_s: $mu_s, v_s: $v_s}\n  coulomb: {");
  for (const std::string law : {"coulomb", "lugre"}) {
    const Recorded run =
        record(yaml, "belt_joint_friction.yaml",
               {"friction=" + law, "integrator=semi_implicit_euler", "dt=1e-4", "duration=3"});
    const TrajectoryRecorder& tr = run.result.trajectory;
    const auto t = tr.column(0);
    const auto rate = tr.column(tr.columnIndex("box_on_belt.rate"));
    const auto friction = tr.column(tr.columnIndex("box_on_belt.friction"));
    int checked = 0;
    for (std::size_t i = 0; i < tr.rows(); ++i) {
      if (t[i] < 0.5) continue;
      ASSERT_LT(rate[i], -0.1) << law;  // the box slower than the belt: slip backwards
      // Pushed forwards (+x) by mu_k m g; coulomb's tanh(|slip| / v_s) is 1 to 1e-8 here.
      EXPECT_NEAR(friction[i], mu_k * m * kG, 1e-6 * m * kG) << law << " " << t[i];
      ++checked;
    }
    EXPECT_GT(checked, 2000) << law;
    if (law == "lugre") {
      const auto zx = tr.column(tr.columnIndex("box_on_belt.z.x"));
      EXPECT_NEAR(zx[tr.rows() - 1], -mu_k / sigma0, 1e-9 * mu_k / sigma0);
    } else {
      const auto& c = tr.columns();
      EXPECT_EQ(std::find(c.begin(), c.end(), "box_on_belt.z.x"), c.end());  // memoryless
    }
  }
}

}  // namespace
}  // namespace tribo::study
