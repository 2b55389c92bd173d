// The branch page's generator (study/view/view_branch.hpp) on hand-written branch folders: the
// data it embeds (points, events, orbits, decimated to the caps with their extremes kept) and
// its errors, each naming the file and what is missing or malformed. The page's behaviour in a
// browser is tested in tests/view/ (case branch), on a branch tribo orbit --continue computes.
#include "study/view/view_branch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fs = std::filesystem;
using namespace tribo::study;

namespace {

const std::string kManifest = R"({
  "scene": "scenes/belt.yaml", "parameter": "v_b", "from": 1.0, "to": 2.0, "observed": "box.x",
  "status": "reached_end", "stop_reason": "reached v_b = 2", "start": "orbit", "points": 3,
  "events": [{"kind": "fold", "parameter": 1.55, "between": [1, 2]}]
})";

const std::string kTable =
    "index,parameter,period,amplitude_pp,largest_multiplier,stable,stick_fraction,min_slip,"
    "x_min,x_max,dp_ds,arclength,iterations,residual,trivial_error,steady_growth_rate,event\n"
    "0,1,1.15,0.4,1e-06,1,0.07,0.001,-0.1,0.3,1,0,2,1e-14,2e-05,0.06,\n"
    "1,1.5,1.14,0.5,0.9,1,0.06,0.002,-0.2,0.3,0.5,0.5,2,1e-14,2e-05,-0.01,\n"
    "2,1.4,1.13,0.45,1.2,0,,,-0.15,0.3,-0.5,0.6,3,1e-14,2e-05,,fold;stability_change\n";

// Sample k of `samples` of an orbit: x from 0.3 at k = 0 down to x_min halfway.
double orbitX(int k, int samples, double x_min) {
  const double u = std::abs(2.0 * k / samples - 1.0);  // 1 at the start, 0 halfway
  return x_min + u * (0.3 - x_min);
}

// Point p's orbit: `samples` rows, t = 0.1 k.
std::string orbitRows(int point, int samples, double x_min) {
  std::ostringstream out;
  out.precision(17);
  for (int k = 0; k < samples; ++k)
    out << point << "," << 0.1 * k << "," << orbitX(k, samples, x_min) << "\n";
  return out.str();
}

double lowest(const nlohmann::json& values) {
  double v = values.at(0).get<double>();
  for (const auto& x : values) v = std::min(v, x.get<double>());
  return v;
}

double highest(const nlohmann::json& values) {
  double v = values.at(0).get<double>();
  for (const auto& x : values) v = std::max(v, x.get<double>());
  return v;
}

void writeText(const fs::path& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
}

