// `tribo modes SCENE.yaml --out DIR [--set NAME=VALUE ...] [--settle] [--boundary NAME=LO:HI]
//  [--growth-tolerance X] [--solver auto|dense|sparse] [--modes N]`: will steady sliding
// squeal? Finds the scene's steady state, linearizes about it and prints its modes (all of
// them by the dense eigensolver, the N of largest growth rate by the sparse one; auto picks
// by size: study/modes/modes.hpp says how); writes
// DIR/modes.json and DIR/modes.csv (study/modes/modes_report.hpp) and, with --boundary, bisects
// the parameter NAME over [LO, HI] for the value where the largest growth rate crosses zero
// (study/modes/stability_boundary.hpp) into DIR/boundary.json.
// Exit status: 0 stable, 1 usage, 2 bad scene or parameter (also: stateful friction, nothing
// dynamic, a --boundary bracket without a crossing), 4 output error, 8 unstable (some mode
// grows), 9 no steady state found, 10 the linearization or the eigenproblem failed.
#pragma once

#include "apps/command.hpp"

namespace tribo::app {

inline constexpr int kExitUnstable = 8;
inline constexpr int kExitNoSteadyState = 9;
inline constexpr int kExitEigenFailure = 10;

// Adds `modes` and its options to `tribo`.
Command addModesCommand(CLI::App& tribo);

}  // namespace tribo::app
