#include "io/scene_expression.hpp"

#include <muParser.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <unordered_set>
#include <utility>
#include <vector>

#include "core/number_text.hpp"

namespace tribo::io {

namespace {

constexpr const char* kNameChars =
    "0123456789_abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ$";

double degrees(double v) { return v * std::numbers::pi / 180.0; }

bool isNameChar(char c) {
  return c == '_' || (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

// The distinct parameter names referenced as $name in `text`, in order of first appearance
// ("" for a '$' not followed by a name).
std::vector<std::string> references(const std::string& text) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '$') continue;
    std::size_t end = i + 1;
    while (end < text.size() && isNameChar(text[end])) ++end;
    std::string name = text.substr(i + 1, end - i - 1);
    if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(std::move(name));
    i = end - 1;
  }
  return out;
}

using Parameter = ParameterTable::Parameter;

// Evaluates expressions at one place of the scene. A parameter's value is computed once and
// kept in the table (Parameter::value), so a parameter referred to many times, directly or
// through others, costs one evaluation per load: `$p + $p` chains are linear, not
// exponential. Parameters are evaluated in dependency order with an explicit stack, not by
// recursion, so a chain of any length (each parameter referring to the one before) needs no
// call stack beyond one level.
class Evaluator {
 public:
  Evaluator(const ParameterTable& parameters, const SourceLocation& where, std::string key_path)
      : parameters_(parameters), where_(where), key_path_(std::move(key_path)) {}

  double value(const std::string& text) {
    for (const std::string& name : references(text))
      if (const Parameter* p = parameters_.find(name); p && !known(*p)) evaluateParameter(*p, text);
    return evaluate(text, text);
  }

 private:
  // The value of p when it is a number or already evaluated.
  static std::optional<double> knownValue(const Parameter& p) {
    if (p.value) return p.value;
    return parseNumber(p.text);
  }
  static bool known(const Parameter& p) { return knownValue(p).has_value(); }

  // Evaluates `text`, whose references are all known (or unknown names: an error).
  // `shown` is the text the message names.
  double evaluate(const std::string& text, const std::string& shown) const {
    mu::Parser parser;
    parser.DefineNameChars(kNameChars);
    parser.DefineConst("pi", std::numbers::pi);
    parser.DefineConst("e", std::numbers::e);
    parser.DefinePostfixOprt("deg", degrees);
    const std::vector<std::string> names = references(text);
    std::vector<double> storage(names.size());  // not resized: stable addresses for DefineVar
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i].empty()) fail(shown, "'$' must be followed by a parameter name");
      const Parameter* p = parameters_.find(names[i]);
      if (!p)
        fail(shown,
             "unknown parameter '$" + names[i] + "' (known: " + parameters_.knownNames() + ")");
      const auto v = knownValue(*p);
      if (!v) fail(shown, "parameter '$" + names[i] + "' has no value yet");  // not reached
      storage[i] = *v;
      parser.DefineVar("$" + names[i], &storage[i]);
    }
    double v = 0.0;
    try {
      parser.SetExpr(text);
      v = parser.Eval();
    } catch (const mu::Parser::exception_type& e) {
      fail(shown, e.GetMsg());
    }
    if (!std::isfinite(v))
      fail(shown, "the result is " + numberText(v) +
                      " (division by zero, or a function outside "
                      "its domain?); expected a finite number");
    return v;
  }

  // Depth-first over the parameters `top` needs, evaluating each once all it refers to is
  // known. `text` is the expression being evaluated, for messages.
  void evaluateParameter(const Parameter& top, const std::string& text) {
    struct Frame {
      const Parameter* p;
      std::vector<std::string> refs;
      std::size_t next = 0;
    };
    std::vector<Frame> stack;
    std::unordered_set<const Parameter*> on_stack;
    auto push = [&](const Parameter& p) {
      stack.push_back({&p, references(p.text)});
      on_stack.insert(&p);
    };
    push(top);
    while (!stack.empty()) {
      Frame& f = stack.back();
      if (f.next < f.refs.size()) {
        const Parameter* q = parameters_.find(f.refs[f.next++]);
        if (!q || known(*q)) continue;  // an unknown name fails in evaluate, naming it
        if (on_stack.count(q)) cycle(stack, *q, text);
        push(*q);
        continue;
      }
      const Parameter& p = *f.p;
      try {
        p.value = evaluate(p.text, p.text);
      } catch (const SceneError& e) {
        std::string via = " (in parameter '" + p.name + "'";
        if (stack.size() > 1) via += ", needed by '" + stack[stack.size() - 2].p->name + "'";
        fail(text, e.detail() + via + ")");
      }
      on_stack.erase(&p);
      stack.pop_back();
    }
  }

  template <typename Stack>
  [[noreturn]] void cycle(const Stack& stack, const Parameter& again,
                          const std::string& text) const {
    std::size_t first = 0;
    while (stack[first].p != &again) ++first;
    std::string loop;
    for (std::size_t i = first; i < stack.size(); ++i) loop += stack[i].p->name + " -> ";
    loop += again.name;
    if (first > 0) loop += " (reached from '" + stack[0].p->name + "')";
    fail(text, "parameters refer to each other in a cycle: " + loop);
  }

  [[noreturn]] void fail(const std::string& text, const std::string& what) const {
    throw SceneError(where_, key_path_, "expression '" + text + "': " + what);
  }

  const ParameterTable& parameters_;
  SourceLocation where_;
  std::string key_path_;
};

}  // namespace

bool looksLikeExpression(const std::string& text) {
  return text.find_first_of("$+-*/^()") != std::string::npos ||
         text.find(" deg") != std::string::npos;
}

double evaluateExpression(const std::string& text, const ParameterTable& parameters,
                          const SourceLocation& where, const std::string& key_path) {
  return Evaluator(parameters, where, key_path).value(text);
}

std::vector<std::pair<std::string, double>> referencedParameters(const std::string& text,
                                                                 const ParameterTable& parameters,
                                                                 const SourceLocation& where,
                                                                 const std::string& key_path) {
  std::vector<std::pair<std::string, double>> out;
  for (const std::string& name : references(text)) {
    if (name.empty())
      throw SceneError(where, key_path,
                       "expression '" + text + "': '$' must be followed by a parameter name");
    if (!parameters.find(name))
      throw SceneError(where, key_path,
                       "expression '" + text + "': unknown parameter '$" + name +
                           "' (known: " + parameters.knownNames() + ")");
    out.emplace_back(name, evaluateExpression("$" + name, parameters, where, key_path));
  }
  return out;
}

}  // namespace tribo::io
