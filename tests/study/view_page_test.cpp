// The replay page's generator (study/view/view_page.hpp and its parts): decimation of
// trajectory.csv to a frame cap and a value budget, the scene's geometry as JSON, and a
// page written from a real run with a stand-in three.js. The page's behaviour in a browser
// is tested in tests/view/.
#include "study/view/view_page.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
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

// Expects the three numbers of a JSON array.
void expectVec(const nlohmann::json& j, double x, double y, double z, const std::string& what) {
  ASSERT_EQ(j.size(), 3u) << what;
  EXPECT_NEAR(j[0].get<double>(), x, 1e-12) << what;
  EXPECT_NEAR(j[1].get<double>(), y, 1e-12) << what;
  EXPECT_NEAR(j[2].get<double>(), z, 1e-12) << what;
}

TEST(ViewScene, BeltSpringJointAndSurfaceDirection) {
  // The belt scene: the wall spring from the world point (-100, 0, z0) to the box's origin,
  // the box on a planar_translation joint of normal y, the belt's surface moving along +x.
  const io::Scene scene = io::loadScene(kBelt, {"v_b=2.5", "x0=0.3"});
  const auto j = nlohmann::json::parse(viewSceneJson(*scene.model));
  const double z0 = 0.05 - 10.0 * 9.81 / (4 * 2.5e5);  // the scene's z0 at m = 10
  ASSERT_EQ(j["springs"].size(), 1u);
  const auto& spring = j["springs"][0];
  EXPECT_EQ(spring["name"], "wall_spring");
  EXPECT_EQ(spring["kind"], "spring");
  EXPECT_EQ(spring["a"], -1);  // the world
  expectVec(spring["point_a"], -100.0, 0.0, z0, "wall anchor, world");
  EXPECT_EQ(spring["b"], 1);  // the box
  expectVec(spring["point_b"], 0.0, 0.0, 0.0, "the box's origin, box frame");
  EXPECT_DOUBLE_EQ(spring["stiffness"].get<double>(), 300.0);
  EXPECT_DOUBLE_EQ(spring["rest_length"].get<double>(), 100.0);
  ASSERT_EQ(j["joints"].size(), 1u);
  const auto& joint = j["joints"][0];
  EXPECT_EQ(joint["name"], "box_on_belt");
  EXPECT_EQ(joint["type"], "planar_translation");
  EXPECT_EQ(joint["parent"], -1);
  EXPECT_EQ(joint["child"], 1);
  expectVec(joint["anchor"], 0.3, 0.0, z0, "joint anchor, world");
  expectVec(joint["anchor_in_child"], 0.0, 0.0, 0.0, "joint anchor, box frame");
  expectVec(joint["axis"], 0.0, 1.0, 0.0, "plane normal, world");
  expectVec(joint["axis_in_parent"], 0.0, 1.0, 0.0, "plane normal, world frame");
  const auto& plane = j["bodies"][0]["geometries"][0];
  expectVec(plane["surface_velocity"], 2.5, 0.0, 0.0, "belt surface velocity");
  EXPECT_FALSE(j["bodies"][1]["geometries"][0].contains("surface_velocity"));  // the box
}

TEST(ViewScene, AttachmentPointsAndAxesInBodyFrames) {
  // A body turned a quarter turn about z at (1, 2, 3): a spring's points and a joint's
  // anchor and axis, given in world coordinates at t = 0, come out in its frame, rotated back
  // by -90 deg about z: (x, y, z) -> (y, -x, z). A bushing's frames are given in body frames.
  const std::string yaml = R"(
simulation: {duration: 0.01, time_step: 0.001}
bodies:
  - name: belt
    kind: kinematic
    surface_velocity: [2, 0, 0]
    geometry: [{name: surface, shape: halfspace, rpy: [0, 0, 1.5707963267948966]}]
  - name: arm
    mass: 1
    position: [1, 2, 3]
    rpy: [0, 0, 1.5707963267948966]
    geometry: [{name: arm_shape, shape: box, size: [0.2, 0.1, 0.1]}]
joints:
  - {name: hinge, type: revolute, parent: world, child: arm, anchor: [1, 2, 3.2], axis: [1, 0, 0]}
springs:
  - {name: tie, a: world, point_a: [0, 0, 1], b: arm, point_b: [1.5, 2, 3], stiffness: 10}
bushings:
  - {name: mount, a: world, b: arm, frame_a: {position: [0, 0, 2]},
     frame_b: {position: [0.5, 0, 0]}, stiffness: [1, 1, 1]}
contacts: []
)";
  const io::Scene scene = io::loadSceneFromString(yaml, "arm.yaml");
  const auto j = nlohmann::json::parse(viewSceneJson(*scene.model));
  ASSERT_EQ(j["springs"].size(), 2u);
  const auto& tie = j["springs"][0];
  EXPECT_EQ(tie["a"], -1);
  expectVec(tie["point_a"], 0.0, 0.0, 1.0, "tie on the world");
  EXPECT_EQ(tie["b"], 1);
  expectVec(tie["point_b"], 0.0, -0.5, 0.0, "tie on the arm, arm frame");
  const auto& mount = j["springs"][1];
  EXPECT_EQ(mount["kind"], "bushing");
  expectVec(mount["point_a"], 0.0, 0.0, 2.0, "mount on the world");
  expectVec(mount["point_b"], 0.5, 0.0, 0.0, "mount on the arm, arm frame");
  ASSERT_EQ(j["joints"].size(), 1u);
  const auto& hinge = j["joints"][0];
  EXPECT_EQ(hinge["type"], "revolute");
  expectVec(hinge["anchor_in_child"], 0.0, 0.0, 0.2, "hinge anchor, arm frame");
  expectVec(hinge["axis_in_child"], 0.0, -1.0, 0.0, "hinge axis, arm frame");
  expectVec(hinge["anchor_in_parent"], 1.0, 2.0, 3.2, "hinge anchor, world");
  expectVec(hinge["axis"], 1.0, 0.0, 0.0, "hinge axis, world");
  // The belt's surface velocity read in its plane's frame, turned a quarter turn: along +y.
  expectVec(j["bodies"][0]["geometries"][0]["surface_velocity"], 0.0, 2.0, 0.0,
            "belt surface velocity, body frame");
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
  // The page's data: each column's unit for the plot's axes, the spring for the drawing.
  const std::string marker = "window.TRIBO_DATA = ";
  const std::size_t from = page.find(marker);
  ASSERT_NE(from, std::string::npos);
  const std::size_t to = page.find(";</script>", from);
  ASSERT_NE(to, std::string::npos);
  const auto data =
      nlohmann::json::parse(page.substr(from + marker.size(), to - from - marker.size()));
  const auto& columns = data["meta"]["columns"];
  const auto& units = data["meta"]["units"];
  ASSERT_EQ(units.size(), columns.size());
  const std::map<std::string, std::string> expected = {{"t", "s"},
                                                       {"box.x", "m"},
                                                       {"box.vx", "m/s"},
                                                       {"box.normal_force", "N"},
                                                       {"box.slip", "m/s"}};
  std::size_t found = 0;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const auto e = expected.find(columns[c].get<std::string>());
    if (e == expected.end()) continue;
    EXPECT_EQ(units[c], e->second) << e->first;
    ++found;
  }
  EXPECT_EQ(found, expected.size());
  EXPECT_EQ(data["scene"]["springs"].size(), 1u);
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
