// The RecurDyn friction law (scene name "recurdyn", keys mu_s mu_k v_s v_d): the two-step
// shape of two_step_law.hpp joined by haversine steps
//   havsin(x, x0, h0, x1, h1) = h0 + (h1 - h0) (1 - cos(pi (x - x0) / (x1 - x0))) / 2
// (RecurDyn Solver Theory, "Friction"; as in Roh & Yoo 2007). Creeps at low slip speed and
// is flat beyond v_d: see two_step_law.hpp.
#pragma once

#include "friction/smooth_step.hpp"
#include "friction/two_step_law.hpp"

namespace tribo::friction {

using RecurDynLaw = TwoStepLaw<Haversine>;

}  // namespace tribo::friction
