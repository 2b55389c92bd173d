// What the two SUNDIALS integrators share (internal to core/; includes SUNDIALS headers):
// the context and state vector, the callbacks into OdeSystem, and the outer contract of
// Integrator::step for an adaptive method:
//
//   continue from the method's own history when `state` is the one it returned last time;
//   otherwise (first call, setState, a failed step, |q| drifted by > 1e-6, or stick anchors
//   re-set by a stateful friction law after the last step) restart there;
//   integrate to t + h in the method's normal mode (it may step past t + h and interpolate);
//   with the model's input breakpoints (core/input_breakpoints.hpp) as stop times: no internal
//   step crosses one; the method ends a step exactly at it and restarts there (like at an
//   event), also when it falls on t + h (within 64 eps |t|: then at t + h);
//   at a located event, restart at the event (the method's history does not cross a kink of
//   the friction law) with the last step size as the first (the methods' own first-step
//   estimate is unreliable at a kink); after kMaxEventRestarts events within one call (a
//   chattering contact) suspend event location until the next call, which restarts;
//   fail as "too much work" beyond maxInternalSteps(h) internal steps within one call;
//   abandon the call when the stop request is set (checked at every right-hand side,
//   which then reports an unrecoverable failure to the method): status interrupted.
//
// Counters survive restarts (SUNDIALS resets its own). A failure names the SUNDIALS error
// and the body and quantity with the largest weighted local error (or the non-finite
// derivative). Not here: the methods' set-up (core/sundials_cvode.cpp,
// core/sundials_arkode.cpp), divergence checks.
#pragma once

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <limits>
#include <string>
#include <vector>

#include "core/integrator.hpp"
#include "core/sundials_system.hpp"

namespace tribo {

class SundialsStepper : public Integrator {
 public:
  // Internal steps allowed within one call of length h before it fails as "too much work":
  // 10^4 + h / (1 us), i.e. an average internal step below a microsecond.
  static long maxInternalSteps(double h) { return 10000 + static_cast<long>(1e6 * h); }
  static constexpr int kMaxEventRestarts = 100;

  SundialsStepper(const Model& model, std::string name);
  ~SundialsStepper() override;
  SundialsStepper(const SundialsStepper&) = delete;
  SundialsStepper& operator=(const SundialsStepper&) = delete;

  IntegratorStatus step(Dynamics& dynamics, State& state, double h, bool start_is_evaluated) final;
  int evaluationsPerStep() const final { return 0; }

 protected:
  enum class Advance { kReached, kStop, kRoot, kFailed };
  struct Stats {
    long steps = 0;
    long rejected = 0;
  };

  // Creates (first time) or re-initializes the method at (t0, y_), with a first internal step
  // of initial_step (0: the method's own estimate).
  virtual void start(double t0, double initial_step) = 0;
  // Frees the method's memory so that the next start() creates it for a y of a new length.
  virtual void discard() = 0;
  // The last internal step taken [s] (0 before the first).
  virtual double lastStep() = 0;
  // Integrates towards tout, no internal step passing `stop` (a stop time: kStop when reached
  // before tout) unless it is kNoStop; y_ then holds y(t).
  virtual Advance advance(double tout, double stop, double& t) = 0;
  static constexpr double kNoStop = std::numeric_limits<double>::infinity();
  // Internal steps allowed per advance() call.
  virtual void setMaxSteps(long steps) = 0;
  // Statistics since the last start().
  virtual Stats statistics() = 0;
  // Index of the component with the largest weighted local error of the last step, or -1.
  virtual int worstComponent() = 0;
  // True when the last failure came from the right-hand side.
  virtual bool failedInRhs() const = 0;

  // For the derived classes' SUNDIALS set-up.
  static int rhsCallback(double t, N_Vector y, N_Vector ydot, void* self);
  static int rootCallback(double t, N_Vector y, double* g, void* self);
  static void errorCallback(int code, const char* module, const char* function, char* message,
                            void* self);
  void fail(const std::string& what);  // records a set-up error (reported by the next step)
  // Index of the largest |error_i * weight_i|, -1 if none is finite and > 0.
  static int largestWeighted(N_Vector error, N_Vector weight);

  const SimulationOptions options_;
  OdeSystem system_;
  SUNContext context_ = nullptr;
  N_Vector y_ = nullptr;
  std::string last_error_;
  bool interrupted_ = false;  // the right-hand side saw the stop request in this call

 private:
  void restart(double t0, bool at_event);
  // The stop time for a call from `now` to `tout`: the first breakpoint after now (within
  // 64 eps of tout: tout itself), or kNoStop. The method's stop time is set at every advance
  // once the model has a breakpoint (past the last one: the largest double).
  double nextStop(double now, double tout) const;
  IntegratorStatus failure(double t, const std::string& what);

  const std::string name_;
  bool running_ = false;  // false: the next call restarts
  State last_out_;
  Stats done_;  // accumulated over earlier starts
  std::string setup_error_;
  std::vector<double> breakpoints_;  // the model's input breakpoints, increasing
};

}  // namespace tribo
