// Scene loading: the shipped belt scene, overrides, and the error messages (file, line,
// key path, expected vs found) for each kind of mistake the loader promises to catch.
#include "io/scene_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <tuple>
#include <vector>

#include "support/scene_text.hpp"

namespace tribo::io {
namespace {

// Does `text` contain `part`? (With the whole text in the failure message.)
::testing::AssertionResult Has(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "\"" << text << "\"\n  does not contain \"" << part << "\"";
}

const std::string kBeltPath = TRIBO_SOURCE_DIR "/scenes/belt.yaml";

// A small valid scene; tests make it wrong one edit at a time.
const std::string kBase = R"(parameters:
  m: 10
  k: 300
  law: coulomb
simulation: {time_step: 0.002, duration: 1}
bodies:
  - name: belt
    kind: kinematic
    geometry:
      - {name: ground, shape: halfspace}
  - name: box
    mass: $m
    position: [0, 0, 0.05]
    geometry:
      - {name: block, shape: box, size: [0.2, 0.2, 0.1]}
joints:
  - {name: slide, type: planar_translation, parent: world, child: box, axis: [0, 1, 0]}
springs:
  - {name: s, a: world, point_a: [-0.5, 0, 0.05], b: box, point_b: [0, 0, 0.05], stiffness: $k}
friction_laws:
  coulomb: {mu: 0.3}
  roh_yoo: {mu_s: 0.35, mu_k: 0.3, v_s: 0.01, a: 0.5, beta: 0.5}
materials:
  - {name: steel, normal: {stiffness: 1e5}, friction: $law}
contacts:
  - {a: ground, b: block, material: steel}
)";

using test::replaced;

// 1-based line of the first line of `text` containing `needle`.
int lineOf(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

// The SceneError message of f, or a test failure when f does not throw one.
std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no SceneError thrown";
  return {};
}

std::string errorOfScene(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  return errorOf([&] { loadSceneFromString(yaml, "test.yaml", overrides); });
}

// "test.yaml:LINE:COL" of the first occurrence of `needle` in `text`.
std::string at(const std::string& text, const std::string& needle) {
  const auto pos = text.find(needle);
  const auto line_start = text.rfind('\n', pos);
  const auto column = line_start == std::string::npos ? pos + 1 : pos - line_start;
  return "test.yaml:" + std::to_string(lineOf(text, needle)) + ":" + std::to_string(column);
}

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SceneLoader, BeltSceneBuildsThePapersModel) {
  const Scene scene = loadScene(kBeltPath);
  const Model& model = *scene.model;
  EXPECT_EQ(scene.path, kBeltPath);
  ASSERT_EQ(model.bodies.size(), 2u);
  EXPECT_EQ(model.bodies[0].name, "belt");
  EXPECT_EQ(model.bodies[0].kind, BodyKind::kKinematic);
  EXPECT_EQ(model.bodies[0].surface_velocity, Vec3(1.5, 0, 0));
  const Body& box = model.bodies[1];
  EXPECT_EQ(box.name, "box");
  EXPECT_EQ(box.kind, BodyKind::kDynamic);
  EXPECT_DOUBLE_EQ(box.mass, 10.0);
  // Centre at half its height less the static contact depth m g / (4 k_c).
  EXPECT_NEAR(box.position.z(), 0.05 - 10.0 * 9.81 / (4 * 2.5e5), 1e-12);
  EXPECT_EQ(box.position.x(), 0.0);
  // Solid box 0.2 x 0.2 x 0.1 m of 10 kg: I = m/12 (b^2 + c^2), ...
  EXPECT_NEAR(box.inertia(0, 0), 10.0 / 12 * (0.04 + 0.01), 1e-12);
  EXPECT_NEAR(box.inertia(1, 1), 10.0 / 12 * (0.04 + 0.01), 1e-12);
  EXPECT_NEAR(box.inertia(2, 2), 10.0 / 12 * (0.04 + 0.04), 1e-12);
  EXPECT_NEAR(box.inertia(0, 1), 0.0, 1e-15);

  ASSERT_EQ(model.geometries.size(), 2u);
  EXPECT_EQ(model.geometries[0].shape.type, contact::ShapeType::kHalfSpace);
  EXPECT_TRUE(model.geometries[1].shape.half_extents.isApprox(Vec3(0.1, 0.1, 0.05)));
  ASSERT_EQ(model.joints.size(), 1u);
  EXPECT_EQ(model.joints[0].type, JointType::kPlanarTranslation);
  ASSERT_EQ(model.springs.size(), 1u);
  EXPECT_DOUBLE_EQ(model.springs[0].stiffness, 300.0);
  EXPECT_DOUBLE_EQ(model.springs[0].rest_length, 100.0);  // anchor far behind: linear
  ASSERT_EQ(model.materials.size(), 1u);
  EXPECT_EQ(model.materials[0].friction->name(), "roh_yoo");
  EXPECT_DOUBLE_EQ(model.materials[0].normal.stiffness, 2.5e5);
  EXPECT_DOUBLE_EQ(model.materials[0].normal.damping, 1.5e3);
  ASSERT_EQ(model.contact_pairs.size(), 1u);
  EXPECT_EQ(model.contact_pairs[0].geometry_b, 1);

  EXPECT_DOUBLE_EQ(model.options.duration, 60.0);
  EXPECT_DOUBLE_EQ(model.options.time_step, 1e-3);
  EXPECT_EQ(model.options.integrator, IntegratorType::kRk4);
  EXPECT_EQ(model.options.gravity, Vec3(0, 0, -9.81));
  EXPECT_DOUBLE_EQ(scene.output.interval, 1e-3);
  EXPECT_EQ(scene.output.summary.body, "box");
  EXPECT_EQ(scene.output.summary.coordinate, 0);
  EXPECT_DOUBLE_EQ(scene.output.summary.stick_speed, 0.01);
  EXPECT_EQ(scene.output.summary.last_cycles, 3);

  ASSERT_FALSE(scene.parameters.empty());
  EXPECT_EQ(scene.parameters[0], (std::pair<std::string, std::string>("m", "10.0")));
  // Table 1 of the paper at the roh_yoo law's stick boundary: mu(v_s) = mu_s.
  EXPECT_NEAR(model.materials[0].friction->coefficient(0.01), 0.35, 1e-12);
}

