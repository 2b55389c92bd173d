#include "study/view/view_page.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "io/file_read.hpp"
#include "io/output_channels.hpp"
#include "io/scene_loader.hpp"
#include "io/scene_source.hpp"
#include "io/urdf_reader.hpp"
#include "io/urdf_scene.hpp"
#include "study/csv_text.hpp"
#include "study/file_commit.hpp"
#include "study/view/page_template.hpp"
#include "study/view/view_assets.hpp"
#include "study/view/view_scene.hpp"
#include "study/view/view_trajectory.hpp"

namespace tribo::study {

namespace {

std::string readText(const std::filesystem::path& file, const std::string& what) {
  return io::readFileBounded(file, what, io::kMaxJsonBytes);
}

void appendSeries(std::string& out, const std::vector<double>& values) {
  out.push_back('[');
  char buf[40];
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) out.push_back(',');
    const double v = values[i];
    if (!std::isfinite(v)) {
      out += "null";
      continue;
    }
    char* end = csvNumberTo(buf, buf + sizeof buf, v, 7);
    out.append(buf, end);
  }
  out.push_back(']');
}

}  // namespace

std::filesystem::path threeJsPath(const ViewOptions& options) {
  if (!options.three_js.empty()) return options.three_js;
  if (const char* env = std::getenv("TRIBO_THREE_JS"); env && *env) return env;
  return "/usr/share/javascript/three/three.min.js";
}

namespace {

nlohmann::json readSummary(const std::filesystem::path& run_dir) {
  try {
    return nlohmann::json::parse(readText(run_dir / "summary.json", "run summary"));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error("'" + (run_dir / "summary.json").string() + "': " + e.what());
  }
}

// three.js's path; throws when it is missing (checked first: a set-up problem).
std::filesystem::path requireThreeJs(const ViewOptions& options) {
  const std::filesystem::path three_path = threeJsPath(options);
  if (!std::filesystem::exists(three_path))
    throw std::runtime_error("three.js not found at '" + three_path.string() +
                             "': install Debian's libjs-three (scripts/setup.sh) or set "
                             "TRIBO_THREE_JS");
  return three_path;
}

}  // namespace

ViewPageInfo writeRunView(const std::filesystem::path& run_dir, const ViewOptions& options) {
  requireThreeJs(options);
  const nlohmann::json summary = readSummary(run_dir);
  const std::string scene_path = summary.value("scene", "");
  std::vector<std::string> overrides;
  if (summary.contains("parameters") && summary["parameters"].is_object())
    for (const auto& [name, value] : summary["parameters"].items())
      overrides.push_back(name + "=" +
                          (value.is_string() ? value.get<std::string>() : value.dump()));
  io::Scene scene;
  try {
    // A robot run from its URDF alone (`tribo run ROBOT.urdf`) reloads as `tribo run` loaded
    // it: its settings are the parameters recorded. Its --package-path folders are not
    // recorded: they come again from options.package_paths (or ROS_PACKAGE_PATH).
    io::SceneRequest request;
    request.package_paths = options.package_paths;
    if (io::isUrdfScene(scene_path)) {
      // summary.json also records what the run derived (support_points...): only the
      // settings go back in.
      for (const std::string& o : overrides)
        for (const std::string& name : io::urdfSceneSettings())
          if (o.rfind(name + "=", 0) == 0) request.overrides.push_back(o);
    } else {
      request.overrides = overrides;
    }
    scene = io::loadAnyScene(scene_path, request);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot reload the run's scene '" + scene_path + "' (" + e.what() +
                             "); run tribo view from the folder the run was started in");
  }
  ViewPageInfo info;
  const std::string page = runViewPage(scene, run_dir, options, &info);
  info.file = run_dir / "view.html";
  writeFileWhole(info.file, page);
  return info;
}

std::string runViewPage(const io::Scene& scene, const std::filesystem::path& run_dir,
                        const ViewOptions& options, ViewPageInfo* info_out) {
  const std::filesystem::path three_path = requireThreeJs(options);
  const nlohmann::json summary = readSummary(run_dir);
  const std::string scene_path = summary.value("scene", "");
  const ViewTrajectory traj =
      readViewTrajectory(run_dir / "trajectory.csv", options.frame_cap, options.value_budget);

  ViewPageInfo info;
  info.frames = traj.frames();
  info.rows = traj.rows;
  info.orientation = false;
  for (const auto& c : traj.columns)
    if (c.size() > 3 && c.compare(c.size() - 3, 3, ".qw") == 0) info.orientation = true;

  // Each column's unit ("" where it has none), for the plot's axis labels.
  nlohmann::json units = nlohmann::json::array();
  for (const auto& c : traj.columns) units.push_back(io::channelUnit(*scene.model, c));
  nlohmann::json meta = {
      {"kind", "run"},
      {"scene_path", scene_path},
      {"run_dir", run_dir.string()},
      {"status", summary.value("status", "")},
      {"parameters", summary.value("parameters", nlohmann::json::object())},
      {"stick_speed", scene.output.summary.stick_speed},
      {"observed", summary.contains("observed") ? summary["observed"].value("channel", "") : ""},
      {"rows", traj.rows},
      {"stride", traj.stride},
      {"frame_cap", options.frame_cap},
      {"columns", traj.columns},
      {"units", units}};
  std::string data =
      "{\"meta\":" + meta.dump() + ",\"scene\":" + viewSceneJson(*scene.model) + ",\"series\":[";
  for (std::size_t c = 0; c < traj.values.size(); ++c) {
    if (c) data += ",\n";
    appendSeries(data, traj.values[c]);
  }
  data += "]}";

  std::string page(view_assets::kPageHtml);
  replaceMarker(page, "/*TRIBO_CSS*/", std::string(view_assets::kPageCss), "replay");
  replaceMarker(page, "/*TRIBO_ERRORS*/", std::string(view_assets::kErrorsScript), "replay");
  replaceMarker(page, "/*TRIBO_THREE*/", scriptSafe(readText(three_path, "three.js")), "replay");
  replaceMarker(page, "/*TRIBO_DATA*/", "window.TRIBO_DATA = " + scriptSafe(data) + ";", "replay");
  std::string js;
  for (std::string_view part : view_assets::kScripts) js += std::string(part) + "\n";
  replaceMarker(page, "/*TRIBO_JS*/", scriptSafe(js), "replay");
  info.bytes = page.size();
  if (info_out) *info_out = info;
  return page;
}

}  // namespace tribo::study
