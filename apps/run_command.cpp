#include "apps/run_command.hpp"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/common_options.hpp"
#include "apps/info_command.hpp"
#include "apps/stop_signals.hpp"
#include "apps/usage_error.hpp"
#include "apps/view_command.hpp"
#include "io/output_channels.hpp"
#include "io/scene_loader.hpp"
#include "io/scene_source.hpp"
#include "io/urdf_reader.hpp"
#include "study/dir_lock.hpp"
#include "study/early_growth.hpp"
#include "study/orbit_shape.hpp"
#include "study/output_budget.hpp"
#include "study/result_writer.hpp"
#include "study/run_progress.hpp"
#include "study/scene_run.hpp"
#include "study/view/view_page.hpp"

namespace tribo::app {
namespace {

struct RunArguments {
  std::string scene_path, out_dir;
  std::vector<std::string> overrides, package_paths;
  bool quiet = false, progress = false, profile = false, view = false;
  std::optional<int> threads;
  tribo::io::UrdfReadOptions read;
  bool verbose = false;
};

void printSummary(const tribo::io::Scene& scene, const tribo::study::RunResult& r,
                  const std::filesystem::path& out) {
  const auto& s = r.summary;
  const auto& o = scene.model->options;
  std::printf("scene            %s\n", scene.path.c_str());
  std::printf("integrator       %s, step %g s, %ld steps\n",
              tribo::integratorName(o.integrator).c_str(), o.time_step, r.stats.steps);
  std::printf("status           %s\n", r.complete      ? "complete"
                                       : r.interrupted ? r.message.c_str()
                                                       : ("DIVERGED: " + r.message).c_str());
  static const char* kAxis[] = {"x", "y", "z"};
  const auto& spec = scene.output.summary;
  if (spec.body.empty() && spec.channel.empty()) {
    std::printf("observed         nothing (the scene's output.summary names no body)\n");
  } else {
    const std::string observed =
        spec.channel.empty() ? spec.body + "." + kAxis[spec.coordinate] : spec.channel;
    std::printf("observed         %s\n", observed.c_str());
    std::printf("oscillating      %s (%zu cycles)\n", s.oscillating ? "yes" : "no",
                s.cycles.size());
    // Units of the observed column (m, rad, m/s, N, ...); none said when it has none.
    const std::string unit = tribo::io::channelUnit(*scene.model, observed);
    const std::string in_unit = unit.empty() ? "" : " " + unit;
    if (s.oscillating) {
      std::printf("amplitude (p-p)  %.6g%s\n", s.amplitude_pp, in_unit.c_str());
      std::printf("period           %.6g s\n", s.period);
      std::printf("time to 98%%      %.6g s\n", s.time_to_98);
    } else {
      std::printf("range            %.6g%s (no cycle: max - min over the record's last half)\n",
                  s.amplitude_pp, in_unit.c_str());
      std::printf("period           none (no cycle)\n");
      std::printf("time to 98%%      none (no cycle)\n");
    }
    if (spec.body.empty())
      std::printf("stuck fraction   n/a (output.summary names no body, so no contact to stick)\n");
    else
      std::printf("stuck fraction   %.4g\n", s.stuck_fraction);
    const tribo::study::OrbitShape orbit = tribo::study::classifyOrbit(s.cycles);
    if (orbit.kind == tribo::study::OrbitKind::kPeriod2)
      std::printf("orbit            period 2: cycles alternate p-p %.6g / %.6g%s, %.6g / %.6g s\n",
                  orbit.peak_to_peak_a, orbit.peak_to_peak_b, in_unit.c_str(), orbit.duration_a,
                  orbit.duration_b);
    else
      std::printf("orbit            %s (last %d cycles)\n",
                  orbit.kind == tribo::study::OrbitKind::kPeriod1     ? "period 1"
                  : orbit.kind == tribo::study::OrbitKind::kIrregular ? "irregular"
                                                                      : "none",
                  orbit.examined);
    const tribo::study::EarlyGrowth g = tribo::study::earlyGrowth(s.cycles);
    if (g.measured && g.trustworthy)
      std::printf("early growth     %.7g 1/s (cycles %d-%d, %.4g-%.4g s)\n", g.rate,
                  g.first_cycle + 1, g.first_cycle + g.cycles, g.t_start, g.t_end);
    else if (g.measured)
      std::printf("early growth     %.7g 1/s, NOT the linear growth rate: %s (cycles %d-%d)\n",
                  g.rate, g.doubt.c_str(), g.first_cycle + 1, g.first_cycle + g.cycles);
    else
      std::printf("early growth     not measured (fewer than 3 cycles after the first)\n");
  }
  if (o.threads != 1) {  // asked for: what the steps ran on
    std::printf("threads          %s: %.3g a step on the mean, of up to %d%s\n",
                o.threads == tribo::kAutoThreads ? "auto (measured choice)"
                                                 : std::to_string(o.threads).c_str(),
                r.stats.meanThreads(), r.stats.most_threads,
                r.stats.most_threads == 1 ? " (the scene is too small to split)" : "");
  }
  std::printf("max penetration  %.3g m\n", r.stats.max_penetration);
  const auto& limit = r.stability.limit;
  const std::string method = tribo::integratorName(o.integrator);
  if (o.integrator == tribo::IntegratorType::kBdf)
    std::printf("stable step      n/a (%s is implicit: no explicit step limit)\n", method.c_str());
  else if (std::isinf(limit.max_step))
    std::printf(
        "stable step      not estimated (no contact, spring or friction slope bounds it)\n");
  else
    std::printf("stable step     < %.4g s (%s%s)\n", limit.max_step, limit.element.c_str(),
                tribo::isAdaptive(o.integrator) ? "; bounds the internal steps" : "");
  // Joint drift of the Baumgarte-stabilized constraints: position level |Phi| [m or -],
  // velocity level |J v| [m/s or rad/s], the largest over the run.
  if (scene.model->constraint_equations > 0)
    std::printf("constraint drift max |Phi| %.2g, max |J v| %.2g\n", r.stats.max_constraint_error,
                r.stats.max_constraint_rate_error);
  std::printf("speed            %.4g simulated s per wall s (%.3g s wall)\n",
              r.simulated_seconds / r.wall_seconds, r.wall_seconds);
  std::printf("results          %s\n", out.string().c_str());
}

// The stage profile of a run (--profile): per stage, microseconds per step and share of the
// step; the rest of the step is the integrator's own work, the checks and the energy guard.
void printProfile(const tribo::StepStats& stats) {
  const tribo::StageProfile& p = stats.profile;
  if (stats.steps == 0 || !(p.step > 0.0)) return;
  const double per_step = 1e6 / static_cast<double>(stats.steps);
  std::printf("stage profile    %.3g us a step, %.3g evaluations a step\n", p.step * per_step,
              static_cast<double>(p.evaluations) / static_cast<double>(stats.steps));
  for (std::size_t s = 0; s < tribo::kStageCount; ++s) {
    const auto stage = static_cast<tribo::Stage>(s);
    std::printf("  %-20s %9.3f us %5.1f%%\n", std::string(tribo::stageName(stage)).c_str(),
                p[stage] * per_step, 100.0 * p[stage] / p.step);
  }
  const double rest = p.step - p.total();
  std::printf("  %-20s %9.3f us %5.1f%%\n", "integrator, checks", rest * per_step,
              100.0 * rest / p.step);
  std::printf("  (fcl inside detect: %.3f us)\n", p.fcl * per_step);
}

int runScene(const CLI::App& command, const RunArguments& a) {
  if (a.quiet && a.progress)
    return usageError(command, "--quiet and --progress contradict each other");
  const std::string& out_dir = a.out_dir;
  const bool verbose = a.verbose, view = a.view, profile = a.profile;
  tribo::io::Scene scene;
  try {
    tribo::io::SceneRequest request;
    request.overrides = a.overrides;
    request.package_paths = a.package_paths;
    request.settings.threads = a.threads;
    request.urdf = a.read;
    scene = tribo::io::loadAnyScene(a.scene_path, request);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo: %s\n", e.what());
    return 2;
  }
  tribo::app::printGrouped(stderr, "note", scene.notes, verbose);  // before the run: why
  // The replay page needs orientations to turn the bodies.
  if (view && !tribo::io::hasGroup(scene.output.channels, "orientation"))
    scene.output.channels.push_back("orientation");
  namespace study = tribo::study;
  const std::filesystem::path out(out_dir);
  try {
    study::checkOutputFitsDisk(scene, out);
  } catch (const study::OutputTooLarge& e) {
    std::fprintf(stderr, "tribo: %s: %s\n", scene.path.c_str(), e.what());
    return 2;
  }
  std::optional<study::DirLock> lock;
  std::optional<study::TrajectoryCsvFile> csv;
  try {
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec)
      throw std::runtime_error("cannot create output folder '" + out_dir + "': " + ec.message());
    lock.emplace(out);
    csv.emplace(out / "trajectory.csv",
                study::TrajectoryRecorder(*scene.model, 0, false, scene.output.channels).columns(),
                scene.output.digits);
  } catch (const study::DirLockedError& e) {
    std::fprintf(stderr, "tribo: %s\n", e.what());
    return 6;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo: %s\n", e.what());
    return 4;
  }
  const bool show_progress = !a.quiet && (a.progress || ::isatty(STDERR_FILENO));
  study::RunProgress progress_line(show_progress ? stderr : nullptr, scene.model->options.duration);
  study::RunOptions options;
  options.sink = &*csv;
  options.spill_dir = out;
  // The first SIGINT or SIGTERM stops the run at once, back at its last output row.
  options.stop = &catchStopSignals();
  options.profile = profile;
  options.progress = [&](double simulated) { progress_line.update(simulated); };
  std::optional<study::RunResult> run_result;
  try {
    run_result.emplace(study::runScene(scene, options));
  } catch (const std::exception& e) {
    progress_line.finish();
    std::fprintf(stderr, "tribo: %s\n", e.what());
    return 4;
  }
  progress_line.finish();
  const study::RunResult& result = *run_result;
  tribo::app::printGrouped(stderr, "warning", result.warnings, verbose);
  try {
    csv->commit();
    study::writeSummaryJson(out / "summary.json", scene, result);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo: %s\n", e.what());
    return 4;
  }
  if (profile) printProfile(result.stats);
  printSummary(scene, result, out_dir);
  if (view) {
    lock.reset();
    const int status =
        tribo::app::writeView(out, tribo::study::ViewOptions{}.frame_cap, "", a.package_paths);
    if (status != 0 && result.complete) return status;
  }
  if (result.interrupted) {
    std::fprintf(stderr, "tribo: %s; results up to there written\n", result.message.c_str());
    return 5;
  }
  if (!result.complete) {
    std::fprintf(stderr, "tribo: run stopped early: %s\n", result.message.c_str());
    return 3;
  }
  return 0;
}

}  // namespace

