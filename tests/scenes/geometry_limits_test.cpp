// Geometry past contact::kMaxLength (1e6 m) is refused at load, for scene files and URDF
// alike, with an error naming the geometry (or link), the key, the limit and the value found;
// geometry at the limit loads and runs through automatic contacts (FCL's dynamic AABB tree)
// without crashing. Sizes: 1e3 (fine), the limit, just above, 1e154 and 1e308 (which once
// crashed the broadphase).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "contact/shape.hpp"
#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "io/urdf_reader.hpp"
#include "io/urdf_scene.hpp"
#include "support/scene_text.hpp"

namespace tribo {
namespace {

namespace fs = std::filesystem;

fs::path testFolder() {
  const fs::path dir =
      fs::temp_directory_path() /
      ("tribo_limits_" +
       std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::create_directories(dir);
  return dir;
}

std::string text(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

constexpr double kLimit = contact::kMaxLength;
const double kJustAbove = kLimit * (1.0 + 1e-9);
// Each size with whether it is within the limit.
const std::vector<std::pair<double, bool>> kSizes = {
    {1e3, true}, {kLimit, true}, {kJustAbove, false}, {1e154, false}, {1e308, false}};

// A unit cube (half extent 0.5) as OBJ.
fs::path writeCube(const fs::path& dir) {
  const fs::path path = dir / "cube.obj";
  std::ofstream out(path);
  for (int k = 0; k < 8; ++k)
    out << "v " << ((k & 1) ? 0.5 : -0.5) << " " << ((k & 2) ? 0.5 : -0.5) << " "
        << ((k & 4) ? 0.5 : -0.5) << "\n";
  for (const char* f : {"1 3 2", "2 3 4", "5 6 7", "6 8 7", "1 2 5", "2 6 5", "3 7 4", "4 7 8",
                        "1 5 3", "3 5 7", "2 4 6", "4 8 6"})
    out << "f " << f << "\n";
  return path;
}

// A scene with a ground and one body `b` carrying geometry `g` (its YAML flow map), at
// `position`.
std::string sceneWith(const std::string& geometry, const std::string& position = "[0, 0, 1]") {
  return "simulation: {duration: 0.01, time_step: 0.001, integrator: rk4}\n"
         "bodies:\n"
         "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}\n"
         "  - {name: b, mass: 1, inertia: [1, 1, 1], position: " +
         position + ", geometry: [{name: g, " + geometry +
         "}]}\n"
         "friction_laws: {coulomb: {mu: 0.3, regularization: tanh, v_eps: 0.05}}\n"
         "materials:\n"
         "  - {name: m, normal: {law: linear, stiffness: 1e4, damping: 10}, friction: coulomb,\n"
         "     default: true}\n";
}

struct Case {
  std::string geometry;  // YAML of the geometry for size s
  std::string key;       // what the message names
};

std::vector<std::pair<std::string, std::function<Case(double)>>> yamlShapes() {
  return {
      {"box",
       [](double s) {
         return Case{"shape: box, size: [" + text(s) + ", 1, 1]", "box size"};
       }},
      {"sphere",
       [](double s) {
         return Case{"shape: sphere, radius: " + text(s), "sphere radius"};
       }},
      {"cylinder",
       [](double s) {
         return Case{"shape: cylinder, radius: 1, length: " + text(s), "cylinder length"};
       }},
      {"capsule",
       [](double s) {
         return Case{"shape: capsule, radius: " + text(s) + ", length: 1", "capsule radius"};
       }},
      {"cone",
       [](double s) {
         return Case{"shape: cone, radius: " + text(s) + ", length: 1", "cone radius"};
       }},
      // A unit cube scaled by 2 s: vertex coordinates +-s.
      {"mesh",
       [](double s) {
         return Case{"shape: mesh, file: cube.obj, scale: " + text(2 * s), "vertex"};
       }},
      {"convex_mesh",
       [](double s) {
         return Case{"shape: convex_mesh, file: cube.obj, scale: " + text(2 * s), "vertex"};
       }},
      {"geometry position",
       [](double s) {
         return Case{"shape: sphere, radius: 0.1, position: [0, " + text(s) + ", 0]", "position"};
       }},
  };
}

TEST(GeometryLimits, SceneGeometryPastTheLimitIsRefusedNamingGeometryKeyLimitAndValue) {
  const fs::path dir = testFolder();
  writeCube(dir);
  const std::string name = (dir / "scene.yaml").string();
  for (const auto& [shape, make] : yamlShapes()) {
    for (const auto& [size, fine] : kSizes) {
      if (shape.find("mesh") != std::string::npos && 2 * size > 1.7e308) continue;  // scale inf
      const Case c = make(size);
      const std::string error = test::sceneErrorOf(sceneWith(c.geometry), name);
      SCOPED_TRACE(shape + " at " + text(size) + ": " + error);
      if (fine) {
        EXPECT_EQ(error, "");
        continue;
      }
      EXPECT_NE(error.find(name), std::string::npos);
      EXPECT_NE(error.find(c.key), std::string::npos);
      EXPECT_NE(error.find("1000000 m"), std::string::npos);                // the limit
      EXPECT_NE(error.find(contact::lengthText(size)), std::string::npos);  // the value found
      if (shape.find("mesh") == std::string::npos)
        EXPECT_NE(error.find("'g'"), std::string::npos);
      else
        EXPECT_NE(error.find("cube.obj"), std::string::npos);
    }
  }
}

TEST(GeometryLimits, BodyPositionPastTheLimitIsRefusedNamingTheBody) {
  for (const auto& [size, fine] : kSizes) {
    for (const double sign : {1.0, -1.0}) {
      const std::string error = test::sceneErrorOf(
          sceneWith("shape: sphere, radius: 0.1", "[" + text(sign * size) + ", 0, 1]"));
      SCOPED_TRACE(text(sign * size) + ": " + error);
      if (fine) {
        EXPECT_EQ(error, "");
        continue;
      }
      EXPECT_NE(error.find("body 'b'"), std::string::npos);
      EXPECT_NE(error.find("position"), std::string::npos);
      EXPECT_NE(error.find("1000000 m"), std::string::npos);
      EXPECT_NE(error.find(contact::lengthText(sign * size)), std::string::npos);
    }
  }
}

// A URDF robot of one link carrying `geometry` (URDF <geometry> content) at `xyz`.
std::string urdfWith(const std::string& geometry, const std::string& xyz = "0 0 0") {
  return R"(<?xml version="1.0"?>
<robot name="r">
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz=")" +
         xyz + R"("/><geometry>)" + geometry + R"(</geometry></collision>
  </link>
</robot>
)";
}

TEST(GeometryLimits, UrdfGeometryPastTheLimitIsAnErrorOfItsLinkAndRefusedByTheRun) {
  const fs::path dir = testFolder();
  writeCube(dir);
  const std::vector<std::pair<std::string, std::function<Case(double)>>> shapes = {
      {"box",
       [](double s) {
         return Case{"<box size=\"" + text(s) + " 1 1\"/>", "box size"};
       }},
      {"sphere",
       [](double s) {
         return Case{"<sphere radius=\"" + text(s) + "\"/>", "radius"};
       }},
      {"cylinder",
       [](double s) {
         return Case{"<cylinder radius=\"1\" length=\"" + text(s) + "\"/>", "length"};
       }},
      {"capsule",
       [](double s) {
         return Case{"<capsule radius=\"" + text(s) + "\" length=\"1\"/>", "radius"};
       }},
      {"origin",
       [](double) {
         return Case{"<sphere radius=\"0.1\"/>", "origin xyz"};
       }},
      {"mesh",
       [](double s) {
         const std::string k = text(2 * s);
         return Case{"<mesh filename=\"cube.obj\" scale=\"" + k + " " + k + " " + k + "\"/>",
                     "vertex"};
       }},
  };
  for (const auto& [shape, make] : shapes) {
    for (const auto& [size, fine] : kSizes) {
      if (shape == "mesh" && 2 * size > 1.7e308) continue;
      const Case c = make(size);
      const fs::path file = dir / (shape + ".urdf");
      std::ofstream(file) << urdfWith(c.geometry,
                                      shape == "origin" ? text(size) + " 0 0" : "0 0 0");
      SCOPED_TRACE(shape + " at " + text(size));
      const io::UrdfRobot robot = io::readUrdf(file.string(), {});
      std::string run_error;
      try {
        io::sceneFromUrdf(file.string(), {}, {});
      } catch (const std::exception& e) {
        run_error = e.what();
      }
      SCOPED_TRACE(run_error);
      if (fine) {
        EXPECT_FALSE(robot.hasErrors());
        // The run lifts the robot until its lowest point is at `drop` (0.05 m): a sphere,
        // capsule or mesh reaching 1e6 m below its centre puts the centre past the limit.
        const bool lifted_past =
            size == kLimit && (shape == "sphere" || shape == "capsule" || shape == "mesh");
        if (lifted_past)
          EXPECT_NE(run_error.find("body 'base': position: expected coordinates within"),
                    std::string::npos);
        else
          EXPECT_EQ(run_error, "");
        continue;
      }
      EXPECT_NE(run_error.find("link 'base'"), std::string::npos);
      EXPECT_NE(run_error.find(c.key), std::string::npos);
      EXPECT_NE(run_error.find("1000000 m"), std::string::npos);
      EXPECT_NE(run_error.find(contact::lengthText(size)), std::string::npos);
      // What the reader's checks see (tribo info's "checks:"): meshes are read by the run.
      if (shape != "mesh") {
        EXPECT_TRUE(robot.hasErrors());
      }
    }
  }
}

// Every shape at the limit, on the ground and touching its neighbours, through automatic
// contacts (the broadphase tree holds them all): steps run and end in a status, never a crash.
TEST(GeometryLimits, SceneAtTheLimitRunsThroughAutomaticContacts) {
  const fs::path dir = testFolder();
  writeCube(dir);
  const double h = kLimit / 2;  // half size
  const std::string L = text(kLimit), H = text(h);
  const std::string yaml =
      "simulation: {duration: 0.01, time_step: 0.001, integrator: rk4}\n"
      "bodies:\n"
      "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}\n"
      "  - {name: box, mass: 1e18, position: [-" +
      L + ", 0, " + H +
      "],"
      " geometry: [{name: g_box, shape: box, size: [" +
      L + ", " + L + ", " + L +
      "]}]}\n"
      "  - {name: ball, mass: 1e18, position: [-" +
      H + ", 0, " + L +
      "],"
      " geometry: [{name: g_ball, shape: sphere, radius: " +
      L +
      "}]}\n"
      "  - {name: can, mass: 1e18, position: [0, 0, " +
      H +
      "],"
      " geometry: [{name: g_can, shape: cylinder, radius: " +
      H + ", length: " + L +
      "}]}\n"
      "  - {name: pill, mass: 1e18, position: [" +
      H + ", 0, " + L +
      "],"
      " geometry: [{name: g_pill, shape: capsule, radius: " +
      H + ", length: " + L +
      "}]}\n"
      "  - {name: hull, mass: 1e18, position: [" +
      L + ", 0, " + H +
      "],"
      " geometry: [{name: g_hull, shape: convex_mesh, file: cube.obj, scale: " +
      L +
      "}]}\n"
      "friction_laws: {coulomb: {mu: 0.3, regularization: tanh, v_eps: 0.05}}\n"
      "materials:\n"
      "  - {name: m, normal: {law: linear, stiffness: 1e20, damping: 1e19}, friction: coulomb,\n"
      "     default: true}\n";
  const io::Scene scene = io::loadSceneFromString(yaml, (dir / "at_limit.yaml").string());
  Simulator sim(scene.model);
  for (int i = 0; i < 5; ++i) sim.step();
  EXPECT_GT(sim.state().time, 0.0);
}

}  // namespace
}  // namespace tribo
