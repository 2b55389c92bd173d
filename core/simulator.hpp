// The one orchestrator of a run: owns the state, the dynamics and the integrator, and
// advances time one model time step at a time (for adaptive integrators that step is the
// communication interval; they take their own internal steps inside it). Each step:
// integrate -> evaluate at the new state (reused by the next step and by outputs) ->
// divergence checks -> advance friction states. The checks, in order:
//   the integrator's own failure (too much work, error test, non-finite derivative);
//   non-finite position, orientation, velocity or angular velocity of a body;
//   a non-finite contact force;
//   energy rising without a source (core/energy.hpp).
// A contact deeper than its geometry's half width along the contact normal
// (contact::Shape::extent: a wheel on its rim, its radius) is not a stop by itself: a small
// sensor sphere on a heavy body may be pushed through while the run is right. It is
// counted in StepStats (the deepest, by its ratio to that width) for a warning after the run,
// and named in the message when the energy guard stops the run.
// A step returns a status; it never throws and never lets a NaN through: on divergence the
// state stays at the last good step and the status names the step, time, body and quantity.
// With `threads: auto` and more than one thread to use, each step is timed (two clock reads)
// and the next step's threads follow the measured choice (core/thread_choice.hpp); the
// results do not depend on it.
// With profiling on (setProfiling), StepStats::profile holds the time per stage of the step
// (core/stage_profile.hpp); off, the default, no clock is read (but for `threads: auto`).
// A warm step does not allocate (tests/core/allocation_test.cpp): messages are built only on
// failure.
// Not here: output (io/), the stop time (the caller's loop), the a-priori step limit
// (core/stability.hpp).
#pragma once

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/dynamics.hpp"
#include "core/energy.hpp"
#include "core/integrator.hpp"
#include "core/stage_profile.hpp"
#include "core/thread_choice.hpp"

namespace tribo {

struct StepStatus {
  bool ok = true;
  std::string message;       // set when !ok: step, time, body and quantity in words
  double time = 0.0;         // [s] of the state that failed the checks (when !ok)
  std::string body;          // the body concerned, empty if none is known
  std::string quantity;      // e.g. "velocity", "penetration", "energy", "integrator"
  bool interrupted = false;  // the stop request ended the step (not a divergence; !ok)
};

struct StepStats {
  long steps = 0;
  int contact_count = 0;
  double max_penetration = 0.0;            // over the run [m]
  double max_constraint_error = 0.0;       // over the run, max |Phi|
  int max_constraint_joint = -1;           // where it was (-1: no joint)
  double max_constraint_rate_error = 0.0;  // over the run, max |J v|
  // Integrator work (core/integrator.hpp), and force evaluations in all (the integrator's
  // plus the simulator's one per step at the new state).
  long integrator_steps = 0;
  long rejected_steps = 0;
  long events = 0;
  double last_event_time = std::numeric_limits<double>::quiet_NaN();  // [s]
  long evaluations = 0;
  // Steps whose state's joint friction (reaction load) did not settle within the iteration
  // cap (core/joint_forces.hpp), and the time of the first.
  long joint_friction_unconverged = 0;
  // Steps whose state had a joint's damping or friction held within I_q |q'| / (2 h)
  // (core/joint_forces.hpp), the time of the first, the largest change to a torque there
  // [N m or N] and its joint (-1: none).
  long joint_held = 0;
  double first_held_time = std::numeric_limits<double>::quiet_NaN();  // [s]
  double joint_held_change = 0.0;
  int joint_held_worst = -1;
  // Contact points deeper than their geometry's half width along the normal (point-steps),
  // the time of the first, and the deepest relative to that width.
  long deep_penetrations = 0;
  double first_deep_time = std::numeric_limits<double>::quiet_NaN();         // [s]
  double deepest_ratio = 0.0;                                                // depth / half width
  int deepest_geometry = -1;                                                 // geometry index
  double deepest_depth = 0.0;                                                // [m]
  double deepest_extent = 0.0;                                               // [m]
  double first_unconverged_time = std::numeric_limits<double>::quiet_NaN();  // [s]
  // The threads a step may run on (Dynamics::mostThreads: the setting, under the scene's size),
  // and the steps that ran on more than one (all of them for a fixed count above one; for
  // `threads: auto`, those of the measured choice).
  int most_threads = 1;
  long threaded_steps = 0;
  // The threads a step ran on, on the mean over the steps (1 before any step).
  double meanThreads() const {
    return steps > 0 ? 1.0 + (most_threads - 1) * static_cast<double>(threaded_steps) /
                                 static_cast<double>(steps)
                     : 1.0;
  }
  // Time per stage since Simulator::setProfiling(true); all zero while profiling is off.
  // With profiling on from the start, profile.evaluations == evaluations.
  StageProfile profile;
};

class Simulator {
 public:
  explicit Simulator(std::shared_ptr<const Model> model);

