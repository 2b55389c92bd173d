// Reading a time signal (core/signal.hpp) from a scene value: a number (or an expression over
// parameters) is a constant; a mapping with one key names the kind:
//   {ramp: {rate, [start], [initial]}}       {step: {time, before, after}}
//   {smooth_step: {start, end, before, after}}  {table: [[t, v], ...]}
//   {sines: [{amplitude, frequency, [phase], [offset]}, ...]}
// Each refusal (unknown kind, a missing key, table times not increasing) is a SceneError at
// the offending value. Internal to io/ (it includes yaml-cpp through io/scene_value.hpp).
// Not here: expressions of t, tables from files.
#pragma once

#include <array>

#include "core/signal.hpp"
#include "io/scene_value.hpp"

namespace tribo::io::scene_detail {

Signal readSignal(const Value& v);
// Three components [x, y, z], each a number or a signal.
std::array<Signal, 3> readSignals3(const Value& v);

}  // namespace tribo::io::scene_detail
