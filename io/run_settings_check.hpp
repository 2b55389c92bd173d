// Checks a run's settings (time step, duration, tolerances, threads) before the model is
// built, so that a bad one, from a scene file, a study's RunSettings, Python or a URDF run's
// --set, is a SceneError naming the file and the setting's key, e.g.
//   robot.urdf: run setting 'dt' (time_step): must be > 0, got 0
// rather than the builder's ModelError naming neither. The checks are the builder's own
// (core/model_builder.hpp), which stays the last word.
// Not here: reading the settings (io/scene_loader.hpp, io/urdf_scene.hpp).
#pragma once

#include <string>

#include "core/model.hpp"

namespace tribo::io {

// How the input that set each option names it: a scene file's keys by default, a URDF
// run's --set names for `urdf()`.
struct RunSettingKeys {
  std::string time_step = "simulation.time_step";
  std::string duration = "simulation.duration";
  std::string relative_tolerance = "simulation.rtol";
  std::string absolute_tolerance = "simulation.atol";
  std::string threads = "simulation.threads";
  static RunSettingKeys urdf();
};

// Throws SceneError "FILE: run setting 'KEY' (FIELD): must be WHAT, got VALUE" for the first
// option the builder would refuse.
void checkRunOptions(const SimulationOptions& options, const std::string& file,
                     const RunSettingKeys& keys = {});

// The same message for one value: throws unless `ok`.
void requireRunSetting(bool ok, const std::string& file, const std::string& key,
                       const std::string& field, const std::string& must, double value);

}  // namespace tribo::io
