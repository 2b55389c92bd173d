// URDF robots placed by a scene file's robots: section (scenes/urdf_robots.yaml): each copy
// of a pendulum moves as the same pendulum written as bodies and joints; a URDF block's
// Gazebo tags set its friction and contact stiffness against the scene's slope (checked
// against the sliding acceleration g (sin theta - mu cos theta) and the static depth
// m g cos(theta) / (4 kp)), unless the scene names a material for that surface pair; and
// mistakes in a robot entry are errors located at their key.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "support/pendulum_scene.hpp"
#include "support/scene_text.hpp"

namespace tribo {
namespace {

namespace fs = std::filesystem;

const fs::path kScene = fs::path(TRIBO_SOURCE_DIR) / "scenes" / "urdf_robots.yaml";
constexpr double kTheta = 0.5235987755982988;  // the scene's slope angle [rad]
constexpr double kG = 9.81;

std::string sceneText() {
  std::ifstream in(kScene);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The scene's text with `from` replaced by `to`, loaded as if it were the scene file itself
// (robot paths resolve against scenes/).
io::Scene variant(const std::string& text, const std::string& from, const std::string& to) {
  return io::loadSceneFromString(test::replaced(text, from, to), kScene.string());
}

struct Track {
  std::vector<Vec3> left, right, block;
};

Track simulate(const io::Scene& scene, int steps) {
  Simulator sim(scene.model);
  const Model& m = *scene.model;
  const int left = m.findBody("left_arm")->value, right = m.findBody("right_arm")->value,
            block = m.findBody("block")->value;
  Track t;
  for (int i = 0; i <= steps; ++i) {
    if (i > 0) {
      EXPECT_TRUE(sim.step().ok) << "step " << i;
    }
    t.left.push_back(sim.state().bodies[left].position);
    t.right.push_back(sim.state().bodies[right].position);
    t.block.push_back(sim.state().bodies[block].position);
  }
  return t;
}

// Block displacement down the slope (its +x axis, (cos theta, 0, -sin theta)) and along the
// slope's normal (sin theta, 0, cos theta).
double downhill(const Vec3& p) { return p.x() * std::cos(kTheta) - p.z() * std::sin(kTheta); }
double normalHeight(const Vec3& p) { return p.x() * std::sin(kTheta) + p.z() * std::cos(kTheta); }

TEST(SceneRobots, EachPendulumMovesAsTheSamePendulumWrittenAsBodiesAndJoints) {
  const io::Scene scene = io::loadScene(kScene.string());
  ASSERT_TRUE(scene.model->findBody("left_arm") && scene.model->findBody("right_arm"));
  EXPECT_FALSE(scene.notes.empty());  // the massless bases are welded to the world: said
  const Track t = simulate(scene, 1000);

  // The left copy: hinge at (0, 2, 2) about y, started at 0.3 rad; centre 0.5 m down the arm.
  const double q = 0.3;
  const io::Scene reference =
      io::loadSceneFromString(test::pendulumSceneYaml(q, Vec3(0, 2, 2), 1.0), "pendulum.yaml");
  Simulator ref(reference.model);
  double gap = 0.0, mirror_gap = 0.0, swing = 0.0;
  for (std::size_t i = 0; i < t.left.size(); ++i) {
    if (i > 0) {
      ASSERT_TRUE(ref.step().ok);
    }
    gap = std::max(gap, (t.left[i] - ref.state().bodies[0].position).norm());
    // The right copy, turned a quarter turn about z and started at -0.3 rad, swings in the
    // y-z plane about (0, -2, 2) (hinge axis -x, angle -0.3: +0.3 about +x): the same
    // height, and its y offset is minus the left's x offset.
    const Vec3 r = t.right[i] - Vec3(0, -2, 0), l = t.left[i] - Vec3(0, 2, 0);
    mirror_gap =
        std::max({mirror_gap, std::abs(r.z() - l.z()), std::abs(r.y() + l.x()), std::abs(r.x())});
    swing = std::max(swing, std::abs(l.x()));
  }
  EXPECT_LT(gap, 1e-9);
  EXPECT_LT(mirror_gap, 1e-9);
  EXPECT_NEAR(swing, 0.5 * std::sin(q), 1e-3);  // it really swings
}

// Distance slid in the last 0.5 s of 1 s, and the acceleration it implies (the first 0.5 s
// let the contact settle and the regularized friction reach its plateau).
double slidingAcceleration(const Track& t) {
  const double s0 = downhill(t.block[500]), s1 = downhill(t.block[750]),
               s2 = downhill(t.block[1000]);
  return (s2 - 2.0 * s1 + s0) / (0.25 * 0.25);
}

TEST(SceneRobots, GazeboMu1SetsTheBlocksFrictionAgainstTheSlope) {
  const Track t = simulate(io::loadScene(kScene.string()), 1000);
  // mu1 = 0.2 (scenes/robots/block.urdf), not the default material's 0.8 (under which the
  // block would stick: tan 30 deg = 0.58).
  const double expected = kG * (std::sin(kTheta) - 0.2 * std::cos(kTheta));
  EXPECT_NEAR(slidingAcceleration(t), expected, 1e-3 * expected);
  EXPECT_GT(downhill(t.block.back() - t.block.front()), 0.4 * expected);  // ~ a t^2 / 2
}

TEST(SceneRobots, AMaterialForTheSurfacePairOverridesTheGazeboTags) {
  const std::string laws = "  coulomb: {mu: 0.8, regularization: tanh, v_eps: 0.01}\n";
  const std::string with_law = test::replaced(
      sceneText(), laws, laws + "  stribeck: {mu_s: 0.45, mu_k: 0.4, v_st: 0.001, v_eps: 0.001}\n");
  const std::string tail = "    default: true\n";
  const Track t = simulate(variant(with_law, tail, tail + R"(  - name: block_on_slope
    normal: {law: linear, stiffness: 1.0e5, damping: 100}
    friction: stribeck
    surfaces: [[block, slope]]
)"),
                           1000);
  // Sliding at over 0.5 m/s, far above v_st: mu = mu_k = 0.4.
  const double expected = kG * (std::sin(kTheta) - 0.4 * std::cos(kTheta));
  EXPECT_NEAR(slidingAcceleration(t), expected, 1e-3 * expected);
}

TEST(SceneRobots, GazeboKpSetsTheBlocksContactStiffness) {
  // The default material is ten times stiffer than the block's kp = 1e5 N/m per corner: the
  // block must sink to m g cos(theta) / (4 kp) all the same.
  const Track t = simulate(variant(sceneText(), "stiffness: 1.0e5, damping: 100}\n    friction",
                                   "stiffness: 1.0e6, damping: 300}\n    friction"),
                           1000);
  double mean = 0.0;
  for (int i = 500; i <= 1000; ++i) mean += normalHeight(t.block[i]) / 501.0;
  const double depth = 1.0 * kG * std::cos(kTheta) / (4.0 * 1e5);
  EXPECT_NEAR(0.05 - mean, depth, 0.02 * depth);
}

std::string errorOf(const std::string& from, const std::string& to) {
  return test::sceneErrorOf(test::replaced(sceneText(), from, to), kScene.string());
}

TEST(SceneRobots, MistakesAreErrorsAtTheirKey) {
  const std::string file = "  - file: robots/block.urdf\n";
  const std::string missing = errorOf(file, "  - file: robots/no_such.urdf\n");
  EXPECT_NE(missing.find("robots[2].file"), std::string::npos) << missing;
  EXPECT_NE(missing.find("no_such.urdf"), std::string::npos) << missing;

  const std::string joint = errorOf("joint_positions: {hinge: 0.3}", "joint_positions: {elbow: 1}");
  EXPECT_NE(joint.find("robots[0]"), std::string::npos) << joint;
  EXPECT_NE(joint.find("no joint named 'elbow' in robot 'pendulum'"), std::string::npos) << joint;

  const std::string key = errorOf("    prefix: left_\n", "    prefix: left_\n    scale: 2\n");
  EXPECT_NE(key.find("unknown key 'scale'"), std::string::npos) << key;
  EXPECT_NE(key.find("joint_positions"), std::string::npos) << key;  // the accepted keys

  const std::string base = errorOf("    base: floating\n", "    base: welded\n");
  EXPECT_NE(base.find("expected one of auto, fixed, floating"), std::string::npos) << base;

  // Two robots with the same prefix collide on names: the builder's error, at the entry.
  const std::string twice = errorOf("    prefix: right_\n", "    prefix: left_\n");
  EXPECT_NE(twice.find("robots[1]"), std::string::npos) << twice;
  EXPECT_NE(twice.find("left_arm"), std::string::npos) << twice;
}

}  // namespace
}  // namespace tribo
