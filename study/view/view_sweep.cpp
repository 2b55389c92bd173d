#include "study/view/view_sweep.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/file_read.hpp"
#include "study/file_commit.hpp"
#include "study/view/page_template.hpp"
#include "study/view/view_assets.hpp"
#include "study/view/view_trajectory.hpp"

namespace tribo::study {

namespace {

std::string readText(const std::filesystem::path& file) {
  return io::readFileBounded(file, "sweep manifest", io::kMaxJsonBytes);
}

}  // namespace

bool isSweepDir(const std::filesystem::path& dir) {
  return std::filesystem::exists(dir / "sweep.json");
}

SweepViewInfo writeSweepView(const std::filesystem::path& dir, const ViewOptions& options) {
  nlohmann::json manifest;
  try {
    manifest = nlohmann::json::parse(readText(dir / "sweep.json"));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error("'" + (dir / "sweep.json").string() + "': " + e.what());
  }
  const std::filesystem::path results = dir / "results.csv";
  io::checkReadableFile(results, "sweep results", io::kMaxSweepResultsBytes);
  std::ifstream in(results);
  if (!in) throw std::runtime_error("cannot read '" + results.string() + "'");
  std::string line;
  io::getLineBounded(in, line, io::kMaxCsvLineBytes, results);
  const std::vector<std::string> columns = csvFieldsOf(line);
  nlohmann::json rows = nlohmann::json::array();
  nlohmann::json linked = nlohmann::json::object();
  SweepViewInfo info;
  // The points' folders by index: named by the sweep with its zero padding ("07" of 12),
  // listed in results.csv's point column without it ("7").
  std::map<unsigned long, std::string> folders;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "points", ec)) {
    const std::string name = entry.path().filename().string();
    if (!name.empty() && name.size() <= 9 &&
        name.find_first_not_of("0123456789") == std::string::npos)
      folders.emplace(std::stoul(name), name);
  }
  std::size_t kept = 0;
  while (io::getLineBounded(in, line, io::kMaxCsvLineBytes, results)) {
    if (line.empty()) continue;
    const std::vector<std::string> fields = csvFieldsOf(line);
    rows.push_back(fields);
    const std::string& index = fields.front();
    if (index.empty() || index.size() > 9 ||
        index.find_first_not_of("0123456789") != std::string::npos)
      continue;
    const auto folder = folders.find(std::stoul(index));
    if (folder == folders.end()) continue;
    const std::filesystem::path point = dir / "points" / folder->second;
    if (!std::filesystem::exists(point / "summary.json")) continue;
    if (++kept > kSweepPointViewCap) continue;
    try {
      writeRunView(point, options);
      linked[index] = "points/" + folder->second + "/view.html";
      ++info.linked;
    } catch (const std::exception&) {
      // not linked; the page says which points kept a trajectory without a page
    }
  }
  info.points = rows.size();
  const nlohmann::json data = {{"meta",
                                {{"kind", "sweep"},
                                 {"scene", manifest.value("scene", "")},
                                 {"set", manifest.value("set", nlohmann::json::array())},
                                 {"axes", manifest.value("axes", nlohmann::json::array())},
                                 {"columns", columns},
                                 {"kept", kept},
                                 {"point_view_cap", kSweepPointViewCap}}},
                               {"rows", rows},
                               {"linked", linked}};
  std::string page(view_assets::kSweepHtml);
  replaceMarker(page, "/*TRIBO_CSS*/", std::string(view_assets::kPageCss), "sweep");
  replaceMarker(page, "/*TRIBO_ERRORS*/", std::string(view_assets::kErrorsScript), "sweep");
  replaceMarker(page, "/*TRIBO_DATA*/", "window.TRIBO_DATA = " + scriptSafe(data.dump()) + ";",
                "sweep");
  replaceMarker(page, "/*TRIBO_JS*/",
                scriptSafe(std::string(view_assets::kPlotScript) + "\n" +
                           std::string(view_assets::kSweepScript)),
                "sweep");
  info.file = dir / "view.html";
  writeFileWhole(info.file, page);
  info.bytes = page.size();
  return info;
}

}  // namespace tribo::study
