// Arithmetic in scene values: where a scene expects a number, it may give an expression over
// parameters and constants, evaluated once when the scene loads (muparser, Debian's
// libmuparser-dev):
//   $k / $m        sqrt($k / $m)        0.05 - $m * 9.81 / (4 * $k)        sin(10 deg)
// `$name` is the current value of parameter `name` (after --set overrides); a parameter's
// own value may be an expression over other parameters (a cycle is an error naming it,
// "a -> b -> a"). Each parameter is evaluated once per load, in dependency order without
// recursion: chains of any length, and parameters referred to many times, cost one
// evaluation each.
// Constants `pi` and `e`; the postfix `deg` turns degrees into radians. Operators + - * / ^,
// comparisons and `?:`; functions sin cos tan asin acos atan sinh cosh tanh sqrt exp ln log
// log2 log10 abs sign rint min max sum avg. A result that is not finite (division by zero,
// sqrt of a negative number) is an error.
// Not here: expressions that give text (law or body names), units other than `deg`,
// evaluation during a run (values are numbers once loaded).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "io/scene_parameters.hpp"

namespace tribo::io {

// Does `text` read as an expression attempt (holds an operator, a bracket or a reference),
// so that a failure to evaluate it deserves the evaluator's reason in the message?
bool looksLikeExpression(const std::string& text);

// The value of `text`; throws SceneError at `where` / `key_path` naming the expression and
// what went wrong (syntax, unknown name, unknown parameter with the known ones, a cycle
// between parameters, a non-finite result).
double evaluateExpression(const std::string& text, const ParameterTable& parameters,
                          const SourceLocation& where, const std::string& key_path);

// Each parameter `text` refers to as $name, with its value, in order of first appearance
// (for expressions evaluated later, io/time_expression.hpp); the errors of
// evaluateExpression for a '$' without a name, an unknown parameter or one that fails.
std::vector<std::pair<std::string, double>> referencedParameters(const std::string& text,
                                                                 const ParameterTable& parameters,
                                                                 const SourceLocation& where,
                                                                 const std::string& key_path);

}  // namespace tribo::io