fs::path branchDir(const std::string& name, int samples = 10) {
  const fs::path d = fs::temp_directory_path() / ("tribo_view_branch_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  writeText(d / "branch.json", kManifest);
  writeText(d / "branch.csv", kTable);
  writeText(d / "branch_orbits.csv", "point,t,box.x\n" + orbitRows(0, samples, -0.1) +
                                         orbitRows(1, samples, -0.2) +
                                         orbitRows(2, samples, -0.15));
  return d;
}

// The JSON the page holds (window.TRIBO_DATA).
nlohmann::json pageData(const fs::path& page) {
  std::ifstream in(page);
  std::ostringstream s;
  s << in.rdbuf();
  const std::string text = s.str();
  const std::string marker = "window.TRIBO_DATA = ";
  const std::size_t from = text.find(marker);
  const std::size_t to = text.find(";</script>", from);
  if (from == std::string::npos || to == std::string::npos) return nullptr;
  return nlohmann::json::parse(text.substr(from + marker.size(), to - from - marker.size()));
}

// The message writeBranchView throws for `dir` ("" when it does not throw).
std::string errorOf(const fs::path& dir, const ViewOptions& options = {}) {
  try {
    writeBranchView(dir, options);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

bool holds(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST(ViewBranch, PageHoldsThePointsEventsAndOrbits) {
  const fs::path dir = branchDir("page");
  EXPECT_TRUE(isBranchDir(dir));
  EXPECT_FALSE(isBranchDir(dir / "nowhere"));
  const BranchViewInfo info = writeBranchView(dir);
  EXPECT_EQ(info.file, dir / "view.html");
  EXPECT_EQ(info.points, 3u);
  EXPECT_EQ(info.events, 1u);
  EXPECT_EQ(info.orbit_rows, 30u);
  EXPECT_EQ(info.orbit_samples, 30u);
  EXPECT_TRUE(info.steady_growth);
  EXPECT_EQ(info.bytes, fs::file_size(info.file));

  const nlohmann::json data = pageData(info.file);
  ASSERT_TRUE(data.is_object());
  EXPECT_EQ(data["meta"]["kind"], "branch");
  EXPECT_EQ(data["meta"]["parameter"], "v_b");
  EXPECT_EQ(data["meta"]["observed"], "box.x");
  ASSERT_EQ(data["points"].size(), 3u);
  const nlohmann::json& last = data["points"][2];
  EXPECT_EQ(last["index"], 2);
  EXPECT_DOUBLE_EQ(last["parameter"].get<double>(), 1.4);
  EXPECT_DOUBLE_EQ(last["period"].get<double>(), 1.13);
  EXPECT_DOUBLE_EQ(last["amplitude_pp"].get<double>(), 0.45);
  EXPECT_DOUBLE_EQ(last["largest_multiplier"].get<double>(), 1.2);
  EXPECT_EQ(last["stable"], false);
  EXPECT_EQ(last["undecided"], false);                // no stability column: decided
  EXPECT_TRUE(last["stick_fraction"].is_null());      // empty in branch.csv
  EXPECT_TRUE(last["steady_growth_rate"].is_null());  // no steady state there
  EXPECT_EQ(last["event"], "fold;stability_change");
  EXPECT_DOUBLE_EQ(data["points"][1]["steady_growth_rate"].get<double>(), -0.01);
  ASSERT_EQ(data["events"].size(), 1u);
  EXPECT_EQ(data["events"][0]["kind"], "fold");
  EXPECT_DOUBLE_EQ(data["events"][0]["parameter"].get<double>(), 1.55);
  EXPECT_TRUE(data["meta"]["hopf"].is_null());
  ASSERT_EQ(data["orbits"].size(), 3u);
  EXPECT_EQ(data["orbits"][1]["t"].size(), 10u);
  EXPECT_NEAR(lowest(data["orbits"][1]["x"]), -0.2, 1e-12);
  EXPECT_NEAR(highest(data["orbits"][1]["x"]), 0.3, 1e-12);
}

TEST(ViewBranch, TheStabilityColumnMarksUndecidedPoints) {
  const fs::path dir = branchDir("undecided");
  writeText(dir / "branch.csv",
            "index,parameter,period,amplitude_pp,largest_multiplier,stable,stability,event\n"
            "0,1,1.15,0.4,0.5,1,stable,\n"
            "1,1.5,1.14,0.5,1.0000001,0,undecided,\n"
            "2,1.4,1.13,0.45,1.2,0,unstable,stability_change\n");
  const nlohmann::json data = pageData(writeBranchView(dir).file);
  ASSERT_EQ(data["points"].size(), 3u);
  EXPECT_EQ(data["points"][0]["undecided"], false);
  EXPECT_EQ(data["points"][1]["undecided"], true);
  EXPECT_EQ(data["points"][1]["stable"], false);
  EXPECT_EQ(data["points"][2]["undecided"], false);
}

TEST(ViewBranch, LongOrbitsDecimatedKeepingEndsAndExtremes) {
  const fs::path dir = branchDir("decimated", 101);
  ViewOptions options;
  options.frame_cap = 10;
  const BranchViewInfo info = writeBranchView(dir, options);
  EXPECT_EQ(info.orbit_rows, 303u);
  EXPECT_LT(info.orbit_samples, 3u * 13u);
  const nlohmann::json data = pageData(info.file);
  const double x_min[] = {-0.1, -0.2, -0.15};
  for (int p = 0; p < 3; ++p) {
    const nlohmann::json& t = data["orbits"][p]["t"];
    EXPECT_LE(t.size(), 13u);  // the cap, the last and the two extremes
    EXPECT_DOUBLE_EQ(t.front().get<double>(), 0.0);
    EXPECT_NEAR(t.back().get<double>(), 10.0, 1e-9);  // the last sample, t = 0.1 * 100
    double sample_min = 1.0;
    for (int k = 0; k < 101; ++k) sample_min = std::min(sample_min, orbitX(k, 101, x_min[p]));
    EXPECT_NEAR(lowest(data["orbits"][p]["x"]), sample_min, 1e-9);
    EXPECT_NEAR(highest(data["orbits"][p]["x"]), 0.3, 1e-9);
  }
}

TEST(ViewBranch, MissingFilesAreNamed) {
  const fs::path no_manifest = branchDir("no_manifest");
  fs::remove(no_manifest / "branch.json");
  EXPECT_FALSE(isBranchDir(no_manifest));
  EXPECT_TRUE(holds(errorOf(no_manifest), (no_manifest / "branch.json").string()));
  EXPECT_FALSE(fs::exists(no_manifest / "view.html"));

  const fs::path no_table = branchDir("no_table");
  fs::remove(no_table / "branch.csv");
  EXPECT_TRUE(holds(errorOf(no_table), (no_table / "branch.csv").string()));

  const fs::path no_orbits = branchDir("no_orbits");
  fs::remove(no_orbits / "branch_orbits.csv");
  EXPECT_TRUE(holds(errorOf(no_orbits), (no_orbits / "branch_orbits.csv").string()));
  EXPECT_FALSE(fs::exists(no_orbits / "view.html"));
}

TEST(ViewBranch, MalformedManifestIsNamed) {
  const fs::path dir = branchDir("bad_manifest");
  writeText(dir / "branch.json", "{\"parameter\": \"v_b\"");
  EXPECT_TRUE(holds(errorOf(dir), "branch.json' is not JSON"));
  writeText(dir / "branch.json", R"({"parameter": "v_b", "events": []})");
  EXPECT_TRUE(holds(errorOf(dir), "has no 'observed'"));
  writeText(dir / "branch.json",
            R"({"parameter": "v_b", "observed": "box.x", "events": [{"kind": "fold",
                "parameter": 1.5, "between": [1, 3]}]})");
  EXPECT_TRUE(holds(errorOf(dir), "event 0's 'between' is not two of branch.csv's points"));
  writeText(dir / "branch.json",
            R"({"parameter": "v_b", "observed": "box.x", "events": [], "points": 4})");
  EXPECT_TRUE(holds(errorOf(dir), "counts 4 points"));
}

TEST(ViewBranch, MalformedTableIsNamed) {
  const fs::path dir = branchDir("bad_table");
  std::string table = kTable;
  table.replace(table.find("1,1.5,1.14"), 10, "1,fast,1.14");
  writeText(dir / "branch.csv", table);
  const std::string e = errorOf(dir);
  EXPECT_TRUE(
      holds(e, (dir / "branch.csv").string() + "' line 3: parameter 'fast' is not a number"))
      << e;
  writeText(dir / "branch.csv", "index,parameter,amplitude_pp,largest_multiplier,stable\n");
  EXPECT_TRUE(holds(errorOf(dir), "has no column period"));
}

TEST(ViewBranch, MalformedOrbitsAreNamed) {
  const fs::path dir = branchDir("bad_orbits");
  const fs::path orbits = dir / "branch_orbits.csv";
  const std::string good =
      "point,t,box.x\n" + orbitRows(0, 10, -0.1) + orbitRows(1, 10, -0.2) + orbitRows(2, 10, -0.15);

  writeText(orbits, "point,t,box.x\n0,0,0.3\n0,0.1,oops\n" + orbitRows(1, 10, -0.2) +
                        orbitRows(2, 10, -0.15));
  std::string e = errorOf(dir);
  EXPECT_TRUE(holds(e, orbits.string() + "' line 3: box.x 'oops' is not a number")) << e;

  writeText(orbits, "point,time,box.x\n" + good.substr(good.find('\n') + 1));
  e = errorOf(dir);
  EXPECT_TRUE(holds(e, orbits.string() + "' has the header 'point,time,box.x'")) << e;

  writeText(orbits, "point,t,box.y\n" + good.substr(good.find('\n') + 1));
  EXPECT_TRUE(holds(errorOf(dir), "holds box.y, branch.json observes box.x"));

  writeText(orbits, good + "3,0,0.1\n");
  e = errorOf(dir);
  EXPECT_TRUE(holds(e, "line 32: point '3' is not one of branch.csv's points (0 to 2)")) << e;

  writeText(orbits, good + "2,0.5\n");
  EXPECT_TRUE(holds(errorOf(dir), "line 32 has 2 fields, expected 3 (point,t,box.x)"));

  writeText(orbits, "point,t,box.x\n" + orbitRows(0, 10, -0.1) + orbitRows(2, 10, -0.15));
  e = errorOf(dir);
  EXPECT_TRUE(holds(e, orbits.string() + "' has no rows for point 1 (branch.csv has 3 points)"))
      << e;

  writeText(orbits, "");
  EXPECT_TRUE(holds(errorOf(dir), orbits.string() + "' is empty"));
  EXPECT_FALSE(fs::exists(dir / "view.html"));
}

TEST(ViewBranch, ASwitchedBranchCarriesTheBranchItLeftAndWhere) {
  const fs::path dir = branchDir("switched");
  EXPECT_EQ(writeBranchView(dir).primary_points, 0u);  // no switch: no primary
  EXPECT_TRUE(pageData(dir / "view.html")["primary"].empty());
  // The branch a --switch left: primary_branch.csv, and branch.json's "switch".
  std::string manifest = kManifest;
  manifest.replace(manifest.find("\"points\": 3"), 11,
                   "\"points\": 3, \"switch\": {\"at\": \"period_doubling\", \"found\": true, "
                   "\"parameter\": 1.25, \"primary_points\": 2}");
  writeText(dir / "branch.json", manifest);
  writeText(dir / "primary_branch.csv",
            "index,parameter,period,amplitude_pp,largest_multiplier,stable,steady_growth_rate,"
            "event\n0,1.5,0.6,0,0.9,1,,\n1,1.2,0.65,0,1.1,0,,period_doubling\n");
  const BranchViewInfo info = writeBranchView(dir);
  EXPECT_EQ(info.primary_points, 2u);
  const nlohmann::json data = pageData(info.file);
  ASSERT_EQ(data["primary"].size(), 2u);
  EXPECT_DOUBLE_EQ(data["primary"][1]["parameter"].get<double>(), 1.2);
  EXPECT_EQ(data["primary"][1]["stable"], false);
  EXPECT_EQ(data["meta"]["switch"]["at"], "period_doubling");
  EXPECT_DOUBLE_EQ(data["meta"]["switch"]["parameter"].get<double>(), 1.25);
  // A malformed primary table is named like branch.csv.
  writeText(dir / "primary_branch.csv",
            "index,parameter,period,amplitude_pp,largest_multiplier,stable\n0,1.5,0.6,0,0.9,2\n");
  EXPECT_TRUE(holds(errorOf(dir),
                    (dir / "primary_branch.csv").string() + "' line 2: stable '2' is not 0 or 1"))
      << errorOf(dir);
}

TEST(ViewBranch, AForcedBranchsEmptySteadyColumnLeavesTheAxisBare) {
  // A forced scene has no steady state: its steady_growth_rate column is empty in every row.
  const fs::path dir = branchDir("forced");
  std::string table = kTable;
  table.replace(table.find(",0.06,\n"), 7, ",,\n");
  table.replace(table.find(",-0.01,\n"), 8, ",,\n");
  writeText(dir / "branch.csv", table);
  EXPECT_FALSE(writeBranchView(dir).steady_growth);
  EXPECT_FALSE(pageData(dir / "view.html")["meta"]["steady_growth"].get<bool>());
}