  const Model& model() const { return dynamics_.model(); }
  const State& state() const { return state_; }
  void setState(const State& state);
  const StepStats& stats() const { return stats_; }
  // Commands joint `joint`'s actuator from now on, in place of its target signal (a
  // controller outside the model: held over each step, zero-order), NaN to return to the
  // signal; the current evaluation is dropped. Throws std::invalid_argument when the joint
  // has no actuator or the command is infinite.
  void setActuatorCommand(int joint, double command);
  // Holds load `load`'s force and/or torque (3 numbers in the load's frame) at these values
  // from now on, in place of its signals (zero-order, as an actuator command); std::nullopt
  // gives that part back to the signals. Throws std::invalid_argument for a load index out of
  // range or a value that is not finite.
  void setLoadCommand(std::size_t load, const std::optional<Vec3>& force,
                      const std::optional<Vec3>& torque);

  // Advances by the model's time step.
  StepStatus step();
  // A flag set from outside (a signal handler, another thread). An adaptive integrator
  // abandons its step when it sees it (within one force evaluation): step() then returns
  // !ok with `interrupted` set and the state unchanged (the step is not counted).
  // Fixed-step integrators finish their step; the caller checks the flag between steps.
  void setStopRequest(const std::atomic<bool>* stop) { integrator_->setStopRequest(stop); }
  // Time per stage into StepStats::profile (core/stage_profile.hpp). Switching it on
  // starts the profile from zero; off (the default) costs nothing.
  void setProfiling(bool on);
  // Forces, contacts and accelerations at the current state (evaluated at most once).
  const Workspace& current();
  // The threads the next step runs on, and the most it may (Dynamics::mostThreads).
  int threads() const { return dynamics_.threads(); }
  int mostThreads() const { return dynamics_.mostThreads(); }
  // Runs every step from now on on `threads` threads (within 1 and mostThreads()), ending the
  // measured choice of `threads: auto`; the results are the same bit for bit.
  void pinThreads(int threads);

 private:
  StepStatus advance();          // step() without the profile
  void useThreads(int threads);  // the dynamics' and the energy guard's count
  StepStatus check();
  EnergyGuard makeEnergyGuard() const;
  // A failed status at the current state's time (or at `time` for the integrator's).
  StepStatus failed(const std::string& body, const std::string& quantity, const std::string& what,
                    double time = NAN) const;

  Dynamics dynamics_;
  std::unique_ptr<Integrator> integrator_;
  State state_;
  State last_good_;
  bool evaluated_ = false;
  EnergyGuard energy_;
  long own_evaluations_ = 0;
  StepStats stats_;
  bool profiling_ = false;
  ThreadChoice choice_;  // measures only for `threads: auto` with more than one thread
  // Per geometry: no contact shallower than this is deeper than its half width
  // (contact::Shape::thinnestHalfWidth); check() measures the width only past it.
  std::vector<double> thinnest_;
  double thinnest_of_all_ = std::numeric_limits<double>::infinity();  // the least of thinnest_
};

}  // namespace tribo
