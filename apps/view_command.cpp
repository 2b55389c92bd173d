#include "apps/view_command.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "apps/common_options.hpp"
#include "io/scene_parameters.hpp"
#include "study/file_commit.hpp"
#include "study/view/view_branch.hpp"
#include "study/view/view_page.hpp"
#include "study/view/view_sweep.hpp"

namespace tribo::app {
int writeView(const std::filesystem::path& run_dir, std::size_t frame_cap,
              const std::string& three_js, const std::vector<std::string>& package_paths) {
  study::ViewOptions options;
  options.frame_cap = frame_cap;
  options.three_js = three_js;
  options.package_paths = package_paths;
  study::ViewPageInfo info;
  try {
    info = study::writeRunView(run_dir, options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo view: %s\n", e.what());
    return std::filesystem::exists(run_dir / "view.html.partial") ? 4 : 2;
  }
  std::printf("view             %s (%.3g MB, %zu frames of %zu rows%s)\n",
              info.file.string().c_str(), static_cast<double>(info.bytes) / 1e6, info.frames,
              info.rows, info.orientation ? "" : "; no orientations recorded");
  return 0;
}

namespace {

struct ViewArguments {
  std::string run_dir, three_js;
  std::vector<std::string> package_paths;
  std::size_t frames = study::ViewOptions{}.frame_cap;
};

int runView(const ViewArguments& a) {
  const std::string& run_dir = a.run_dir;
  const std::string& three_js = a.three_js;
  const std::size_t frames = a.frames;
  if (study::isBranchDir(run_dir)) {
    study::ViewOptions options;
    options.frame_cap = frames;
    try {
      const study::BranchViewInfo info = study::writeBranchView(run_dir, options);
      std::printf(
          "view             %s (%.3g MB, %zu points, %zu events, %zu of %zu orbit samples)\n",
          info.file.string().c_str(), static_cast<double>(info.bytes) / 1e6, info.points,
          info.events, info.orbit_samples, info.orbit_rows);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "tribo view: %s\n", e.what());
      const auto partial = study::partialPath(std::filesystem::path(run_dir) / "view.html");
      return std::filesystem::exists(partial) ? 4 : 2;
    }
    return 0;
  }
  if (study::isSweepDir(run_dir)) {
    study::ViewOptions options;
    options.frame_cap = frames;
    options.three_js = three_js;
    try {
      const study::SweepViewInfo info = study::writeSweepView(run_dir, options);
      std::printf("view             %s (%.3g MB, %zu points, %zu with a replay page)\n",
                  info.file.string().c_str(), static_cast<double>(info.bytes) / 1e6, info.points,
                  info.linked);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "tribo view: %s\n", e.what());
      return 2;
    }
    return 0;
  }
  return writeView(run_dir, frames, three_js, a.package_paths);
}

}  // namespace

Command addViewCommand(CLI::App& tribo) {
  auto a = std::make_shared<ViewArguments>();
  CLI::App* view = tribo.add_subcommand(
      "view", "write RUN_DIR/view.html: replay a run, map a sweep or draw an orbit branch");
  addPathArgument(*view, "RUN_DIR", a->run_dir,
                  "a folder of tribo run, of tribo sweep (sweep.json, results.csv) or of\n"
                  "tribo orbit --continue (branch.json, branch.csv, branch_orbits.csv)");
  addCheckedOption(
      *view, "--frames", "N",
      "frames the page holds at most, 2 to 1e8 (20000; long runs are decimated;\n"
      "a branch: samples of each orbit)",
      [a](const std::string& v) {
        const auto n = io::parseNumber(v);
        if (!n || !(*n >= 2) || *n > 1e8 || *n != static_cast<double>(static_cast<long>(*n)))
          throw std::invalid_argument("--frames needs a whole number from 2 to 1e8, not '" + v +
                                      "'");
        a->frames = static_cast<std::size_t>(*n);
      });
  view->add_option("--three", a->three_js,
                   "three.js to inline (default $TRIBO_THREE_JS, else Debian's libjs-three:\n"
                   "/usr/share/javascript/three/three.min.js)")
      ->type_name("PATH");
  addPackagePathOption(*view, a->package_paths);
  view->footer(
      "The page is one file, no server, no network: the scene's bodies and geometry, the\n"
      "recorded motion, play/pause/speed/scrub/frame steps, orbit camera (drag: turn, right\n"
      "drag: pan, wheel: zoom), follow a body, trails, force arrows and stick/slip colours (when\n"
      "recorded), a plot of chosen channels; docs/view.md. Run it from the folder the run was\n"
      "started in (the scene is reloaded from summary.json's path with the run's parameters).\n"
      "tribo run SCENE --out DIR --view does the same after the run and records orientations.\n"
      "A sweep's folder gets a heat map of a chosen result over two swept parameters (a line\n"
      "over one); points kept with --keep-trajectories link to their replay.\n"
      "A branch's folder (tribo orbit --continue) gets its bifurcation diagram: amplitude\n"
      "against the parameter, stable orbits solid, unstable dashed, steady sliding on the\n"
      "axis, events labelled; a click on a point (left/right arrows: the previous/next one)\n"
      "replays its orbit over one period; that page needs no three.js.\n"
      "exit status: 0 written, 1 usage, 2 run, sweep, branch, scene or three.js unreadable,\n"
      "4 write error");
  return {view, [a] { return runView(*a); }};
}

}  // namespace tribo::app
