#include "apps/sweep_command.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <optional>

#include "io/scene_parameters.hpp"
#include "study/sweep/sweep_results.hpp"
#include "study/sweep/sweep_runner.hpp"
#ifdef TRIBO_WITH_MPI
#include "study/sweep/sweep_mpi.hpp"
#endif

namespace tribo::app {

const char* const kSweepUsage =
    "usage: tribo sweep SCENE.yaml --out DIR (--grid NAME=START:STOP:COUNT | --list "
    "NAME=V1,V2,...)...\n"
    "                   [--set NAME=VALUE ...] [--settle TOL] [--settle-every SECONDS]\n"
    "                   [--jobs N] [--keep-trajectories] [--quiet] [--analysis run|modes]\n"
    "\n"
    "  sweep   run the scene at every combination of the swept values; one row per point\n"
    "          in DIR/results.csv, written as each point finishes; run again with the same\n"
    "          arguments to resume an interrupted sweep. Under mpirun the points are spread\n"
    "          over the ranks.\n"
    "  --grid  COUNT values from START to STOP, both included (repeatable)\n"
    "  --list  the values given (repeatable)\n"
    "  --set   fix a parameter for every point (repeatable)\n"
    "  --settle TOL  stop each point once the amplitude of its last cycles changes by less\n"
    "          than TOL (relative, e.g. 1e-3); the scene's duration is then the cap\n"
    "  --settle-every SECONDS  simulated time between settle checks (default 5)\n"
    "  --jobs  threads per process (default: every core, shared among the ranks of a node)\n"
    "  --keep-trajectories  also write DIR/points/<point>/trajectory.csv and summary.json\n"
    "  --quiet no progress line\n"
    "  --analysis modes  per point the linear stability of the steady state instead of a run\n"
    "          (tribo modes): columns max_growth_rate, frequency, unstable_modes\n";

namespace {

namespace fs = std::filesystem;

int usage(const std::string& problem) {
  std::fprintf(stderr, "tribo sweep: %s\n\n%s", problem.c_str(), kSweepUsage);
  return 1;
}

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

std::optional<double> positive(const std::string& text) {
  const auto v = io::parseNumber(text);
  if (!v || !(*v > 0)) return std::nullopt;
  return v;
}

}  // namespace

int sweepCommand(const std::vector<std::string>& args) {
  study::SweepSpec spec;
  std::string out;
  unsigned jobs = 0;
  bool quiet = false;
  study::SettleRule settle;
  bool want_settle = false, have_every = false;
  for (const auto& a : args)
    if (a == "--help" || a == "-h") {
      std::printf("%s", kSweepUsage);
      return 0;
    }
  try {
    for (std::size_t i = 0; i < args.size(); ++i) {
      const std::string& a = args[i];
      const bool takes_value = a == "--out" || a == "--set" || a == "--grid" || a == "--list" ||
                               a == "--settle" || a == "--settle-every" || a == "--jobs" ||
                               a == "--analysis";
      if (takes_value && i + 1 >= args.size()) return usage(a + " needs a value");
      if (a == "--out") {
        out = args[++i];
      } else if (a == "--set") {
        spec.fixed_overrides.push_back(args[++i]);
      } else if (a == "--grid") {
        spec.axes.push_back(study::parseGridAxis(args[++i]));
      } else if (a == "--list") {
        spec.axes.push_back(study::parseListAxis(args[++i]));
      } else if (a == "--settle" || a == "--settle-every") {
        const auto v = positive(args[++i]);
        if (!v) return usage(a + ": expected a positive number, found '" + args[i] + "'");
        (a == "--settle" ? settle.tolerance : settle.check_interval) = *v;
        (a == "--settle" ? want_settle : have_every) = true;
      } else if (a == "--jobs") {
        const auto v = io::parseNumber(args[++i]);
        if (!v || *v < 1 || *v > 4096 || *v != static_cast<unsigned>(*v))
          return usage("--jobs: expected a whole number from 1 to 4096, found '" + args[i] + "'");
        jobs = static_cast<unsigned>(*v);
      } else if (a == "--analysis") {
        const auto v = study::kSweepAnalysisNames.find(args[++i]);
        if (!v) return usage("--analysis: expected run or modes, found '" + args[i] + "'");
        spec.analysis = *v;
      } else if (a == "--keep-trajectories") {
        spec.keep_trajectories = true;
      } else if (a == "--quiet") {
        quiet = true;
      } else if (a.rfind("--", 0) == 0) {
        return usage("unknown option '" + a + "'");
      } else if (spec.scene_path.empty()) {
        spec.scene_path = a;
      } else {
        return usage("more than one scene given ('" + spec.scene_path + "', '" + a + "')");
      }
    }
  } catch (const study::SweepSpecError& e) {
    return usage(e.what());
  }
  if (spec.scene_path.empty()) return usage("no scene file given");
  if (out.empty()) return usage("no output folder given (--out DIR)");
  if (spec.axes.empty()) return usage("nothing to sweep (give --grid or --list)");
  if (have_every && !want_settle) return usage("--settle-every needs --settle");
  if (want_settle) spec.settle = settle;

  const int world = launcherWorldSize();
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
    return usage("started by an MPI launcher with " + std::to_string(world) +
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

}  // namespace tribo::app