TEST(SceneLoader, OverridesSelectTheLawAndChangeValues) {
  const Scene recurdyn = loadScene(kBeltPath, {"friction=recurdyn"});
  EXPECT_EQ(recurdyn.model->materials[0].friction->name(), "recurdyn");
  bool listed = false;
  for (const auto& [name, value] : recurdyn.parameters)
    listed |= name == "friction" && value == "recurdyn";
  EXPECT_TRUE(listed);

  const Scene stiff = loadScene(kBeltPath, {"k=500"});
  EXPECT_DOUBLE_EQ(stiff.model->springs[0].stiffness, 500.0);
  // The last override of a name wins; spaces around the '=' do not matter.
  const Scene twice = loadScene(kBeltPath, {"k=500", " k = 700 "});
  EXPECT_DOUBLE_EQ(twice.model->springs[0].stiffness, 700.0);
}

TEST(SceneLoader, DocumentParsedOnceBuildsEachOverrideAfresh) {
  std::ifstream in(kBeltPath);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const SceneDocument document(text, kBeltPath);
  // Each load starts from the file's values: an override of one load does not stay for the
  // next, and every derived value (the law, the spring, the body's mass) follows.
  for (const auto& [overrides, k, m, law] :
       {std::tuple{std::vector<std::string>{"k=500", "friction=recurdyn"}, 500.0, 10.0, "recurdyn"},
        {std::vector<std::string>{"m=3"}, 300.0, 3.0, "roh_yoo"},
        {std::vector<std::string>{}, 300.0, 10.0, "roh_yoo"}}) {
    const Scene a = document.load(overrides);
    const Scene b = loadSceneFromString(text, kBeltPath, overrides);
    EXPECT_DOUBLE_EQ(a.model->springs[0].stiffness, k);
    EXPECT_DOUBLE_EQ(b.model->springs[0].stiffness, k);
    EXPECT_DOUBLE_EQ(a.model->bodies[1].mass, m);
    EXPECT_EQ(a.model->materials[0].friction->name(), law);
    EXPECT_EQ(a.parameters, b.parameters);
    EXPECT_EQ(a.path, kBeltPath);
  }
  // Errors name the document as loadSceneFromString's do.
  const std::string e = errorOf([&] { document.load({"kk=3"}); });
  EXPECT_TRUE(Has(e, "belt.yaml"));
  EXPECT_TRUE(Has(errorOf([] { SceneDocument("a: [1, 2", "bad.yaml"); }), "bad.yaml"));
}

