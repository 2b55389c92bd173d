#include "core/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tribo {

Simulator::Simulator(std::shared_ptr<const Model> model)
    : dynamics_(std::move(model)),
      integrator_(makeIntegrator(dynamics_.model().options.integrator, dynamics_.model())),
      state_(dynamics_.initialState()),
      last_good_(state_) {}

void Simulator::setState(const State& state) {
  state_ = state;
  evaluated_ = false;
}

const Workspace& Simulator::current() {
  if (!evaluated_) {
    dynamics_.evaluate(state_);
    evaluated_ = true;
  }
  return dynamics_.workspace();
}

StepStatus Simulator::step() {
  last_good_ = state_;
  integrator_->step(dynamics_, state_, model().options.time_step, evaluated_);
  evaluated_ = false;
  ++stats_.steps;
  StepStatus status = check();
  if (!status.ok) {
    state_ = last_good_;
    evaluated_ = false;
  }
  return status;
}

StepStatus Simulator::check() {
  const Model& m = model();
  auto fail = [&](const std::string& what) {
    std::ostringstream s;
    s << "diverged at step " << stats_.steps << " (t = " << state_.time << " s): " << what;
    return StepStatus{false, s.str()};
  };
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const BodyState& s = state_.bodies[b];
    const std::string who = "body '" + m.bodies[b].name + "' ";
    if (!s.position.allFinite()) return fail(who + "position is not finite");
    if (!s.orientation.coeffs().allFinite()) return fail(who + "orientation is not finite");
    if (!s.velocity.allFinite()) return fail(who + "velocity is not finite");
    if (!s.angular_velocity.allFinite()) return fail(who + "angular velocity is not finite");
  }
  const Workspace& ws = current();
  for (const auto& c : ws.contacts) {
    const ContactPair& pair = m.contact_pairs[c.point.pair];
    for (int g : {pair.geometry_a, pair.geometry_b}) {
      const double size = m.geometries[g].shape.size();
      if (c.point.depth > size) {
        std::ostringstream s;
        s << "penetration " << c.point.depth << " m into geometry '" << m.geometries[g].name
          << "' exceeds its size " << size << " m (contact too soft or step too large)";
        return fail(s.str());
      }
    }
    if (!std::isfinite(c.normal_force) || !c.friction_force.allFinite())
      return fail("contact force on geometry '" + m.geometries[pair.geometry_b].name +
                  "' is not finite");
  }
  stats_.contact_count = static_cast<int>(ws.contacts.size());
  stats_.max_penetration = std::max(stats_.max_penetration, ws.max_penetration);
  stats_.max_constraint_error = std::max(stats_.max_constraint_error, ws.max_constraint_error);
  stats_.max_constraint_rate_error =
      std::max(stats_.max_constraint_rate_error, ws.max_constraint_rate_error);
  return {};
}

}  // namespace tribo
