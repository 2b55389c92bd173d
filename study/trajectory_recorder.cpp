#include "study/trajectory_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/constraint_rows.hpp"
#include "core/energy.hpp"

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
  joints_ = io::hasGroup(groups, "joints");
  energy_ = io::hasGroup(groups, "energy");
  for (int j = 0; j < static_cast<int>(model.joints.size()); ++j)
    if (joints_ && hasScalarCoordinate(model.joints[static_cast<std::size_t>(j)].type))
      joints_recorded_.push_back(j);
  friction_.resize(model.bodies.size());
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
  if (contact_ || friction_force_) {
    std::fill(slip_.begin(), slip_.end(), 0.0);
    std::fill(normal_.begin(), normal_.end(), 0.0);
    std::fill(friction_.begin(), friction_.end(), Vec3::Zero());
    for (const auto& c : ws.contacts) {
      const ContactPair& pair = model_.contact_pairs[c.point.pair];
      for (const auto& [g, sign] : {std::pair{pair.geometry_a, -1.0}, {pair.geometry_b, 1.0}}) {
        const BodyIndex b = model_.geometries[g].body;
        if (b.isWorld()) continue;
        slip_[b.value] = std::max(slip_[b.value], c.slip.norm());
        normal_[b.value] += c.normal_force;
        friction_[b.value] += sign * c.friction_force;
      }
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
    if (friction_force_) row_[col++] = friction_[b].norm();
  }
  if (joints_) {
    const MotionView motion(state, ws.rotation);
    for (int j : joints_recorded_) {
      const JointCoordinate c = jointCoordinate(model_.joints[static_cast<std::size_t>(j)]);
      CoordinateValue v;
      evaluateCoordinate(c, motion(c.parent), motion(c.child), v);
      row_[col++] = v.q;
      row_[col++] = v.rate;
    }
  }
  if (energy_) {
    const EnergyAccount e = measureEnergy(model_, state, ws);
    row_[col++] = e.kinetic;
    row_[col++] = e.gravity;
    row_[col++] = e.elastic;
    row_[col++] = e.input_power;
  }
  for (RowSink* sink : sinks_) sink->row(row_);
  if (keep_rows_)
    for (std::size_t c = 0; c < row_.size(); ++c) data_[c].push_back(row_[c]);
  ++rows_;
}

}  // namespace tribo::study
