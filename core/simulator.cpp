#include "core/simulator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/flush_denormals.hpp"
#include "core/prescribed_motion.hpp"

namespace tribo {

Simulator::Simulator(std::shared_ptr<const Model> model)
    : dynamics_(std::move(model)),
      integrator_(makeIntegrator(dynamics_.model().options.integrator, dynamics_.model())),
      state_(dynamics_.initialState()),
      last_good_(state_),
      energy_(makeEnergyGuard()),
      choice_(dynamics_.model().options.threads == kAutoThreads ? dynamics_.mostThreads() : 1) {
  stats_.most_threads = dynamics_.mostThreads();
  thinnest_.reserve(dynamics_.model().geometries.size());
  for (const Geometry& g : dynamics_.model().geometries) {
    thinnest_.push_back(g.shape.thinnestHalfWidth());
    thinnest_of_all_ = std::min(thinnest_of_all_, thinnest_.back());
  }
}

void Simulator::setState(const State& state) {
  state_ = state;
  evaluated_ = false;
  energy_ = makeEnergyGuard();
}

void Simulator::setActuatorCommand(int joint, double command) {
  if (std::isinf(command))
    throw std::invalid_argument("actuator command must be finite (or NaN for the signal)");
  if (!dynamics_.setActuatorCommand(joint, command))
    throw std::invalid_argument("joint " + std::to_string(joint) + " has no actuator");
  evaluated_ = false;
}

void Simulator::setLoadCommand(std::size_t load, const std::optional<Vec3>& force,
                               const std::optional<Vec3>& torque) {
  if (load >= model().loads.size())
    throw std::invalid_argument("load " + std::to_string(load) + " of " +
                                std::to_string(model().loads.size()));
  if ((force && !force->allFinite()) || (torque && !torque->allFinite()))
    throw std::invalid_argument("load '" + model().loads[load].name +
                                "': a commanded force or torque must be finite");
  dynamics_.setLoadCommand(load, force, torque);
  evaluated_ = false;
}

const Workspace& Simulator::current() {
  if (!evaluated_) {
    dynamics_.evaluate(state_, /*point_energy=*/true);  // the evaluation the guard reads
    ++own_evaluations_;
    evaluated_ = true;
  }
  return dynamics_.workspace();
}

void Simulator::setProfiling(bool on) {
  if (on && !profiling_) stats_.profile = {};
  profiling_ = on;
  dynamics_.setProfiling(on);
}

void Simulator::pinThreads(int threads) {
  choice_ = ThreadChoice();
  useThreads(threads);
}

void Simulator::useThreads(int threads) {
  dynamics_.useThreads(threads);
  energy_.setThreads(dynamics_.threads());
}

StepStatus Simulator::step() {
  const bool threaded = dynamics_.threads() > 1;
  const bool timed = profiling_ || choice_.measuring();
  const auto start =
      timed ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
  StepStatus status = advance();
  if (threaded && !status.interrupted) ++stats_.threaded_steps;
  if (!timed) return status;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (choice_.measuring()) {
    choice_.record(seconds);
    if (choice_.threads() != dynamics_.threads()) useThreads(choice_.threads());
  }
  if (profiling_) {
    const double step_seconds = stats_.profile.step + seconds;
    stats_.profile = dynamics_.profile();
    stats_.profile.step = step_seconds;
  }
  return status;
}

StepStatus Simulator::advance() {
  const ScopedFlushDenormals flush;  // core/flush_denormals.hpp: why
  if (!energy_.started()) energy_.reset(state_, current());
  last_good_ = state_;
  // Dynamic friction: every contact point of the evaluation at the step's start gets its
  // internal state's record before the integrator carries the states with the bodies.
  if (dynamics_.frictionMemory().dynamic()) {
    current();
    if (dynamics_.beforeStep(state_)) evaluated_ = false;
  }
  const IntegratorStatus integrated =
      integrator_->step(dynamics_, state_, model().options.time_step, evaluated_);
  if (integrated.ok) {
    // Kinematic bodies along signals end the step exactly where their signals put them.
    placePrescribedBodies(model().bodies, dynamics_.prescribedBodies(), state_);
    dynamics_.projectConstraints(state_);  // no-op unless enabled
  }
  evaluated_ = false;
  StepStatus status;
  if (integrated.interrupted) {
    status = {false, integrated.message, integrated.time, "", "interrupted", true};
  } else {
    ++stats_.steps;
    status = integrated.ok
                 ? check()
                 : failed(integrated.body, "integrator", integrated.message, integrated.time);
  }
  const IntegratorCounters& c = integrator_->counters();
  stats_.integrator_steps = c.steps;
  stats_.rejected_steps = c.rejected_steps;
  stats_.events = c.events;
  stats_.last_event_time = c.last_event_time;
  stats_.evaluations = c.evaluations + own_evaluations_;
  if (!status.ok) {
    state_ = last_good_;
    evaluated_ = false;
    energy_ = makeEnergyGuard();
    return status;
  }
  // Advance friction states: stateful laws decide from the evaluation at the new state;
  // when their anchors move, the next evaluation must see them.
  if (dynamics_.frictionMemory().stateful() && dynamics_.afterStep(state_)) evaluated_ = false;
  return status;
}

EnergyGuard Simulator::makeEnergyGuard() const {
  const SimulationOptions& o = model().options;
  return EnergyGuard(model(),
                     o.integrator == IntegratorType::kSemiImplicitEuler ? o.time_step : 0.0,
                     dynamics_.threads());
}

StepStatus Simulator::failed(const std::string& body, const std::string& quantity,
                             const std::string& what, double time) const {
  const double t = std::isnan(time) ? state_.time : time;
  std::ostringstream s;
  s << "diverged at step " << stats_.steps << " (t = " << t << " s): " << what;
  return {false, s.str(), t, body, quantity, false};
}

namespace {

// Geometry g's half width along contact point i's normal (Shape::extent).
double halfWidth(const Model& m, const Workspace& ws, std::size_t i, int g) {
  const Geometry& geometry = m.geometries[static_cast<std::size_t>(g)];
  const Mat3 r = geometry.body.isWorld()
                     ? geometry.local_pose.linear()
                     : Mat3(ws.rotation[geometry.body.value] * geometry.local_pose.linear());
  return geometry.shape.extent(r.transpose() * ws.contacts[i].point.normal);
}

}  // namespace

StepStatus Simulator::check() {
  const Model& m = model();
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const BodyState& s = state_.bodies[b];
    // The message is built only on failure: a warm step does not allocate.
    const char* quantity = !s.position.allFinite()               ? "position"
                           : !s.orientation.coeffs().allFinite() ? "orientation"
                           : !s.velocity.allFinite()             ? "velocity"
                           : !s.angular_velocity.allFinite()     ? "angular_velocity"
                                                                 : nullptr;
    if (quantity != nullptr) {
      const std::string& name = m.bodies[b].name;
      std::string words = quantity;
      std::replace(words.begin(), words.end(), '_', ' ');
      return failed(name, quantity, "body '" + name + "' " + words + " is not finite");
    }
  }
  if (dynamics_.frictionMemory().dynamic()) {
    std::string body;
    if (std::string what = dynamics_.frictionMemory().nonFinite(state_, body); !what.empty())
      return failed(body, "friction_state", what);
  }
  const Workspace& ws = current();
  // When the deepest point (ws.max_penetration) is within every geometry's bound, no point
  // needs a width measured and the pass reads the forces alone: the same outcome, for a
  // point whose depth passes no bound is skipped below (a NaN depth passes none either).
  // And when the points' pass found every force finite (Workspace::forces_finite), the pass
  // has nothing left to find.
  const bool some_deep = ws.max_penetration > thinnest_of_all_;
  const std::size_t points = some_deep || !ws.forces_finite ? ws.contacts.size() : 0;
  for (std::size_t i = 0; i < points; ++i) {
    const contact::ContactRecord& c = ws.contacts[i];
    const ContactPair& pair = ws.contact_pair[i];
    // Deeper than the geometry's half width along the normal: a warning (recorded here,
    // worded after the run), not a stop; a contact that is failing shows as energy rising.
    // No shallower contact needs the width (Shape::thinnestHalfWidth bounds it from below).
    if (some_deep)
      for (int g : {pair.geometry_a, pair.geometry_b}) {
        if (!(c.point.depth > thinnest_[static_cast<std::size_t>(g)])) continue;
        const double extent = halfWidth(m, ws, i, g);
        if (c.point.depth > extent && c.point.depth / extent > stats_.deepest_ratio) {
          if (stats_.deep_penetrations == 0) stats_.first_deep_time = state_.time;
          stats_.deepest_ratio = c.point.depth / extent;
          stats_.deepest_geometry = g;
          stats_.deepest_depth = c.point.depth;
          stats_.deepest_extent = extent;
        }
        if (c.point.depth > extent) ++stats_.deep_penetrations;
      }
    if (!std::isfinite(c.normal_force) || !c.friction_force.allFinite()) {
      const BodyIndex b = m.geometries[pair.geometry_b].body;
      const std::string body = b.isWorld() ? "world" : m.bodies[b.value].name;
      return failed(body, "contact_force",
                    "body '" + body + "' contact force on geometry '" +
                        m.geometries[pair.geometry_b].name + "' is not finite");
    }
  }
  const EnergyVerdict energy = energy_.update(state_, ws);
  if (!energy.ok) {
    std::ostringstream s;
    if (!std::isfinite(energy.rise) || !std::isfinite(energy.available))  // never "nan J"
      s << "body '" << energy.body << "' energy balance not finite since t = " << energy.since
        << " s: a force or its work overflowed (step too large for the stiffest element?)";
    else
      s << "body '" << energy.body << "' energy rising without a source: the mechanical energy "
        << "less the work of sources rose by " << energy.rise << " J since t = " << energy.since
        << " s, more than the " << energy.available
        << " J the system had and received (step too large for the stiffest element?)";
    if (stats_.deep_penetrations > 0) {
      const Geometry& g = m.geometries[stats_.deepest_geometry];
      s << "; geometry '" << g.name << "' penetrated " << stats_.deepest_depth << " m, deeper "
        << "than its half width " << stats_.deepest_extent << " m along the contact normal";
    }
    return failed(energy.body, "energy", s.str());
  }
  if (!ws.joint_friction_converged && stats_.joint_friction_unconverged++ == 0)
    stats_.first_unconverged_time = state_.time;
  if (ws.joint_held >= 0) {
    if (stats_.joint_held++ == 0) stats_.first_held_time = state_.time;
    if (ws.joint_held_change > stats_.joint_held_change) {
      stats_.joint_held_change = ws.joint_held_change;
      stats_.joint_held_worst = ws.joint_held;
    }
  }
  stats_.contact_count = static_cast<int>(ws.contacts.size());
  stats_.max_penetration = std::max(stats_.max_penetration, ws.max_penetration);
  if (ws.max_constraint_error > stats_.max_constraint_error) {
    stats_.max_constraint_error = ws.max_constraint_error;
    stats_.max_constraint_joint = ws.max_constraint_joint;
  }
  if (ws.max_constraint_error > m.options.constraints.drift_stop && ws.max_constraint_joint >= 0) {
    const Joint& j = m.joints[static_cast<std::size_t>(ws.max_constraint_joint)];
    const std::string body = m.bodies[(j.child.isWorld() ? j.parent : j.child).value].name;
    std::ostringstream s;
    s << "joint '" << j.name << "' came apart (constraint drift): its constraint error |Phi| is "
      << ws.max_constraint_error
      << " (m or rad), more than constraints.drift_stop = " << m.options.constraints.drift_stop
      << " (body '" << body
      << "'; a step too large for the mechanism, or a pose near a singular one; "
         "constraints: {projection: true} holds the joints)";
    return failed(body, "constraint_drift", s.str());
  }
  stats_.max_constraint_rate_error =
      std::max(stats_.max_constraint_rate_error, ws.max_constraint_rate_error);
  return {};
}

}  // namespace tribo
