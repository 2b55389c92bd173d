// Fixed-step time integrators over all bodies' poses (unit quaternions) and world-frame
// velocities. Kinematic bodies move with their constant velocities (zero acceleration).
//
//   semi_implicit_euler: v+ = v + h a(y);  p+ = p + h v+;  q+ = exp(h w+) q
//                        (first order, symplectic for conservative forces, 1 evaluation)
//   rk4:                 classical Runge-Kutta, fourth order, 4 evaluations; the
//                        quaternion is integrated in R^4 and renormalized at the end.
// `start_is_evaluated` lets the caller say the Dynamics workspace already holds the
// evaluation at `state` (it was needed for output), so it is not done twice.
// Not here: error control, implicit or adaptive methods, event location.
#pragma once

#include <memory>

#include "core/dynamics.hpp"

namespace tribo {

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual void step(Dynamics& dynamics, State& state, double h, bool start_is_evaluated) = 0;
  virtual int evaluationsPerStep() const = 0;
};

std::unique_ptr<Integrator> makeIntegrator(IntegratorType type, const Model& model);

}  // namespace tribo
