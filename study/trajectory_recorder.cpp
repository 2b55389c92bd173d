#include "study/trajectory_recorder.hpp"

#include <algorithm>
#include <stdexcept>

namespace tribo::study {

TrajectoryRecorder::TrajectoryRecorder(const Model& model, std::size_t expected_rows)
    : model_(model) {
  names_.push_back("t");
  for (const Body& b : model.bodies)
    for (const char* c : {".x", ".y", ".z", ".vx", ".vy", ".vz", ".slip", ".normal_force"})
      names_.push_back(b.name + c);
  data_.resize(names_.size());
  for (auto& col : data_) col.reserve(expected_rows);
  slip_.resize(model.bodies.size());
  normal_.resize(model.bodies.size());
}

std::size_t TrajectoryRecorder::columnIndex(const std::string& name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end()) throw std::out_of_range("no trajectory column '" + name + "'");
  return static_cast<std::size_t>(it - names_.begin());
}

void TrajectoryRecorder::record(const State& state, const Workspace& ws) {
  std::fill(slip_.begin(), slip_.end(), 0.0);
  std::fill(normal_.begin(), normal_.end(), 0.0);
  for (const auto& c : ws.contacts) {
    const ContactPair& pair = model_.contact_pairs[c.point.pair];
    for (int g : {pair.geometry_a, pair.geometry_b}) {
      const BodyIndex b = model_.geometries[g].body;
      if (b.isWorld()) continue;
      slip_[b.value] = std::max(slip_[b.value], c.slip.norm());
      normal_[b.value] += c.normal_force;
    }
  }
  std::size_t col = 0;
  data_[col++].push_back(state.time);
  for (std::size_t b = 0; b < state.bodies.size(); ++b) {
    const BodyState& s = state.bodies[b];
    for (int i = 0; i < 3; ++i) data_[col++].push_back(s.position[i]);
    for (int i = 0; i < 3; ++i) data_[col++].push_back(s.velocity[i]);
    data_[col++].push_back(slip_[b]);
    data_[col++].push_back(normal_[b]);
  }
}

}  // namespace tribo::study