TEST(SceneLoader, LawsNoMaterialSelectsAreNotValidated) {
  // a <= 1 is invalid for roh_yoo, which the recurdyn run does not use.
  const Scene scene = loadScene(kBeltPath, {"friction=recurdyn", "a=0.5"});
  EXPECT_EQ(scene.model->materials[0].friction->name(), "recurdyn");
  // kBase carries a bad roh_yoo entry but selects coulomb.
  EXPECT_EQ(loadSceneFromString(kBase, "test.yaml").model->materials[0].friction->name(),
            "coulomb");
}

// A law's value may be an expression over parameters, as any number of the scene; words stay
// options (the law checks them).
TEST(SceneLoader, LawValuesMayBeExpressions) {
  std::string yaml = replaced(kBase, "  coulomb: {mu: 0.3}\n",
                              "  coulomb: {mu: '$m / 20', regularization: linear}\n");
  const Scene scene = loadSceneFromString(yaml, "test.yaml", {"m=4"});
  EXPECT_DOUBLE_EQ(scene.model->materials[0].friction->coefficient(1.0), 0.2);
  yaml = replaced(yaml, "regularization: linear", "regularization: '$m + nosuch'");
  EXPECT_TRUE(Has(errorOf([&] { loadSceneFromString(yaml, "test.yaml"); }), "regularization"));
}

TEST(SceneLoader, UnknownOverrideNameListsTheKnownOnes) {
  const std::string e = errorOf([] { loadScene(kBeltPath, {"kk=3"}); });
  EXPECT_TRUE(Has(e, "belt.yaml"));
  EXPECT_TRUE(Has(e, "unknown parameter 'kk'"));
  EXPECT_TRUE(Has(e, "known parameters: m, k, v_b"));
  EXPECT_TRUE(Has(errorOf([] { loadScene(kBeltPath, {"k"}); }), "expected NAME=VALUE"));
}

TEST(SceneLoader, NumericParameterTakesOnlyNumbers) {
  const std::string e = errorOf([] { loadScene(kBeltPath, {"k=abc"}); });
  const std::string belt = readFile(kBeltPath);
  EXPECT_TRUE(Has(e, "belt.yaml:" + std::to_string(lineOf(belt, "  k: 300")) + ":"));  // k's value
  EXPECT_TRUE(Has(e, "parameters.k"));
  EXPECT_TRUE(Has(e, "parameter 'k': expected a number or an expression, got 'abc'"));
  EXPECT_TRUE(Has(errorOf([] { loadScene(kBeltPath, {"k=3e"}); }), "got '3e'"));
  EXPECT_TRUE(Has(errorOf([] { loadScene(kBeltPath, {"k=inf"}); }), "got 'inf'"));
}

TEST(SceneLoader, FrictionNamingNoDefinedLawListsTheDefinedOnes) {
  const std::string e = errorOf([] { loadScene(kBeltPath, {"friction=rohyoo"}); });
  EXPECT_TRUE(Has(e, "belt.yaml:"));
  EXPECT_TRUE(Has(e, "materials[0].friction"));
  EXPECT_TRUE(Has(e, "'rohyoo'"));
  EXPECT_TRUE(Has(e, "defined: roh_yoo, recurdyn, adams, coulomb, stribeck"));
}

