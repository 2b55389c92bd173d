// The YAML values of a scene file as the reader sees them: a node with its key path, read as
// a string, number (or expression over parameters), flag, word or sequence, each refusal a
// SceneError at the node's file:line:col and key path ("expected X, found Y"); a mapping
// checked against its accepted keys (io/scene_keys.hpp) as soon as it is opened; and the few
// readers every section shares (orientation or rpy, collision bit sets, errors of the model
// builder located at the element that caused them).
// Internal to io/ (it includes yaml-cpp, which no other module sees): the scene reader's
// files (io/scene_reader.hpp) use it; nothing outside io/ includes it.
// Not here: what any section means (docs/scene-format.md), parameters and expressions
// themselves (io/scene_parameters.hpp, io/scene_expression.hpp).
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/math.hpp"
#include "core/model_builder.hpp"
#include "io/scene_parameters.hpp"

namespace tribo::io::scene_detail {

using Keys = std::vector<std::string>;

// "a, b, c", or "(none)" for no words.
std::string joined(const Keys& words);

// One YAML value and its key path. Scalars are read through the parameter table, so a
// "$name" scalar reads as the parameter's current value.
class Value {
 public:
  Value(const std::string& file, const ParameterTable& params, YAML::Node node, std::string path)
      : file_(&file), params_(&params), node_(std::move(node)), path_(std::move(path)) {}

  Value child(const YAML::Node& node, const std::string& key) const {
    return {*file_, *params_, node, path_.empty() ? key : path_ + "." + key};
  }
  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }
  const std::string& file() const { return *file_; }  // the scene file, as it was named
  const ParameterTable& parameters() const { return *params_; }
  SourceLocation where() const;
  [[noreturn]] void fail(const std::string& what) const;

  // What is there, for "expected X, found Y" messages.
  std::string found() const;

  std::string text() const;
  // A number, or an expression over parameters (io/scene_expression.hpp).
  double number() const;
  double positive() const;
  double nonNegative() const;
  int integer(int at_least) const;
  bool flag() const;
  // Index of the text in `names`.
  int choice(const Keys& names) const;

  // Items of a sequence (`null` reads as empty when allowed).
  std::vector<Value> items(const std::string& what, bool null_is_empty = false) const;
  // A sequence of numbers whose length is one of `sizes`; `what` describes it.
  std::vector<double> numbers(std::initializer_list<std::size_t> sizes,
                              const std::string& what) const;
  Vec3 vec3(const std::string& what = "3 numbers [x, y, z]") const;

 private:
  const std::string* file_;
  const ParameterTable* params_;
  YAML::Node node_;
  std::string path_;
};

// A mapping whose keys are checked at once: an unknown or repeated key is an error at that
// key, listing the accepted ones. An empty accepted list accepts any key.
class Map {
 public:
  Map(const Value& self, const Keys& accepted);

  const Value& self() const { return self_; }
  const std::vector<std::pair<std::string, Value>>& entries() const { return entries_; }
  std::optional<Value> get(const std::string& key) const;
  Value required(const std::string& key) const;
  Vec3 vec3(const std::string& key, const Vec3& fallback) const;

 private:
  Value self_;
  std::vector<std::pair<std::string, Value>> entries_;
};

// Runs f; an error of the model builder, a law factory or a name lookup becomes a SceneError
// located at `at`.
template <typename F>
auto guarded(const Value& at, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const ModelError& e) {
    at.fail(e.what());
  } catch (const std::invalid_argument& e) {  // incl. friction::FrictionParameterError
    at.fail(e.what());
  }
}

// The rotation a mapping gives by `orientation` (a quaternion [w, x, y, z], normalized) or
// `rpy` (R = Rz(yaw) Ry(pitch) Rx(roll)), not both; the identity when neither.
Quat orientation(const Map& m);

// A collision filter bit set.
std::uint32_t bitSet(const Value& x);

}  // namespace tribo::io::scene_detail
