#include "study/scene_run.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "core/constraint_rank.hpp"

namespace tribo::study {

OscillationSummary summarize(const TrajectoryRecorder& trajectory, const Model& model,
                             const io::SummarySpec& spec) {
  if (spec.body.empty() || trajectory.rows() < 3) return {};
  const auto index = model.findBody(spec.body);
  if (!index || index->isWorld()) return {};
  const Body& body = model.bodies[index->value];
  static const char* kAxis[] = {".x", ".y", ".z"};
  const auto x = trajectory.column(trajectory.columnIndex(body.name + kAxis[spec.coordinate]));
  // Stuck means in contact and slipping slower than the stick speed: out of contact the
  // slip channel reads 0, which must not count as stuck.
  const auto slip_column = trajectory.column(trajectory.columnIndex(body.name + ".slip"));
  const auto normal = trajectory.column(trajectory.columnIndex(body.name + ".normal_force"));
  std::vector<double> slip(slip_column.begin(), slip_column.end());
  for (std::size_t i = 0; i < slip.size(); ++i)
    if (!(normal[i] > 0.0)) slip[i] = std::numeric_limits<double>::max();
  OscillationOptions options;
  options.last_cycles = spec.last_cycles;
  options.stick_speed = spec.stick_speed;
  return summarizeOscillation(trajectory.column(0), x, slip, options);
}

RunResult runScene(const io::Scene& scene, const RunMonitor& monitor) {
  const Model& model = *scene.model;
  const double dt = model.options.time_step;
  const long steps = std::lround(model.options.duration / dt);
  const double interval = std::max(scene.output.interval, dt);
  RunResult result{
      false,
      "",
      {},
      0.0,
      0.0,
      TrajectoryRecorder(model, static_cast<std::size_t>(model.options.duration / interval + 2)),
      {},
      {},
      {},
      {}};
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
  for (const std::string& note : droppedEquationNotes(model)) result.warnings.push_back(note);
  Simulator sim(scene.model);
  const auto start = std::chrono::steady_clock::now();
  result.trajectory.record(sim.state(), sim.current());
  double next_output = interval;
  double next_check = monitor.interval;
  result.complete = true;
  for (long i = 0; i < steps; ++i) {
    const StepStatus status = sim.step();
    if (!status.ok) {
      result.complete = false;
      result.message = status.message;
      result.stop = status;
      break;
    }
    if (sim.state().time >= next_output - 0.5 * dt) {
      result.trajectory.record(sim.state(), sim.current());
      next_output += interval;
    }
    if (monitor.stop && sim.state().time >= next_check - 0.5 * dt) {
      next_check += monitor.interval;
      if (monitor.stop(result.trajectory)) break;
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
  result.summary = summarize(result.trajectory, model, scene.output.summary);
  return result;
}

}  // namespace tribo::study
