// Overrides of any scene value by its path (io/scene_path_override.hpp): `--set` reaches
// simulation, output, bodies, materials and contacts as it reaches parameters, by key, list
// index or element name, with YAML values (numbers, words, flow maps) and the parameters'
// expressions; the value is checked as the file's own is, and every mistake names the
// override, the step of the path that does not exist and what is there. The scene file's
// document is left as it was (a second load without the override gets the file's values)
// and errors elsewhere keep their lines.
#include "io/scene_path_override.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/model.hpp"
#include "friction/friction_law.hpp"
#include "io/scene_loader.hpp"

namespace tribo::io {
namespace {

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

const Body& body(const Scene& s, const std::string& name) {
  return s.model->bodies[s.model->findBody(name)->value];
}

std::string errorOf(const std::vector<std::string>& overrides) {
  try {
    (void)loadScene(kBelt, overrides);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ScenePathOverride, TellsPathsFromParameters) {
  for (const char* path : {"output.interval=1", "bodies[box].mass=1", "a.b=1", "x[0]=1"})
    EXPECT_TRUE(isPathOverride(path)) << path;
  for (const char* name : {"v_b=1", "dt=1e-3", "k=2*$m", "friction=lugre", "x=a.b"})
    EXPECT_FALSE(isPathOverride(name)) << name;
}

TEST(ScenePathOverride, ReachesValuesBeyondTheParameters) {
  const Scene s = loadScene(
      kBelt, {"output.interval=0.002", "bodies[box].mass=12", "simulation.time_step=$dt / 2",
              "v_b=0.7", "output.summary={channel: box.vx, last_cycles: 5}"});
  EXPECT_EQ(s.output.interval, 0.002);
  EXPECT_EQ(body(s, "box").mass, 12.0);
  EXPECT_EQ(s.model->options.time_step, 0.0005);  // the expression, over the parameter dt
  EXPECT_EQ(s.output.summary.channel, "box.vx");
  EXPECT_TRUE(s.output.summary.body.empty());
  EXPECT_EQ(s.output.summary.last_cycles, 5);
  bool v_b = false;  // parameters still apply beside paths
  for (const auto& [name, value] : s.parameters) v_b = v_b || (name == "v_b" && value == "0.7");
  EXPECT_TRUE(v_b);
  // By index as by name; a list element replaced whole.
  EXPECT_EQ(body(loadScene(kBelt, {"bodies[1].mass=3"}), "box").mass, 3.0);
  EXPECT_EQ(loadScene(kBelt, {"materials[0].friction=lugre"}).model->materials[0].friction->name(),
            "lugre");
}

TEST(ScenePathOverride, LeavesTheFileAsItWas) {
  const SceneDocument doc(
      "simulation: {duration: 1, time_step: 0.01}\n"
      "bodies:\n"
      "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}\n"
      "  - {name: box, mass: 2, inertia: [1, 1, 1]}\n",
      "doc.yaml");
  EXPECT_EQ(body(doc.load({"bodies[box].mass=5"}), "box").mass, 5.0);
  EXPECT_EQ(body(doc.load(), "box").mass, 2.0);
  EXPECT_EQ(doc.load({"simulation.duration=3"}).model->options.duration, 3.0);
  EXPECT_EQ(doc.load().model->options.duration, 1.0);
}

TEST(ScenePathOverride, EveryMistakeNamesTheOverrideAndWhatIsThere) {
  struct Case {
    std::string item;
    std::vector<std::string> said;
  };
  const std::vector<Case> cases = {
      {"bodies[boxx].mass=2", {"--set bodies[boxx].mass=2", "no element [boxx]", "belt, box"}},
      {"bodies[7].mass=2", {"no element [7]", "2 elements"}},
      {"output.sumary.channel=x", {"unknown key 'sumary'", "(with --set output.sumary.channel=x)"}},
      {"outptu.interval=1", {"unknown key 'outptu'", "(with --set outptu.interval=1)"}},
      {"output.interval.x=1", {"'output.interval' is not a map"}},
      {"simulation[0]=1", {"'simulation' is not a list"}},
      {"output..x=1", {"an empty key"}},
      {"bodies[=1", {"unclosed or empty '[]'"}},
      {"output.interval=", {"expected a value after '='"}},
      {"output.interval=[1, 2", {"not valid YAML"}},
      // The reader's own checks, said with the override they come from (no file line).
      {"output.interval=abc", {"output.interval", "(from --set output.interval=abc)"}},
      {"output.intervall=0.1", {"unknown key 'intervall'", "(from --set output.intervall=0.1)"}},
      {"simulation.integrator=nope", {"unknown integrator 'nope'", "(from --set"}},
      {"materials[0].friction=nope", {"friction law 'nope' is not defined", "(from --set"}},
      {"output.summary.channel=box.vx", {"either channel or coordinate", "(from --set"}},
  };
  for (const Case& c : cases) {
    const std::string message = errorOf({c.item});
    for (const std::string& s : c.said) EXPECT_NE(message.find(s), message.npos) << message;
    EXPECT_EQ(message.find("belt.yaml:1:1"), message.npos) << "a line that is not the file's";
  }
  // A check one level up keeps the file's line of that level and names the override.
  const std::string up = errorOf({"bodies[box].mass=-1"});
  EXPECT_NE(up.find("mass must be > 0"), up.npos) << up;
  EXPECT_NE(up.find("(with --set bodies[box].mass=-1)"), up.npos) << up;
  EXPECT_NE(up.find("belt.yaml:53:"), up.npos) << up;  // the box's entry in the file
  // An error elsewhere keeps its own line.
  const std::string other = errorOf({"output.interval=0.01", "v_b=x"});
  EXPECT_NE(other.find("belt.yaml:12:"), other.npos) << other;
  const std::string bad_utf8 = errorOf({"output.interval=\xff"});
  EXPECT_NE(bad_utf8.find("expected UTF-8 text"), bad_utf8.npos) << bad_utf8;
}

}  // namespace
}  // namespace tribo::io
