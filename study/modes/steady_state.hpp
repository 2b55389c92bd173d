// The steady state of a scene: the configuration where every dynamic body is at rest while
// kinematic bodies and belt surfaces keep their motion (a belt's surface velocity makes
// steady sliding a true equilibrium), i.e. the root of the reduced accelerations
//   g(q) = q''(x0 + N q, v = 0) = 0           (study/modes/reduced_coordinates.hpp)
// found by Newton's method on the full model (springs, contacts, friction at the steady
// slip, joint constraints): the Jacobian dg/dq by central differences
// (study/modes/linearization.hpp), the step dq = -(dg/dq)^-1 g halved until |g| falls (Armijo
// backtracking), the new configuration projected back onto the joint constraints
// (core/constraint_projection.hpp) and the basis N rebuilt there. It converges when
// max |g| <= tolerance.
// Optional fallback (settle): a damped settling run first, from the scene's initial state:
// semi-implicit Euler steps of the full dynamics with an added artificial damping
//   v' = a(x, v) - gamma (v - v_steady)
// (gamma = settle_damping; step min(time_step, half the a-priori stable step)) until the
// bodies are at rest (max |v| < 1e-6 and max |a| < 1e-3) or settle_time has passed, then
// Newton from there. Kinematic bodies stay at their poses of t = 0.
// Errors: NoSteadyState when Newton's Jacobian is singular (a direction nothing restrains,
// named: e.g. a box on a belt with no spring), when the line search stalls or the
// iterations run out; std::invalid_argument for a scene with nothing to move.
// Not here: stateful friction (its anchors would hold any configuration: refused by
// study/modes/modes.hpp), steady motions other than rest (a spinning dynamic disc), periodic
// orbits, the stability of the state (study/modes/modes.hpp).
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/dynamics.hpp"
#include "core/model.hpp"
#include "core/state.hpp"

namespace tribo::study {

class NoSteadyState : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SteadyStateOptions {
  double tolerance = 1e-8;  // max |q''| at the solution [m/s^2 or rad/s^2]
  int max_iterations = 50;
  bool settle = false;          // settling run before Newton
  double settle_time = 0.0;     // [s]; 0: the scene's duration
  double settle_damping = 5.0;  // gamma [1/s]
};

struct SteadyState {
  State state;               // dynamic bodies at rest, kinematic ones at t = 0
  int iterations = 0;        // Newton steps taken
  double residual = 0.0;     // max |q''| at the solution
  double settled_for = 0.0;  // simulated seconds of the settling run (0 without one)
  int evaluations = 0;
};

SteadyState findSteadyState(Dynamics& dynamics, const SteadyStateOptions& options = {});

}  // namespace tribo::study