TEST(SceneLoader, BadValueOfTheSelectedLawIsLocated) {
  const std::string e = errorOf([] { loadScene(kBeltPath, {"a=0.9"}); });
  EXPECT_TRUE(Has(e, "belt.yaml:"));
  EXPECT_TRUE(Has(e, "friction_laws.roh_yoo"));
  EXPECT_TRUE(Has(e, "a must be > 1 (got 0.9)"));
  EXPECT_TRUE(Has(e, "selected by materials[0].friction"));
  // A key the law does not take, in the law in use.
  const std::string key = errorOfScene(replaced(kBase, "{mu: 0.3}", "{mu: 0.3, mu_s: 0.4}"));
  EXPECT_TRUE(Has(key, at(kBase, "{mu: 0.3}")));
  EXPECT_TRUE(Has(key, "unknown key 'mu_s'"));
}

TEST(SceneLoader, UnknownKeyIsLocatedAndListsTheAcceptedKeys) {
  const std::string yaml = replaced(kBase, "mass: $m", "masss: $m");
  const std::string e = errorOfScene(yaml);
  EXPECT_TRUE(Has(e, at(yaml, "masss") + ": bodies[1].masss: unknown key 'masss'"));
  EXPECT_TRUE(Has(e, "accepted keys: name, kind, mass, inertia"));
  // Top level, and inside an inline mapping.
  EXPECT_TRUE(Has(errorOfScene(kBase + "outptu: {}\n"), "unknown key 'outptu'"));
  const std::string inline_key = replaced(kBase, "{stiffness: 1e5}", "{stifness: 1e5}");
  EXPECT_TRUE(
      Has(errorOfScene(inline_key), at(inline_key, "stifness") + ": materials[0].normal.stifness"));
  EXPECT_TRUE(
      Has(errorOfScene(replaced(kBase, "kind: kinematic", "kind: kinematic\n    kind: dynamic")),
          "key 'kind' given twice"));
}

TEST(SceneLoader, UndefinedReferenceIsLocated) {
  const std::string yaml = replaced(kBase, "mass: $m", "mass: $undefined");
  const std::string e = errorOfScene(yaml);
  EXPECT_TRUE(Has(e, at(yaml, "$undefined") + ": bodies[1].mass"));
  EXPECT_TRUE(Has(e, "'$undefined' refers to no parameter (known parameters: m, k, law)"));
}

TEST(SceneLoader, MissingFileAndSyntaxError) {
  EXPECT_TRUE(Has(errorOf([] { loadScene("/nonexistent/scene.yaml"); }),
                  "cannot open scene file '/nonexistent/scene.yaml'"));
  const std::string yaml = replaced(kBase, "position: [0, 0, 0.05]", "position: [0, 0, 0.05");
  const std::string e = errorOfScene(yaml);
  EXPECT_TRUE(Has(e, "test.yaml:"));
  EXPECT_TRUE(Has(e, "invalid YAML"));
  EXPECT_TRUE(Has(errorOfScene("bodies: {a: [1, 2}\n"), "test.yaml:1:"));
  EXPECT_TRUE(Has(errorOfScene(""), "test.yaml: expected a mapping"));
}

TEST(SceneLoader, ModelErrorsComeBackWithFileAndKeyPath) {
  const std::string yaml = replaced(kBase, "m: 10", "m: -1");
  const std::string e = errorOfScene(yaml);
  EXPECT_TRUE(Has(e, at(yaml, "name: box") + ": bodies[1]: body 'box': mass must be > 0"));
  // Negative spring stiffness through an override, located at the spring.
  EXPECT_TRUE(Has(errorOfScene(kBase, {"k=-3"}),
                  at(kBase, "{name: s,") + ": springs[0]: spring 's': stiffness"));
  // A bad normal law, located at the normal block.
  EXPECT_TRUE(Has(errorOfScene(replaced(kBase, "{stiffness: 1e5}", "{stiffness: 0}")),
                  "materials[0].normal: normal law: stiffness must be > 0"));
  EXPECT_TRUE(Has(errorOfScene(replaced(kBase, "planar_translation", "sliding")),
                  "joints[0].type: unknown joint type"));
}

