// An expression of time t for the `expression` signal kind (io/scene_signal.hpp), compiled
// with muparser into a callable double(double) that core/signal.hpp's function kind holds
// (core does not see muparser):
//   0.5 * sin(2*pi*3*t) + $F0        $F * (t > $t1 ? 1 : t / $t1)
// The syntax is that of parameter expressions (io/scene_expression.hpp: pi, e, deg, the
// operators, functions and `?:`), plus the variable `t` [s]. Each `$name` is replaced by the
// parameter's value when the scene loads (after --set overrides): a constant of the
// compiled expression, not re-read during the run.
// Checked at load, before anything runs: the text parses, names nothing but t, constants,
// functions and known parameters, and its value at t = 0 is finite; each failure is a
// SceneError at the expression's file:line:column and key path, naming the expression and
// muparser's reason ("Unexpected token "x" found at position 4").
// Threads: a muparser parser is not thread-safe (Eval writes its stack and reads the
// variable t through a pointer). Each TimeExpression owns its parser, its t and a mutex on
// the heap (so a move keeps the parser's pointer to t valid); copying one compiles a fresh
// parser from the text, so copies of a Signal (one per scene, one per sweep thread) never
// share one; and the mutex makes one object safe even if a Model were evaluated from
// several threads at once (uncontended, a lock costs ~20 ns against ~100 ns of Eval).
// Not here: derivatives (the signal's five-point difference, or a second expression),
// vectors, evaluation of t-free parts once (muparser's optimizer folds constants).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "io/scene_parameters.hpp"

namespace tribo::io {

class TimeExpression {
 public:
  // Compiles `text`, checking it as described above; errors at `where` / `key_path`.
  TimeExpression(const std::string& text, const ParameterTable& parameters,
                 const SourceLocation& where, const std::string& key_path);
  TimeExpression(const TimeExpression& other);
  TimeExpression& operator=(const TimeExpression& other);
  TimeExpression(TimeExpression&&) noexcept;
  TimeExpression& operator=(TimeExpression&&) noexcept;
  ~TimeExpression();

  double operator()(double t) const;
  const std::string& text() const { return text_; }

 private:
  struct Compiled;
  std::string text_;
  std::vector<std::pair<std::string, double>> constants_;  // "$name" -> its value
  std::unique_ptr<Compiled> compiled_;
};

}  // namespace tribo::io
