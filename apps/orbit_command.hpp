// `tribo orbit SCENE --out DIR`: the scene's periodic orbit (the limit cycle of stick-slip)
// by shooting on the engine's own step (study/orbit/periodic_orbit.hpp): its period,
// amplitude and Floquet multipliers, written to DIR/orbit.json and DIR/orbit.csv (the
// observed coordinate over one period). With --continue NAME=FROM:TO: the orbit's branch in a
// parameter (study/orbit/orbit_branch.hpp), written to DIR/branch.csv, DIR/branch.json and
// DIR/branch_orbits.csv. Exit status: 0 a stable orbit, 1 usage, 2 bad scene, 4 output error, 8 an
// unstable orbit, 11 no orbit found (study::OrbitError: not autonomous, no oscillation, Newton not
// converging), 12 a branch lost before TO.
#pragma once

#include "apps/command.hpp"

namespace tribo::app {

inline constexpr int kExitNoOrbit = 11;
inline constexpr int kExitBranchLost = 12;  // --continue: the branch stopped short of TO
inline constexpr int kExitNoSwitch = 13;    // --switch: the branch had no such bifurcation
inline constexpr int kExitInterrupted = 5;  // --continue: SIGINT or SIGTERM (as `tribo run`)

// Adds `orbit` and its options to `tribo`.
Command addOrbitCommand(CLI::App& tribo);

}  // namespace tribo::app