// materials[].anisotropy (contact/anisotropy.hpp): bad ratios, axes, frames and a sphere's
// frame are refused at their key; a non-unit axis is a direction, normalised.
TEST(SceneLoader, AnisotropyErrorsNameTheirKey) {
  auto with = [](const std::string& anisotropy) {
    return replaced(kBase, "friction: $law}", "friction: $law, anisotropy: " + anisotropy + "}");
  };
  for (const char* bad : {"[0, 1]", "[1, -2]", "[1, .nan]", "[1]", "[1, 2, 3]"}) {
    const std::string yaml = with(std::string("{ratio: ") + bad + "}");
    EXPECT_TRUE(Has(errorOfScene(yaml), "materials[0].anisotropy.ratio")) << bad;
  }
  const std::string backward = with("{backward: [1, 0]}");
  EXPECT_TRUE(Has(errorOfScene(backward),
                  at(backward, "[1, 0]") +
                      ": materials[0].anisotropy.backward: expected 2 ratios > 0 [along the "
                      "axis, across it], found"));
  const std::string zero = with("{axis: [0, 0, 0]}");
  EXPECT_TRUE(Has(errorOfScene(zero),
                  "materials[0].anisotropy: anisotropy: axis must be a finite, non-zero "
                  "direction (got [0, 0, 0])"));
  EXPECT_TRUE(Has(errorOfScene(with("{frame: c}")), "materials[0].anisotropy.frame"));
  EXPECT_TRUE(Has(errorOfScene(with("{grain: 1}")),
                  "materials[0].anisotropy.grain: unknown key 'grain' (accepted keys: frame, axis, "
                  "ratio, backward)"));
  // A sphere has no direction its surface keeps: refused at the contact, naming the other side.
  const std::string ball =
      replaced(with("{frame: b}"), "{name: block, shape: box, size: [0.2, 0.2, 0.1]}",
               "{name: block, shape: sphere, radius: 0.05}");
  EXPECT_TRUE(Has(errorOfScene(ball),
                  "whose surface has no direction of its own; fix it in the "
                  "other geometry (anisotropy.frame: a)"));
  // A direction of any length; the model holds it unit.
  const Scene scene = loadSceneFromString(with("{axis: [3, 4, 0], ratio: [0.5, 2]}"), "t.yaml");
  const contact::Anisotropy& an = scene.model->materials[0].anisotropy;
  EXPECT_TRUE(an.active);
  EXPECT_NEAR(an.axis.x(), 0.6, 1e-15);
  EXPECT_NEAR(an.axis.y(), 0.8, 1e-15);
  EXPECT_EQ(an.backward[1], 2.0);
}

// materials[].rolling and .spinning (contact/rolling_resistance.hpp): missing, non-positive
// and unknown keys are refused at their key; the limits are mu_r and mu_spin r_c.
TEST(SceneLoader, RollingAndSpinningErrorsNameTheirKey) {
  auto with = [](const std::string& part) {
    return replaced(kBase, "friction: $law}", "friction: $law, " + part + "}");
  };
  EXPECT_TRUE(Has(errorOfScene(with("rolling: {stiffness: 5}")),
                  "materials[0].rolling: missing required key 'length'"));
  EXPECT_TRUE(Has(errorOfScene(with("rolling: {length: -0.001, stiffness: 5}")),
                  "materials[0].rolling.length"));
  EXPECT_TRUE(Has(errorOfScene(with("rolling: {length: 0.001, stiffness: 0}")),
                  "materials[0].rolling.stiffness"));
  EXPECT_TRUE(Has(errorOfScene(with("rolling: {length: 0.001, stiffness: 5, damping: -1}")),
                  "materials[0].rolling.damping"));
  EXPECT_TRUE(Has(errorOfScene(with("spinning: {mu: 0.3, stiffness: 5}")),
                  "materials[0].spinning: missing required key 'radius'"));
  EXPECT_TRUE(Has(errorOfScene(with("spinning: {mu: 0.3, radius: 0.01, stiffness: 5, mu_r: 1}")),
                  "materials[0].spinning.mu_r: unknown key 'mu_r'"));
  const Scene scene = loadSceneFromString(
      with("rolling: {length: 0.002, stiffness: 5}, spinning: {mu: 0.3, radius: 0.01, "
           "stiffness: 2, damping: 0.1, stick_speed: 0.01}"),
      "t.yaml");
  const contact::RollingResistance& r = scene.model->materials[0].resistance;
  ASSERT_TRUE(r.rolling && r.spinning);
  EXPECT_EQ(r.rolling->params().mu_s, 0.002);
  EXPECT_EQ(r.rolling->params().stick_speed, 1e-3);  // the documented default
  EXPECT_NEAR(r.spinning->params().mu_s, 0.003, 1e-18);
  EXPECT_EQ(r.spinning->params().stick_speed, 0.01);
}

