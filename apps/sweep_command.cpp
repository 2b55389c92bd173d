#include "apps/sweep_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "apps/common_options.hpp"
#include "apps/usage_error.hpp"
#include "io/scene_parameters.hpp"
#include "study/sweep/sweep_results.hpp"
#include "study/sweep/sweep_runner.hpp"
#include "study/sweep/sweep_slice.hpp"
#ifdef TRIBO_WITH_MPI
#include "study/sweep/sweep_mpi.hpp"
#endif

namespace tribo::app {

namespace {

namespace fs = std::filesystem;

// Number of processes of the MPI job this process was started in, 0 when none.
int launcherWorldSize() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"})
    if (const char* v = std::getenv(var)) return std::max(1, std::atoi(v));
  return std::getenv("PMIX_RANK") ? 1 : 0;
}

void printReport(const study::SweepReport& r, const study::SweepSpec& spec, const fs::path& out,
                 const std::string& workers) {
  std::string shape;
  for (const auto& a : spec.axes) {
    if (!shape.empty()) shape += " x ";
    shape += std::to_string(a.values.size()) + " " + a.name;
  }
  std::printf("sweep            %s, %zu points (%s)\n", spec.scene_path.c_str(), r.points,
              shape.c_str());
  std::printf("points           %zu recorded now (%zu failed), %zu resumed, %zu left\n", r.ran,
              r.failed, r.resumed, r.points - r.ran - r.resumed);
  if (r.dropped)
    std::printf("dropped          %zu cut-off line(s) of the earlier run\n", r.dropped);
  if (spec.settle)
    std::printf("unsettled        %zu point(s) still changing at the duration cap\n", r.unsettled);
  std::printf("wall time        %.3g s (%s)\n", r.wall_seconds, workers.c_str());
  std::printf("results          %s%s\n", (out / "results.csv").string().c_str(),
              r.complete ? "" : " (incomplete)");
}

// The exit status for an error of planning or running a sweep (see the header).
int failure(const std::exception& e, bool print) {
  if (print) std::fprintf(stderr, "tribo sweep: %s\n", e.what());
  if (dynamic_cast<const io::SceneError*>(&e) || dynamic_cast<const study::SweepSpecError*>(&e))
    return 2;
  if (const auto* o = dynamic_cast<const study::SweepOutputError*>(&e))
    return o->reason() == study::SweepOutputError::Reason::kCannotWrite ? 4 : 1;
  return 4;
}

// The value of `option`: a number > 0.
double positive(const std::string& option, const std::string& text) {
  const auto v = io::parseNumber(text);
  if (!v || !(*v > 0))
    throw std::invalid_argument(option + ": expected a positive number, found '" + text + "'");
  return *v;
}

struct SweepArguments {
  study::SweepSpec spec;
  std::string out;
  unsigned jobs = 0;
  bool quiet = false;
  study::SettleRule settle;
  bool want_settle = false, have_every = false;
  std::optional<study::SweepSlice> slice;  // --slice I/N
  std::string merge;                       // --merge DIR
};

void printSliceReport(const study::SliceReport& r, const study::SweepSlice& slice,
                      const study::SweepSpec& spec, const fs::path& out, unsigned threads) {
  const study::SweepReport& s = r.slice;
  std::printf("sweep            %s, %zu points, slice %zu/%zu: %zu points\n",
              spec.scene_path.c_str(), r.sweep_points, slice.index, slice.count, s.points);
  std::printf("points           %zu recorded now (%zu failed), %zu resumed, %zu left\n", s.ran,
              s.failed, s.resumed, s.points - s.ran - s.resumed);
  if (spec.settle)
    std::printf("unsettled        %zu point(s) still changing at the duration cap\n", s.unsettled);
  std::printf("wall time        %.3g s (%u thread(s))\n", s.wall_seconds, threads);
  std::printf("sweep            %zu of %zu points done in %s\n", r.sweep_done, r.sweep_points,
              out.string().c_str());
  if (r.results_written)
    std::printf("results          %s\n", (out / "results.csv").string().c_str());
  else
    std::printf("results          when every slice is done: tribo sweep --merge %s\n",
                out.string().c_str());
}

// tribo sweep --merge DIR: 0 results.csv written, 3 points missing (named), else as a sweep.
int runMerge(const fs::path& dir) {
  const study::MergeReport r = study::mergeSweep(dir);
  if (r.written) {
    std::printf("merged           %zu points into %s\n", r.points,
                (dir / "results.csv").string().c_str());
    return 0;
  }
  std::fprintf(stderr, "tribo sweep: %s: %zu of %zu points missing (results.csv not written):\n",
               dir.string().c_str(), r.missing.size(), r.points);
  for (std::size_t k = 0; k < r.missing_values.size(); ++k) {
    std::string values;
    for (std::size_t a = 0; a < r.axis_names.size(); ++a)
      values += (a ? ", " : "") + r.axis_names[a] + "=" + r.missing_values[k][a];
    std::fprintf(stderr, "  point %zu (%s)\n", r.missing[k], values.c_str());
  }
  if (r.missing.size() > r.missing_values.size())
    std::fprintf(stderr, "  and %zu more\n", r.missing.size() - r.missing_values.size());
  std::fprintf(stderr,
               "run the slices that hold them again (point k is in slice k mod N + 1), or the "
               "sweep without --slice\n");
  return 3;
}

int runSweep(const CLI::App& command, SweepArguments a) {
  study::SweepSpec& spec = a.spec;
  const std::string& out = a.out;
  const unsigned jobs = a.jobs;
  const bool quiet = a.quiet;
  if (!a.merge.empty()) {
    if (!spec.scene_path.empty() || !out.empty() || !spec.axes.empty() || a.slice)
      return usageError(command,
                        "--merge DIR reads the sweep from DIR/sweep.json: give it alone (no "
                        "SCENE, --out, --grid, --list or --slice)");
    try {
      return runMerge(a.merge);
    } catch (const std::exception& e) {
      return failure(e, true);
    }
  }
  if (spec.scene_path.empty()) return usageError(command, "SCENE is required");
  if (out.empty()) return usageError(command, "--out is required");
  if (spec.axes.empty()) return usageError(command, "nothing to sweep (give --grid or --list)");
  if (a.have_every && !a.want_settle) return usageError(command, "--settle-every needs --settle");
  if (a.want_settle) spec.settle = a.settle;

  const int world = launcherWorldSize();
  if (a.slice && world > 1)
    return usageError(command, "--slice: expected separate processes, found an MPI job of " +
                                   std::to_string(world) +
                                   " ranks (under mpirun the ranks share the points already)");
  if (a.slice) {
    try {
      const study::SweepPlan plan = study::planSweep(spec);
      const unsigned threads = jobs ? jobs : study::defaultJobs();
      const study::SliceReport r =
          study::runSweepSlice(plan, out, *a.slice, {threads, quiet ? nullptr : stderr, 0});
      printSliceReport(r, *a.slice, spec, out, threads);
      return 0;
    } catch (const std::exception& e) {
      return failure(e, true);
    }
  }
#ifdef TRIBO_WITH_MPI
  if (world > 0) {
    // Every rank agrees on the outcome; only rank 0 speaks.
    study::MpiSession mpi(nullptr, nullptr);
    try {
      const study::SweepReport r =
          study::runSweepDistributed(mpi, spec, out, jobs, quiet || mpi.rank() ? nullptr : stderr);
      if (mpi.rank() == 0) {
        const unsigned per_rank = jobs ? jobs : study::defaultJobs(mpi.ranksOnThisNode());
        printReport(
            r, spec, out,
            std::to_string(mpi.size()) + " MPI ranks x " + std::to_string(per_rank) + " thread(s)");
      }
      return 0;
    } catch (const std::exception& e) {
      return failure(e, mpi.rank() == 0);
    }
  }
#else
  if (world > 1)
    return usageError(command,
                      "started by an MPI launcher with " + std::to_string(world) +
                          " ranks, but this tribo was built without MPI (TRIBO_WITH_MPI=OFF)");
#endif
  try {
    const study::SweepPlan plan = study::planSweep(spec);
    const unsigned threads = jobs ? jobs : study::defaultJobs();
    const study::SweepReport r =
        study::runSweepLocally(plan, out, {threads, quiet ? nullptr : stderr, 0});
    printReport(r, spec, out, std::to_string(threads) + " thread(s)");
    return 0;
  } catch (const std::exception& e) {
    return failure(e, true);
  }
}

}  // namespace

