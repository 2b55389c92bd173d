// `tribo run SCENE --out DIR`: loads the scene (a YAML scene or a URDF robot, io/scene_source.hpp),
// runs it (study/scene_run.hpp), writes DIR/trajectory.csv and DIR/summary.json and prints a
// short summary. Exit status: 0 success, 1 usage error, 2 bad scene or parameters (also an
// output that would not fit the disk), 3 the run diverged (partial results written and
// marked so), 4 output error, 5 interrupted by SIGINT or SIGTERM (results up to there
// written, marked so), 6 the output folder is in use by another run.
// A run streams trajectory.csv as it goes; a first SIGINT/SIGTERM stops it at once (back at
// the last output row, study/scene_run.hpp), a second one ends the process at once (the files
// stay under their .partial names).
// Not here: the run loop and the figures of the summary (study/), the shared options
// (apps/common_options.hpp).
#pragma once

#include "apps/command.hpp"

namespace tribo::app {

// Adds `run` and its options to `tribo`.
Command addRunCommand(CLI::App& tribo);

}  // namespace tribo::app
