// `tribo orbit SCENE --out DIR`: the scene's periodic orbit (the limit cycle of stick-slip)
// by shooting on the engine's own step (study/orbit/periodic_orbit.hpp): its period,
// amplitude and Floquet multipliers, written to DIR/orbit.json and DIR/orbit.csv (the
// observed coordinate over one period). Exit status: 0 a stable orbit, 1 usage, 2 bad scene,
// 4 output error, 8 an unstable orbit, 11 no orbit found (study::OrbitError: not autonomous,
// no oscillation, Newton not converging).
#pragma once

#include "apps/command.hpp"

namespace tribo::app {

inline constexpr int kExitNoOrbit = 11;

// Adds `orbit` and its options to `tribo`.
Command addOrbitCommand(CLI::App& tribo);

}  // namespace tribo::app
