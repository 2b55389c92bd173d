// Output channels (io/output_channels.hpp) against motions known in closed form:
//   a free body spinning at w about z without gravity: quaternion (cos(w t/2), 0, 0,
//   sin(w t/2)), yaw = w t wrapped to (-pi, pi], angular velocity (0, 0, w); the summary
//   observing its qz finds the period 4 pi / w;
//   a pendulum bob on a revolute joint about y, released at 30 deg: the joint's q equals the
//   bob's pitch read from its orientation (the same angle, measured twice), its rate equals
//   the angular velocity's y, and kinetic plus gravitational energy stays at its start
//   (conservation, RK4 at 1 ms) while the spring-free model's elastic energy stays zero;
//   the same body pushed by a follower force F along its own x: the `loads` columns read the
//   world force F (cos w t, sin w t, 0);
// the default columns are the historic eight per body; bad groups and channels are refused
// naming what is known.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/scene_loader.hpp"
#include "study/scene_run.hpp"
#include "support/scene_text.hpp"

namespace tribo::study {
namespace {

std::string spinner(double w, const std::string& output, int duration = 3) {
  return "simulation: {duration: " + std::to_string(duration) +
         R"(, time_step: 0.001, integrator: rk4, gravity: [0, 0, 0]}
bodies:
  - {name: wheel, mass: 2, inertia: [0.2, 0.2, 0.3], angular_velocity: [0, 0, )" +
         std::to_string(w) + R"(]}
output: )" +
         output + "\n";
}

TEST(OutputChannels, SpinningBodyQuaternionYawAndRateFollowTheClosedForm) {
  for (const double w : {0.7, 5.0, -12.0}) {
    const io::Scene scene = io::loadSceneFromString(
        spinner(w, "{interval: 0.01, channels: [orientation, rpy, angular_velocity]}"), "s.yaml");
    const RunResult r = runScene(scene);
    ASSERT_TRUE(r.complete) << r.message;
    const auto& tr = r.trajectory;
    const auto t = tr.column(0);
    const auto qw = tr.column(tr.columnIndex("wheel.qw"));
    const auto qz = tr.column(tr.columnIndex("wheel.qz"));
    const auto yaw = tr.column(tr.columnIndex("wheel.yaw"));
    const auto wz = tr.column(tr.columnIndex("wheel.wz"));
    EXPECT_THROW(tr.columnIndex("wheel.x"), std::out_of_range);  // position not asked
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double sign = qw[i] * std::cos(w * t[i] / 2) >= 0 ? 1.0 : -1.0;  // q and -q
      EXPECT_NEAR(sign * qw[i], std::cos(w * t[i] / 2), 1e-9);
      EXPECT_NEAR(sign * qz[i], std::sin(w * t[i] / 2), 1e-9);
      EXPECT_NEAR(std::remainder(yaw[i] - w * t[i], 2 * M_PI), 0.0, 1e-9);
      EXPECT_NEAR(wz[i], w, 1e-12);
    }
  }
}

TEST(OutputChannels, LoadsRecordEachLoadsWorldForce) {
  const double w = 5.0, f = 3.0;
  const io::Scene scene =
      io::loadSceneFromString(spinner(w, "{interval: 0.01, channels: [loads]}") +
                                  "loads: [{name: push, body: wheel, force: [" + std::to_string(f) +
                                  ", 0, 0], frame: body}]\n",
                              "s.yaml");
  const RunResult r = runScene(scene);
  ASSERT_TRUE(r.complete) << r.message;
  const auto& tr = r.trajectory;
  const auto t = tr.column(0);
  const auto fx = tr.column(tr.columnIndex("push.fx"));
  const auto fy = tr.column(tr.columnIndex("push.fy"));
  const auto fz = tr.column(tr.columnIndex("push.fz"));
  ASSERT_GT(t.size(), 100u);
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_NEAR(fx[i], f * std::cos(w * t[i]), 1e-9 * f);
    EXPECT_NEAR(fy[i], f * std::sin(w * t[i]), 1e-9 * f);
    EXPECT_EQ(fz[i], 0.0);
  }
}

