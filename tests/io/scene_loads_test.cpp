// The `loads:` section (io/scene_loads.cpp, io/scene_signal.cpp): every signal kind read into
// the model with its values, numbers and parameter expressions as constants, the frame and
// point, the `loads` output channels; and the errors, each naming its key: table times not
// increasing, an unknown signal kind, a missing kind key, an unknown or kinematic body,
// a wrong component count, a load with neither force nor torque.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "io/output_channels.hpp"
#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo::io {
namespace {

using test::replaced;
using test::sceneErrorOf;

const std::string kScene = R"(parameters: {f: 2.5, w: 3}
simulation: {duration: 0.01, time_step: 0.001, gravity: [0, 0, 0]}
bodies:
  - {name: wall, kind: kinematic}
  - {name: block, mass: 2, inertia: [0.1, 0.1, 0.1]}
loads:
  - name: push
    body: block
    force: [$f, "2 * $f", {ramp: {rate: 4, start: 0.5, initial: 1}}]
    torque: [{step: {time: 1, before: 0, after: 3}},
             {smooth_step: {start: 1, end: 2, before: -1, after: 1}},
             {table: [[0, 0], [1, 2], [3, -2]]}]
    frame: body
    point: [0.1, 0, 0]
  - name: shake
    body: block
    force: [{sines: [{amplitude: 1, frequency: $w},
                     {amplitude: 2, frequency: 1, phase: 0.5, offset: 3}]}, 0, 0]
output: {channels: [position, loads]}
)";

TEST(SceneLoads, EverySignalKindIsRead) {
  const Scene scene = loadSceneFromString(kScene, "loads.yaml");
  const Model& m = *scene.model;
  ASSERT_EQ(m.loads.size(), 2u);
  const AppliedLoad& push = m.loads[0];
  EXPECT_EQ(push.name, "push");
  EXPECT_EQ(push.body.value, 1);
  EXPECT_EQ(push.frame, LoadFrame::kBody);
  EXPECT_EQ(push.point, Vec3(0.1, 0, 0));
  EXPECT_EQ(push.force[0].value(7.0), 2.5);
  EXPECT_EQ(push.force[1].value(7.0), 5.0);
  EXPECT_EQ(push.force[2].value(0.2), 1.0);
  EXPECT_EQ(push.force[2].value(1.5), 5.0);
  EXPECT_EQ(push.torque[0].value(0.9), 0.0);
  EXPECT_EQ(push.torque[0].value(1.0), 3.0);
  EXPECT_EQ(push.torque[1].value(1.5), 0.0);
  EXPECT_EQ(push.torque[1].kind(), Signal::Kind::kSmoothStep);
  EXPECT_EQ(push.torque[2].value(2.0), 0.0);
  EXPECT_EQ(push.torque[2].value(0.5), 1.0);
  const AppliedLoad& shake = m.loads[1];
  EXPECT_EQ(shake.frame, LoadFrame::kWorld);
  EXPECT_EQ(shake.point, Vec3::Zero());
  EXPECT_NEAR(shake.force[0].value(0.0), 3.0 + 2.0 * std::sin(0.5), 1e-15);
  EXPECT_NEAR(shake.force[0].derivative(0.0),
              2 * std::numbers::pi * 3 + 2 * 2 * std::numbers::pi * std::cos(0.5), 1e-12);
  EXPECT_TRUE(shake.torque[0].isZero() && shake.torque[2].isZero());
  const std::vector<std::string> columns = channelColumns(m, scene.output.channels);
  const std::vector<std::string> tail(columns.end() - 6, columns.end());
  EXPECT_EQ(tail, (std::vector<std::string>{"push.fx", "push.fy", "push.fz", "shake.fx", "shake.fy",
                                            "shake.fz"}));
  EXPECT_EQ(channelUnit(m, "push.fy"), "N");
}

TEST(SceneLoads, ErrorsNameTheirKey) {
  struct Case {
    std::string from, to, says;
  };
  for (const Case& c : {
           Case{"[[0, 0], [1, 2], [3, -2]]", "[[0, 0], [1, 2], [1, -2]]",
                "loads[0].torque[2].table: table: times must be strictly increasing"},
           Case{"{step: {time: 1,", "{stair: {time: 1,",
                "unknown key 'stair' (accepted keys: ramp, step, smooth_step, table, sines, "
                "expression)"},
           Case{"{ramp: {rate: 4, start: 0.5, initial: 1}}", "{}",
                "loads[0].force[2]: expected a number or a mapping with one signal kind"},
           Case{"{ramp: {rate: 4, start: 0.5, initial: 1}}",
                "{ramp: {rate: 4}, step: {time: 1, before: 0, after: 1}}", "found 2 keys"},
           Case{"{ramp: {rate: 4, start: 0.5, initial: 1}}", "{ramp: {start: 1}}",
                "loads[0].force[2].ramp"},
           Case{"end: 2,", "end: 1,", "smooth_step: end (1) must be after start (1)"},
           Case{"    body: block\n    force: [$f", "    body: blok\n    force: [$f",
                "loads[0].body: unknown body 'blok' (known bodies: world, wall, block)"},
           Case{"    body: block\n    force: [$f", "    body: wall\n    force: [$f",
                "load 'push': body 'wall' is kinematic"},
           Case{"[$f, \"2 * $f\", ", "[$f, ", "loads[0].force: expected 3 components"},
           Case{"frame: body", "frame: tool", "loads[0].frame"},
           Case{"point: [0.1, 0, 0]", "point: [0.1, 0]", "loads[0].point"},
           Case{"{amplitude: 1, frequency: $w}", "{amplitude: 1, frequency: -1}",
                "sines: frequency must be >= 0"},
           Case{"{amplitude: 1, frequency: $w}", "{amplitude: 1}", "frequency"},
           Case{"  - name: shake\n    body: block\n    force:",
                "  - name: push\n    body: block\n    force:",
                "load 'push': a load of that name already exists"},
       }) {
    const std::string e = sceneErrorOf(replaced(kScene, c.from, c.to));
    EXPECT_NE(e.find(c.says), std::string::npos) << c.to << "\n -> " << e;
  }
  const std::string none = sceneErrorOf(
      "bodies: [{name: block, mass: 1, inertia: [1, 1, 1]}]\nloads: [{name: idle, body: block}]\n");
  EXPECT_NE(none.find("load 'idle' needs a force, a torque or both"), std::string::npos) << none;
}

}  // namespace
}  // namespace tribo::io
