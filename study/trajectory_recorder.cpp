#include "study/trajectory_recorder.hpp"

#include <algorithm>
#include <stdexcept>

namespace tribo::study {

TrajectoryRecorder::TrajectoryRecorder(const Model& model, std::size_t expected_rows,
                                       bool keep_rows)
    : model_(model), keep_rows_(keep_rows) {
  names_.push_back("t");
  for (const Body& b : model.bodies)
    for (const char* c : {".x", ".y", ".z", ".vx", ".vy", ".vz", ".slip", ".normal_force"})
      names_.push_back(b.name + c);
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
  row_[col++] = state.time;
  for (std::size_t b = 0; b < state.bodies.size(); ++b) {
    const BodyState& s = state.bodies[b];
    for (int i = 0; i < 3; ++i) row_[col++] = s.position[i];
    for (int i = 0; i < 3; ++i) row_[col++] = s.velocity[i];
    row_[col++] = slip_[b];
    row_[col++] = normal_[b];
  }
  for (RowSink* sink : sinks_) sink->row(row_);
  if (keep_rows_)
    for (std::size_t c = 0; c < row_.size(); ++c) data_[c].push_back(row_[c]);
  ++rows_;
}

}  // namespace tribo::study
