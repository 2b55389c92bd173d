// The replay page's generator (study/view/view_page.hpp and its parts): decimation of
// trajectory.csv to a frame cap and a value budget, the scene's geometry as JSON, and a
// page written from a real run with a stand-in three.js. The page's behaviour in a browser
// is tested in tests/view/.
#include "study/view/view_page.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/scene_loader.hpp"
#include "io/urdf_scene.hpp"
#include "study/result_writer.hpp"
#include "study/scene_run.hpp"
#include "study/view/view_scene.hpp"
#include "study/view/view_trajectory.hpp"

namespace fs = std::filesystem;
using namespace tribo;
using namespace tribo::study;

namespace {

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

fs::path freshDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("tribo_view_page_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// t = 0.01 i, a = i, b = -2 i for i in [0, rows).
fs::path writeCsv(const fs::path& dir, int rows) {
  const fs::path file = dir / "trajectory.csv";
  std::ofstream out(file);
  out << "t,a,b\n";
  for (int i = 0; i < rows; ++i) out << 0.01 * i << "," << i << "," << -2 * i << "\n";
  return file;
}

std::string readAll(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(ViewTrajectory, KeepsEveryRowUnderTheCap) {
  const ViewTrajectory v = readViewTrajectory(writeCsv(freshDir("all"), 50), 100, 1000000);
  EXPECT_EQ(v.rows, 50u);
  EXPECT_EQ(v.stride, 1u);
  ASSERT_EQ(v.frames(), 50u);
  EXPECT_EQ(v.column("b"), 2);
  EXPECT_EQ(v.column("nope"), -1);
  EXPECT_DOUBLE_EQ(v.values[2][49], -98.0);
}

TEST(ViewTrajectory, DecimatesToTheCapKeepingFirstAndLastRows) {
  // 1001 rows under a cap of 100: every 11th row (0, 11, ..., 990) and the last, 1000.
  const ViewTrajectory v = readViewTrajectory(writeCsv(freshDir("cap"), 1001), 100, 1000000);
  EXPECT_EQ(v.rows, 1001u);
  EXPECT_EQ(v.stride, 11u);
  ASSERT_EQ(v.frames(), 92u);
  EXPECT_DOUBLE_EQ(v.values[1][0], 0.0);
  EXPECT_DOUBLE_EQ(v.values[1][1], 11.0);
  EXPECT_DOUBLE_EQ(v.values[1][90], 990.0);
  EXPECT_DOUBLE_EQ(v.values[1][91], 1000.0);
  EXPECT_DOUBLE_EQ(v.values[0][91], 10.0);
}

TEST(ViewTrajectory, ValueBudgetLowersTheCap) {
  // 3 columns and a budget of 60 numbers: at most 20 frames.
  const ViewTrajectory v = readViewTrajectory(writeCsv(freshDir("budget"), 1001), 20000, 60);
  EXPECT_LE(v.frames(), 20u);
  EXPECT_GE(v.frames(), 15u);
  EXPECT_DOUBLE_EQ(v.values[1].back(), 1000.0);
}

TEST(ViewTrajectory, RejectsBadFiles) {
  const fs::path d = freshDir("bad");
  EXPECT_THROW(readViewTrajectory(d / "missing.csv", 10, 100), std::runtime_error);
  std::ofstream(d / "no_t.csv") << "x,y\n1,2\n";
  EXPECT_THROW(readViewTrajectory(d / "no_t.csv", 10, 100), std::runtime_error);
  std::ofstream(d / "short.csv") << "t,x\n0,1\n0.1\n";
  EXPECT_THROW(readViewTrajectory(d / "short.csv", 10, 100), std::runtime_error);
}

TEST(ViewScene, BeltGeometryAsJson) {
  const io::Scene scene = io::loadScene(kBelt, {"v_b=2.5"});
  const auto j = nlohmann::json::parse(viewSceneJson(*scene.model));
  ASSERT_EQ(j["bodies"].size(), 2u);
  const auto& belt = j["bodies"][0];
  EXPECT_EQ(belt["name"], "belt");
  EXPECT_EQ(belt["kind"], "kinematic");
  EXPECT_DOUBLE_EQ(belt["surface_velocity"][0].get<double>(), 2.5);
  EXPECT_EQ(belt["geometries"][0]["shape"], "halfspace");
  const auto& box = j["bodies"][1]["geometries"][0];
  EXPECT_EQ(box["shape"], "box");
  EXPECT_DOUBLE_EQ(box["half_extents"][0].get<double>(), 0.1);
  EXPECT_DOUBLE_EQ(box["half_extents"][2].get<double>(), 0.05);
  EXPECT_DOUBLE_EQ(box["quaternion"][0].get<double>(), 1.0);
  EXPECT_TRUE(j["world"].empty());
}

TEST(ViewPage, WrittenFromARunWithItsParameters) {
  const fs::path d = freshDir("run");
  const io::Scene scene = io::loadScene(kBelt, {"duration=0.2", "v_b=2.5"});
  writeResults(d, scene, runScene(scene));
  std::ofstream(d / "three.js") << "var THREE = {}; // stand-in </script> inside";
  ViewOptions options;
  options.three_js = d / "three.js";
  options.frame_cap = 50;
  const ViewPageInfo info = writeRunView(d, options);
  EXPECT_EQ(info.rows, 201u);
  EXPECT_LE(info.frames, 50u);
  EXPECT_FALSE(info.orientation);  // the belt's default channels
  const std::string page = readAll(d / "view.html");
  EXPECT_EQ(page.size(), info.bytes);
  EXPECT_NE(page.find("var THREE = {};"), std::string::npos);
  EXPECT_EQ(page.find("stand-in </script>"), std::string::npos);  // escaped: <\/script>
  EXPECT_NE(page.find("stand-in <\\/script>"), std::string::npos);
  // The scene was reloaded with the run's parameters: the belt moves at 2.5 m/s.
  EXPECT_NE(page.find("\"surface_velocity\":[2.5,0.0,0.0]"), std::string::npos);
  EXPECT_EQ(page.find("/*TRIBO_"), std::string::npos);  // every template marker filled
}

TEST(ViewPage, WrittenFromAUrdfRobotRun) {
  // `tribo run ROBOT.urdf`: the robot on its ground; the page's scene holds its links.
  const fs::path d = freshDir("urdf");
  const std::string urdf = std::string(TRIBO_SOURCE_DIR) + "/scenes/robots/pendulum.urdf";
  const io::Scene scene = io::sceneFromUrdf(urdf, {}, {"duration=0.05"});
  writeResults(d, scene, runScene(scene));
  std::ofstream(d / "three.js") << "var THREE = {};";
  ViewOptions options;
  options.three_js = d / "three.js";
  const ViewPageInfo info = writeRunView(d, options);
  EXPECT_GT(info.rows, 1u);
  const std::string page = readAll(d / "view.html");
  for (const Body& b : scene.model->bodies)
    EXPECT_NE(page.find("\"name\":\"" + b.name + "\""), std::string::npos) << b.name;
}

TEST(ViewPage, MissingThreeJsOrRunIsAnError) {
  const fs::path d = freshDir("missing");
  ViewOptions options;
  options.three_js = d / "no_three.js";
  try {
    writeRunView(d, options);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("libjs-three"), std::string::npos) << e.what();
  }
  std::ofstream(d / "three.js") << "var THREE = {};";
  options.three_js = d / "three.js";
  EXPECT_THROW(writeRunView(d, options), std::runtime_error);  // no summary.json
  EXPECT_FALSE(fs::exists(d / "view.html"));
}
