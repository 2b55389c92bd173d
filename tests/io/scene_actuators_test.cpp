// The `actuators:` section (io/scene_actuators.cpp): each type read into the model with its
// gains, limits and target signal, the `actuators` output channels and their units, a
// robot's URDF <limit effort velocity> as the default limits; and the errors, each naming
// its key: an unknown joint (listing the revolute and prismatic ones), a fixed joint, a
// negative gain, a limit of 0, an unknown type, gains the type does not take, a driven
// joint, a repeated name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/output_channels.hpp"
#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo::io {
namespace {

using test::replaced;
using test::sceneErrorOf;

const std::string kScene = R"(parameters: {r: 0.02}
simulation: {duration: 0.01, time_step: 0.001, gravity: [0, 0, 0]}
bodies:
  - {name: block, mass: 2, inertia: [0.1, 0.1, 0.1]}
  - {name: wheel, mass: 1, inertia: [0.1, 0.1, 0.2]}
  - {name: tag, mass: 1, inertia: [0.1, 0.1, 0.1]}
joints:
  - {name: slide, type: prismatic, parent: world, child: block, anchor: [0, 0, 0], axis: [1, 0, 0]}
  - {name: axle, type: revolute, parent: world, child: wheel, anchor: [0, 0, 0], axis: [0, 0, 1]}
  - {name: weld, type: fixed, parent: world, child: tag, anchor: [0, 0, 0]}
actuators:
  - {name: servo, joint: slide, type: position, target: {ramp: {rate: $r}}, kp: 400, kd: 40,
     effort_limit: 5}
  - {name: spin, joint: axle, type: velocity, target: 3, kd: 0.5, velocity_limit: 2}
output: {channels: [position, actuators]}
)";

TEST(SceneActuators, EachTypeIsRead) {
  const Scene scene = loadSceneFromString(kScene, "actuators.yaml");
  const Model& m = *scene.model;
  const JointActuator& servo = *m.joints[0].elements.actuator;
  EXPECT_EQ(servo.name, "servo");
  EXPECT_EQ(servo.kind, ActuatorKind::kPositionServo);
  EXPECT_EQ(servo.kp, 400.0);
  EXPECT_EQ(servo.kd, 40.0);
  EXPECT_EQ(servo.max_effort, 5.0);
  EXPECT_TRUE(std::isinf(servo.max_velocity));
  EXPECT_DOUBLE_EQ(servo.target.value(2.0), 0.04);
  EXPECT_DOUBLE_EQ(servo.target.derivative(2.0), 0.02);
  const JointActuator& spin = *m.joints[1].elements.actuator;
  EXPECT_EQ(spin.kind, ActuatorKind::kVelocityServo);
  EXPECT_EQ(spin.kd, 0.5);
  EXPECT_EQ(spin.max_velocity, 2.0);
  EXPECT_TRUE(std::isinf(spin.max_effort));
  EXPECT_FALSE(m.joints[2].elements.actuator);
  const std::vector<std::string> columns = channelColumns(m, scene.output.channels);
  const std::vector<std::string> tail(columns.end() - 6, columns.end());
  EXPECT_EQ(tail, (std::vector<std::string>{"servo.target", "servo.effort", "servo.saturated",
                                            "spin.target", "spin.effort", "spin.saturated"}));
  EXPECT_EQ(channelUnit(m, "servo.target"), "m");
  EXPECT_EQ(channelUnit(m, "servo.effort"), "N");
  EXPECT_EQ(channelUnit(m, "spin.target"), "rad/s");
  EXPECT_EQ(channelUnit(m, "spin.effort"), "N m");
  EXPECT_EQ(channelUnit(m, "spin.saturated"), "");
}

TEST(SceneActuators, ErrorsNameTheirKey) {
  struct Case {
    std::string from, to, says;
  };
  for (const Case& c : {
           Case{"joint: slide", "joint: slid",
                "unknown joint 'slid' (revolute and prismatic joints: slide, axle)"},
           Case{"joint: slide", "joint: weld",
                "an actuator needs a revolute or prismatic joint (this one is fixed)"},
           Case{"kp: 400", "kp: -1", "expected a number >= 0, found '-1'"},
           Case{"effort_limit: 5", "effort_limit: 0", "expected a number > 0, found '0'"},
           Case{"type: position", "type: torque", "torque"},
           Case{"type: velocity, target: 3, kd: 0.5", "type: velocity, target: 3, kp: 1, kd: 0.5",
                "a velocity servo takes kd only"},
           Case{"type: velocity, target: 3, kd: 0.5", "type: motor, target: 3, kd: 0.5",
                "a motor takes no gains"},
           Case{"kp: 400, kd: 40,", "", "a position servo needs kp > 0 or kd > 0"},
           Case{"name: spin", "name: servo", "an actuator of that name is on joint 'slide'"},
           Case{"target: {ramp: {rate: $r}}, ", "", "missing required key 'target'"},
           Case{"axis: [1, 0, 0]}", "axis: [1, 0, 0], drive: {constant: 0}}",
                "the joint has a drive"},
       }) {
    const std::string error = sceneErrorOf(replaced(kScene, c.from, c.to));
    EXPECT_NE(error.find(c.says), std::string::npos) << c.to << "\n -> " << error;
    EXPECT_NE(error.find("test.yaml:"), std::string::npos) << error;
  }
}

TEST(SceneActuators, RobotJointsLendTheirRatedEffortAndVelocity) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "tribo_scene_actuators_test";
  fs::create_directories(dir);
  std::ofstream(dir / "arm.urdf") << R"(<?xml version="1.0"?>
<robot name="arm">
  <link name="base"/>
  <link name="link"><inertial><origin xyz="0 0 -0.2"/><mass value="1.5"/>
    <inertia ixx="0.02" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.001"/></inertial></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="link"/>
    <axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="12.5" velocity="1.75"/></joint>
</robot>)";
  const std::string scene = R"(simulation: {duration: 0.01, time_step: 0.001}
robots: [{file: arm.urdf, prefix: a_}]
actuators:
  - {name: hold, joint: a_shoulder, type: position, target: 0.1, kp: 30, kd: 2}
  - {name: own, joint: b_shoulder, type: position, target: 0.1, kp: 30, kd: 2, effort_limit: 3}
)";
  const std::string two = replaced(scene, "[{file: arm.urdf, prefix: a_}]",
                                   "[{file: arm.urdf, prefix: a_}, {file: arm.urdf, prefix: b_}]");
  const Scene s = loadSceneFromString(two, (dir / "scene.yaml").string());
  const auto find = [&](const std::string& name) -> const JointActuator& {
    for (const Joint& j : s.model->joints)
      if (j.elements.actuator && j.elements.actuator->name == name) return *j.elements.actuator;
    throw std::runtime_error("no actuator " + name);
  };
  EXPECT_EQ(find("hold").max_effort, 12.5);
  EXPECT_EQ(find("hold").max_velocity, 1.75);
  EXPECT_EQ(find("own").max_effort, 3.0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tribo::io
