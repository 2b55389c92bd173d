// The ADAMS-style friction law (scene name "adams", keys mu_s mu_k v_s v_d): the two-step
// shape of two_step_law.hpp joined by cubic STEP functions
//   step(x, x0, h0, x1, h1) = h0 + (h1 - h0) s^2 (3 - 2 s),  s = clamp((x - x0)/(x1 - x0), 0, 1)
// (MSC ADAMS/Solver reference, STEP function; as in Roh & Yoo 2007). Creeps at low slip
// speed and is flat beyond v_d: see two_step_law.hpp.
#pragma once

#include "friction/smooth_step.hpp"
#include "friction/two_step_law.hpp"

namespace tribo::friction {

using AdamsLaw = TwoStepLaw<CubicStep>;

}  // namespace tribo::friction
