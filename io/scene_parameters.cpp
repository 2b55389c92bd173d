#include "io/scene_parameters.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <system_error>

#include "io/scene_expression.hpp"
#include "io/utf8_check.hpp"

namespace tribo::io {
namespace {

std::string located(const SourceLocation& where, const std::string& key_path,
                    const std::string& what) {
  std::ostringstream out;
  if (!where.file.empty()) {
    out << where.file;
    if (where.line > 0) out << ':' << where.line;
    if (where.line > 0 && where.column > 0) out << ':' << where.column;
    out << ": ";
  }
  if (!key_path.empty()) out << key_path << ": ";
  out << what;
  return out.str();
}

std::string_view trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t");
  return s.substr(first, last - first + 1);
}

}  // namespace

SceneError::SceneError(const SourceLocation& where, const std::string& key_path,
                       const std::string& what)
    : std::runtime_error(located(where, key_path, what)),
      where_(where),
      key_path_(key_path),
      detail_(what) {}

SceneError::SceneError(const std::string& what) : std::runtime_error(what), detail_(what) {}

std::optional<double> parseNumber(std::string_view text) {
  // from_chars takes no leading '+'; accept exactly one before a digit or '.'.
  if (text.size() > 1 && text.front() == '+' && text[1] != '-' && text[1] != '+')
    text.remove_prefix(1);
  if (text.empty()) return std::nullopt;
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

bool isParameterName(std::string_view name) {
  if (name.empty()) return false;
  auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (!alpha(name.front())) return false;
  for (const char c : name)
    if (!alpha(c) && !(c >= '0' && c <= '9')) return false;
  return true;
}

void ParameterTable::add(const std::string& name, const std::string& text,
                         const SourceLocation& where) {
  const std::string key_path = "parameters." + name;
  if (!isParameterName(name))
    throw SceneError(where, key_path,
                     "a parameter name must be letters, digits and '_', not starting with a "
                     "digit (got '" +
                         name + "')");
  if (find(name)) throw SceneError(where, key_path, "parameter '" + name + "' defined twice");
  if (const std::size_t bad = firstBadUtf8(text); bad != std::string::npos)
    throw SceneError(where, key_path, "expected UTF-8 text, found " + badUtf8Reason(text, bad));
  index_.emplace(name, parameters_.size());
  parameters_.push_back({name, text, parseNumber(text).has_value(), where, key_path, false, {}});
}

void ParameterTable::forgetValues() {
  for (const Parameter& p : parameters_) p.value.reset();
}

void ParameterTable::applyOverrides(std::span<const std::string> overrides,
                                    const std::string& file) {
  const SourceLocation in_file{file, 0, 0};
  std::vector<std::pair<Parameter*, const std::string*>> expressions;  // to check once all set
  for (const std::string& item : overrides) {
    if (const std::size_t bad = firstBadUtf8(item); bad != std::string::npos)
      throw SceneError(in_file, "--set " + printableText(item),
                       "expected UTF-8 text, found " + badUtf8Reason(item, bad) + " at byte " +
                           std::to_string(bad + 1));
    const auto eq = item.find('=');
    if (eq == std::string::npos)
      throw SceneError(in_file, "--set", "expected NAME=VALUE, got '" + item + "'");
    const std::string name(trimmed(std::string_view(item).substr(0, eq)));
    const std::string value(trimmed(std::string_view(item).substr(eq + 1)));
    const auto at = index_.find(name);
    if (at == index_.end())
      throw SceneError(in_file, "--set " + item,
                       "unknown parameter '" + name + "' (known parameters: " + knownNames() + ")");
    Parameter* p = &parameters_[at->second];
    const bool expression = !parseNumber(value) && looksLikeExpression(value);
    if (p->numeric && !parseNumber(value) && !expression)
      throw SceneError(p->where, p->key_path,
                       "parameter '" + name + "': expected a number or an expression, got '" +
                           value + "' (from --set " + item + ")");
    p->text = value;
    p->overridden = true;
    if (p->numeric && expression) expressions.emplace_back(p, &item);
  }
  forgetValues();
  // A numeric parameter's expression must have a value, with every override in place (it
  // may refer to another overridden parameter).
  for (const auto& [p, item] : expressions) {
    try {
      (void)evaluateExpression(p->text, *this, p->where, p->key_path);
    } catch (const SceneError& e) {
      throw SceneError(p->where, p->key_path, e.detail() + " (from --set " + *item + ")");
    }
  }
}

void requireUtf8Scene(std::string_view text, const std::string& file) {
  const std::size_t bad = firstBadUtf8(text);
  if (bad == std::string::npos) return;
  const TextPosition at = positionOf(text, bad);
  throw SceneError({printableText(file), at.line, at.column}, "",
                   "expected UTF-8 text, found " + badUtf8Reason(text, bad));
}

const ParameterTable::Parameter& ParameterTable::resolve(std::string_view reference,
                                                         const SourceLocation& where,
                                                         const std::string& key_path) const {
  const std::string_view name = reference.substr(isReference(reference) ? 1 : 0);
  if (const Parameter* p = find(name)) return *p;
  throw SceneError(where, key_path,
                   "'" + std::string(reference) +
                       "' refers to no parameter (known parameters: " + knownNames() + ")");
}

const ParameterTable::Parameter* ParameterTable::find(std::string_view name) const {
  const auto at = index_.find(std::string(name));
  return at == index_.end() ? nullptr : &parameters_[at->second];
}

std::string ParameterTable::knownNames() const {
  std::string out;
  for (const auto& p : parameters_) out += (out.empty() ? "" : ", ") + p.name;
  return out.empty() ? "(none)" : out;
}

std::vector<std::pair<std::string, std::string>> ParameterTable::values() const {
  std::vector<std::pair<std::string, std::string>> out;
  out.reserve(parameters_.size());
  for (const auto& p : parameters_) out.emplace_back(p.name, p.text);
  return out;
}

}  // namespace tribo::io
