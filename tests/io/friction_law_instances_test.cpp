// Named friction-law instances: `friction_laws: {steel: {law: coulomb, mu: 0.2}, rubber:
// {law: coulomb, mu: 0.9}}` lets two materials (or joints) use two parameter sets of one law,
// for memoryless and dynamic laws alike; the old form (an entry named after its law) still
// reads; an instance of the same parameters gives the same run bit for bit; and the
// mistakes (an unknown law, an entry named after another law, a name the caller's laws
// also use) are errors naming the entry.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "core/model.hpp"
#include "core/simulator.hpp"
#include "friction/friction_law.hpp"
#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo::io {
namespace {

std::string fileText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Two boxes on the ground, each with its own material and the friction law `law_a` /
// `law_b`, under the `laws` section given.
std::string twoBoxes(const std::string& laws, const std::string& law_a, const std::string& law_b) {
  return "simulation: {duration: 0.1, time_step: 1.0e-4}\n"
         "friction_laws:\n" +
         laws +
         "materials:\n"
         "  - {name: ma, normal: {law: linear, stiffness: 1.0e5, damping: 200}, friction: " +
         law_a +
         "}\n"
         "  - {name: mb, normal: {law: linear, stiffness: 1.0e5, damping: 200}, friction: " +
         law_b +
         "}\n"
         "bodies:\n"
         "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}\n"
         "  - {name: a, mass: 1, position: [0, 0, 0.049975475], velocity: [0.5, 0, 0],\n"
         "     geometry: [{name: sa, shape: box, size: [0.1, 0.1, 0.1]}]}\n"
         "  - {name: b, mass: 1, position: [1, 0, 0.049975475], velocity: [0.5, 0, 0],\n"
         "     geometry: [{name: sb, shape: box, size: [0.1, 0.1, 0.1]}]}\n"
         "contacts:\n"
         "  - {a: floor, b: sa, material: ma}\n"
         "  - {a: floor, b: sb, material: mb}\n";
}

TEST(FrictionLawInstances, TwoParameterSetsOfOneLaw) {
  const Scene s = loadSceneFromString(
      twoBoxes("  steel: {law: coulomb, mu: 0.2, regularization: tanh, v_eps: 1.0e-4}\n"
               "  rubber: {law: coulomb, mu: 0.9, regularization: tanh, v_eps: 1.0e-4}\n",
               "steel", "rubber"),
      "t.yaml");
  ASSERT_EQ(s.model->materials.size(), 2u);
  EXPECT_NEAR(s.model->materials[0].friction->coefficient(1.0), 0.2, 1e-12);
  EXPECT_NEAR(s.model->materials[1].friction->coefficient(1.0), 0.9, 1e-12);
  // Physics: each box decelerates at its own mu g (sliding at 0.5 m/s, v_eps far below;
  // started at its static depth, 9.81 / (4 1e5) m).
  Simulator sim(s.model);
  for (int i = 0; i < 200; ++i) ASSERT_TRUE(sim.step().ok);
  const double t = sim.state().time;
  const auto& bodies = sim.state().bodies;
  const int a = s.model->findBody("a")->value, b = s.model->findBody("b")->value;
  EXPECT_NEAR(bodies[a].velocity.x(), 0.5 - 0.2 * 9.81 * t, 2e-3);
  EXPECT_NEAR(bodies[b].velocity.x(), 0.5 - 0.9 * 9.81 * t, 2e-3);
}

TEST(FrictionLawInstances, TwoLuGreParameterSetsAreTwoLaws) {
  const Scene s = loadSceneFromString(
      twoBoxes("  soft: {law: lugre, sigma0: 1.0e3, sigma1: 30, sigma2: 0, mu_c: 0.3, mu_s: 0.4, "
               "v_s: 0.01}\n"
               "  stiff: {law: lugre, sigma0: 1.0e5, sigma1: 300, sigma2: 0, mu_c: 0.5, mu_s: 0.6, "
               "v_s: 0.01}\n",
               "soft", "stiff"),
      "t.yaml");
  EXPECT_NE(s.model->materials[0].friction, s.model->materials[1].friction);
  EXPECT_NEAR(s.model->materials[0].friction->coefficient(1.0), 0.3, 1e-6);
  EXPECT_NEAR(s.model->materials[1].friction->coefficient(1.0), 0.5, 1e-6);
  EXPECT_EQ(s.model->materials[0].friction->name(), "lugre");
}

TEST(FrictionLawInstances, AnInstanceRunsAsTheLawUnderItsOwnName) {
  const std::string path = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt_joint_friction.yaml";
  const std::string old_form = fileText(path);
  const std::string named =
      test::replaced(old_form, "  roh_yoo: {mu_s:", "  table1: {law: roh_yoo, mu_s:");
  ASSERT_NE(named, old_form);
  const Scene a = loadSceneFromString(old_form, path, {"duration=2"});
  const Scene b = loadSceneFromString(named, path, {"duration=2", "friction=table1"});
  Simulator sa(a.model), sb(b.model);
  for (int i = 0; i < 2000; ++i) ASSERT_TRUE(sa.step().ok && sb.step().ok);
  for (std::size_t i = 0; i < sa.state().bodies.size(); ++i)
    EXPECT_EQ(sa.state().bodies[i].position, sb.state().bodies[i].position);
}

TEST(FrictionLawInstances, MistakesNameTheEntry) {
  const std::string unknown_type =
      test::sceneErrorOf(twoBoxes("  x: {law: colomb, mu: 0.2}\n", "x", "x"));
  EXPECT_NE(unknown_type.find("friction_laws.x.law: unknown friction law 'colomb'"),
            std::string::npos)
      << unknown_type;
  const std::string unknown_name = test::sceneErrorOf(twoBoxes("  x: {mu: 0.2}\n", "x", "x"));
  EXPECT_NE(unknown_name.find("unknown friction law 'x'"), std::string::npos) << unknown_name;
  EXPECT_NE(unknown_name.find("x: {law: coulomb, mu: 0.3}"), std::string::npos) << unknown_name;
  const std::string misnamed = test::sceneErrorOf(
      twoBoxes("  coulomb: {law: lugre, sigma0: 1.0e3}\n", "coulomb", "coulomb"));
  EXPECT_NE(misnamed.find("named after a law but is a lugre"), std::string::npos) << misnamed;
  // The law's own keys are checked as before, naming the instance.
  const std::string bad_value =
      test::sceneErrorOf(twoBoxes("  x: {law: coulomb, mu: -1}\n", "x", "x"));
  EXPECT_NE(bad_value.find("friction_laws.x"), std::string::npos) << bad_value;
  EXPECT_NE(bad_value.find("mu"), std::string::npos) << bad_value;
  // An entry named after its own law with law: given is the old form spelled out.
  EXPECT_EQ(
      test::sceneErrorOf(twoBoxes("  coulomb: {law: coulomb, mu: 0.2}\n", "coulomb", "coulomb")),
      "");
}

}  // namespace
}  // namespace tribo::io
