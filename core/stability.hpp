// A-priori step-size limit for the explicit integrators, from the stiffest element of the
// model, so a run whose step is too large is flagged before it produces a plausible-looking
// wrong answer.
//
// Each element is reduced to the linear test system  x'' + (c/m) x' + (k/m) x = 0:
//   contact pair:  k = n k_point, c = n c_point, n = 4 points (a box resting on a face),
//                  m = the dynamic body's mass (reduced mass if both are dynamic);
//                  Hunt-Crossley is linearized at the static depth under m g;
//   spring-damper: k, c as given, m as above;
//   friction:      c/m = g mu'(v) (the sticking slope of the law under the body's weight), at
//                  the steepest of 16 samples over [0, stick speed]; for a law whose slope is
//                  unbounded at zero slip (roh_yoo with beta < 1) the slope at the stick speed,
//                  so that at the limit the numerical chatter stays below the stick speed.
// The limit is the largest h for which the integrator's one-step matrix for that system has
// spectral radius <= 1 (undamped: RK4 h w < 2 sqrt(2), semi-implicit Euler h w < 2; real
// axis: RK4 2.785, Dormand-Prince 5(4) 3.307). For dopri5 it bounds the internal steps the
// error control will settle on (a cost estimate, not a warning); bdf has no explicit limit.
// Not here: nonlinear instability, contact chatter, accuracy (see the README's measurements).
#pragma once

#include <string>
#include <vector>

#include "core/model.hpp"

namespace tribo {

struct StabilityLimit {
  double max_step = 0.0;  // [s], +infinity when nothing limits it
  std::string element;    // e.g. "contact pair (belt_surface, box_shape)"
};

struct StabilityReport {
  StabilityLimit limit;            // the most restrictive element
  std::vector<std::string> notes;  // elements that could not be bounded, and why
};

// Largest stable step of `integrator` on x'' + c_over_m x' + k_over_m x = 0.
double stableStep(IntegratorType integrator, double k_over_m, double c_over_m);

StabilityReport estimateStableStep(const Model& model);

}  // namespace tribo
