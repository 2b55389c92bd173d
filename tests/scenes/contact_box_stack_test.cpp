// scenes/box_stack.yaml: five boxes stacked on the ground stay standing (automatic
// contacts through the broadphase, FCL box/box manifolds, elastic_stick friction whose
// anchors follow FCL's points by nearest-point matching). Reported: penetration against
// the static depth of the bottom contact 5 m g / (4 k), each box's drift and tilt.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/box_stack.yaml";
constexpr double kM = 1.0, kG = 9.81, kK = 1e5;

struct StackRun {
  State start, settled, end;  // at 0 s, at duration - 5 s, at duration
  double max_depth = 0;       // over the run [m]
  double final_depth = 0;     // at the end [m]
  std::size_t contacts = 0;   // at the end
};

StackRun run(const std::vector<std::string>& overrides, double duration) {
  auto o = overrides;
  char buf[64];
  std::snprintf(buf, sizeof buf, "duration=%g", duration);
  o.push_back(buf);
  const auto scene = io::loadScene(kScene, o);
  EXPECT_TRUE(scene.model->automatic_contacts);
  Simulator sim(scene.model);
  StackRun r;
  r.start = sim.state();
  const long steps = std::lround(duration / scene.model->options.time_step);
  for (long i = 1; i <= steps; ++i) {
    EXPECT_TRUE(sim.step().ok);
    r.max_depth = std::max(r.max_depth, sim.current().max_penetration);
    if (i == steps - std::lround(5.0 / scene.model->options.time_step)) r.settled = sim.state();
  }
  r.end = sim.state();
  r.final_depth = sim.current().max_penetration;
  r.contacts = sim.current().contacts.size();
  std::printf(
      "box stack: %zu contact points, penetration %.4g m at the end (static bottom %.4g m),"
      " %.3g m at most\n",
      r.contacts, r.final_depth, 5 * kM * kG / (4 * kK), r.max_depth);
  for (std::size_t b = 1; b < r.end.bodies.size(); ++b) {
    const BodyState& s = r.end.bodies[b];
    std::printf("  box%zu drift %.3g m (last 5 s: %.3g m) tilt %.3g rad\n", b,
                (s.position - r.start.bodies[b].position).head<2>().norm(),
                (s.position - r.settled.bodies[b].position).norm(),
                Eigen::AngleAxisd(s.orientation).angle());
  }
  return r;
}

TEST(BoxStackScene, FiveBoxesStayStandingForTenSeconds) {
  const StackRun r = run({}, 10.0);
  const double static_depth = 5 * kM * kG / (4 * kK);
  EXPECT_EQ(r.contacts, 20u);  // 4 points under every box: face manifolds
  EXPECT_NEAR(r.final_depth / static_depth, 1.0, 1e-3);
  EXPECT_LT(r.max_depth, 2.0 * static_depth);  // released at zero depth: it overshoots
  for (std::size_t b = 1; b < r.end.bodies.size(); ++b) {
    EXPECT_LT((r.end.bodies[b].position - r.start.bodies[b].position).head<2>().norm(), 1e-9);
    EXPECT_LT(Eigen::AngleAxisd(r.end.bodies[b].orientation).angle(), 1e-9);
    EXPECT_LT(r.end.bodies[b].velocity.norm(), 1e-6);
  }
}

TEST(BoxStackScene, AStaggeredStackLeansStaticallyAndDoesNotCreep) {
  // Each box 1.5 cm further along x than the one below: every face contact carries a
  // tipping moment, which only a manifold of several points can hold. The bottom box tilts
  // by the moment of the four above, m g (0.015 + 0.03 + 0.045 + 0.06), over the rotational
  // stiffness of its four corners, 4 k (0.1 m)^2; after settling nothing moves any more.
  const StackRun r = run({"x2=0.015", "x3=0.03", "x4=0.045", "x5=0.06"}, 20.0);
  EXPECT_EQ(r.contacts, 20u);
  const double tilt = kM * kG * 0.15 / (4 * kK * 0.01);
  EXPECT_NEAR(Eigen::AngleAxisd(r.end.bodies[1].orientation).angle() / tilt, 1.0, 0.02);
  for (std::size_t b = 1; b < r.end.bodies.size(); ++b)
    EXPECT_LT((r.end.bodies[b].position - r.settled.bodies[b].position).norm(), 1e-6) << b;
}

}  // namespace
}  // namespace tribo
