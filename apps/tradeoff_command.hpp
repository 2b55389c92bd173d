// `tribo tradeoff SCENE.yaml [--set NAME=VALUE ...] [--out DIR] [--window S] [--repeat N]
//  [--integrators A,B,...]`: the speed-accuracy trade of a scene, measured.
//
// Runs every integrator over a ladder of settings, fixed steps G/n (G = 40 ms, n = 2 .. 640,
// those between limit/64 and 2.5 limit of the a-priori stability estimate) for
// semi_implicit_euler and rk4, tolerances rtol = 1e-3 .. 1e-8 (atol = 1e-3 rtol) at a
// 10 ms communication interval for dopri5 and bdf (with and without event location), and
// compares each run with a converged reference (rk4 at a step of at most limit/8 and
// 0.1 ms, checked against half that step):
//   amplitude error   |A - A_ref| / A_ref of the summary's limit-cycle amplitude, A_ref from
//                     the reference sampled at the run's own output interval (the same
//                     estimator on the same grid, so sampling does not count as error);
//   trajectory error  max |x(t_k) - x_ref(t_k)| / A_ref over t_k = k G <= window (10 s) of
//                     the summary coordinate (cubic Hermite in x and its velocity between
//                     samples; exact on the sample times, which the ladder is chosen to hit);
// against its cost: processor time of the run (stepping, recording, summary) and wall time of
// the stepping, each the least of `repeat` runs. Writes DIR/tradeoff.csv (one row per run),
// prints a table and, for errors of 1%, 0.1% and 0.01%, the cheapest (processor time)
// complete run without a stability warning that reaches it in amplitude, and in amplitude and
// trajectory (an amplitude that lands close while the trajectory is off is a fluke).
// Exit status: 0 done, 1 usage, 2 bad scene, 3 the reference itself did not complete,
// 4 output error. Not here: the plot (scripts/plot_work_precision.sh).
#pragma once

#include <string>
#include <vector>

namespace tribo::app {

int tradeoffCommand(const std::vector<std::string>& args);

}  // namespace tribo::app
