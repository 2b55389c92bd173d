// Expressions in scene values (io/scene_expression.hpp): values against the same arithmetic
// done here in C++, parameters that refer to parameters, --set overrides flowing through,
// and errors that name file, line, key, the expression and what went wrong.
#include "io/scene_expression.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo::io {
namespace {

using test::sceneErrorOf;

// A box on the ground whose mass, position and spring come from `mass`, `x`, `z` and `k`.
std::string scene(const std::string& parameters, const std::string& mass, const std::string& x,
                  const std::string& z = "0.5", const std::string& k = "100") {
  return "parameters:\n" + parameters +
         "simulation: {duration: 1, time_step: 0.001}\n"
         "bodies:\n"
         "  - {name: box, mass: " +
         mass + ", position: [" + x + ", 0, " + z +
         "],\n"
         "     geometry: [{name: g, shape: box, size: [0.1, 0.1, 0.1]}]}\n"
         "springs:\n"
         "  - {name: s, a: world, point_a: [0, 0, 0.5], b: box, point_b: [0, 0, 0.5],\n"
         "     stiffness: " +
         k + ", rest_length: 0}\n";
}

const std::string kParameters = "  k: 300\n  m: 10\n  angle: 10\n  w: sqrt($k / $m)\n";

TEST(SceneExpression, ValuesAreTheArithmeticTheyWrite) {
  const Scene s = loadSceneFromString(scene(kParameters, "$k / $m", "sin($angle deg) * 2",
                                            "0.05 - $m * 9.81 / (4 * 2.5e5)", "$w ^ 2 * $m"),
                                      "expr.yaml");
  const Model& m = *s.model;
  EXPECT_DOUBLE_EQ(m.bodies[0].mass, 300.0 / 10.0);
  EXPECT_DOUBLE_EQ(m.bodies[0].position.x(), std::sin(10.0 * std::numbers::pi / 180.0) * 2);
  EXPECT_DOUBLE_EQ(m.bodies[0].position.z(), 0.05 - 10.0 * 9.81 / (4 * 2.5e5));
  EXPECT_NEAR(m.springs[0].stiffness, 300.0, 1e-12);  // (sqrt(k/m))^2 m
  const Scene constants = loadSceneFromString(scene("  k: 1\n", "pi", "e - 2"), "c.yaml");
  EXPECT_DOUBLE_EQ(constants.model->bodies[0].mass, std::numbers::pi);
  EXPECT_DOUBLE_EQ(constants.model->bodies[0].position.x(), std::numbers::e - 2);
}

TEST(SceneExpression, OverridesFlowThroughExpressions) {
  const Scene s = loadSceneFromString(scene(kParameters, "$k / $m", "0", "0.5", "$w ^ 2"),
                                      "expr.yaml", {"k=450", "m=9"});
  EXPECT_DOUBLE_EQ(s.model->bodies[0].mass, 450.0 / 9.0);
  EXPECT_NEAR(s.model->springs[0].stiffness, 50.0, 1e-12);
  // An expression parameter may itself be overridden, by a number or another expression.
  const Scene w =
      loadSceneFromString(scene(kParameters, "1", "0", "0.5", "$w"), "expr.yaml", {"w=2 * $k"});
  EXPECT_DOUBLE_EQ(w.model->springs[0].stiffness, 600.0);
}

TEST(SceneExpression, ErrorsNameWhereAndWhat) {
  const auto err = [](const std::string& params, const std::string& mass) {
    return sceneErrorOf(scene(params, mass, "0"), "expr.yaml");
  };
  // Where: file, line (bodies[0] is on line 6 with one parameter line), key.
  const std::string unknown = err("  k: 1\n", "$k / $q");
  EXPECT_NE(unknown.find("expr.yaml:5:"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("bodies[0].mass"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("expression '$k / $q'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("unknown parameter '$q' (known: k)"), std::string::npos) << unknown;
  EXPECT_NE(err("  k: 1\n", "foo($k)").find("expression 'foo($k)'"), std::string::npos);
  const std::string zero = err("  k: 0\n", "1 / $k");
  EXPECT_NE(zero.find("the result is inf"), std::string::npos) << zero;
  const std::string domain = err("  k: -4\n", "sqrt($k)");
  EXPECT_NE(domain.find("expected a finite number"), std::string::npos) << domain;
  const std::string syntax = err("  k: 1\n", "2 * ($k");
  EXPECT_NE(syntax.find("expression '2 * ($k'"), std::string::npos) << syntax;
  const std::string cycle = err("  a: $b + 1\n  b: 2 * $a\n", "$a");
  // mass: $a stands for a's text "$b + 1", whose evaluation meets b, then a, then b again.
  EXPECT_NE(cycle.find("cycle: b -> a -> b"), std::string::npos) << cycle;
  const std::string self = err("  a: $a + 1\n", "$a * 2");
  EXPECT_NE(self.find("cycle: a -> a"), std::string::npos) << self;
  // Text that is no expression attempt keeps the plain message.
  const std::string word = err("  k: 1\n", "heavy");
  EXPECT_NE(word.find("expected a number, found 'heavy'"), std::string::npos) << word;
  EXPECT_EQ(word.find("expression"), std::string::npos) << word;
}

}  // namespace
}  // namespace tribo::io
