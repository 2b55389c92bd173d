#include "io/scene_source.hpp"

#include <cctype>
#include <filesystem>

#include "io/urdf_scene.hpp"

namespace tribo::io {

bool isUrdfScene(const std::string& path) {
  if (looksLikeUrdf(path)) return true;
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".urdf";
}

Scene loadAnyScene(const std::string& path, const SceneRequest& request) {
  if (isUrdfScene(path))
    return sceneFromUrdf(path, request.package_paths, request.overrides, request.urdf,
                         request.settings);
  return loadScene(path, request.overrides, request.package_paths, request.settings,
                   request.user_laws);
}

}  // namespace tribo::io