TEST(SceneLoader, WrongTypesSayWhatWasExpectedAndFound) {
  const std::string two = replaced(kBase, "position: [0, 0, 0.05]", "position: [0, 0.05]");
  EXPECT_TRUE(Has(errorOfScene(two),
                  at(two, "[0, 0.05]") +
                      ": bodies[1].position: expected 3 numbers [x, y, z], found a sequence "
                      "of 2 items"));
  EXPECT_TRUE(Has(errorOfScene(replaced(kBase, "mass: $m", "mass: heavy")),
                  "bodies[1].mass: expected a number, found 'heavy'"));
  EXPECT_TRUE(Has(errorOfScene(replaced(kBase, "mass: $m", "mass: $law")),
                  "bodies[1].mass: expected a number, found 'coulomb' (from $law)"));
  EXPECT_TRUE(Has(errorOfScene(replaced(kBase, "[0, 0, 0.05]", "[0, x, 0.05]")),
                  "bodies[1].position[1]: expected a number, found 'x'"));
  EXPECT_TRUE(Has(errorOfScene(replaced(kBase, "kind: kinematic", "kind: static")),
                  "bodies[0].kind: expected one of dynamic, kinematic, found 'static'"));
  EXPECT_TRUE(Has(errorOfScene(replaced(kBase, "time_step: 0.002", "time_step: -1")),
                  "simulation.time_step: expected a number > 0, found '-1'"));
  EXPECT_TRUE(Has(errorOfScene(replaced(kBase, "material: steel", "material: rubber")),
                  "contacts[0].material: unknown material 'rubber' (known materials: steel)"));
  EXPECT_TRUE(Has(errorOfScene(replaced(kBase, "a: ground", "a: floor")),
                  "contacts[0].a: unknown geometry 'floor' (known geometries: ground, block)"));
  EXPECT_TRUE(Has(errorOfScene(replaced(kBase, "child: box", "child: bx")),
                  "joints[0].child: unknown body 'bx' (known bodies: world, belt, box)"));
  EXPECT_TRUE(Has(errorOfScene(replaced(kBase, "  coulomb: {mu: 0.3}", "  colomb: {mu: 0.3}")),
                  "friction_laws.colomb: unknown friction law 'colomb'"));
  EXPECT_TRUE(Has(errorOfScene(replaced(kBase, "{name: ground, shape: halfspace}",
                                        "{name: ground, shape: halfspace, size: [1, 1, 1]}")),
                  "bodies[0].geometry[0].size: a halfspace takes no size"));
  EXPECT_TRUE(Has(errorOfScene(replaced(kBase, "position: [0, 0, 0.05]",
                                        "position: [0, 0, 0.05]\n    rpy: [0, 0, 0]\n    "
                                        "orientation: [1, 0, 0, 0]")),
                  "bodies[1].rpy: give orientation or rpy, not both"));
  EXPECT_TRUE(Has(errorOfScene(replaced(kBase, "    mass: $m\n", "")),
                  "bodies[1]: missing required key 'mass'"));
}

