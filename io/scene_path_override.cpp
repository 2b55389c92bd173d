#include "io/scene_path_override.hpp"

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <vector>

#include "io/scene_parameters.hpp"
#include "io/utf8_check.hpp"

namespace tribo::io {
namespace {

// One step of a path: a map key, or a list element by index or by name.
struct Step {
  std::string key;
  bool element = false;  // [..]
};

std::vector<Step> stepsOf(std::string_view path, const auto& fail) {
  std::vector<Step> steps;
  std::size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string_view::npos || close == i + 1) fail("an unclosed or empty '[]'");
      steps.push_back({std::string(path.substr(i + 1, close - i - 1)), true});
      i = close + 1;
      if (i < path.size() && path[i] == '.') ++i;
      continue;
    }
    std::size_t end = i;
    while (end < path.size() && path[end] != '.' && path[end] != '[') ++end;
    if (end == i) fail("an empty key");
    steps.push_back({std::string(path.substr(i, end - i)), false});
    i = end;
    if (i < path.size() && path[i] == '.') {
      ++i;
      if (i == path.size()) fail("an empty key at the end");
    }
  }
  if (steps.empty()) fail("an empty path");
  return steps;
}

bool allDigits(const std::string& s) {
  for (const char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return !s.empty();
}

// The element of the list `list` chosen by index or by its name: key; -1 when none.
long elementOf(const YAML::Node& list, const std::string& key) {
  if (allDigits(key)) {
    const std::size_t i = key.size() > 9 ? list.size() : std::stoul(key);
    return i < list.size() ? static_cast<long>(i) : -1;
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YAML::Node item = list[i];
    if (item.IsMap() && item["name"] && item["name"].IsScalar() && item["name"].Scalar() == key)
      return static_cast<long>(i);
  }
  return -1;
}

std::string namesOf(const YAML::Node& list) {
  std::string out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YAML::Node item = list[i];
    if (!item.IsMap() || !item["name"] || !item["name"].IsScalar()) continue;
    if (!out.empty()) out += ", ";
    out += item["name"].Scalar();
  }
  return out.empty() ? "none named" : out;
}

}  // namespace

bool isPathOverride(std::string_view item) {
  const std::string_view name = item.substr(0, item.find('='));
  return name.find('.') != std::string_view::npos || name.find('[') != std::string_view::npos;
}

std::string applyPathOverride(YAML::Node& root, const std::string& item, const std::string& file) {
  const SourceLocation where{file, 0, 0};
  if (const std::size_t bad = firstBadUtf8(item); bad != std::string::npos)
    throw SceneError(where, "--set " + printableText(item),
                     "expected UTF-8 text, found " + badUtf8Reason(item, bad) + " at byte " +
                         std::to_string(bad + 1));
  const std::string key_path = "--set " + item;
  const auto fail = [&](const std::string& what) -> void {
    throw SceneError(where, key_path, "expected a path to a scene value, found " + what);
  };
  const std::size_t eq = item.find('=');
  if (eq == std::string::npos) fail("no '=' (NAME=VALUE)");
  std::string_view path(item.data(), eq);
  while (!path.empty() && path.back() == ' ') path.remove_suffix(1);
  while (!path.empty() && path.front() == ' ') path.remove_prefix(1);
  std::string_view text = std::string_view(item).substr(eq + 1);
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  const std::vector<Step> steps = stepsOf(path, fail);
  YAML::Node value;
  try {
    value = YAML::Load(std::string(text));
  } catch (const YAML::Exception& e) {
    throw SceneError(where, key_path, "the value is not valid YAML: " + e.msg);
  }
  if (!value.IsDefined() || value.IsNull())
    throw SceneError(where, key_path, "expected a value after '=', found none");
  // The walk rebinds (reset), never assigns: assigning a yaml-cpp node replaces the value
  // it refers to.
  YAML::Node at;
  at.reset(root);
  std::string walked;
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const Step& step = steps[s];
    const bool last = s + 1 == steps.size();
    const std::string here = walked.empty() ? "the top of the scene" : "'" + walked + "'";
    if (step.element) {
      if (!at.IsSequence())
        throw SceneError(where, key_path,
                         here + " is not a list, so [" + step.key + "] selects nothing");
      const long i = elementOf(at, step.key);
      if (i < 0)
        throw SceneError(where, key_path,
                         here + " has no element [" + step.key + "] (" + std::to_string(at.size()) +
                             " elements; names: " + namesOf(at) + ")");
      walked.push_back('[');
      walked.append(std::to_string(i));
      walked.push_back(']');
      if (last) {
        at[static_cast<std::size_t>(i)] = value;
        return walked;
      }
      YAML::Node next = at[static_cast<std::size_t>(i)];
      at.reset(next);
      continue;
    }
    if (!at.IsMap())
      throw SceneError(where, key_path,
                       here + " is not a map, so it has no key '" + step.key + "'");
    const YAML::Node& view = at;
    const bool present = static_cast<bool>(view[step.key]);
    walked += (walked.empty() ? "" : ".") + step.key;
    if (last) {
      at[step.key] = value;
      return walked;
    }
    // A missing mapping on the way is made (`--set output.digits=17` in a scene without
    // output:); the reader then checks every key, so a misspelt one is still refused.
    if (!present) at[step.key] = YAML::Node(YAML::NodeType::Map);
    YAML::Node next = at[step.key];
    at.reset(next);
  }
  return walked;
}

namespace {

bool within(const std::string& path, const std::string& prefix) {
  return path.starts_with(prefix) &&
         (path.size() == prefix.size() || path[prefix.size()] == '.' || path[prefix.size()] == '[');
}

}  // namespace

SceneError attributedToOverride(const SceneError& error, const std::string& path,
                                const std::string& item) {
  if (within(error.keyPath(), path))
    return SceneError({error.where().file, 0, 0}, error.keyPath(),
                      error.detail() + " (from --set " + item + ")");
  if (!error.keyPath().empty() && within(path, error.keyPath()))
    return SceneError(error.where(), error.keyPath(),
                      error.detail() + " (with --set " + item + ")");
  return error;
}

}  // namespace tribo::io
