// A-priori step-size limit for the explicit integrators, from the stiffest element of the
// model, so a run whose step is too large is flagged before it produces a plausible-looking
// wrong answer.
//
// Each element is reduced to the linear test system  x'' + (c/m) x' + (k/m) x = 0, with m
// the dynamic body's mass (reduced mass if both are dynamic):
//   contact pair, normal: k = n dF/dd, c = n dF/dd' of the pair's normal law at rest, n = 4
//                  points (a box resting on a face). Linear: k, c as given. Nonlinear
//                  (hertz, hunt_crossley, recurdyn): the tangent at the static depth d0
//                  where the n points share the resting load W (the dynamic body's weight,
//                  the heavier one's if both are dynamic): k d0^p = W / n, so
//                    dF/dd = p W / (n d0);  dF/dd' = 0 (hertz), alpha W / n
//                    (hunt_crossley), havsin(d0, 0, 0, d_max, c) (recurdyn).
//                  Without gravity there is no static depth: the stated depth 1e-4 m, with
//                  a note. A deeper contact (an impact, a stack's lower pairs) is stiffer:
//                  the limit falls as d^-(p-1)/2;
//   contact pair, stateful friction (elastic_stick): its stick spring-damper, k = n k_t,
//                  c = n c_t (read off the law's stuck force), tangential;
//   spring-damper: k, c as given, m as above;
//   friction:      c/m = g mu'(v) (the sticking slope of the law under the body's weight), at
//                  the steepest of 16 samples over [0, stick speed]; for a law whose slope is
//                  unbounded at zero slip (roh_yoo with beta < 1) the slope at the stick speed,
//                  so that at the limit the numerical chatter stays below the stick speed.
// The limit is the largest h for which the integrator's one-step matrix for that system has
// spectral radius <= 1 (undamped: RK4 h w < 2 sqrt(2), semi-implicit Euler h w < 2; real
// axis: RK4 2.785, Dormand-Prince 5(4) 3.307). For dopri5 it bounds the internal steps the
// error control will settle on (a cost estimate, not a warning); bdf has no explicit limit.
// Not here: rotational modes (a flat box's pitch on its corners, or its yaw on the stick
// springs, has up to sqrt(3) times the frequency of its translation), shapes resting on more
// or fewer than 4 points (linear law: a disc on 8 rim points has sqrt(2) times the
// frequency, a sphere on one point half), nonlinear instability, contact chatter, accuracy
// (see the README's measurements).
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
