// Reading a time signal (core/signal.hpp) from a scene value: a number (or an expression over
// parameters) is a constant; a mapping with one key names the kind:
//   {ramp: {rate, [start], [initial]}}       {step: {time, before, after}}
//   {smooth_step: {start, end, before, after}}  {table: [[t, v], ...]}
//   {table: {points: [[t, v], ...] | file: forces.csv, [column: fx | 3],
//            [interpolation: linear | cubic]}}
//   {sines: [{amplitude, frequency, [phase], [offset]}, ...]}
//   {expression: "0.5 * sin(2*pi*3*t) + $F0"}
//   {expression: {value: "...", [derivative: "..."], [time_scale: 1e-3],
//                 [breakpoints: [t1, t2, ...]]}}   (the times of its kinks and jumps)
// A table file is a CSV named relative to the scene file's folder (io/signal_table_file.hpp);
// an expression of t is compiled and checked at load (io/time_expression.hpp), its
// derivative the given expression or the signal's five-point difference at the time scale
// (core/signal.hpp). Each refusal (unknown kind, a missing key, table times not increasing,
// a CSV problem, an expression that does not parse) is a SceneError at the offending value
// (file:line:column and key path), naming the CSV file, line and column where there is one.
// Internal to io/ (it includes yaml-cpp through io/scene_value.hpp).
// Not here: the CSV format and the expression syntax (the files above), finding the
// breakpoints of an expression (only those listed are reported: a kink in `t > 1 ? ...` is
// not seen by itself).
#pragma once

#include <array>

#include "core/signal.hpp"
#include "io/scene_value.hpp"

namespace tribo::io::scene_detail {

Signal readSignal(const Value& v);
// Three components [x, y, z], each a number or a signal.
std::array<Signal, 3> readSignals3(const Value& v);

}  // namespace tribo::io::scene_detail
