// The equations of motion as the first-order system y' = f(t, y) that the SUNDIALS
// integrators see, and the event functions they locate.
//
//   y = [p (3), q (4, order x y z w), v (3), w (3)] per dynamic body     (13 values each)
//       then the internal states of dynamic friction laws (State::friction_values)
//   f = [v, 0.5 [0, w] (x) q, a, alpha]       a, alpha from Dynamics::evaluate
//       then dz/dt (Workspace::friction_state_rate)
// The friction states' records (which contact owns which values) are those of the segment
// start: y's length follows their count, so a change of the records restarts the method.
// q is normalized before each force evaluation but the integrator's copy is left alone: the
// quaternion rate is linear in q with a skew matrix, so |q| stays constant up to the local
// error, and the stepper restarts from a normalized q when it drifts. Kinematic bodies are
// not in y: they follow their constant velocities from their pose at the segment start,
// p = p0 + v (t - t0), q = exp((t - t0) w) q0.
//
// Events (friction regime changes), a fixed number per contact pair so that root finding
// can track them through contacts appearing and vanishing:
//   g = s_max - s_k      for each speed s_k of {stickSpeed} and the law's breakpoints
//                        (s_max: largest slip speed over the pair's points, 0 out of contact)
//   g = mean_i(s_i . d) + 1e-12 m/s   slip along the pair's reference direction d (its first
//                        non-zero slip direction): changes sign when the slip reverses (the
//                        offset keeps an exactly sticking contact from making g vanish
//                        identically); +1 m/s out of contact
// Event values are kept from the last force evaluation, so evaluating g where f was just
// evaluated (the end of an explicit step) costs nothing.
// Not here: the integration itself (core/sundials_stepper.hpp), divergence checks.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/dynamics.hpp"

namespace tribo {

class OdeSystem {
 public:
  static constexpr int kPerBody = 13;

  OdeSystem(const Model& model, bool events);

  // Length of y for the segment begun last, and for a segment starting at `state`.
  int size() const { return kPerBody * static_cast<int>(dynamic_.size()) + values_; }
  int sizeFor(const State& state) const {
    return kPerBody * static_cast<int>(dynamic_.size()) +
           static_cast<int>(state.friction_values.size());
  }
  int eventCount() const { return events_ ? event_count_ : 0; }

  // The Dynamics to evaluate with (must outlive the calls that follow).
  void attach(Dynamics& dynamics) { dynamics_ = &dynamics; }
  // Starts a segment at `state`: fills y, takes the kinematic bodies' poses from it, and
  // fixes the reference slip direction of pairs that have none yet from `ws` (the evaluation
  // at `state`).
  void begin(const State& state, const Workspace& ws, double* y);
  // The state at (t, y): dynamic bodies from y (q normalized), kinematic ones from the
  // segment start. `out` must have one BodyState per model body.
  void unpack(double t, const double* y, State& out) const;
  // y' = f(t, y). Returns false when a derivative is not finite (see badComponent()).
  bool rhs(double t, const double* y, double* ydot);
  // Event functions g(t, y), eventCount() values; all +1 while events are suspended.
  void events(double t, const double* y, double* g);
  void suspendEvents(bool suspend) { suspended_ = suspend; }
  bool eventsSuspended() const { return suspended_; }

  // Largest | |q| - 1 | over the bodies in y, and the normalization of every q in y.
  double quaternionDrift(const double* y) const;
  void normalizeQuaternions(double* y) const;

  long evaluations() const { return evaluations_; }
  // Index into y of the first non-finite derivative of the last failed rhs(), or -1.
  int badComponent() const { return bad_component_; }
  // The body and quantity of component i of y, e.g. {"box", "velocity.z"}.
  std::pair<std::string, std::string> componentName(int i) const;

 private:
  struct PairEvents {
    std::vector<double> speeds;  // s_k, ascending
    Vec3 direction = Vec3::UnitX();
    bool direction_known = false;
  };

  void eventValues(const Workspace& ws, double* g);

  const Model& model_;
  const bool events_;
  Dynamics* dynamics_ = nullptr;
  std::vector<int> dynamic_;  // model body index of each block of y
  State base_;                // segment start (kinematic bodies' poses)
  State scratch_;             // the state of the current evaluation
  PairSlots slots_;           // events only: per pair
  std::vector<PairEvents> pairs_;
  int event_count_ = 0;
  // Event values at the last evaluation, and where it was.
  std::vector<double> cached_g_, cached_y_;
  double cached_t_ = 0.0;
  bool cache_valid_ = false;
  bool suspended_ = false;
  std::vector<double> max_slip_, signed_slip_;
  std::vector<int> points_;
  long evaluations_ = 0;
  int bad_component_ = -1;
  int values_ = 0;  // friction-state values in y (after the bodies)
};

}  // namespace tribo
