#include "python/scene_handle.hpp"

#include <filesystem>

#include "io/scene_parameters.hpp"
#include "io/urdf_scene.hpp"
#include "study/csv_text.hpp"

namespace tribo::python {
namespace {

bool anySetting(const io::RunSettings& s) {
  return s.integrator || s.time_step || s.duration || s.relative_tolerance ||
         s.absolute_tolerance || s.event_location || s.output_interval;
}

}  // namespace

io::Scene SceneHandle::reload() const { return loadWith({}); }

io::Scene SceneHandle::withSettings(const io::RunSettings& settings) const {
  if (!anySetting(settings)) return scene;
  return loadWith(settings);
}

io::Scene SceneHandle::loadWith(const io::RunSettings& settings) const {
  switch (source) {
    case Source::kFile:
      return io::loadScene(origin, overrides, package_paths, settings, user_laws);
    case Source::kText:
      return io::loadSceneFromString(origin, scene.path, overrides, package_paths, settings,
                                     user_laws);
    case Source::kUrdf: {
      // A URDF scene's run settings are its parameters (io/urdf_scene.hpp).
      if (settings.relative_tolerance || settings.absolute_tolerance || settings.event_location ||
          settings.output_interval)
        throw io::SceneError(origin +
                             ": a URDF scene takes duration, time_step and integrator only");
      std::vector<std::string> more = overrides;
      if (settings.duration) more.push_back("duration=" + study::csvNumber(*settings.duration, 17));
      if (settings.time_step) more.push_back("dt=" + study::csvNumber(*settings.time_step, 17));
      if (settings.integrator) more.push_back("integrator=" + integratorName(*settings.integrator));
      io::UrdfReadOptions read;
      read.strict = strict_urdf;
      return io::sceneFromUrdf(origin, package_paths, more, read);
    }
  }
  return scene;
}

SceneHandle loadSceneHandle(const std::string& source, std::vector<std::string> overrides,
                            std::vector<std::string> package_paths, io::UserLaws user_laws) {
  SceneHandle h;
  // A string that names an existing file is a path; anything else with a line break or a
  // colon is YAML text; the rest a path that does not exist (the loader says so).
  std::error_code ec;
  const bool is_file = std::filesystem::is_regular_file(source, ec);
  const bool is_text = !is_file && source.find_first_of("\n:") != std::string::npos;
  h.source = is_text ? SceneHandle::Source::kText : SceneHandle::Source::kFile;
  h.origin = source;
  h.overrides = std::move(overrides);
  h.package_paths = std::move(package_paths);
  h.user_laws = std::move(user_laws);
  h.scene = is_text ? io::loadSceneFromString(source, "<string>", h.overrides, h.package_paths, {},
                                              h.user_laws)
                    : io::loadScene(source, h.overrides, h.package_paths, {}, h.user_laws);
  return h;
}

SceneHandle loadUrdfHandle(const std::string& path, std::vector<std::string> overrides,
                           std::vector<std::string> package_paths, bool strict) {
  SceneHandle h;
  h.source = SceneHandle::Source::kUrdf;
  h.origin = path;
  h.overrides = std::move(overrides);
  h.package_paths = std::move(package_paths);
  h.strict_urdf = strict;
  io::UrdfReadOptions read;
  read.strict = strict;
  h.scene = io::sceneFromUrdf(path, h.package_paths, h.overrides, read);
  return h;
}

}  // namespace tribo::python
