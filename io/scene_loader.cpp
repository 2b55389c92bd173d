// The scene format, key by key: docs/scene-format.md.
#include "io/scene_loader.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <memory>
#include <optional>

#include "friction/friction_law.hpp"
#include "io/file_read.hpp"
#include "io/scene_path_override.hpp"
#include "io/scene_reader.hpp"
#include "io/urdf_reader.hpp"
#include "io/utf8_check.hpp"

namespace tribo::io {
namespace {

[[noreturn]] void yamlError(const YAML::Exception& e, const std::string& name) {
  const int line = e.mark.line < 0 ? 0 : e.mark.line + 1;
  const int column = e.mark.column < 0 ? 0 : e.mark.column + 1;
  throw SceneError({name, line, column}, "", "invalid YAML: " + e.msg);
}

}  // namespace

SceneDocument::SceneDocument(const std::string& yaml, const std::string& name_for_errors)
    : name_(name_for_errors), text_(std::make_shared<const std::string>(yaml)) {
  requireUtf8Scene(yaml, name_);
  try {
    root_ = std::make_shared<const YAML::Node>(YAML::Load(yaml));
  } catch (const YAML::Exception& e) {
    yamlError(e, name_);
  }
}

Scene SceneDocument::load(const std::vector<std::string>& overrides,
                          const std::vector<std::string>& package_paths,
                          const RunSettings& settings, const UserLaws& user_laws) const {
  for (const auto& [name, law] : user_laws) {
    for (const auto* known :
         {&friction::knownFrictionLaws(), &friction::knownStatefulFrictionLaws(),
          &friction::knownDynamicFrictionLaws()})
      if (std::find(known->begin(), known->end(), name) != known->end() || name == "tabulated")
        throw SceneError(name_ + ": user friction law '" + name +
                         "' takes a built-in law's name; give it another");
    if (!law) throw SceneError(name_ + ": user friction law '" + name + "' is empty");
  }
  // Overrides of a value by its path change a copy of the document; the parameters' go to
  // the reader.
  std::vector<std::string> parameter_overrides;
  std::optional<YAML::Node> changed;
  std::vector<std::pair<std::string, std::string>> applied;  // path, override
  for (const std::string& item : overrides) {
    if (!isPathOverride(item)) {
      parameter_overrides.push_back(item);
      continue;
    }
    if (!changed) changed = YAML::Load(*text_);  // a tree of its own, with the file's lines
    applied.emplace_back(applyPathOverride(*changed, item, name_), item);
  }
  try {
    return scene_detail::Loader(name_, changed ? *changed : *root_, package_paths, user_laws)
        .load(parameter_overrides, settings);
  } catch (const YAML::Exception& e) {  // any the reader did not foresee
    yamlError(e, name_);
  } catch (const SceneError& e) {
    for (const auto& [path, item] : applied) {
      SceneError said = attributedToOverride(e, path, item);
      if (said.detail() != e.detail()) throw said;
    }
    throw;
  }
}

Scene loadSceneFromString(const std::string& yaml, const std::string& name_for_errors,
                          const std::vector<std::string>& overrides,
                          const std::vector<std::string>& package_paths,
                          const RunSettings& settings, const UserLaws& user_laws) {
  return SceneDocument(yaml, name_for_errors).load(overrides, package_paths, settings, user_laws);
}

Scene loadScene(const std::string& path, const std::vector<std::string>& overrides,
                const std::vector<std::string>& package_paths, const RunSettings& settings,
                const UserLaws& user_laws) {
  if (const std::size_t bad = firstBadUtf8(path); bad != std::string::npos)
    throw SceneError("scene file path '" + printableText(path) + "': expected UTF-8 text, found " +
                     badUtf8Reason(path, bad));
  if (looksLikeUrdf(path))
    throw SceneError(path + ": a URDF robot (its first element is <robot>), not a scene file: " +
                     "load it with sceneFromUrdf (`tribo run FILE`) or name it in a scene's " +
                     "robots:");
  std::string text;
  try {
    text = readFileBounded(path, "scene file", kMaxSceneBytes);
  } catch (const FileReadError& e) {
    throw SceneError(e.what());
  }
  return loadSceneFromString(text, path, overrides, package_paths, settings, user_laws);
}

}  // namespace tribo::io
