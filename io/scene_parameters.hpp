// The `parameters:` table of a scene file, the error type of scene loading, and the two
// text rules everything else in the loader relies on:
//   - a scalar "$name" anywhere in the scene stands for the current value of parameter
//     `name` (whole scalars only: "x$name" and "${name}" are not references);
//   - a number is text that parses fully as a finite double ("1e-3", "+2", ".5"; not
//     "1.5m", "inf", "nan").
// Command-line overrides (`--set NAME=VALUE`) replace a parameter's value before any
// reference is resolved; a parameter whose value in the file is a number takes a number or
// an expression (`--set k_t=6+0.5`, `--set k=2*$m`), evaluated when the override is applied.
// A parameter's value may be an expression over other parameters; where a number is
// expected, io/scene_expression.hpp evaluates it, each parameter once per load (the value is
// kept in the table until the next override).
// All text given here (names, values, overrides) must be well-formed UTF-8 (io/utf8_check.hpp).
// Not here: YAML (the scene reader, io/scene_reader.hpp, reads the file and feeds this
// table), evaluation.
#pragma once

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace tribo::io {

// A place in a scene file; line and column are 1-based, 0 when unknown.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

// Any problem with a scene file or its overrides. what() reads
//   "FILE:LINE:COL: key.path: what was expected, what was found"
// where the parts that are unknown are left out (e.g. "FILE: --set: ...").
class SceneError : public std::runtime_error {
 public:
  SceneError(const SourceLocation& where, const std::string& key_path, const std::string& what);
  explicit SceneError(const std::string& what);

  const SourceLocation& where() const { return where_; }
  const std::string& keyPath() const { return key_path_; }
  const std::string& detail() const { return detail_; }  // the message without location

 private:
  SourceLocation where_;
  std::string key_path_;
  std::string detail_;
};

// The number `text` spells, if it is one (see the header comment).
std::optional<double> parseNumber(std::string_view text);

// Is `name` usable as a parameter name: [A-Za-z_][A-Za-z0-9_]*.
bool isParameterName(std::string_view name);

// Does `text` refer to a parameter as a whole: '$' then a parameter name? ("$k / $m" is an
// expression, io/scene_expression.hpp.)
inline bool isReference(std::string_view text) {
  return !text.empty() && text.front() == '$' && isParameterName(text.substr(1));
}

class ParameterTable {
 public:
  struct Parameter {
    std::string name;
    std::string text;         // current value: the file's, or the last override
    bool numeric = false;     // the file's value is a number (overrides must be too)
    SourceLocation where;     // of the value in the file
    std::string key_path;     // "parameters.NAME"
    bool overridden = false;  // text came from --set
    // The evaluated value of `text` once an expression needed it (io/scene_expression.cpp);
    // cleared by applyOverrides. (A parameter added later cannot change it: a reference to
    // a name not yet added fails, and failures are not kept.)
    mutable std::optional<double> value;
  };

  // Adds a parameter read from the file, in file order. Throws SceneError at `where` for an
  // invalid or duplicate name.
  void add(const std::string& name, const std::string& text, const SourceLocation& where);

  // Applies NAME=VALUE overrides in order (the last one for a name wins). Throws SceneError
  // (naming `file`) for text that is not UTF-8, text without '=', an unknown NAME (listing
  // the known names), or a VALUE for a numeric parameter that is neither a number nor an
  // expression with a finite value ("parameter 'k': expected a number or an expression, got
  // 'abc'").
  void applyOverrides(std::span<const std::string> overrides, const std::string& file);

  // The parameter `reference` ("$name") stands for. Throws SceneError at `where`/`key_path`
  // naming the reference and the known names when there is no such parameter.
  const Parameter& resolve(std::string_view reference, const SourceLocation& where,
                           const std::string& key_path) const;

  const Parameter* find(std::string_view name) const;
  // "m, k, v_b" in file order, or "(none)".
  std::string knownNames() const;
  // name -> current value text, in file order.
  std::vector<std::pair<std::string, std::string>> values() const;
  const std::vector<Parameter>& parameters() const { return parameters_; }

 private:
  void forgetValues();

  std::vector<Parameter> parameters_;
  std::unordered_map<std::string, std::size_t> index_;  // name -> position in parameters_
};

// Throws SceneError naming `file` and the line and column of the first byte of `text` that
// is not well-formed UTF-8 (io/utf8_check.hpp).
void requireUtf8Scene(std::string_view text, const std::string& file);

}  // namespace tribo::io
