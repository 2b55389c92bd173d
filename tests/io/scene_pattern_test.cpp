// Bodies made by a pattern (io/scene_bodies.cpp, `bodies[].pattern`): a grid of boxes
// written as one entry is the same model, and runs the same trajectory to the last bit, as
// the scene written body by body; a jitter stays within its bound, repeats with its seed and
// changes with another; a 20 000-body pattern loads; malformed patterns are refused with
// file:line and key.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo::io {
namespace {

using test::replaced;
using test::sceneErrorOf;

const std::string kHead =
    "simulation: {duration: 0.2, time_step: 0.001, integrator: rk4, gravity: [0, 0, -9.81]}\n"
    "friction_laws:\n  coulomb: {mu: 0.4, regularization: tanh, v_eps: 0.01}\n"
    "materials:\n  - {name: m, normal: {law: linear, stiffness: 1.0e5, damping: 100}, "
    "friction: coulomb, default: true}\n"
    "bodies:\n"
    "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}\n";

// Boxes 0.1 m apart in x and y, dropped from 1 cm above their resting height, spinning a
// little so that they touch and slide.
std::string patterned(const std::string& extra = "") {
  return kHead +
         "  - {name: box, mass: 2, position: [0, 0, 0.06], angular_velocity: [0, 0, 1],\n"
         "     geometry: [{name: s, shape: box, size: [0.09, 0.09, 0.1]}],\n"
         "     pattern: {grid: [3, 2, 1], spacing: [0.1, 0.1, 0]" +
         extra + "}}\n";
}

std::string listed() {
  std::string text = kHead;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) {
      char suffix_text[32];
      std::snprintf(suffix_text, sizeof suffix_text, "_%d_%d_0", i, j);
      const std::string suffix = suffix_text;
      char position[64];
      std::snprintf(position, sizeof position, "[%.17g, %.17g, 0.06]", i * 0.1, j * 0.1);
      text += "  - {name: box" + suffix + ", mass: 2, position: " + position +
              ", angular_velocity: [0, 0, 1],\n     geometry: [{name: s" + suffix +
              ", shape: box, size: [0.09, 0.09, 0.1]}]}\n";
    }
  return text;
}

TEST(ScenePattern, AGridIsTheSceneWrittenBodyByBodyToTheLastBit) {
  const Scene a = loadSceneFromString(patterned(), "pattern.yaml");
  const Scene b = loadSceneFromString(listed(), "listed.yaml");
  ASSERT_EQ(a.model->bodies.size(), 7u);
  ASSERT_EQ(a.model->bodies.size(), b.model->bodies.size());
  for (std::size_t i = 0; i < a.model->bodies.size(); ++i) {
    EXPECT_EQ(a.model->bodies[i].name, b.model->bodies[i].name);
    EXPECT_EQ(a.model->bodies[i].position, b.model->bodies[i].position) << i;
  }
  for (std::size_t g = 0; g < a.model->geometries.size(); ++g)
    EXPECT_EQ(a.model->geometries[g].name, b.model->geometries[g].name);
  EXPECT_EQ(a.model->bodies[6].name, "box_2_1_0");
  Simulator sa(a.model), sb(b.model);
  for (int k = 0; k < 200; ++k) {
    ASSERT_TRUE(sa.step().ok);
    ASSERT_TRUE(sb.step().ok);
  }
  for (std::size_t i = 0; i < a.model->bodies.size(); ++i) {
    EXPECT_EQ(sa.state().bodies[i].position, sb.state().bodies[i].position) << i;
    EXPECT_EQ(sa.state().bodies[i].velocity, sb.state().bodies[i].velocity) << i;
  }
  // They touched: the boxes settled onto the ground and turned against friction.
  EXPECT_LT(sa.state().bodies[1].angular_velocity.z(), 0.9);
}

TEST(ScenePattern, AJitterStaysInItsBoundAndRepeatsWithItsSeed) {
  const Scene one = loadSceneFromString(patterned(", jitter: 0.004, seed: 7"), "p.yaml");
  const Scene again = loadSceneFromString(patterned(", jitter: 0.004, seed: 7"), "p.yaml");
  const Scene other = loadSceneFromString(patterned(", jitter: 0.004, seed: 8"), "p.yaml");
  const Scene plain = loadSceneFromString(patterned(), "p.yaml");
  double largest = 0.0, differs = 0.0;
  for (std::size_t i = 1; i < plain.model->bodies.size(); ++i) {
    const Vec3 offset = one.model->bodies[i].position - plain.model->bodies[i].position;
    largest = std::max(largest, offset.cwiseAbs().maxCoeff());
    EXPECT_EQ(one.model->bodies[i].position, again.model->bodies[i].position);
    differs += (one.model->bodies[i].position - other.model->bodies[i].position).norm();
  }
  EXPECT_LE(largest, 0.004);
  EXPECT_GT(largest, 0.001);  // 18 draws: all within a quarter of the bound has odds 2e-11
  EXPECT_GT(differs, 0.0);
}

TEST(ScenePattern, TwentyThousandBodiesAreOneEntry) {
  const std::string text =
      kHead +
      "  - {name: box, mass: 8, position: [0, 0, 0.1], geometry: [{name: s, shape: box, size: "
      "[0.2, 0.2, 0.2]}], pattern: {grid: [200, 100, 1], spacing: [0.25, 0.25, 0]}}\n";
  const auto start = std::chrono::steady_clock::now();
  const Scene s = loadSceneFromString(text, "field.yaml");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(s.model->bodies.size(), 20001u);
  EXPECT_EQ(s.model->bodies.back().name, "box_199_99_0");
  EXPECT_EQ(s.model->bodies.back().position, Vec3(199 * 0.25, 99 * 0.25, 0.1));
  std::printf("20 000 patterned boxes loaded in %.3f s\n", seconds);  // bench/: the figure
}

TEST(ScenePattern, MalformedPatternsAreRefusedWithLineAndKey) {
  struct Case {
    std::string from, to, says;
  };
  const Case cases[] = {
      {"grid: [3, 2, 1]", "grid: [3, 0, 1]", "expected 3 whole counts >= 1"},
      {"grid: [3, 2, 1]", "grid: [3, 2.5, 1]", "expected 3 whole counts >= 1"},
      {"grid: [3, 2, 1]", "grid: [3, 2]", "3 counts [nx, ny, nz]"},
      {"grid: [3, 2, 1]", "grid: [1000, 1000, 1000]", "more than the 1000000 one entry may make"},
      {", spacing: [0.1, 0.1, 0]", "", "missing required key 'spacing'"},
      {"spacing: [0.1, 0.1, 0]", "spacing: [0.1, 0.1, 0], jitter: -1", "expected a distance >= 0"},
      {"spacing: [0.1, 0.1, 0]", "spacing: [0.1, 0.1, 0], rows: 2", "rows"},
  };
  for (const Case& c : cases) {
    const std::string e = sceneErrorOf(replaced(patterned(), c.from, c.to), "p.yaml");
    EXPECT_NE(e.find("p.yaml:"), std::string::npos) << c.to << ": " << e;
    EXPECT_NE(e.find("bodies[1].pattern"), std::string::npos) << c.to << ": " << e;
    EXPECT_NE(e.find(c.says), std::string::npos) << c.to << ": " << e;
  }
}

}  // namespace
}  // namespace tribo::io
