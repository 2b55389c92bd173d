// Time integrators over all bodies' poses (unit quaternions) and world-frame velocities,
// behind one interface. Kinematic bodies move with their constant velocities.
//
// Fixed step, hand-written (the fast path; the step h is the model's time_step):
//   semi_implicit_euler: v+ = v + h a(y);  p+ = p + h v+;  q+ = exp(h w+) q
//                        (first order, symplectic for conservative forces, 1 evaluation)
//   rk4:                 classical Runge-Kutta, fourth order, 4 evaluations; the
//                        quaternion is integrated in R^4 and renormalized at the end.
// Adaptive, with local error control, from SUNDIALS (core/sundials_integrators.hpp; Hindmarsh
// et al. 2005, ACM TOMS 31(3):363-396): h is then the communication interval and the method
// takes its own internal steps inside it:
//   dopri5: ARKODE explicit Dormand-Prince 5(4) (Dormand & Prince 1980, J. Comput. Appl.
//           Math. 6:19-26); stability still bounds its steps on stiff contacts.
//   bdf:    CVODE variable-order (1-5) BDF with Newton iterations on a dense
//           difference-quotient Jacobian; implicit, for very stiff contacts.
// Both locate friction regime changes (slip speed crossing zero or a friction law's
// breakpoints) by root finding and restart there, when the model asks for event location,
// and end a step exactly at each breakpoint of the model's input signals and restart there
// (core/input_breakpoints.hpp).
// `start_is_evaluated` lets the caller say the Dynamics workspace already holds the
// evaluation at `state` (it was needed for output), so it is not done twice.
// Not here: divergence checks (core/simulator.hpp), the a-priori step limit
// (core/stability.hpp).
#pragma once

#include <atomic>
#include <limits>
#include <memory>
#include <string>

#include "core/dynamics.hpp"

namespace tribo {

// Outcome of one call to Integrator::step. An adaptive method can fail (too much work, error
// test or convergence failures, a non-finite right-hand side); the message then says why
// and, where the integrator knows it, which body and quantity carried the largest error.
struct IntegratorStatus {
  bool ok = true;
  std::string message;       // set when !ok
  std::string body;          // body concerned, empty if unknown
  std::string quantity;      // e.g. "velocity.z", empty if unknown
  double time = 0.0;         // [s] where the method stopped (when !ok)
  bool interrupted = false;  // stopped by the stop request, not by the method (when !ok)
};

// Work done so far, cumulative over the integrator's life.
struct IntegratorCounters {
  long steps = 0;           // internal steps accepted (fixed step: one per call)
  long rejected_steps = 0;  // error-test and convergence failures (adaptive only)
  long evaluations = 0;     // Dynamics::evaluate calls made by the integrator
  long events = 0;          // friction regime changes located (adaptive only)
  long restarts = 0;        // (re)starts of an adaptive method: first call, events, setState
  double last_event_time = std::numeric_limits<double>::quiet_NaN();  // [s]
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Advances `state` by h. On failure the state is unspecified; the caller restores it.
  virtual IntegratorStatus step(Dynamics& dynamics, State& state, double h,
                                bool start_is_evaluated) = 0;
  // Evaluations per step for the fixed-step methods, 0 for adaptive ones (it varies).
  virtual int evaluationsPerStep() const = 0;
  const IntegratorCounters& counters() const { return counters_; }
  // A flag set from outside (a signal handler, another thread): an adaptive method checks it
  // at each right-hand-side evaluation and abandons the step (status interrupted), so a long
  // stiff step ends within one evaluation. Fixed-step methods finish their short step.
  void setStopRequest(const std::atomic<bool>* stop) { stop_ = stop; }

 protected:
  bool stopRequested() const { return stop_ && stop_->load(std::memory_order_relaxed); }

  IntegratorCounters counters_;
  const std::atomic<bool>* stop_ = nullptr;
};

// True for dopri5 and bdf: time_step is a communication interval, not the step.
bool isAdaptive(IntegratorType type);

std::unique_ptr<Integrator> makeIntegrator(IntegratorType type, const Model& model);

}  // namespace tribo
