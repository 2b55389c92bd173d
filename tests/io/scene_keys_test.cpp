// The scene's key tables (io/scene_keys.hpp) are the loader's: an unknown key in each section
// is refused listing exactly that section's table; and the committed fuzzing dictionary
// (fuzz/dictionaries/scene.dict) holds every word generated from the tables
// (io/scene_dictionary.hpp), so a new key cannot be left out of fuzzing.
#include "io/scene_keys.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <string>

#include "friction/friction_law.hpp"
#include "friction/law_keys.hpp"
#include "io/scene_dictionary.hpp"
#include "support/scene_text.hpp"

namespace tribo::io {
namespace {

using test::replaced;
using test::sceneErrorOf;

std::string joined(const scene_keys::List& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

// Every section that takes a mapping, in one valid scene.
const std::string kScene = R"(parameters: {m: 1}
simulation: {duration: 0.01, time_step: 0.001, baumgarte: {alpha: 1},
             collision: {broadphase: true}, constraints: {projection: true}}
bodies:
  - {name: a, mass: $m, geometry: [{name: ga, shape: box, size: [0.1, 0.1, 0.1]}]}
  - {name: b, mass: 1, position: [1, 0, 0], geometry: [{name: gb, shape: sphere, radius: 0.1}]}
joints:
  - {name: j, type: revolute, parent: world, child: a, anchor: [0, 0, 0], axis: [0, 0, 1],
     limit: {lower: -1, upper: 1}, spring: {stiffness: 1}, drive: {mode: velocity, constant: 0},
     friction: {law: coulomb, load: constant, normal_force: 1}}
springs:
  - {name: s, a: a, point_a: [0, 0, 0], b: b, point_b: [0, 0, 0], stiffness: 1}
bushings:
  - {name: bu, a: a, b: b, frame_a: {position: [0, 0, 0]}, stiffness: [1, 1, 1]}
torsional_springs:
  - {name: t, a: a, b: b, axis: [0, 0, 1], stiffness: 1}
loads:
  - {name: l, body: a, force: [{ramp: {rate: 1}}, {sines: [{amplitude: 1, frequency: 2}]}, 0]}
friction_laws:
  coulomb: {mu: 0.3}
materials:
  - {name: m1, normal: {stiffness: 1e5}, friction: coulomb}
contacts:
  - {a: ga, b: gb, material: m1}
output: {interval: 0.001, summary: {body: a}}
)";

TEST(SceneKeys, EachSectionRefusesAnUnknownKeyListingItsTable) {
  ASSERT_EQ(sceneErrorOf(kScene), "");
  struct Case {
    std::string from, to;
    const scene_keys::List* keys;
  };
  for (const Case& c :
       {Case{"parameters: {m: 1}", "parameters: {m: 1}\nbogus: 1", &scene_keys::kTop},
        Case{"duration: 0.01,", "duration: 0.01, bogus: 1,", &scene_keys::kSimulation},
        Case{"{alpha: 1}", "{alpha: 1, bogus: 1}", &scene_keys::kBaumgarte},
        Case{"{broadphase: true}", "{broadphase: true, bogus: 1}", &scene_keys::kCollision},
        Case{"{projection: true}", "{projection: true, bogus: 1}", &scene_keys::kConstraints},
        Case{"{name: a, mass", "{bogus: 1, name: a, mass", &scene_keys::kBody},
        Case{"{name: ga,", "{bogus: 1, name: ga,", &scene_keys::kGeometry},
        Case{"{name: j,", "{bogus: 1, name: j,", &scene_keys::kJoint},
        Case{"{lower: -1,", "{bogus: 1, lower: -1,", &scene_keys::kJointLimit},
        Case{"{stiffness: 1}, drive", "{stiffness: 1, bogus: 1}, drive", &scene_keys::kJointSpring},
        Case{"{mode: velocity,", "{bogus: 1, mode: velocity,", &scene_keys::kJointDrive},
        Case{"{law: coulomb,", "{bogus: 1, law: coulomb,", &scene_keys::kJointFriction},
        Case{"{name: s,", "{bogus: 1, name: s,", &scene_keys::kSpring},
        Case{"{name: bu,", "{bogus: 1, name: bu,", &scene_keys::kBushing},
        Case{"{position: [0, 0, 0]}", "{bogus: 1}", &scene_keys::kFrame},
        Case{"{name: t,", "{bogus: 1, name: t,", &scene_keys::kTorsionalSpring},
        Case{"{name: l,", "{bogus: 1, name: l,", &scene_keys::kLoad},
        Case{"{ramp: {rate: 1}}", "{bogus: {rate: 1}}", &scene_keys::kSignal},
        Case{"{rate: 1}", "{rate: 1, bogus: 1}", &scene_keys::kRampSignal},
        Case{"{amplitude: 1,", "{bogus: 1, amplitude: 1,", &scene_keys::kSineTerm},
        Case{"{name: m1,", "{bogus: 1, name: m1,", &scene_keys::kMaterial},
        Case{"{stiffness: 1e5}", "{bogus: 1}", &scene_keys::kNormal},
        Case{"{a: ga,", "{bogus: 1, a: ga,", &scene_keys::kContact},
        Case{"{interval: 0.001,", "{bogus: 1, interval: 0.001,", &scene_keys::kOutput},
        Case{"{body: a}", "{body: a, bogus: 1}", &scene_keys::kSummary}}) {
    const std::string e = sceneErrorOf(replaced(kScene, c.from, c.to));
    EXPECT_NE(e.find("unknown key 'bogus' (accepted keys: " + joined(*c.keys) + ")"),
              std::string::npos)
        << c.to << ": " << e;
  }
}

// The quoted words of a libFuzzer dictionary file.
std::set<std::string> dictionaryWords(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::set<std::string> out;
  for (std::string line; std::getline(in, line);) {
    const auto open = line.find('"');
    const auto close = line.rfind('"');
    if (line.empty() || line.front() == '#' || open == std::string::npos || close <= open) continue;
    out.insert(line.substr(open + 1, close - open - 1));
  }
  return out;
}

TEST(SceneKeys, TheCommittedDictionaryHoldsEveryGeneratedWord) {
  const std::set<std::string> committed =
      dictionaryWords(TRIBO_SOURCE_DIR "/fuzz/dictionaries/scene.dict");
  const std::vector<std::string> generated = sceneDictionaryWords();
  std::string missing;
  for (const std::string& w : generated)
    if (!committed.count(w)) missing += dictionaryLine(w) + "\n";
  EXPECT_EQ(missing, "") << "add these lines to fuzz/dictionaries/scene.dict (or run the "
                            "scene_dictionary tool of a fuzz build):\n"
                         << missing;
  // The generated list covers each source: scene keys, law names and keys, normal laws,
  // joint types, integrators, solvers, output channel groups.
  for (const char* w : {"torsional_springs", "rest_angle", "rotational_stiffness", "lugre",
                        "rate_state", "elasto_plastic", "dahl", "z_ba_fraction", "evolution",
                        "aging", "regularization", "hunt_crossley", "planar_translation",
                        "continuous", "dopri5", "sparse", "friction_states", "tabulated"})
    EXPECT_TRUE(std::find(generated.begin(), generated.end(), w) != generated.end()) << w;
}

TEST(SceneKeys, EveryKnownFrictionLawListsTheKeysItsFactoryAccepts) {
  for (const auto* laws : {&friction::knownFrictionLaws(), &friction::knownStatefulFrictionLaws(),
                           &friction::knownDynamicFrictionLaws()})
    for (const std::string& law : *laws) {
      const friction::LawKeys keys = friction::frictionLawKeys(law);
      EXPECT_FALSE(keys.keys.empty()) << law;
      // An unknown key is refused listing the same keys.
      friction::LawSpec spec{law, {{"bogus", 1.0}}, {}};
      try {
        (void)friction::makeFrictionLaw(spec);
        ADD_FAILURE() << law << " took an unknown key";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("accepted keys: " + joined(keys.keys)),
                  std::string::npos)
            << e.what();
      }
    }
  EXPECT_THROW(friction::frictionLawKeys("nope"), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::io
