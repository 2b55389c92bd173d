// The forcing of a scene as periodic-orbit shooting sees it: which inputs vary in time
// (applied loads, actuator targets, joint drives, surface velocities, kinematic bodies'
// motion) and the period they share. A scene with none is autonomous (its orbit's period is
// an unknown); one whose inputs all repeat with a common period P has forced orbits, of
// period P or a multiple of it (a subharmonic), with the phase the forcing fixes (Seydel,
// "Practical Bifurcation and Stability Analysis", 3rd ed., Springer 2010, sec. 7.1: the
// Poincare map of a periodically forced system is the flow over one forcing period).
//   sines     sum_k offset_k + A_k sin(2 pi f_k t + phi_k): P = q / f_min with q the smallest
//             whole number <= 64 making every P f_k whole (to 1e-9 relative)
//   drive     c0 + c1 t + A sin(w t + phi) with c1 = 0 and A != 0: P = 2 pi / w
//   constant  (a constant, a ramp of rate 0, a step to the same value): no period needed
//   others    (ramps, steps, tables, expressions of t): not known to repeat; a period the user
//             gives is accepted for them after a check that each repeats with it (64 samples
//             over one period, to 1e-9 of its largest magnitude there)
// A kinematic body that moves at a constant velocity (no signal) counts as constant here:
// its geometry must look the same one period on (a plane moving along itself), which the
// orbit's residual then confirms or not.
// Not here: the shooting (study/orbit/periodic_orbit.hpp).
#pragma once

#include <string>
#include <vector>

#include "core/model.hpp"

namespace tribo::study {

// An input of the scene that depends on time: its name ("load 'push' force x", "body 'belt'
// surface velocity x", "joint 'j' drive", "joint 'j' actuator target", "body 'b' motion
// velocity x", "body 'b' motion spin rate", "kinematic body 'b' moves") and its period: 0
// for one that is constant in time (no period needed), > 0 its smallest period, < 0 none
// known.
struct TimeInput {
  std::string name;
  double period = 0.0;
  std::vector<double> frequencies;  // [Hz] of a sines signal or a drive, for the common period
  const Signal* signal = nullptr;   // the signal, when there is one, for the repetition check
};

std::vector<TimeInput> timeInputs(const Model& model);

// Why the scene's motion depends on time ("it has applied loads that vary in time ...",
// naming the first input that varies), or empty when it is autonomous (every input constant,
// no kinematic body moving).
std::string nonAutonomous(const Model& model);

// The period of the scene's forcing: `given` when > 0 (after checking that it is a whole
// multiple of every input's known period and that the others repeat with it), else the
// common period of every input that varies. Throws OrbitError naming the input that has no
// period known (asking for --period), a given period that does not fit one, or frequencies
// without a common period; a scene with no time-varying input has no forcing period (an
// error too: its orbits are autonomous).
double forcingPeriod(const Model& model, double given);

}  // namespace tribo::study
