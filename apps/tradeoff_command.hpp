// `tribo tradeoff SCENE.yaml [--set NAME=VALUE ...] [--out DIR] [--window S] [--repeat N]
//  [--integrators A,B,...]`: the speed-accuracy trade of a scene, measured by
// study/tradeoff.hpp (which says what is run and how errors are defined). Parses
// arguments, prints a table as rows arrive and, for errors of 1%, 0.1% and 0.01%, the
// cheapest complete run without a stability warning that reaches it in amplitude, and in
// amplitude and trajectory; writes DIR/tradeoff.csv (default DIR: out/tradeoff).
// Exit status: 0 done, 1 usage, 2 bad scene, 3 the reference itself did not complete,
// 4 output error.
#pragma once

#include "apps/command.hpp"

namespace tribo::app {

// Adds `tradeoff` and its options to `tribo`.
Command addTradeoffCommand(CLI::App& tribo);

}  // namespace tribo::app
