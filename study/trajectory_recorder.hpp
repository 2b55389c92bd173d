// In-memory recording of a run at a fixed output interval: one column per channel, so the
// summary analysis reads a column without copying. Channels: t, then per body
// NAME.x NAME.y NAME.z NAME.vx NAME.vy NAME.vz (world frame, body origin),
// NAME.slip (largest contact slip speed on the body [m/s], 0 out of contact) and
// NAME.normal_force (sum of its contact normal forces [N]).
// The step loop never writes files; io/trajectory_writer.hpp does, after the run.
// Not here: file formats, analysis.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/model.hpp"
#include "core/state.hpp"
#include "core/workspace.hpp"

namespace tribo::study {

class TrajectoryRecorder {
 public:
  static constexpr int kChannelsPerBody = 8;

  // `expected_rows` only reserves memory.
  TrajectoryRecorder(const Model& model, std::size_t expected_rows = 0);

  // Appends one row: `ws` must be the evaluation at `state`.
  void record(const State& state, const Workspace& ws);

  const std::vector<std::string>& columns() const { return names_; }
  std::size_t rows() const { return data_.empty() ? 0 : data_[0].size(); }
  std::span<const double> column(std::size_t c) const { return data_[c]; }
  // Column index of "BODY.channel"; throws std::out_of_range if absent.
  std::size_t columnIndex(const std::string& name) const;

 private:
  const Model& model_;
  std::vector<std::string> names_;
  std::vector<std::vector<double>> data_;
  std::vector<double> slip_, normal_;  // per body, scratch
};

}  // namespace tribo::study