TEST(SceneLoader, OptionalBlocks) {
  const std::string yaml =
      replaced(kBase, "    mass: $m\n",
               "    mass: $m\n    inertia: [1, 2, 2.5, 0.1, 0, 0]\n    rpy: [0, 0, "
               "1.5707963267948966]\n") +
      "output:\n  interval: 0.01\n  summary: {body: box, coordinate: z, last_cycles: 5}\n";
  const Scene scene = loadSceneFromString(
      replaced(yaml, "{time_step: 0.002, duration: 1}",
               "{time_step: 0.002, duration: 1, integrator: semi_implicit_euler, "
               "baumgarte: {alpha: 5, beta: 6}, collision: {broadphase: true}}"),
      "test.yaml");
  const Body& box = scene.model->bodies[1];
  EXPECT_DOUBLE_EQ(box.inertia(1, 1), 2.0);
  EXPECT_DOUBLE_EQ(box.inertia(0, 1), 0.1);
  EXPECT_DOUBLE_EQ(box.inertia(1, 0), 0.1);
  EXPECT_TRUE((box.orientation * Vec3::UnitX()).isApprox(Vec3::UnitY(), 1e-12));
  const auto& o = scene.model->options;
  EXPECT_EQ(o.integrator, IntegratorType::kSemiImplicitEuler);
  EXPECT_DOUBLE_EQ(o.baumgarte_alpha, 5.0);
  EXPECT_DOUBLE_EQ(o.baumgarte_beta, 6.0);
  EXPECT_TRUE(o.collision.broadphase);
  EXPECT_TRUE(o.collision.closed_form_box_halfspace);
  EXPECT_DOUBLE_EQ(scene.output.interval, 0.01);
  EXPECT_EQ(scene.output.summary.coordinate, 2);
  EXPECT_EQ(scene.output.summary.last_cycles, 5);
  // The spring's rest length defaults to the initial distance.
  EXPECT_DOUBLE_EQ(scene.model->springs[0].rest_length, 0.5);
  // No output block: defaults, and no summary body.
  const Scene plain = loadSceneFromString(kBase, "test.yaml");
  EXPECT_DOUBLE_EQ(plain.output.interval, 1e-3);
  EXPECT_TRUE(plain.output.summary.body.empty());
}

TEST(SceneLoader, LoadsFromATemporaryFile) {
  const auto path = std::filesystem::temp_directory_path() / "tribo_scene_loader_test.yaml";
  {
    std::ofstream out(path);
    out << replaced(kBase, "mass: $m", "mass: [1]");
  }
  const std::string e = errorOf([&] { loadScene(path.string()); });
  EXPECT_TRUE(Has(e, path.string() + ":" + std::to_string(lineOf(kBase, "mass: $m"))));
  std::filesystem::remove(path);
}

TEST(SceneParameters, NumbersParseFullyAndFinitely) {
  EXPECT_EQ(parseNumber("2.5e5"), 2.5e5);
  EXPECT_EQ(parseNumber("+1"), 1.0);
  EXPECT_EQ(parseNumber("-0.25"), -0.25);
  EXPECT_EQ(parseNumber(".5"), 0.5);
  EXPECT_EQ(parseNumber("0.3333333333333333"), 0.3333333333333333);
  for (const char* bad : {"", "+", "abc", "1.5m", " 1", "1 ", "inf", "nan", ".inf", "+-1", "1e999"})
    EXPECT_FALSE(parseNumber(bad).has_value()) << bad;
}

TEST(SceneParameters, StringParametersTakeAnyText) {
  ParameterTable table;
  table.add("law", "roh_yoo", {"f.yaml", 2, 8});
  table.add("k", "300", {"f.yaml", 3, 6});
  const std::vector<std::string> overrides{"law=42", "k=1e3"};
  table.applyOverrides(overrides, "f.yaml");
  EXPECT_EQ(table.find("law")->text, "42");
  EXPECT_EQ(table.find("k")->text, "1e3");
  EXPECT_TRUE(table.find("k")->overridden);
  EXPECT_TRUE(Has(errorOf([&] {
                    table.add("k", "1", {"f.yaml", 4, 1});
                  }),
                  "f.yaml:4:1: parameters.k: parameter 'k' defined twice"));
  EXPECT_TRUE(Has(errorOf([&] {
                    table.add("2x", "1", {"f.yaml", 5, 1});
                  }),
                  "a parameter name must be"));
  // A value may refer to other parameters (io/scene_expression.hpp evaluates it).
  EXPECT_NO_THROW(table.add("y", "$k", {"f.yaml", 6, 1}));
}

}  // namespace
}  // namespace tribo::io
