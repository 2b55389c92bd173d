// Runs a parameter sweep on the local cores: every point of the grid is one independent
// scene run (study/sweep/sweep_point.hpp), taken from a shared queue by one of `jobs` std::threads,
// and its row goes to DIR/results.csv as soon as it is done (study/sweep/sweep_results.hpp), with a
// progress line on the terminal. Points already in the folder from an interrupted run of
// the same sweep are skipped; a failed point is recorded with its error and the sweep goes
// on. The distributed runner (study/sweep/sweep_mpi.hpp) plans the same way and shares the threads.
// Not here: argument parsing (apps/sweep_command.cpp), plotting (scripts/figures/).
#pragma once

#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "study/sweep/sweep_grid.hpp"
#include "study/sweep/sweep_point.hpp"

namespace tribo::study {

// What a sweep is, as the command line gives it.
struct SweepSpec {
  std::string scene_path;
  std::vector<std::string> fixed_overrides;      // --set NAME=VALUE
  std::vector<SweepAxis> axes;                   // --grid/--list, in order
  std::optional<SettleRule> settle;              // --settle
  bool keep_trajectories = false;                // DIR/points/<point>/{trajectory.csv,summary.json}
  SweepAnalysis analysis = SweepAnalysis::kRun;  // --analysis
  // Laws the scene may select besides its own (SweepSetup::user_laws); none on the command line.
  std::map<std::string, std::shared_ptr<const friction::FrictionLaw>> user_laws = {};
};

// A checked sweep, ready to run anywhere.
struct SweepPlan {
  SweepSetup setup;
  SweepGrid grid;
  std::string manifest;  // the text of sweep.json
  bool keep_trajectories = false;
};

// Checks the sweep against its scene (given as text, e.g. read once and shared): the scene
// loads with the fixed overrides (alone or with the first point's values), every swept
// name is a parameter of it, numeric parameters get numbers, and a settle rule has a
// coordinate to watch. Throws SceneError (the scene) or SweepSpecError (the axes).
SweepPlan planSweep(const SweepSpec& spec, const std::string& scene_text);
// The same, reading spec.scene_path (SceneError if it cannot be read).
SweepPlan planSweep(const SweepSpec& spec);
std::string readSceneText(const std::string& path);

struct SweepReport {
  std::size_t points = 0;     // in the grid
  std::size_t resumed = 0;    // found done in the folder at the start
  std::size_t ran = 0;        // run and recorded now
  std::size_t failed = 0;     // of those: diverged or error
  std::size_t unsettled = 0;  // of those: complete but still changing at the duration cap
  std::size_t dropped = 0;    // lines of the folder dropped at the start (cut off)
  double wall_seconds = 0;
  bool complete = false;  // every point is in results.csv, now in point order
};

struct LocalRunOptions {
  unsigned jobs = 0;             // threads; 0: one per core
  std::FILE* progress = stderr;  // null: silent
  std::size_t stop_after = 0;    // > 0: stop after recording this many (as if killed)
};

SweepReport runSweepLocally(const SweepPlan& plan, const std::filesystem::path& out,
                            const LocalRunOptions& options);

// Shared by the local and distributed runners.
struct FinishedPoint {
  std::size_t index = 0;
  std::string line;  // the results row
  bool failed = false;
  bool unsettled = false;
};
// Runs points on `jobs` threads until `next` (called under no lock by several threads; it
// must be thread-safe) has none left; `done` gets each finished point (from any thread).
void runPointsOnThreads(const SweepPlan& plan, const std::filesystem::path& out, unsigned jobs,
                        const std::function<std::optional<std::size_t>()>& next,
                        const std::function<void(const FinishedPoint&)>& done);
// Threads to use when none are asked for: the cores, shared among `ranks_here` processes.
unsigned defaultJobs(unsigned ranks_here = 1);

}  // namespace tribo::study
