#include "study/trajectory_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/constraint_rows.hpp"
#include "core/energy.hpp"
#include "core/joint_forces.hpp"
#include "friction/dynamic_law.hpp"

namespace tribo::study {

TrajectoryRecorder::TrajectoryRecorder(const Model& model, std::size_t expected_rows,
                                       bool keep_rows, const std::vector<std::string>& groups)
    : model_(model), keep_rows_(keep_rows), names_(io::channelColumns(model, groups)) {
  position_ = io::hasGroup(groups, "position");
  orientation_ = io::hasGroup(groups, "orientation");
  rpy_ = io::hasGroup(groups, "rpy");
  velocity_ = io::hasGroup(groups, "velocity");
  angular_velocity_ = io::hasGroup(groups, "angular_velocity");
  contact_ = io::hasGroup(groups, "contact");
  friction_force_ = io::hasGroup(groups, "friction");
  resistance_ = io::hasGroup(groups, "resistance");
  pairs_ = io::hasGroup(groups, "pairs");
  pair_resistance_ = io::hasGroup(groups, "pair_resistance");
  joints_ = io::hasGroup(groups, "joints");
  friction_states_ = io::hasGroup(groups, "friction_states");
  energy_ = io::hasGroup(groups, "energy");
  loads_ = io::hasGroup(groups, "loads");
  if (io::hasGroup(groups, "actuators"))
    for (int j = 0; j < static_cast<int>(model.joints.size()); ++j)
      if (model.joints[static_cast<std::size_t>(j)].elements.actuator)
        actuated_joints_.push_back(j);
  for (int j = 0; j < static_cast<int>(model.joints.size()); ++j)
    if (joints_ && hasScalarCoordinate(model.joints[static_cast<std::size_t>(j)].type))
      joints_recorded_.push_back({j, jointCoordinate(model.joints[static_cast<std::size_t>(j)])});
  if (pairs_ || pair_resistance_ || friction_states_) slots_ = PairSlots(model);
  const std::size_t pairs = slots_.size();
  if (pairs_) {
    pair_normal_.resize(pairs);
    pair_slip_.resize(pairs);
    pair_friction_.resize(pairs);
  }
  if (pair_resistance_) {
    pair_dissipation_.resize(pairs);
    pair_slip_load_.resize(pairs);
    pair_moment_.resize(pairs);
  }
  if (friction_states_) {
    // The same order as io::channelColumns: joints, then pairs.
    const std::vector<int> offsets = jointFrictionStateOffsets(model);
    for (std::size_t j = 0; j < model.joints.size(); ++j)
      if (offsets[j] >= 0)
        joint_states_.emplace_back(offsets[j],
                                   model.joints[j].elements.friction->law->dynamic()->stateSize());
    int next = 0;
    for (const ContactPair& p : slots_.pairs()) {
      const friction::DynamicFrictionLaw* law =
          model.materials[static_cast<std::size_t>(p.material)].friction->dynamic();
      pair_state_offset_.push_back(next);
      pair_state_size_.push_back(law != nullptr ? law->stateSize() : 0);
      next += pair_state_size_.back();
    }
    pair_state_.resize(static_cast<std::size_t>(next));
    pair_points_.resize(pairs);
  }
  friction_.resize(model.bodies.size());
  moment_.resize(model.bodies.size());
  data_.resize(names_.size());
  if (keep_rows_)
    for (auto& col : data_) col.reserve(std::min(expected_rows, kMaxReservedRows));
  row_.resize(names_.size());
  slip_.resize(model.bodies.size());
  normal_.resize(model.bodies.size());
}

std::size_t TrajectoryRecorder::columnIndex(const std::string& name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end()) throw std::out_of_range("no trajectory column '" + name + "'");
  return static_cast<std::size_t>(it - names_.begin());
}

