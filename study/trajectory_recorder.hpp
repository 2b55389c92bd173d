// Recording of a run at a fixed output interval. Columns: the channel groups asked for
// (io/output_channels.hpp; by default t, then per body NAME.x NAME.y NAME.z NAME.vx NAME.vy
// NAME.vz (world frame, body origin), NAME.slip (largest contact slip speed on the body
// [m/s], 0 out of contact) and NAME.normal_force (sum of its contact normal forces [N])).
// Each row goes to the sinks added (e.g. trajectory.csv written as the run goes,
// study/result_writer.hpp) and, unless the recorder was made without, into memory, one
// column per channel, so an analysis reads a column without copying (sweeps, the tradeoff).
// A recorder that keeps no rows holds one row of scratch, whatever the duration.
// Magnitudes (slip speeds, friction forces) are taken without overflow in the squares
// (Eigen's stableNorm): a finite force of 1e200 N on a diverging run is written as such, never
// as an empty field.
// Not here: file formats, analysis.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/constraint_rows.hpp"
#include "core/model.hpp"
#include "core/state.hpp"
#include "core/workspace.hpp"
#include "io/output_channels.hpp"

namespace tribo::study {

// Receives every row as it is recorded, in the recorder's column order.
class RowSink {
 public:
  virtual ~RowSink() = default;
  virtual void row(std::span<const double> values) = 0;
};

class TrajectoryRecorder {
 public:
  // The most rows `expected_rows` reserves memory for (a hint must not allocate gigabytes).
  static constexpr std::size_t kMaxReservedRows = std::size_t{1} << 20;

  // `expected_rows` only reserves memory (at most kMaxReservedRows). Without `keep_rows`
  // the rows only go to the sinks.
  // `groups`: the channel groups recorded (io/output_channels.hpp).
  TrajectoryRecorder(const Model& model, std::size_t expected_rows = 0, bool keep_rows = true,
                     const std::vector<std::string>& groups = io::defaultChannelGroups());

  // `sink` (not owned, outliving the recorder's use) receives every later row.
  void addSink(RowSink* sink) { sinks_.push_back(sink); }
  void clearSinks() { sinks_.clear(); }

  // Appends one row: `ws` must be the evaluation at `state`.
  void record(const State& state, const Workspace& ws);

  const std::vector<std::string>& columns() const { return names_; }
  // Rows recorded so far (kept or not).
  std::size_t rows() const { return rows_; }
  bool keepsRows() const { return keep_rows_; }
  // A kept column (empty when the recorder keeps no rows).
  std::span<const double> column(std::size_t c) const { return data_[c]; }
  // Column index of "BODY.channel"; throws std::out_of_range if absent.
  std::size_t columnIndex(const std::string& name) const;

 private:
  const Model& model_;
  bool keep_rows_;
  std::size_t rows_ = 0;
  std::vector<std::string> names_;
  std::vector<std::vector<double>> data_;
  std::vector<double> row_;            // scratch: the row being recorded
  std::vector<double> slip_, normal_;  // per body, scratch
  std::vector<Vec3> friction_;         // per body, scratch
  std::vector<Vec3> moment_;           // per body: rolling and spinning resistance, scratch
  // Per contact pair, scratch: normal force sum, friction force sum, largest slip; and for
  // friction_states the sum of its records' states and their count.
  std::vector<double> pair_normal_, pair_slip_, pair_state_;
  std::vector<Vec3> pair_friction_;
  std::vector<int> pair_points_;
  // Per contact pair for pair_resistance, scratch: over its slipping points sum(-F . s / |s|)
  // and sum(F_n); the sum of its points' moments.
  std::vector<double> pair_dissipation_, pair_slip_load_;
  std::vector<Vec3> pair_moment_;
  PairSlots slots_;  // pairs, pair_resistance and friction_states only: every pair's slot
  // The groups asked for, by flag (io/output_channels.hpp's order).
  bool position_ = false, orientation_ = false, rpy_ = false, velocity_ = false,
       angular_velocity_ = false, contact_ = false, friction_force_ = false, pairs_ = false,
       joints_ = false, friction_states_ = false, energy_ = false, loads_ = false,
       resistance_ = false, pair_resistance_ = false;
  std::vector<int> actuated_joints_;  // joints whose actuator is recorded, in model order
  struct RecordedJoint {
    int joint = -1;
    JointCoordinate coordinate;  // fixed per model: built once
  };
  std::vector<RecordedJoint> joints_recorded_;  // joints with a scalar coordinate
  // friction_states: per joint with a dynamic law its slice {offset, size}; per contact pair
  // the offset of its columns in pair_state_ and its state size (0: memoryless law).
  std::vector<std::pair<int, int>> joint_states_;
  std::vector<int> pair_state_offset_, pair_state_size_;
  std::vector<RowSink*> sinks_;
};

}  // namespace tribo::study