TEST(OutputChannels, SummaryObservesAnyChannel) {
  const double w = 5.0;
  const io::Scene scene = io::loadSceneFromString(
      spinner(w, "{interval: 0.001, channels: [orientation], summary: {channel: wheel.qz}}", 12),
      "s.yaml");
  const RunResult r = runScene(scene);
  ASSERT_TRUE(r.complete);
  // qz = sin(w t / 2): a smooth sine of period 4 pi / w, its maxima refined between samples.
  EXPECT_NEAR(r.summary.period, 4 * M_PI / w, 1e-6);
  EXPECT_NEAR(r.summary.amplitude_pp, 2.0, 1e-6);
}

TEST(OutputChannels, PendulumJointAngleIsTheBobsPitchAndEnergyIsConserved) {
  const double l = 1.0, a0 = 30 * M_PI / 180;
  char text[1024];
  std::snprintf(text, sizeof text, R"(simulation: {duration: 4, time_step: 0.001, integrator: rk4}
bodies:
  - {name: bob, mass: 1, inertia: [1.0e-4, 1.0e-4, 1.0e-4], position: [%.17g, 0, %.17g]}
joints:
  - {name: pivot, type: revolute, parent: world, child: bob, anchor: [0, 0, 0], axis: [0, 1, 0]}
output: {interval: 0.01, channels: [rpy, angular_velocity, joints, energy]}
)",
                -l * std::sin(a0), -l * std::cos(a0));
  const RunResult r = runScene(io::loadSceneFromString(text, "p.yaml"));
  ASSERT_TRUE(r.complete) << r.message;
  const auto& tr = r.trajectory;
  const auto q = tr.column(tr.columnIndex("pivot.q"));
  const auto rate = tr.column(tr.columnIndex("pivot.rate"));
  const auto pitch = tr.column(tr.columnIndex("bob.pitch"));
  const auto wy = tr.column(tr.columnIndex("bob.wy"));
  const auto kinetic = tr.column(tr.columnIndex("energy.kinetic"));
  const auto gravity = tr.column(tr.columnIndex("energy.gravity"));
  const auto elastic = tr.column(tr.columnIndex("energy.elastic"));
  const double e0 = kinetic[0] + gravity[0];
  double q_max = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    EXPECT_NEAR(q[i], pitch[i], 1e-9);  // |angle| < 90 deg: pitch is the angle about y
    EXPECT_NEAR(rate[i], wy[i], 1e-9);
    EXPECT_NEAR(kinetic[i] + gravity[i], e0, 1e-6 * std::abs(e0) + 1e-9);
    EXPECT_EQ(elastic[i], 0.0);
    q_max = std::max(q_max, std::abs(q[i]));
  }
  // q counts from the pose the scene gives (released at +30 deg): it swings to -30 deg.
  EXPECT_NEAR(q_max, 2 * a0, 1e-3);
}

TEST(OutputChannels, DefaultColumnsAndBadInput) {
  const io::Scene scene = io::loadSceneFromString(spinner(1, "{interval: 0.01}"), "s.yaml");
  EXPECT_EQ(TrajectoryRecorder(*scene.model, 0, false, scene.output.channels).columns(),
            (std::vector<std::string>{"t", "wheel.x", "wheel.y", "wheel.z", "wheel.vx", "wheel.vy",
                                      "wheel.vz", "wheel.slip", "wheel.normal_force"}));
  const std::string bad = test::sceneErrorOf(spinner(1, "{channels: [position, attitude]}"));
  EXPECT_NE(bad.find("unknown channel group 'attitude'"), std::string::npos) << bad;
  EXPECT_NE(bad.find("rpy"), std::string::npos) << bad;  // the known groups are listed
  const std::string twice = test::sceneErrorOf(spinner(1, "{channels: [rpy, rpy]}"));
  EXPECT_NE(twice.find("listed twice"), std::string::npos) << twice;
  const std::string missing =
      test::sceneErrorOf(spinner(1, "{channels: [position], summary: {channel: wheel.yaw}}"));
  EXPECT_NE(missing.find("no recorded channel 'wheel.yaw'"), std::string::npos) << missing;
  EXPECT_NE(missing.find("needs rpy"), std::string::npos) << missing;
}

}  // namespace
}  // namespace tribo::study
