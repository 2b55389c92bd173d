// Scene files: a YAML description of bodies, geometry, joints, force elements, friction laws,
// materials, contact pairs and output, turned into a validated, immutable Model through
// ModelBuilder. The format is documented in docs/scene-format.md, with scenes/belt.yaml as
// a commented example; in short, the top-level keys are
//   parameters, simulation, bodies, robots (URDF files), joints, springs, bushings,
//   torsional_springs, loads, friction_laws, materials, contacts, output
// and a scalar "$name" anywhere stands for parameter `name` (io/scene_parameters.hpp).
// The loader is strict: unknown keys, wrong types and dangling names are SceneErrors that
// give file:line:col, the key path (e.g. "bodies[1].mass") and what was expected vs found;
// errors of ModelBuilder, the friction-law factory and the normal laws come back the same
// way, located at the element that caused them.
// Not here: running the scene or writing results; reading URDF (io/urdf_reader.hpp, placed
// by io/urdf_model.hpp); writing scene files.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/model.hpp"
#include "io/output_channels.hpp"
#include "io/scene_parameters.hpp"

namespace YAML {
class Node;
}

namespace tribo::io {

// Which body coordinate the run summary analyses (study/oscillation_summary.hpp).
struct SummarySpec {
  std::string body;    // body name; empty when the scene asks for no summary
  int coordinate = 0;  // of the body origin, world frame: 0 = x, 1 = y, 2 = z
  // Or any recorded column (io/output_channels.hpp), e.g. "flywheel.yaw" or "hinge.q";
  // then `body` (optional) only gives the slip for the stuck fraction.
  std::string channel;
  double stick_speed = 1e-3;  // [m/s] slip speed below which the body counts as stuck
  int last_cycles = 3;        // cycles averaged for amplitude and period
};

struct OutputSpec {
  double interval = 1e-3;  // [s] sampling of trajectory.csv
  int digits = 10;  // significant digits of trajectory.csv's numbers (17: every double exactly)
  std::vector<std::string> channels = defaultChannelGroups();  // io/output_channels.hpp
  SummarySpec summary;
};

struct Scene {
  std::string path;  // the file it came from (or the name given for a string)
  std::shared_ptr<const tribo::Model> model;
  OutputSpec output;
  // Resolved parameter name -> value text (after overrides), in file order, for the run
  // summary.
  std::vector<std::pair<std::string, std::string>> parameters;
  // What the loader changed or assumed to make the input simulable (e.g. a massless URDF
  // link given a stand-in mass); reported with the results.
  std::vector<std::string> notes;
};

// Run settings that studies vary (the tradeoff's ladder, a Python caller, a sweep): each one
// given replaces the scene's own value before the model is built, so the builder validates
// it and everything derived from it follows (automatic joint-limit gains from the time step,
// for one). The one path for changing how a loaded scene runs; a built Model is never
// copied and edited.
struct RunSettings {
  std::optional<IntegratorType> integrator;
  std::optional<double> time_step;           // [s]; the communication interval for dopri5, bdf
  std::optional<double> duration;            // [s]
  std::optional<double> relative_tolerance;  // dopri5, bdf
  std::optional<double> absolute_tolerance;  // dopri5, bdf
  std::optional<bool> event_location;        // dopri5, bdf
  std::optional<double> output_interval;     // [s] output.interval
  std::optional<int> threads;                // simulation.threads (kAutoThreads or >= 1)
};

// Friction laws the caller defines (e.g. one written in Python), by name: a material's
// `friction: NAME` may select one as it selects an entry of friction_laws. A name may not be
// a built-in law's (SceneError).
using UserLaws = std::map<std::string, std::shared_ptr<const friction::FrictionLaw>>;

// Loads a scene file. `overrides` are NAME=VALUE strings (the command line's --set), applied
// to the parameters: section before any "$name" is resolved; `package_paths` are the
// command line's --package-path folders for the robots' package:// meshes. Throws SceneError,
// also for a bad run setting (naming the file and the setting's key, io/run_settings_check.hpp)
// and for a URDF file (io/urdf_scene.hpp loads one as a scene).
Scene loadScene(const std::string& path, const std::vector<std::string>& overrides = {},
                const std::vector<std::string>& package_paths = {},
                const RunSettings& settings = {}, const UserLaws& user_laws = {});

// `settings` (RunSettings) replace the scene's own run settings.
// The same from YAML text; `name_for_errors` stands for the file name in messages and in
// Scene::path.
Scene loadSceneFromString(const std::string& yaml, const std::string& name_for_errors,
                          const std::vector<std::string>& overrides = {},
                          const std::vector<std::string>& package_paths = {},
                          const RunSettings& settings = {}, const UserLaws& user_laws = {});

// A scene's YAML text parsed once and built into Scenes many times: a sweep's points differ
// only in their overrides, and parsing the text is most of the cost of loading a small
// scene. load() gives what loadSceneFromString gives for the same text and arguments (the
// model is rebuilt from the parsed tree, so everything derived from a parameter follows).
// One document per thread: yaml-cpp's nodes are not safe to read from several threads at
// once. Throws SceneError for text that is not YAML.
class SceneDocument {
 public:
  SceneDocument(const std::string& yaml, const std::string& name_for_errors);
  Scene load(const std::vector<std::string>& overrides = {},
             const std::vector<std::string>& package_paths = {}, const RunSettings& settings = {},
             const UserLaws& user_laws = {}) const;

 private:
  std::string name_;
  std::shared_ptr<const YAML::Node> root_;
  std::shared_ptr<const std::string> text_;  // read again for overrides of values by path
};

}  // namespace tribo::io
