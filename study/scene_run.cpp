#include "study/scene_run.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/constraint_rank.hpp"
#include "core/number_text.hpp"
#include "study/output_budget.hpp"
#include "study/output_stride.hpp"
#include "study/series_spill.hpp"

namespace tribo::study {

OscillationSummary summarize(const TrajectoryRecorder& trajectory, const Model& model,
                             const io::SummarySpec& spec) {
  if ((spec.body.empty() && spec.channel.empty()) || trajectory.rows() < 3) return {};
  static const char* kAxis[] = {".x", ".y", ".z"};
  const auto x = trajectory.column(trajectory.columnIndex(
      spec.channel.empty() ? spec.body + kAxis[spec.coordinate] : spec.channel));
  // Stuck means in contact and slipping slower than the stick speed: out of contact the
  // slip channel reads 0, which must not count as stuck. No body: no stuck fraction.
  std::vector<double> slip;
  const auto index = model.findBody(spec.body);
  if (!spec.body.empty() && index && !index->isWorld()) {
    const auto slip_column = trajectory.column(trajectory.columnIndex(spec.body + ".slip"));
    const auto normal = trajectory.column(trajectory.columnIndex(spec.body + ".normal_force"));
    slip.assign(slip_column.begin(), slip_column.end());
    for (std::size_t i = 0; i < slip.size(); ++i)
      if (!(normal[i] > 0.0)) slip[i] = std::numeric_limits<double>::max();
  }
  OscillationOptions options;
  options.last_cycles = spec.last_cycles;
  options.stick_speed = spec.stick_speed;
  return summarizeOscillation(trajectory.column(0), x, slip, options);
}

namespace {

// Columns of the observed coordinate or channel, and of its body's slip and normal force
// when the spec names a body of the model (a channel alone has no stuck fraction, as in
// summarize()); empty when the spec observes nothing.
struct SummaryColumns {
  std::size_t x;
  std::optional<std::array<std::size_t, 2>> slip_and_normal;
};

std::optional<SummaryColumns> summaryColumns(const TrajectoryRecorder& trajectory,
                                             const Model& model, const io::SummarySpec& spec) {
  if (spec.body.empty() && spec.channel.empty()) return std::nullopt;
  static const char* kAxis[] = {".x", ".y", ".z"};
  SummaryColumns c{trajectory.columnIndex(spec.channel.empty() ? spec.body + kAxis[spec.coordinate]
                                                               : spec.channel),
                   std::nullopt};
  const auto index = model.findBody(spec.body);
  if (!spec.body.empty() && index && !index->isWorld())
    c.slip_and_normal = std::array{trajectory.columnIndex(spec.body + ".slip"),
                                   trajectory.columnIndex(spec.body + ".normal_force")};
  return c;
}

// The summary's series (t, x, and when there is a body the slip speed read as "not stuck"
// out of contact, as summarize() masks it) spilled to scratch files as the rows go by.
class SummarySpill : public RowSink {
 public:
  SummarySpill(SummaryColumns columns, const std::filesystem::path& dir)
      : columns_(columns), t_(dir), x_(dir), slip_(dir) {}
  void row(std::span<const double> v) override {
    t_.append(v[0]);
    x_.append(v[columns_.x]);
    if (const auto& sn = columns_.slip_and_normal)
      slip_.append(v[(*sn)[1]] > 0.0 ? v[(*sn)[0]] : std::numeric_limits<double>::max());
  }
  OscillationSummary summarize(const io::SummarySpec& spec) const {
    if (t_.size() < 3) return {};
    OscillationOptions options;
    options.last_cycles = spec.last_cycles;
    options.stick_speed = spec.stick_speed;
    return summarizeOscillation(t_, x_, columns_.slip_and_normal ? &slip_ : nullptr, options);
  }

