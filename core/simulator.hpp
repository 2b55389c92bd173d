// The one orchestrator of a run: owns the state, the dynamics and the integrator, and
// advances time one fixed step at a time. Each step: finite-state check -> integrate ->
// evaluate at the new state (reused by the next step and by outputs) -> divergence checks.
// A step returns a status; it never throws and never lets a NaN through: on divergence
// the state stays at the last good step and the status names the step, time, body and
// quantity. Not here: output (io/), the stop time (the caller's loop).
#pragma once

#include <memory>
#include <string>

#include "core/dynamics.hpp"
#include "core/integrator.hpp"

namespace tribo {

struct StepStatus {
  bool ok = true;
  std::string message;  // set when !ok
};

struct StepStats {
  long steps = 0;
  int contact_count = 0;
  double max_penetration = 0.0;        // over the run [m]
  double max_constraint_error = 0.0;   // over the run, max |Phi|
  double max_constraint_rate_error = 0.0;  // over the run, max |J v|
};

class Simulator {
 public:
  explicit Simulator(std::shared_ptr<const Model> model);

  const Model& model() const { return dynamics_.model(); }
  const State& state() const { return state_; }
  void setState(const State& state);
  const StepStats& stats() const { return stats_; }

  // Advances by the model's time step.
  StepStatus step();
  // Forces, contacts and accelerations at the current state (evaluated at most once).
  const Workspace& current();

 private:
  StepStatus check();

  Dynamics dynamics_;
  std::unique_ptr<Integrator> integrator_;
  State state_;
  State last_good_;
  bool evaluated_ = false;
  StepStats stats_;
};

}  // namespace tribo
