#include "apps/view_command.hpp"

#include <cstdio>
#include <exception>
#include <filesystem>

#include "io/scene_parameters.hpp"
#include "study/view/view_page.hpp"
#include "study/view/view_sweep.hpp"

namespace tribo::app {
namespace {

constexpr const char* kUsage =
    "usage: tribo view RUN_DIR [--frames N] [--three PATH] [--package-path DIR ...]\n"
    "       tribo view SWEEP_DIR (a folder of tribo sweep: sweep.json, results.csv)\n"
    "  writes RUN_DIR/view.html: the run replayed in a browser (one file, no server, no\n"
    "  network): the scene's bodies and geometry, the recorded motion, play/pause/speed/\n"
    "  scrub/frame steps, orbit camera (drag: turn, right drag: pan, wheel: zoom), follow a\n"
    "  body, trails, force arrows and stick/slip colours (when recorded), a plot of chosen\n"
    "  channels; docs/view.md. Run it from the folder the run was started in (the scene is\n"
    "  reloaded from summary.json's path with the run's parameters).\n"
    "  --frames  frames the page holds at most (20000; long runs are decimated)\n"
    "  --three   three.js to inline (default $TRIBO_THREE_JS, else Debian's libjs-three:\n"
    "            /usr/share/javascript/three/three.min.js)\n"
    "  --package-path  a folder holding ROS packages, as the run was given (robot meshes)\n"
    "  tribo run SCENE --out DIR --view  does the same after the run and records\n"
    "  orientations for it\n"
    "  A sweep's folder gets a heat map of a chosen result over two swept parameters\n"
    "  (a line over one); points kept with --keep-trajectories link to their replay.\n"
    "exit status: 0 written, 1 usage, 2 run, scene or three.js unreadable, 4 write error\n";

int usage(const std::string& problem) {
  std::fprintf(stderr, "tribo view: %s\n\n%s", problem.c_str(), kUsage);
  return 1;
}

}  // namespace

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

int viewCommand(const std::vector<std::string>& args) {
  std::string run_dir, three_js;
  std::vector<std::string> package_paths;
  std::size_t frames = study::ViewOptions{}.frame_cap;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      std::printf("%s", kUsage);
      return 0;
    }
    if (a == "--frames" || a == "--three" || a == "--package-path") {
      if (i + 1 >= args.size()) return usage(a + " needs a value");
      const std::string& v = args[++i];
      if (a == "--three") {
        three_js = v;
        continue;
      }
      if (a == "--package-path") {
        package_paths.push_back(v);
        continue;
      }
      const auto n = io::parseNumber(v);
      if (!n || !(*n >= 2) || *n > 1e8 || *n != static_cast<double>(static_cast<long>(*n)))
        return usage("--frames needs a whole number from 2 to 1e8, not '" + v + "'");
      frames = static_cast<std::size_t>(*n);
    } else if (a.rfind("--", 0) == 0) {
      return usage("unknown option '" + a + "'");
    } else if (run_dir.empty()) {
      run_dir = a;
    } else {
      return usage("more than one folder given ('" + run_dir + "', '" + a + "')");
    }
  }
  if (run_dir.empty()) return usage("no run folder given");
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
  return writeView(run_dir, frames, three_js, package_paths);
}

}  // namespace tribo::app
