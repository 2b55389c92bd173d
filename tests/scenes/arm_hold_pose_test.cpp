// scenes/experiments/arm_hold_pose.yaml (a URDF two-link arm held by PD position servos)
// against the closed form of its rest: with no gravity compensation the pose settles where
// each servo's torque carries the gravity torque,
//   kp1 (r1 - q1) = g [(m1 c1 + m2 l1) sin q1 + m2 c2 sin(q1 + q2)],
//   kp2 (r2 - q2) = g m2 c2 sin(q1 + q2),
// solved here by Newton's method from the URDF's numbers, at two gain sets (the offset
// shrinking as 1 / kp); and the servos' default effort limits taken from the URDF's rated
// efforts, saturating when the gain is large.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/constraint_rows.hpp"
#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/experiments/arm_hold_pose.yaml";
constexpr double kG = 9.81, kM1 = 2.0, kC1 = 0.25, kL1 = 0.5, kM2 = 1.0, kC2 = 0.2;

// The rest pose (q1, q2) for targets r and gains kp.
Eigen::Vector2d restPose(const Eigen::Vector2d& r, const Eigen::Vector2d& kp) {
  Eigen::Vector2d q = r;
  for (int i = 0; i < 50; ++i) {
    const double s1 = std::sin(q(0)), s12 = std::sin(q(0) + q(1));
    const double c1 = std::cos(q(0)), c12 = std::cos(q(0) + q(1));
    const double a = kM1 * kC1 + kM2 * kL1, b = kM2 * kC2;
    const Eigen::Vector2d f(kp(0) * (r(0) - q(0)) - kG * (a * s1 + b * s12),
                            kp(1) * (r(1) - q(1)) - kG * b * s12);
    Eigen::Matrix2d j;
    j << -kp(0) - kG * (a * c1 + b * c12), -kG * b * c12, -kG * b * c12, -kp(1) - kG * b * c12;
    q -= j.partialPivLu().solve(f);
  }
  return q;
}

struct ArmRun {
  Eigen::Vector2d q, rate;
  double peak_effort = 0.0;  // largest |shoulder effort|
  bool saturated = false;    // the shoulder's, at any step
};

ArmRun run(const std::vector<std::string>& overrides) {
  const io::Scene scene = io::loadScene(kScene, overrides);
  Simulator sim(scene.model);
  const Model& m = *scene.model;
  ArmRun out;
  while (sim.state().time < m.options.duration - 1e-9) {
    const StepStatus s = sim.step();
    EXPECT_TRUE(s.ok) << s.message;
    if (!s.ok) return out;
    for (std::size_t j = 0; j < m.joints.size(); ++j)
      if (m.joints[j].name == "shoulder") {
        const ActuatorOutput& a = sim.current().actuator_output[j];
        out.peak_effort = std::max(out.peak_effort, std::abs(a.effort));
        out.saturated = out.saturated || a.saturated;
      }
  }
  const Workspace& ws = sim.current();
  const MotionView motion(sim.state(), ws.rotation);
  for (std::size_t j = 0; j < m.joints.size(); ++j) {
    const JointCoordinate c = jointCoordinate(m.joints[j]);
    CoordinateValue v;
    evaluateCoordinate(c, motion(c.parent), motion(c.child), v);
    const int i = m.joints[j].name == "shoulder" ? 0 : 1;
    out.q(i) = v.q;
    out.rate(i) = v.rate;
  }
  return out;
}

TEST(ArmHoldPose, SettlesWhereTheServosCarryGravity) {
  const Eigen::Vector2d r(0.8, -0.6);
  for (const double scale : {1.0, 4.0}) {
    const Eigen::Vector2d kp = Eigen::Vector2d(400.0, 150.0) * scale;
    const Eigen::Vector2d kd = Eigen::Vector2d(40.0, 8.0) * std::sqrt(scale);
    const ArmRun got = run({"kp1=" + std::to_string(kp(0)), "kp2=" + std::to_string(kp(1)),
                            "kd1=" + std::to_string(kd(0)), "kd2=" + std::to_string(kd(1))});
    const Eigen::Vector2d want = restPose(r, kp);
    std::printf("kp x%g: q (%.9f, %.9f), rest (%.9f, %.9f), offset %.3g rad\n", scale, got.q(0),
                got.q(1), want(0), want(1), (r - want).norm());
    EXPECT_LT((got.q - want).norm(), 1e-6) << scale;
    EXPECT_LT(got.rate.norm(), 1e-5);
    // The offset is the gravity torque over the gain: it is there, and it shrinks with kp.
    EXPECT_GT((r - want).norm(), 4e-3 / scale);
    EXPECT_LE(got.peak_effort, 40.0);
  }
}

TEST(ArmHoldPose, ServoSaturatesAtTheUrdfRatedEffort) {
  // A target stepped to 0.8 rad at t = 0 with kp 4000 N m/rad asks for 3200 N m at once.
  const ArmRun got =
      run({"actuators[shoulder_servo].target=0.8", "kp1=4000", "kd1=120", "duration=0.5"});
  EXPECT_TRUE(got.saturated);
  EXPECT_EQ(got.peak_effort, 40.0);
}

}  // namespace
}  // namespace tribo
