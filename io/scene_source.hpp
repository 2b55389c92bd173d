// One entry point that loads any scene file the command line or a study is given: a scene
// YAML (io/scene_loader.hpp) or a URDF robot run on its own (io/urdf_scene.hpp), told apart by
// content (a <robot> root element, whatever the name ends with) or, for a file that is not
// even XML, by a name ending in .urdf (the URDF reader then says what is wrong with it).
// The request carries what every caller may pass: --set overrides, --package-path folders,
// run settings (io::RunSettings; a URDF run takes only `threads`, its other settings are
// --set names), the URDF reader's options and friction laws defined by the caller.
// Not here: scene text given as a string (io::loadSceneFromString), `tribo info`'s report.
#pragma once

#include <string>
#include <vector>

#include "io/scene_loader.hpp"
#include "io/urdf_reader.hpp"

namespace tribo::io {

struct SceneRequest {
  std::vector<std::string> overrides;      // NAME=VALUE (--set)
  std::vector<std::string> package_paths;  // --package-path folders
  RunSettings settings;
  UrdfReadOptions urdf;  // a URDF file only
  UserLaws user_laws;    // a scene file only
};

// True when `path` is loaded as a URDF robot (above).
bool isUrdfScene(const std::string& path);

// Loads `path` as its kind says. Throws SceneError or UrdfError.
Scene loadAnyScene(const std::string& path, const SceneRequest& request);

}  // namespace tribo::io