Command addSweepCommand(CLI::App& tribo) {
  auto a = std::make_shared<SweepArguments>();
  CLI::App* sweep = tribo.add_subcommand(
      "sweep", "run a scene at every combination of swept values; one row per point");
  CLI::Option* scene = addPathArgument(*sweep, "SCENE", a->spec.scene_path, "the YAML scene");
  CLI::Option* out =
      addOutOption(*sweep, a->out, "output folder: DIR/results.csv and DIR/sweep.json")->required();
  // --grid and --list add to one list of axes, in the order given.
  addCheckedOption(*sweep, "--grid", "NAME=START:STOP:COUNT",
                   "COUNT values from START to STOP, both included (repeatable)",
                   [a](const std::string& v) { a->spec.axes.push_back(study::parseGridAxis(v)); });
  addCheckedOption(*sweep, "--list", "NAME=V1,V2,...", "the values given (repeatable)",
                   [a](const std::string& v) { a->spec.axes.push_back(study::parseListAxis(v)); });
  addSetOption(*sweep, a->spec.fixed_overrides, "fix a parameter for every point (repeatable)");
  addCheckedOption(*sweep, "--settle", "TOL",
                   "stop each point once the amplitude of its last cycles changes by less than\n"
                   "TOL (relative, e.g. 1e-3); the scene's duration is then the cap",
                   [a](const std::string& v) {
                     a->settle.tolerance = positive("--settle", v);
                     a->want_settle = true;
                   });
  addCheckedOption(*sweep, "--settle-every", "SECONDS",
                   "simulated time between settle checks (default 5; needs --settle)",
                   [a](const std::string& v) {
                     a->settle.check_interval = positive("--settle-every", v);
                     a->have_every = true;
                   });
  addCheckedOption(*sweep, "--jobs", "N",
                   "threads per process, 1 to 4096 (default: every core, shared among the ranks\n"
                   "of a node)",
                   [a](const std::string& v) {
                     const auto n = io::parseNumber(v);
                     if (!n || *n < 1 || *n > 4096 || *n != static_cast<unsigned>(*n))
                       throw std::invalid_argument(
                           "--jobs: expected a whole number from 1 to 4096, found '" + v + "'");
                     a->jobs = static_cast<unsigned>(*n);
                   });
  sweep->add_flag("--keep-trajectories", a->spec.keep_trajectories,
                  "also write DIR/points/<point>/trajectory.csv and summary.json");
  addQuietOption(*sweep, a->quiet);
  addCheckedOption(*sweep, "--slice", "I/N",
                   "run only slice I of N (1 <= I <= N: points k with k mod N = I - 1) into\n"
                   "DIR, with the other slices running at once (a job array); the slice that\n"
                   "ends last, or --merge, writes results.csv",
                   [a](const std::string& v) { a->slice = study::parseSweepSlice(v); });
  // Read as the line is parsed, before CLI11 checks what is required: SCENE and --out are
  // then not (runSweep refuses them with --merge).
  addCheckedOption(*sweep, "--merge", "DIR",
                   "complete DIR/results.csv from the slices' rows (DIR/rows/), or name the\n"
                   "points still missing; alone, without SCENE or other options",
                   [a, scene, out](const std::string& v) {
                     a->merge = v;
                     scene->required(false);
                     out->required(false);
                   });
  addCheckedOption(*sweep, "--analysis", "run|modes|orbit",
                   "modes: per point the linear stability of the steady state instead of a run\n"
                   "(tribo modes): columns max_growth_rate, frequency, unstable_modes;\n"
                   "orbit: per point the periodic orbit (tribo orbit; a forced scene's over a\n"
                   "forcing frequency is its frequency-response curve): columns period,\n"
                   "amplitude_pp, x_min, x_max, largest_multiplier, stable, iterations, residual",
                   [a](const std::string& v) {
                     const auto analysis = study::kSweepAnalysisNames.find(v);
                     if (!analysis)
                       throw std::invalid_argument(
                           "--analysis: expected run, modes or orbit, found '" + v + "'");
                     a->spec.analysis = *analysis;
                   });
  sweep->footer(
      "Rows are written to DIR/results.csv as each point finishes; run again with the same\n"
      "arguments to resume an interrupted sweep. Under mpirun the points are spread over the\n"
      "ranks; on a cluster without MPI run slices (--slice, docs/sweeps-on-clusters.md).\n"
      "exit status: 0 every point recorded (failed points are rows with their error; with\n"
      "--slice: every point of the slice), 1 usage or DIR holds another sweep or is in use,\n"
      "2 bad scene or swept parameter, 3 --merge: points missing (named), 4 write error");
  return {sweep, [sweep, a] { return runSweep(*sweep, *a); }};
}

}  // namespace tribo::app