void TrajectoryRecorder::record(const State& state, const Workspace& ws) {
  if (contact_ || friction_force_ || resistance_) {
    std::fill(slip_.begin(), slip_.end(), 0.0);
    std::fill(normal_.begin(), normal_.end(), 0.0);
    std::fill(friction_.begin(), friction_.end(), Vec3::Zero());
    std::fill(moment_.begin(), moment_.end(), Vec3::Zero());
    for (const auto& c : ws.contacts) {
      const ContactPair pair = model_.contactPair(c.point.pair);
      for (const auto& [g, sign] : {std::pair{pair.geometry_a, -1.0}, {pair.geometry_b, 1.0}}) {
        const BodyIndex b = model_.geometries[g].body;
        if (b.isWorld()) continue;
        slip_[b.value] = std::max(slip_[b.value], c.slip.stableNorm());
        normal_[b.value] += c.normal_force;
        friction_[b.value] += sign * c.friction_force;
        moment_[b.value] += sign * c.moment;
      }
    }
  }
  if (pairs_) {
    std::fill(pair_normal_.begin(), pair_normal_.end(), 0.0);
    std::fill(pair_slip_.begin(), pair_slip_.end(), 0.0);
    std::fill(pair_friction_.begin(), pair_friction_.end(), Vec3::Zero());
    for (const auto& c : ws.contacts) {
      const auto p = static_cast<std::size_t>(slots_.slot(c.point.pair));
      pair_normal_[p] += c.normal_force;
      pair_friction_[p] += c.friction_force;
      pair_slip_[p] = std::max(pair_slip_[p], c.slip.stableNorm());
    }
  }
  if (pair_resistance_) {
    std::fill(pair_dissipation_.begin(), pair_dissipation_.end(), 0.0);
    std::fill(pair_slip_load_.begin(), pair_slip_load_.end(), 0.0);
    std::fill(pair_moment_.begin(), pair_moment_.end(), Vec3::Zero());
    for (const auto& c : ws.contacts) {
      const auto p = static_cast<std::size_t>(slots_.slot(c.point.pair));
      pair_moment_[p] += c.moment;
      // A slipping point: its friction's part against its own slip direction, and its load.
      const double slip = c.slip.stableNorm();
      if (slip == 0.0 || !(c.normal_force > 0.0)) continue;
      pair_dissipation_[p] -= c.friction_force.dot(c.slip / slip);
      pair_slip_load_[p] += c.normal_force;
    }
  }
  if (friction_states_) {
    // Records used by a contact point at this evaluation; their states as stored.
    std::fill(pair_state_.begin(), pair_state_.end(), 0.0);
    std::fill(pair_points_.begin(), pair_points_.end(), 0);
    for (std::size_t r = 0; r < state.friction_states.size(); ++r) {
      if (r >= ws.friction_state_contact.size() || ws.friction_state_contact[r] < 0) continue;
      const contact::FrictionStateRecord& rec = state.friction_states[r];
      const auto p = static_cast<std::size_t>(slots_.slot(contact::keyPair(rec.key)));
      const double* z = &state.friction_values[static_cast<std::size_t>(rec.state)];
      for (int i = 0; i < pair_state_size_[p]; ++i)
        pair_state_[static_cast<std::size_t>(pair_state_offset_[p] + i)] += z[i];
      ++pair_points_[p];
    }
  }
  std::size_t col = 0;
  row_[col++] = state.time;
  for (std::size_t b = 0; b < state.bodies.size(); ++b) {
    const BodyState& s = state.bodies[b];
    if (position_)
      for (int i = 0; i < 3; ++i) row_[col++] = s.position[i];
    if (orientation_) {
      row_[col++] = s.orientation.w();
      for (int i = 0; i < 3; ++i) row_[col++] = s.orientation.vec()[i];
    }
    if (rpy_) {  // R = Rz(yaw) Ry(pitch) Rx(roll)
      const Mat3 r = s.orientation.toRotationMatrix();
      row_[col++] = std::atan2(r(2, 1), r(2, 2));
      row_[col++] = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
      row_[col++] = std::atan2(r(1, 0), r(0, 0));
    }
    if (velocity_)
      for (int i = 0; i < 3; ++i) row_[col++] = s.velocity[i];
    if (angular_velocity_)
      for (int i = 0; i < 3; ++i) row_[col++] = s.angular_velocity[i];
    if (contact_) {
      row_[col++] = slip_[b];
      row_[col++] = normal_[b];
    }
    if (friction_force_) row_[col++] = friction_[b].stableNorm();
    if (resistance_) row_[col++] = moment_[b].stableNorm();
  }
  if (pairs_)
    for (std::size_t p = 0; p < pair_normal_.size(); ++p) {
      row_[col++] = pair_normal_[p];
      row_[col++] = pair_friction_[p].stableNorm();
      row_[col++] = pair_slip_[p];
    }
  if (pair_resistance_)
    for (std::size_t p = 0; p < pair_moment_.size(); ++p) {
      // No slipping point under load: no direction to take the coefficient in. A finite force
      // on a vanishing load saturates at the largest double rather than overflow.
      const double load = pair_slip_load_[p];
      const double mu = load > 0.0 ? pair_dissipation_[p] / load : 0.0;
      row_[col++] = std::isfinite(mu) ? mu : std::copysign(std::numeric_limits<double>::max(), mu);
      row_[col++] = pair_moment_[p].stableNorm();
    }
  if (joints_) {
    const MotionView motion(state, ws.rotation);
    for (const RecordedJoint& j : joints_recorded_) {
      CoordinateValue v;
      evaluateCoordinate(j.coordinate, motion(j.coordinate.parent), motion(j.coordinate.child), v);
      row_[col++] = v.q;
      row_[col++] = v.rate;
      row_[col++] = ws.joint_friction[static_cast<std::size_t>(j.joint)];
    }
  }
  if (friction_states_) {
    for (const auto& [offset, size] : joint_states_)
      for (int i = 0; i < size; ++i)
        row_[col++] = state.friction_values[static_cast<std::size_t>(offset + i)];
    for (std::size_t p = 0; p < pair_state_size_.size(); ++p) {
      const double n = pair_points_[p] > 0 ? pair_points_[p] : 1.0;
      for (int i = 0; i < pair_state_size_[p]; ++i)
        row_[col++] = pair_state_[static_cast<std::size_t>(pair_state_offset_[p] + i)] / n;
    }
  }
  if (energy_) {
    const EnergyAccount e = measureEnergy(model_, state, ws);
    row_[col++] = e.kinetic;
    row_[col++] = e.gravity;
    row_[col++] = e.elastic;
    row_[col++] = e.input_power;
  }
  if (loads_)
    for (const Vec3& f : ws.load_force)
      for (int i = 0; i < 3; ++i) row_[col++] = f[i];
  for (const int j : actuated_joints_) {
    const ActuatorOutput& a = ws.actuator_output[static_cast<std::size_t>(j)];
    row_[col++] = a.target;
    row_[col++] = a.effort;
    row_[col++] = a.saturated ? 1.0 : 0.0;
  }
  for (RowSink* sink : sinks_) sink->row(row_);
  if (keep_rows_)
    for (std::size_t c = 0; c < row_.size(); ++c) data_[c].push_back(row_[c]);
  ++rows_;
}

}  // namespace tribo::study