Command addRunCommand(CLI::App& tribo) {
  auto a = std::make_shared<RunArguments>();
  CLI::App* run = tribo.add_subcommand(
      "run", "simulate a scene; write DIR/trajectory.csv and DIR/summary.json");
  addPathArgument(*run, "SCENE", a->scene_path,
                  "a YAML scene, or a URDF robot (ROBOT.urdf) run at automatic settings");
  addOutOption(*run, a->out_dir, "output folder (created if missing)")->required();
  addSetOption(*run, a->overrides);
  addPackagePathOption(*run, a->package_paths);
  addQuietOption(*run, a->quiet);
  run->add_flag("--progress", a->progress,
                "show the progress line of a long run even when stderr is not a terminal");
  run->add_flag("--profile", a->profile, "time each stage of the step and print the share of each");
  run->add_flag("--view", a->view, "also record orientations and write DIR/view.html (tribo view)");
  addThreadsOption(*run, a->threads);
  addUrdfOptions(*run, a->read, a->verbose);
  run->footer(
      "A first SIGINT or SIGTERM stops the run at its last output row and writes the results up\n"
      "to there; a second one ends the process at once.\n"
      "exit status: 0 done, 1 usage, 2 bad scene or parameters (or an output too large for the\n"
      "disk), 3 diverged (partial results), 4 output error, 5 interrupted, 6 output folder in use");
  return {run, [run, a] { return runScene(*run, *a); }};
}

}  // namespace tribo::app
