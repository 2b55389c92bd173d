// The Python module's scene: a loaded io::Scene plus what it was loaded from (a file, YAML
// text or a URDF, with the overrides and package paths), so that a run with other run
// settings (duration, step, integrator...) reloads it and the builder checks them
// (io::RunSettings: a built Model is never edited). Shared by the scene, simulator and
// study bindings. Not here: the bindings themselves.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/scene_loader.hpp"

namespace tribo::python {

struct SceneHandle {
  enum class Source { kFile, kText, kUrdf } source = Source::kFile;
  std::string origin;  // the path, or the YAML text
  std::vector<std::string> overrides;
  std::vector<std::string> package_paths;
  bool strict_urdf = false;
  io::UserLaws user_laws;  // laws given by the caller (python/python_law.hpp)
  io::Scene scene;

  // The same scene with `settings` replacing its own (itself when none is given).
  io::Scene withSettings(const io::RunSettings& settings) const;
  // The scene loaded again from its origin with the current overrides (and its run settings).
  io::Scene reload() const;

 private:
  io::Scene loadWith(const io::RunSettings& settings) const;
};

SceneHandle loadSceneHandle(const std::string& source, std::vector<std::string> overrides,
                            std::vector<std::string> package_paths, io::UserLaws user_laws);
SceneHandle loadUrdfHandle(const std::string& path, std::vector<std::string> overrides,
                           std::vector<std::string> package_paths, bool strict);

}  // namespace tribo::python
