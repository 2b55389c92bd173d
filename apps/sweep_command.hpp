// `tribo sweep`: runs a scene over a grid of parameter values, in parallel on the local
// cores, or across MPI ranks when started by mpirun (builds with TRIBO_WITH_MPI), writing
// one row per point to DIR/results.csv (study/sweep/sweep_results.hpp). Parses arguments and
// prints; the work is in study/sweep/sweep_runner.hpp and study/sweep/sweep_mpi.hpp. Exit status: 0
// every point is recorded (points that failed are rows with their error), 1 usage error, or DIR
// holds another sweep or is in use, 2 bad scene or swept parameter, 4 the results cannot be
// written.
#pragma once

#include "apps/command.hpp"

namespace tribo::app {

// Adds `sweep` and its options to `tribo`.
Command addSweepCommand(CLI::App& tribo);

}  // namespace tribo::app
