#include "io/time_expression.hpp"

#include <muParser.h>

#include <cmath>
#include <mutex>
#include <numbers>

#include "core/number_text.hpp"
#include "io/scene_expression.hpp"

namespace tribo::io {

namespace {

double degrees(double v) { return v * std::numbers::pi / 180.0; }

}  // namespace

struct TimeExpression::Compiled {
  std::mutex mutex;
  double t = 0.0;
  mu::Parser parser;

  Compiled(const std::string& text, const std::vector<std::pair<std::string, double>>& constants) {
    parser.DefineNameChars("0123456789_abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ$");
    parser.DefineConst("pi", std::numbers::pi);
    parser.DefineConst("e", std::numbers::e);
    parser.DefinePostfixOprt("deg", degrees);
    for (const auto& [name, value] : constants) parser.DefineConst("$" + name, value);
    parser.DefineVar("t", &t);
    parser.SetExpr(text);
    parser.Eval();  // parses now: errors at load, and no parse (allocation) during a run
  }
};

TimeExpression::TimeExpression(const std::string& text, const ParameterTable& parameters,
                               const SourceLocation& where, const std::string& key_path)
    : text_(text), constants_(referencedParameters(text, parameters, where, key_path)) {
  const auto fail = [&](const std::string& what) {
    throw SceneError(where, key_path, "expression '" + text + "': " + what);
  };
  double v = 0.0;
  try {
    compiled_ = std::make_unique<Compiled>(text_, constants_);  // syntax, unknown names
    v = (*this)(0.0);
  } catch (const mu::Parser::exception_type& e) {
    fail(e.GetMsg());
  }
  if (!std::isfinite(v))
    fail("the value at t = 0 is " + numberText(v) +
         " (division by zero, or a function outside its domain?); expected a finite number");
}

TimeExpression::TimeExpression(const TimeExpression& other)
    : text_(other.text_),
      constants_(other.constants_),
      compiled_(std::make_unique<Compiled>(text_, constants_)) {}

TimeExpression& TimeExpression::operator=(const TimeExpression& other) {
  if (this != &other) *this = TimeExpression(other);
  return *this;
}

TimeExpression::TimeExpression(TimeExpression&&) noexcept = default;
TimeExpression& TimeExpression::operator=(TimeExpression&&) noexcept = default;
TimeExpression::~TimeExpression() = default;

double TimeExpression::operator()(double t) const {
  const std::lock_guard<std::mutex> lock(compiled_->mutex);
  compiled_->t = t;
  return compiled_->parser.Eval();
}

}  // namespace tribo::io
