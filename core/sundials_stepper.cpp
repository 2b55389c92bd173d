#include "core/sundials_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/input_breakpoints.hpp"

namespace tribo {

namespace {

constexpr double kQuaternionDrift = 1e-6;  // restart from a normalized q beyond this

// The records of dynamic friction states, by what y depends on (not where they were set).
bool sameRecords(const std::vector<contact::FrictionStateRecord>& a,
                 const std::vector<contact::FrictionStateRecord>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const auto& x, const auto& y) {
    return x.key == y.key && x.state == y.state && x.state_size == y.state_size &&
           x.normal == y.normal && x.axis == y.axis;
  });
}

bool sameState(const State& a, const State& b) {
  if (a.time != b.time || a.bodies.size() != b.bodies.size() ||
      a.stick_anchors != b.stick_anchors || a.friction_values != b.friction_values ||
      !sameRecords(a.friction_states, b.friction_states))
    return false;
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    const BodyState& s = a.bodies[i];
    const BodyState& t = b.bodies[i];
    if (s.position != t.position || s.velocity != t.velocity ||
        s.angular_velocity != t.angular_velocity ||
        s.orientation.coeffs() != t.orientation.coeffs())
      return false;
  }
  return true;
}

}  // namespace

SundialsStepper::SundialsStepper(const Model& model, std::string name)
    : options_(model.options),
      system_(model, model.options.event_location),
      name_(std::move(name)),
      breakpoints_(inputBreakpoints(model)) {
  if (SUNContext_Create(nullptr, &context_) != 0 || !context_)
    throw std::runtime_error(name_ + ": cannot create the SUNDIALS context");
  y_ = N_VNew_Serial(static_cast<sunindextype>(system_.size()), context_);
  if (!y_) {
    SUNContext_Free(&context_);
    throw std::runtime_error(name_ + ": cannot allocate the SUNDIALS state vector");
  }
}

SundialsStepper::~SundialsStepper() {
  if (y_) N_VDestroy(y_);
  if (context_) SUNContext_Free(&context_);
}

int SundialsStepper::rhsCallback(double t, N_Vector y, N_Vector ydot, void* self) {
  auto* me = static_cast<SundialsStepper*>(self);
  if (me->stopRequested()) {  // unrecoverable for the method: it returns at once
    me->interrupted_ = true;
    return -1;
  }
  return me->system_.rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot)) ? 0 : 1;
}

int SundialsStepper::rootCallback(double t, N_Vector y, double* g, void* self) {
  static_cast<SundialsStepper*>(self)->system_.events(t, N_VGetArrayPointer(y), g);
  return 0;
}

void SundialsStepper::errorCallback(int, const char* module, const char* function, char* message,
                                    void* self) {
  std::ostringstream s;
  s << module << "/" << function << ": " << message;
  static_cast<SundialsStepper*>(self)->last_error_ = s.str();
}

void SundialsStepper::fail(const std::string& what) {
  if (setup_error_.empty()) setup_error_ = what;
}

int SundialsStepper::largestWeighted(N_Vector error, N_Vector weight) {
  const double* e = N_VGetArrayPointer(error);
  const double* w = N_VGetArrayPointer(weight);
  int best = -1;
  double largest = 0.0;
  for (sunindextype i = 0; i < N_VGetLength(error); ++i) {
    const double v = std::abs(e[i] * w[i]);
    if (std::isfinite(v) && v > largest) {
      largest = v;
      best = static_cast<int>(i);
    }
  }
  return best;
}

void SundialsStepper::restart(double t0, bool at_event) {
  const double initial_step = at_event ? lastStep() : 0.0;
  const Stats s = statistics();  // zero before the first start
  done_.steps += s.steps;
  done_.rejected += s.rejected;
  ++counters_.restarts;
  start(t0, initial_step);
}

double SundialsStepper::nextStop(double now, double tout) const {
  if (breakpoints_.empty()) return kNoStop;
  const double eps = std::numeric_limits<double>::epsilon();
  const double near_now = 64.0 * eps * std::max(std::abs(now), std::abs(tout));
  const auto next = std::upper_bound(breakpoints_.begin(), breakpoints_.end(), now + near_now);
  if (next == breakpoints_.end()) return std::numeric_limits<double>::max();
  return *next >= tout - near_now && *next <= tout + near_now ? tout : *next;
}

