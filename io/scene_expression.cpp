#include "io/scene_expression.hpp"

#include <muParser.h>

#include <cmath>
#include <deque>
#include <numbers>
#include <set>
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

// The parameter names referenced as $name in `text`, in order of appearance.
std::vector<std::string> references(const std::string& text) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '$') continue;
    std::size_t end = i + 1;
    while (end < text.size() && isNameChar(text[end])) ++end;
    out.push_back(text.substr(i + 1, end - i - 1));
    i = end - 1;
  }
  return out;
}

class Evaluator {
 public:
  Evaluator(const ParameterTable& parameters, const SourceLocation& where, std::string key_path)
      : parameters_(parameters), where_(where), key_path_(std::move(key_path)) {}

  double value(const std::string& text) {
    mu::Parser parser;
    parser.DefineNameChars(kNameChars);
    parser.DefineConst("pi", std::numbers::pi);
    parser.DefineConst("e", std::numbers::e);
    parser.DefinePostfixOprt("deg", degrees);
    std::deque<double> storage;  // stable addresses for DefineVar
    for (const std::string& name : references(text)) {
      if (name.empty()) fail(text, "'$' must be followed by a parameter name");
      storage.push_back(parameterValue(name, text));
      parser.DefineVar("$" + name, &storage.back());
    }
    double v = 0.0;
    try {
      parser.SetExpr(text);
      v = parser.Eval();
    } catch (const mu::Parser::exception_type& e) {
      fail(text, e.GetMsg());
    }
    if (!std::isfinite(v))
      fail(text, "the result is " + numberText(v) +
                     " (division by zero, or a function outside "
                     "its domain?); expected a finite number");
    return v;
  }

 private:
  double parameterValue(const std::string& name, const std::string& text) {
    const ParameterTable::Parameter* p = parameters_.find(name);
    if (!p)
      fail(text, "unknown parameter '$" + name + "' (known: " + parameters_.knownNames() + ")");
    if (const auto v = parseNumber(p->text)) return *v;
    if (!visiting_.insert(name).second) {
      std::string loop;
      for (const std::string& n : chain_) loop += n + " -> ";
      fail(text, "parameters refer to each other in a cycle: " + loop + name);
    }
    chain_.push_back(name);
    const double v = value(p->text);
    chain_.pop_back();
    visiting_.erase(name);
    return v;
  }

  [[noreturn]] void fail(const std::string& text, const std::string& what) const {
    throw SceneError(where_, key_path_, "expression '" + text + "': " + what);
  }

  const ParameterTable& parameters_;
  SourceLocation where_;
  std::string key_path_;
  std::set<std::string> visiting_;
  std::vector<std::string> chain_;
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

}  // namespace tribo::io
