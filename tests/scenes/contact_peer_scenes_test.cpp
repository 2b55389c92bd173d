// The scene variants of the peer comparison (bench/peers, docs/performance.md):
// scenes/box_grid20_box_ground.yaml (the 20 x 20 grid on a ground that is a kinematic box, its
// pairs FCL box/box manifolds) rests as the half-space grid does, at the static corner depth
// m g / (4 k) for several stiffnesses, with the weight carried and nothing sliding; and
// scenes/sphere_pile_stiff.yaml (the pile with 1.5e5 N/m contacts at 1 ms) settles no deeper
// than 0.64 mm with its weight carried by the container.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

const std::string kScenes = std::string(TRIBO_SOURCE_DIR) + "/scenes/";

struct Rest {
  std::size_t points = 0;
  double min_depth = 1e9, max_depth = 0;
  double support = 0;  // vertical force of the kinematic body on the dynamic ones, mean over
                       // the last quarter of the run [N]
  double weight = 0;   // [N]
  double drift = 0;    // largest horizontal displacement [m]
  double speed = 0;    // fastest body [m/s]
};

Rest settle(const std::string& file, const std::vector<std::string>& overrides, double seconds) {
  io::RunSettings settings;
  settings.duration = seconds;
  const io::Scene scene = io::loadScene(kScenes + file, overrides, {}, settings);
  const Model& m = *scene.model;
  Simulator sim(scene.model);
  const State start = sim.state();
  const long steps = std::lround(seconds / m.options.time_step);
  const auto kind = [&](int g) {
    return m.bodies[static_cast<std::size_t>(m.geometries[static_cast<std::size_t>(g)].body.value)]
        .kind;
  };
  // The vertical force of the kinematic ground or container on the dynamic bodies now.
  const auto support = [&](const Workspace& w) {
    double f = 0;
    for (const auto& rec : w.contacts) {
      const ContactPair pair = m.contactPair(rec.point.pair);
      if (kind(pair.geometry_a) == BodyKind::kKinematic) f += rec.force().z();  // force on B
      if (kind(pair.geometry_b) == BodyKind::kKinematic) f -= rec.force().z();
    }
    return f;
  };
  Rest r;
  const long averaged = steps / 4;
  for (long i = 0; i < steps; ++i) {
    const StepStatus s = sim.step();
    if (!s.ok) {
      ADD_FAILURE() << file << ": " << s.message;
      return {};
    }
    if (i >= steps - averaged) r.support += support(sim.current()) / static_cast<double>(averaged);
  }
  const Workspace& w = sim.current();
  r.points = w.contacts.size();
  for (const auto& rec : w.contacts) {
    r.min_depth = std::min(r.min_depth, rec.point.depth);
    r.max_depth = std::max(r.max_depth, rec.point.depth);
  }
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    if (m.bodies[b].kind != BodyKind::kDynamic) continue;
    r.weight += -m.bodies[b].mass * m.options.gravity.z();
    r.drift = std::max(
        r.drift, (sim.state().bodies[b].position - start.bodies[b].position).head<2>().norm());
    r.speed = std::max(r.speed, sim.state().bodies[b].velocity.norm());
  }
  std::printf(
      "%s %s: %zu points, depth %.6g..%.6g m, support %.6g N of %.6g N, drift %.3g m, "
      "speed %.3g m/s\n",
      file.c_str(), overrides.empty() ? "" : overrides[0].c_str(), r.points, r.min_depth,
      r.max_depth, r.support, r.weight, r.drift, r.speed);
  return r;
}

TEST(PeerScenes, BoxGridOnABoxGroundRestsAtTheStaticCornerDepthAsOnAHalfSpace) {
  // {stiffness per corner [N/m], step [s]}: the shipped 6e5 and stiffer corners at the step
  // their rocking needs under semi-implicit Euler.
  for (const auto& [k, dt] :
       std::vector<std::pair<double, double>>{{6.0e5, 1e-3}, {3.0e5, 1e-3}, {1.2e6, 5e-4}}) {
    const std::vector<std::string> set{"k=" + std::to_string(k), "dt=" + std::to_string(dt)};
    const double static_depth = 8.0 * 9.81 / (4 * k);
    for (const char* file : {"box_grid20_box_ground.yaml", "box_grid20.yaml"}) {
      const Rest r = settle(file, set, 0.25);
      EXPECT_EQ(r.points, 1600u) << file << " k " << k;  // four corners under each box
      EXPECT_NEAR(r.min_depth / static_depth, 1.0, 1e-3) << file << " k " << k;
      EXPECT_NEAR(r.max_depth / static_depth, 1.0, 1e-3) << file << " k " << k;
      EXPECT_NEAR(r.support / r.weight, 1.0, 1e-6) << file << " k " << k;
      EXPECT_LT(r.drift, 1e-9) << file << " k " << k;
      EXPECT_LT(r.speed, 1e-5) << file << " k " << k;
    }
  }
}

TEST(PeerScenes, StiffPileSettlesNoDeeperThanTheComparisonAllowsAndIsCarried) {
  const Rest r = settle("sphere_pile_stiff.yaml", {}, 2.0);
  EXPECT_GT(r.points, 400u);        // 200 spheres in a pile touch the floor, walls and each other
  EXPECT_LE(r.max_depth, 0.64e-3);  // MuJoCo 2.2.2's resting depth on the same pile
  // Spheres may still roll and jostle, but the pile no longer falls: over the last 0.5 s the
  // container carries its weight on average.
  EXPECT_NEAR(r.support / r.weight, 1.0, 0.01);
  // The same pile with the original 5e4 N/m contacts rests deeper than the comparison allows:
  // what the stiff variant is for.
  const Rest soft = settle("sphere_pile.yaml", {}, 2.0);
  EXPECT_GT(soft.max_depth, 0.64e-3);
  EXPECT_NEAR(soft.support / soft.weight, 1.0, 0.01);
}

}  // namespace
}  // namespace tribo