 private:
  SummaryColumns columns_;
  SpilledColumn t_, x_, slip_;
};

// The fixed-step rule held a joint's damping or friction within I_q |q'| / (2 h)
// (core/joint_forces.hpp): where, how often, how much, and the step that avoids it.
std::string heldJointWarning(const Model& model, const RunResult& result) {
  const StepStats& s = result.stats;
  const Joint& joint = model.joints[static_cast<std::size_t>(s.joint_held_worst)];
  std::ostringstream w;
  w << "joint '" << joint.name << "': its damping and friction were held to I_q |q'| / (2 h), "
    << "the fixed-step rule for light links (docs/joints.md), at " << s.joint_held << " of "
    << s.steps << " steps (first at t = " << s.first_held_time << " s), changing its "
    << (isAngular(joint.type) ? "torque by up to " : "force by up to ") << s.joint_held_change
    << (isAngular(joint.type) ? " N m" : " N") << " from the law's";
  for (const HeldJoint& h : result.stability.held_joints)
    if (h.joint == s.joint_held_worst)
      w << "; a step of at most " << h.rule_step << " s (or integrator bdf or dopri5) gives "
        << "the law as written";
  return w.str();
}

}  // namespace

RunResult runScene(const io::Scene& scene, const RunMonitor& monitor) {
  RunOptions options;
  options.monitor = monitor;
  return runScene(scene, options);
}

RunResult runScene(const io::Scene& scene, const RunOptions& options) {
  const RunMonitor& monitor = options.monitor;
  const bool keep = options.sink == nullptr;
  if (!keep && monitor.stop)
    throw std::invalid_argument("runScene: a run monitor needs the rows kept (no sink)");
  if (keep) checkOutputFitsMemory(scene);
  const Model& model = *scene.model;
  const double dt = model.options.time_step;
  const long steps = std::lround(model.options.duration / dt);
  // Rows fall on steps: every `every` steps, the whole multiple of the step nearest to the
  // interval asked for, so that they are evenly spaced (an FFT of the CSV needs it).
  const long every = outputStride(scene.output.interval, dt);
  const double interval = outputInterval(scene.output.interval, dt);
  RunResult result{
      false,
      false,
      "",
      {},
      0.0,
      0.0,
      TrajectoryRecorder(model, static_cast<std::size_t>(model.options.duration / interval + 2),
                         keep, scene.output.channels),
      {},
      {},
      {},
      {}};
  std::optional<SummarySpill> spill;
  if (!keep) {
    result.trajectory.addSink(options.sink);
    if (const auto columns = summaryColumns(result.trajectory, model, scene.output.summary)) {
      spill.emplace(*columns, options.spill_dir);
      result.trajectory.addSink(&*spill);
    }
  }
  result.stability = estimateStableStep(model);
  // Adaptive integrators choose their own steps (dt is the communication interval).
  if (!isAdaptive(model.options.integrator) && dt > result.stability.limit.max_step) {
    std::ostringstream w;
    w << "time step " << dt << " s exceeds the estimated stability limit "
      << result.stability.limit.max_step << " s of " << integratorName(model.options.integrator)
      << " (set by " << result.stability.limit.element
      << "); results may be wrong even if the run completes";
    result.warnings.push_back(w.str());
  }
  if (const auto note = outputStrideNote(scene.output.interval, dt))
    result.warnings.push_back(*note);
  for (const std::string& note : droppedEquationNotes(model)) result.warnings.push_back(note);
  Simulator sim(scene.model);
  sim.setStopRequest(options.stop);
  const auto start = std::chrono::steady_clock::now();
  double next_control = 0.0;
  // The controller's turn before the step from the current state: false when it stopped the run.
  const auto control = [&] {
    if (!options.controller || sim.state().time < next_control - 0.5 * dt) return true;
    next_control += std::max(options.control_interval, dt);
    const std::string stop = options.controller(sim);
    if (stop.empty()) return true;
    result.complete = false;
    result.message = stop;
    result.stop.ok = false;
    result.stop.message = stop;
    result.stop.time = sim.state().time;
    result.stop.quantity = "controller";
    return false;
  };
  const bool controlled = control();
  result.trajectory.record(sim.state(), sim.current());
  // The profile is of the steps: the first row's evaluation (cold, outside any step) would
  // count in the stages and not in the step.
  if (options.profile) sim.setProfiling(true);
  // The state of the last row: an interrupted run goes back to it, so the trajectory ends
  // at the state the result reports and its rows are those of an uninterrupted run.
  State row_state = sim.state();
  double next_check = monitor.interval;
  result.complete = controlled;
  bool at_row = true;  // the last row recorded is the current state
  const auto interrupt = [&] {
    if (!at_row) sim.setState(row_state);
    result.complete = false;
    result.interrupted = true;
    result.message = "interrupted at t = " + numberText(sim.state().time) + " s";
  };
  int since_clock = 0;
  auto last_progress = start;
  for (long i = 0; i < steps && controlled; ++i) {
    if (options.stop && options.stop->load(std::memory_order_relaxed)) {
      interrupt();
      break;
    }
    if (i > 0 && !control()) break;
    const StepStatus status = sim.step();
    if (status.interrupted) {
      interrupt();
      break;
    }
    if (!status.ok) {
      result.complete = false;
      result.message = status.message;
      result.stop = status;
      break;
    }
    at_row = false;
    if ((i + 1) % every == 0) {
      result.trajectory.record(sim.state(), sim.current());
      row_state = sim.state();
      at_row = true;
    }
    if (monitor.stop && sim.state().time >= next_check - 0.5 * dt) {
      next_check += monitor.interval;
      if (monitor.stop(result.trajectory)) break;
    }
    if (options.progress && ++since_clock == 64) {
      since_clock = 0;
      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - last_progress).count() >= options.progress_interval) {
        last_progress = now;
        options.progress(sim.state().time);
      }
    }
  }
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.simulated_seconds = sim.state().time;
  result.stats = sim.stats();
  if (result.stats.joint_friction_unconverged > 0) {
    std::ostringstream w;
    w << "joint friction under reaction load did not settle within its iteration cap at "
      << result.stats.joint_friction_unconverged
      << " steps (first at t = " << result.stats.first_unconverged_time
      << " s): its torque there is approximate (friction coefficient times pin radius large "
         "against the joint's lever; see docs/joints.md)";
    result.warnings.push_back(w.str());
  }
  if (result.stats.joint_held > 0) result.warnings.push_back(heldJointWarning(model, result));
  if (result.stats.max_constraint_error > model.options.constraints.drift_warning &&
      result.stats.max_constraint_joint >= 0) {
    const Joint& j = model.joints[static_cast<std::size_t>(result.stats.max_constraint_joint)];
    std::ostringstream w;
    w << "joint '" << j.name << "' drifted: its constraint error |Phi| reached "
      << result.stats.max_constraint_error << " (m or rad), more than constraints.drift_warning = "
      << model.options.constraints.drift_warning
      << ": positions along it are off by that much (constraints: {projection: true} holds "
         "the joints; a smaller step reduces the drift)";
    result.warnings.push_back(w.str());
  }
  if (result.stats.deep_penetrations > 0) {
    const Geometry& g = model.geometries[result.stats.deepest_geometry];
    const std::string body = g.body.isWorld() ? "world" : model.bodies[g.body.value].name;
    std::ostringstream w;
    w << "body '" << body << "': geometry '" << g.name << "' penetrated "
      << result.stats.deepest_depth << " m, deeper than its half width "
      << result.stats.deepest_extent
      << " m along the contact normal (first at t = " << result.stats.first_deep_time
      << " s; the energy stayed bounded, so the run went on): the contact is soft for it "
         "(raise the stiffness) or it is a small feature on a heavier body";
    result.warnings.push_back(w.str());
  }
  result.trajectory.clearSinks();
  result.summary = keep    ? summarize(result.trajectory, model, scene.output.summary)
                   : spill ? spill->summarize(scene.output.summary)
                           : OscillationSummary{};
  return result;
}

}  // namespace tribo::study
