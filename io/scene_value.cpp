#include "io/scene_value.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "io/scene_expression.hpp"

namespace tribo::io::scene_detail {

std::string joined(const Keys& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out.empty() ? "(none)" : out;
}

SourceLocation Value::where() const {
  const YAML::Mark m = node_.Mark();
  return {*file_, m.line < 0 ? 0 : m.line + 1, m.column < 0 ? 0 : m.column + 1};
}

void Value::fail(const std::string& what) const { throw SceneError(where(), path_, what); }

std::string Value::found() const {
  if (node_.IsNull()) return "nothing";
  if (node_.IsSequence()) return "a sequence of " + std::to_string(node_.size()) + " items";
  if (node_.IsMap()) return "a mapping";
  const std::string& s = node_.Scalar();
  if (isReference(s)) return "'" + text() + "' (from " + s + ")";
  return "'" + s + "'";
}

std::string Value::text() const {
  if (!node_.IsScalar()) fail("expected a string, found " + found());
  const std::string& s = node_.Scalar();
  return isReference(s) ? params_->resolve(s, where(), path_).text : s;
}

double Value::number() const {
  if (node_.IsScalar()) {
    const std::string t = text();
    if (const auto v = parseNumber(t)) return *v;
    try {
      return evaluateExpression(t, *params_, where(), path_);
    } catch (const SceneError&) {
      if (looksLikeExpression(t)) throw;  // else: a word, say so plainly below
    }
  }
  fail("expected a number, found " + found());
}

double Value::positive() const {
  const double v = number();
  if (!(v > 0.0)) fail("expected a number > 0, found " + found());
  return v;
}

double Value::nonNegative() const {
  const double v = number();
  if (!(v >= 0.0)) fail("expected a number >= 0, found " + found());
  return v;
}

int Value::integer(int at_least) const {
  const double v = number();
  if (v != std::floor(v) || v < at_least || v > 1e9)
    fail("expected a whole number >= " + std::to_string(at_least) + ", found " + found());
  return static_cast<int>(v);
}

bool Value::flag() const {
  const std::string t = node_.IsScalar() ? text() : "";
  if (t != "true" && t != "false") fail("expected true or false, found " + found());
  return t == "true";
}

int Value::choice(const Keys& names) const {
  const std::string t = node_.IsScalar() ? text() : "";
  const auto it = std::find(names.begin(), names.end(), t);
  if (!node_.IsScalar() || it == names.end())
    fail("expected one of " + joined(names) + ", found " + found());
  return static_cast<int>(it - names.begin());
}

std::vector<Value> Value::items(const std::string& what, bool null_is_empty) const {
  std::vector<Value> out;
  if (null_is_empty && node_.IsNull()) return out;
  if (!node_.IsSequence()) fail("expected a sequence of " + what + ", found " + found());
  for (std::size_t i = 0; i < node_.size(); ++i)
    out.push_back({*file_, *params_, node_[i], path_ + "[" + std::to_string(i) + "]"});
  return out;
}

std::vector<double> Value::numbers(std::initializer_list<std::size_t> sizes,
                                   const std::string& what) const {
  if (!node_.IsSequence() || std::find(sizes.begin(), sizes.end(), node_.size()) == sizes.end())
    fail("expected " + what + ", found " + found());
  std::vector<double> out;
  for (const Value& item : items(what)) out.push_back(item.number());
  return out;
}

Vec3 Value::vec3(const std::string& what) const {
  const auto v = numbers({3}, what);
  return {v[0], v[1], v[2]};
}

Map::Map(const Value& self, const Keys& accepted) : self_(self) {
  const YAML::Node& node = self.node();
  if (!node.IsMap())
    self.fail("expected a mapping" +
              (accepted.empty() ? std::string() : " with keys " + joined(accepted)) + ", found " +
              self.found());
  std::set<std::string> seen;  // not get(): a parameters: table may hold 10,000 keys
  for (auto it = node.begin(); it != node.end(); ++it) {
    const Value key = self.child(it->first, it->first.Scalar());
    if (!it->first.IsScalar()) key.fail("expected a key name, found " + key.found());
    const std::string name = it->first.Scalar();
    if (!accepted.empty() && std::find(accepted.begin(), accepted.end(), name) == accepted.end())
      key.fail("unknown key '" + name + "' (accepted keys: " + joined(accepted) + ")");
    if (!seen.insert(name).second) key.fail("key '" + name + "' given twice");
    entries_.emplace_back(name, self.child(it->second, name));
  }
}

std::optional<Value> Map::get(const std::string& key) const {
  for (const auto& [name, value] : entries_)
    if (name == key) return value;
  return std::nullopt;
}

Value Map::required(const std::string& key) const {
  if (auto v = get(key)) return *v;
  self_.fail("missing required key '" + key + "'");
}

Vec3 Map::vec3(const std::string& key, const Vec3& fallback) const {
  const auto v = get(key);
  return v ? v->vec3() : fallback;
}

Quat orientation(const Map& m) {
  const auto q = m.get("orientation");
  const auto rpy = m.get("rpy");
  if (q && rpy) rpy->fail("give orientation or rpy, not both");
  if (q) {
    const auto v = q->numbers({4}, "a quaternion [w, x, y, z]");
    const Quat out(v[0], v[1], v[2], v[3]);
    if (out.norm() < 1e-12) q->fail("expected a non-zero quaternion [w, x, y, z]");
    return out.normalized();
  }
  if (rpy) {
    const Vec3 a = rpy->vec3("3 angles [roll, pitch, yaw] [rad]");
    return Quat(Eigen::AngleAxisd(a.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(a.y(), Vec3::UnitY()) *
                Eigen::AngleAxisd(a.x(), Vec3::UnitX()));
  }
  return Quat::Identity();
}

std::uint32_t bitSet(const Value& x) {
  const double b = x.number();
  if (b != std::floor(b) || b < 0 || b > 4294967295.0)
    x.fail("expected a whole number in [0, 4294967295] (a bit set), found " + x.found());
  return static_cast<std::uint32_t>(b);
}

}  // namespace tribo::io::scene_detail
