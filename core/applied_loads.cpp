#include "core/applied_loads.hpp"

#include <algorithm>

namespace tribo {

AppliedLoads::AppliedLoads(const Model& model) {
  for (const AppliedLoad& load : model.loads) {
    entries_.push_back({&load, SignalVectorMemo(load.force), SignalVectorMemo(load.torque),
                        load.point == Vec3::Zero()});
    if (std::find(loaded_bodies_.begin(), loaded_bodies_.end(), load.body.value) ==
        loaded_bodies_.end())
      loaded_bodies_.push_back(load.body.value);
  }
}

void AppliedLoads::setOffset(std::size_t load, const Vec3& force, const Vec3& torque) {
  if (offsets_.empty()) offsets_.assign(entries_.size(), {});
  offsets_.at(load) = {force, torque};
}

void AppliedLoads::setCommand(std::size_t load, const std::optional<Vec3>& force,
                              const std::optional<Vec3>& torque) {
  if (commands_.empty()) commands_.assign(entries_.size(), {});
  commands_.at(load) = {force, torque};
}

void AppliedLoads::accumulate(const State& state, Workspace& ws) {
  for (const int b : loaded_bodies_) ws.load_wrench[static_cast<std::size_t>(b)].setZero();
  const double t = state.time;
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    Entry& e = entries_[i];
    const AppliedLoad& load = *e.load;
    const auto b = static_cast<std::size_t>(load.body.value);
    const Vec3& origin = state.bodies[b].position;
    const Mat3& r = ws.rotation[b];
    const bool follower = load.frame == LoadFrame::kBody;
    Wrench& on = ws.load_wrench[b];
    if (!offsets_.empty() || !commands_.empty()) {  // commanded or perturbed: in full
      const Command* command = commands_.empty() ? nullptr : &commands_[i];
      Vec3 force = command && command->force ? *command->force : e.force.at(t);
      Vec3 torque = command && command->torque ? *command->torque : e.torque.at(t);
      if (follower) {
        force = r * force;
        torque = r * torque;
      }
      const Vec3 point = origin + r * load.point;
      const Mat3 frame = follower ? r : Mat3::Identity();
      if (!offsets_.empty()) {
        force += frame * offsets_[i].force;
        torque += frame * offsets_[i].torque;
      }
      on.force += force;
      on.torque += (point - origin).cross(force);
      on.torque += torque;
      ws.load_force[i] = force;
      continue;
    }
    const Vec3 force = follower ? Vec3(r * e.force.at(t)) : e.force.at(t);
    if (!e.force.zero()) {
      on.force += force;
      if (!e.at_origin) {
        const Vec3 point = origin + r * load.point;
        on.torque += (point - origin).cross(force);
      }
    }
    if (!e.torque.zero()) on.torque += follower ? Vec3(r * e.torque.at(t)) : e.torque.at(t);
    ws.load_force[i] = force;
  }
}

}  // namespace tribo
