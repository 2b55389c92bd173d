#include "core/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/flush_denormals.hpp"

namespace tribo {

Simulator::Simulator(std::shared_ptr<const Model> model)
    : dynamics_(std::move(model)),
      integrator_(makeIntegrator(dynamics_.model().options.integrator, dynamics_.model())),
      state_(dynamics_.initialState()),
      last_good_(state_),
      energy_(makeEnergyGuard()) {}

void Simulator::setState(const State& state) {
  state_ = state;
  evaluated_ = false;
  energy_ = makeEnergyGuard();
}

const Workspace& Simulator::current() {
  if (!evaluated_) {
    dynamics_.evaluate(state_);
    ++own_evaluations_;
    evaluated_ = true;
  }
  return dynamics_.workspace();
}

StepStatus Simulator::step() {
  const ScopedFlushDenormals flush;  // core/flush_denormals.hpp: why
  if (!energy_.started()) energy_.reset(state_, current());
  last_good_ = state_;
  const IntegratorStatus integrated =
      integrator_->step(dynamics_, state_, model().options.time_step, evaluated_);
  if (integrated.ok) dynamics_.projectConstraints(state_);  // no-op unless enabled
  evaluated_ = false;
  ++stats_.steps;
  StepStatus status =
      integrated.ok ? check()
                    : failed(integrated.body, "integrator", integrated.message, integrated.time);
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
  if (dynamics_.hasStatefulFriction() && dynamics_.advanceFrictionStates(state_))
    evaluated_ = false;
  return status;
}

EnergyGuard Simulator::makeEnergyGuard() const {
  const SimulationOptions& o = model().options;
  return EnergyGuard(model(),
                     o.integrator == IntegratorType::kSemiImplicitEuler ? o.time_step : 0.0);
}

StepStatus Simulator::failed(const std::string& body, const std::string& quantity,
                             const std::string& what, double time) const {
  const double t = std::isnan(time) ? state_.time : time;
  std::ostringstream s;
  s << "diverged at step " << stats_.steps << " (t = " << t << " s): " << what;
  return {false, s.str(), t, body, quantity};
}

StepStatus Simulator::check() {
  const Model& m = model();
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const BodyState& s = state_.bodies[b];
    const std::string& name = m.bodies[b].name;
    const std::string who = "body '" + name + "' ";
    if (!s.position.allFinite()) return failed(name, "position", who + "position is not finite");
    if (!s.orientation.coeffs().allFinite())
      return failed(name, "orientation", who + "orientation is not finite");
    if (!s.velocity.allFinite()) return failed(name, "velocity", who + "velocity is not finite");
    if (!s.angular_velocity.allFinite())
      return failed(name, "angular_velocity", who + "angular velocity is not finite");
  }
  const Workspace& ws = current();
  for (const auto& c : ws.contacts) {
    const ContactPair& pair = m.contact_pairs[c.point.pair];
    for (int g : {pair.geometry_a, pair.geometry_b}) {
      const double size = m.geometries[g].shape.size();
      if (c.point.depth > size) {
        const BodyIndex b = m.geometries[g].body;
        const std::string body = b.isWorld() ? "world" : m.bodies[b.value].name;
        std::ostringstream s;
        s << "body '" << body << "' penetration " << c.point.depth << " m into geometry '"
          << m.geometries[g].name << "' exceeds its size " << size
          << " m (contact too soft or step too large)";
        return failed(body, "penetration", s.str());
      }
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
    return failed(energy.body, "energy", s.str());
  }
  if (!ws.joint_friction_converged && stats_.joint_friction_unconverged++ == 0)
    stats_.first_unconverged_time = state_.time;
  stats_.contact_count = static_cast<int>(ws.contacts.size());
  stats_.max_penetration = std::max(stats_.max_penetration, ws.max_penetration);
  stats_.max_constraint_error = std::max(stats_.max_constraint_error, ws.max_constraint_error);
  stats_.max_constraint_rate_error =
      std::max(stats_.max_constraint_rate_error, ws.max_constraint_rate_error);
  return {};
}

}  // namespace tribo
