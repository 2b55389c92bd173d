// The times where a model's inputs are not smooth: the breakpoints (core/signal.hpp) of its
// loads' components, its actuators' targets, its joint drives' signals and its bodies'
// surface velocities, in increasing order, each once. The adaptive integrators
// (core/sundials_stepper.hpp) end a step exactly at each and restart there, so no step's
// polynomial spans a jump or a kink of an input.
// Not here: a function signal's kinks it does not report (an expression's `t > 1 ? ...`), the
// fixed-step integrators (they step over breakpoints), friction laws' breakpoints (located
// by the integrators' event functions, core/sundials_system.hpp).
#pragma once

#include <vector>

#include "core/model.hpp"

namespace tribo {

std::vector<double> inputBreakpoints(const Model& model);

}  // namespace tribo
