// The replay page of a run: `tribo view RUN_DIR` writes RUN_DIR/view.html, one file that
// opens in a browser without a server or network. It holds three.js (read from Debian's
// libjs-three at generation time), the page's own HTML/CSS/JS (view/, embedded at build
// time), the scene's geometry (the scene reloaded with the run's parameters) and the
// recorded motion, decimated to a frame cap. docs/view.md describes the page.
// Not here: the page's behaviour (view/*.js), running scenes.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace tribo::io {
struct Scene;
}

namespace tribo::study {

struct ViewOptions {
  std::size_t frame_cap = 20000;           // frames at most
  std::size_t value_budget = 4'000'000;    // numbers of the trajectory at most (page size)
  std::filesystem::path three_js;          // empty: $TRIBO_THREE_JS, else Debian's path
  std::vector<std::string> package_paths;  // the run's --package-path folders (robot meshes)
};

struct ViewPageInfo {
  std::filesystem::path file;
  std::size_t bytes = 0;
  std::size_t frames = 0;    // frames the page holds
  std::size_t rows = 0;      // rows of trajectory.csv
  bool orientation = false;  // the run recorded orientations
};

// Where three.js is read from: options.three_js, else $TRIBO_THREE_JS, else
// /usr/share/javascript/three/three.min.js.
std::filesystem::path threeJsPath(const ViewOptions& options);

// Reads RUN_DIR/summary.json and trajectory.csv, reloads the scene and writes
// RUN_DIR/view.html (whole or not at all). Throws std::runtime_error naming what is missing.
ViewPageInfo writeRunView(const std::filesystem::path& run_dir, const ViewOptions& options = {});

// The page's text for RUN_DIR's summary.json and trajectory.csv, drawing `scene`, the scene
// the run ran, given already loaded (a Python Result's, which may come from YAML text that no
// file holds) instead of reloaded. `info` (optional) gets the frames, rows and size; its file
// is left empty. Throws std::runtime_error naming what is missing.
std::string runViewPage(const io::Scene& scene, const std::filesystem::path& run_dir,
                        const ViewOptions& options = {}, ViewPageInfo* info = nullptr);

}  // namespace tribo::study
