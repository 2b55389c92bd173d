// Poincare-map (Picard) iteration towards a periodic orbit that contracts strongly, before
// Newton's method: one flow of a period an iteration instead of Newton's 2 (n + 1). On a
// stick-slip orbit the stick phase collapses every direction but the one along the orbit
// (multipliers ~1e-5), so the return map alone shrinks the error by that factor a period, and
// what is left is the phase: where along the orbit the iterate lies. That part is solved as
// Newton-Picard methods solve their small dominant subspace (Lust, Roose, Spence & Champneys,
// "An adaptive Newton-Picard algorithm with subspace iteration for computing periodic
// solutions", SIAM J. Sci. Comput. 19(4), 1998), here with the one direction known in
// advance, the vector field f:
//   autonomous: end = phi_T(y); f at end from two steps of the flow (a one-sided difference
//               of second order: vectorField in picard.cpp); the section crossing
//               y_obs' = 0 near end is tau = -end_phase / f_phase away, so
//               y <- end + tau f,   T <- T + tau
//               (a fixed point has tau = 0 and end = y: the orbit, on the section)
//   forced:     y <- phi_T(y)     (the forcing fixes the phase; T is known)
// The iteration stops when the residual |(phi_T(y) - y, y_phase)| <= tolerance (1 + |y|), when
// an iteration shrinks it by less than kPicardContraction (an orbit that contracts slowly,
// or an unstable one: Newton's method takes over), or after kPicardMostIterations; y and T
// are then the best iterate seen. Convergence is linear at the rate of the largest
// non-trivial multiplier, and quadratic in the phase. From a guess off the orbit the first
// iterate lands on the orbit shifted along it (the guess's error along the trivial direction),
// so its T is off by that shift and the second iterate corrects it: a stick-slip orbit
// converges on the third (residuals 4e-6, 2e-7, 1e-11 from a continuation's prediction on the
// belt).
// Not here: the multipliers (the monodromy is still differenced once at the orbit found);
// continuation's corrector, whose parameter moves too.
#pragma once

#include <Eigen/Dense>
#include <functional>

#include "study/orbit/shooting.hpp"

namespace tribo::study::shooting {

// An iteration must shrink the residual at least this many times, or Newton's method goes on.
inline constexpr double kPicardContraction = 4.0;
inline constexpr int kPicardMostIterations = 8;

struct PicardOutcome {
  int iterations = 0;      // return-map iterations taken (flows of a period)
  double residual = 0;     // of the iterate returned, relative to 1 + |y|
  bool converged = false;  // residual <= tolerance
  Eigen::VectorXd end;     // phi_T of the iterate returned (empty if no flow came back)
};

// The vector field at y by a one-sided difference of second order over two steps of h:
// f = (-3 y + 4 phi_h(y) - phi_2h(y)) / 2h.
Eigen::VectorXd vectorField(const Flow& flow, const Eigen::VectorXd& y, double h);

// The flow of iterate number `iterate` (0 the first), where a caller gives one: it must
// return flow(y, T) and may do other work beside it (the branch's return-map step runs there
// the products with the monodromy it will want: branch_return_map.hpp).
using IterateFlow = std::function<Eigen::VectorXd(const Eigen::VectorXd& y, double T, int iterate)>;

// Autonomous orbits: y on (or near) the section y[phase] = 0, T its return time; `step` the
// time over which the vector field is differenced (the integrator's step). y and T are
// replaced by the best iterate.
PicardOutcome picardAutonomous(const Flow& flow, Eigen::VectorXd& y, double& T, Eigen::Index phase,
                               double step, double tolerance, const IterateFlow& flow_of = {});

// Forced orbits of known period T.
PicardOutcome picardForced(const Flow& flow, Eigen::VectorXd& y, double T, double tolerance,
                           const IterateFlow& flow_of = {});

}  // namespace tribo::study::shooting