IntegratorStatus SundialsStepper::failure(double t, const std::string& what) {
  running_ = false;
  IntegratorStatus status;
  status.ok = false;
  status.time = t;
  const int component = failedInRhs() ? system_.badComponent() : worstComponent();
  const auto [body, quantity] = system_.componentName(component);
  status.body = body;
  status.quantity = quantity;
  std::ostringstream s;
  s << "integrator " << name_ << " failed: " << what;
  if (!last_error_.empty()) s << " (" << last_error_ << ")";
  if (!body.empty())
    s << "; " << (failedInRhs() ? "non-finite derivative of" : "largest local error in")
      << " body '" << body << "' " << quantity;
  status.message = s.str();
  last_error_.clear();
  return status;
}

IntegratorStatus SundialsStepper::step(Dynamics& dynamics, State& state, double h,
                                       bool start_is_evaluated) {
  if (!setup_error_.empty()) return failure(state.time, setup_error_);
  if (system_.sizeFor(state) == 0) {
    // Nothing to integrate (kinematic bodies only; SUNDIALS refuses an empty system): the
    // bodies move as prescribed, those along signals placed by the Simulator after the step.
    for (std::size_t b = 0; b < state.bodies.size(); ++b) {
      BodyState& s = state.bodies[b];
      s.position += h * s.velocity;
      s.orientation = rotateBy(s.angular_velocity, h, s.orientation);
    }
    state.time += h;
    ++counters_.steps;
    return {};
  }
  system_.attach(dynamics);
  double* y = N_VGetArrayPointer(y_);
  if (system_.eventsSuspended()) {  // chattering in the last call: back on, from a restart
    system_.suspendEvents(false);
    running_ = false;
  }
  if (!running_ || !sameState(state, last_out_) || system_.quaternionDrift(y) > kQuaternionDrift) {
    if (N_VGetLength(y_) != system_.sizeFor(state)) {  // friction-state records came or went
      const Stats s = statistics();
      done_.steps += s.steps;
      done_.rejected += s.rejected;
      discard();
      N_VDestroy(y_);
      y_ = N_VNew_Serial(static_cast<sunindextype>(system_.sizeFor(state)), context_);
      if (!y_) throw std::runtime_error(name_ + ": cannot allocate the SUNDIALS state vector");
      y = N_VGetArrayPointer(y_);
    }
    if (!start_is_evaluated) ++counters_.evaluations;
    const Workspace& ws = start_is_evaluated ? dynamics.workspace() : dynamics.evaluate(state);
    system_.begin(state, ws, y);
    restart(state.time, false);
    if (!setup_error_.empty()) return failure(state.time, setup_error_);
    running_ = true;
  }
  const long own_evaluations = counters_.evaluations - system_.evaluations();
  const long steps_before = done_.steps + statistics().steps;
  const double tout = state.time + h;
  int restarts_here = 0;
  IntegratorStatus status;
  setMaxSteps(maxInternalSteps(h));
  interrupted_ = false;
  double now = state.time;
  for (;;) {
    double t = now;
    const double stop = nextStop(now, tout);
    const Advance result = advance(tout, stop, t);
    if (stop == tout && (result == Advance::kReached || result == Advance::kStop)) {
      system_.normalizeQuaternions(y);  // an input's breakpoint at tout: restart there
      restart(tout, true);
      break;
    }
    if (result == Advance::kReached) break;
    if (result == Advance::kStop) {  // at an input's breakpoint, before tout
      system_.normalizeQuaternions(y);
      restart(t, true);
      now = t;
      continue;
    }
    if (interrupted_) {
      running_ = false;
      last_error_.clear();
      status.ok = false;
      status.interrupted = true;
      status.time = t;
      std::ostringstream what;
      what << "integrator " << name_ << " interrupted at t = " << t << " s";
      status.message = what.str();
      break;
    }
    if (done_.steps + statistics().steps - steps_before > maxInternalSteps(h)) {
      std::ostringstream what;
      what << "more than " << maxInternalSteps(h) << " internal steps from t = " << state.time
           << " s, stopped at " << t << " s (too stiff for the method, or a chattering contact)";
      status = failure(t, what.str());
      break;
    }
    if (result == Advance::kFailed) {
      std::ostringstream what;
      what << "could not advance from t = " << state.time << " s to " << tout << " s, stopped at "
           << t << " s";
      status = failure(t, what.str());
      break;
    }
    ++counters_.events;
    counters_.last_event_time = t;
    system_.normalizeQuaternions(y);
    restart(t, true);
    now = t;
    if (++restarts_here >= kMaxEventRestarts) system_.suspendEvents(true);
  }
  if (status.ok) {
    system_.unpack(tout, y, state);
    state.time = tout;
    last_out_ = state;
  }
  const Stats s = statistics();
  counters_.steps = done_.steps + s.steps;
  counters_.rejected_steps = done_.rejected + s.rejected;
  counters_.evaluations = own_evaluations + system_.evaluations();
  return status;
}

}  // namespace tribo
