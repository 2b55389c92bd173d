// The adaptive integrators taken from SUNDIALS 6 (Hindmarsh et al. 2005, "SUNDIALS: Suite of
// nonlinear and differential/algebraic equation solvers", ACM TOMS 31(3):363-396), built for
// a model. No SUNDIALS type appears here; core/sundials_stepper.hpp holds the shared part.
//
//   dopri5: ARKODE ERKStep with the Dormand-Prince 5(4) table (ARKODE_DORMAND_PRINCE_7_4_5),
//           cubic Hermite dense output.
//   bdf:    CVODE, BDF orders 1-5, Newton iteration with SUNDIALS' dense direct solver on a
//           difference-quotient Jacobian, stability-limit detection on.
// Both use the model's relative/absolute tolerance and max internal step, treat time_step as
// the communication interval, and locate friction regime changes when event_location is on.
// Not here: the fixed-step methods (core/integrator.cpp).
#pragma once

#include <memory>

#include "core/integrator.hpp"

namespace tribo {

std::unique_ptr<Integrator> makeArkodeDopri5(const Model& model);
std::unique_ptr<Integrator> makeCvodeBdf(const Model& model);

}  // namespace tribo
