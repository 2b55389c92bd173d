// Joint drives that take a time signal (core/joint_elements.hpp, JointDrive::signal) against
// closed forms: a position drive along a smooth step and a sum of sines (the angle, and the
// drive's torque I q''), a velocity drive along a piecewise-linear table of speeds (the
// position is the table's area, written out here), a velocity drive stepping up and down
// with the velocity projection (the speed is the new one from the step that crosses the
// jump on, and the position the step function's area), a velocity drive along a function
// signal (q = its integral, sin); the drive's breakpoints are the integrators' stop times.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "core/input_breakpoints.hpp"
#include "core/model_builder.hpp"
#include "core/simulator.hpp"

namespace tribo {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kIz = 0.04;  // disk inertia about its axis [kg m^2]

// A disk turning about the world z axis through its centre; no gravity. Returns the joint.
int disk(ModelBuilder& b) {
  Body body;
  body.name = "disk";
  body.inertia = Vec3(kIz / 2, kIz / 2, kIz).asDiagonal();
  const BodyIndex i = b.addBody(body);
  b.options().gravity = Vec3::Zero();
  return b.addJoint("axle", JointType::kRevolute, BodyIndex::world(), i, Vec3::Zero(),
                    Vec3::UnitZ());
}

// A slider of `mass` on a rail along x through the origin, gravity -z (across the rail).
int slider(ModelBuilder& b, double mass, double v0 = 0.0) {
  Body body;
  body.name = "slider";
  body.mass = mass;
  body.inertia = Mat3::Identity() * 0.01 * mass;
  body.velocity = Vec3(v0, 0, 0);
  const BodyIndex i = b.addBody(body);
  return b.addJoint("rail", JointType::kPrismatic, BodyIndex::world(), i, Vec3::Zero(),
                    Vec3::UnitX());
}

double angleOf(const BodyState& s) {
  const Mat3 r = s.orientation.toRotationMatrix();
  return std::atan2(r(1, 0), r(0, 0));
}

JointDrive driveOf(DriveMode mode, Signal signal) {
  JointDrive d;
  d.mode = mode;
  d.signal = std::move(signal);
  return d;
}

// The ways through a drive's kinks: a fixed step of rk4 evaluates its last stage at the
// step's end with the signal's right-continuous slope, so a step that ends on or straddles
// a kink errs by about h / 6 times the jump of the rate's slope (5e-4 m/s at 3.2 m/s^2 and
// 1 ms), which Baumgarte then decays; the projection puts the motion back on the drive at
// every step's end (to its tolerance, 1e-10 here); dopri5 ends a step on each breakpoint.
struct Way {
  const char* name;
  IntegratorType integrator;
  bool projection;
};
constexpr Way kWays[] = {{"rk4 + projection", IntegratorType::kRk4, true},
                         {"dopri5", IntegratorType::kDopri5, false}};

void setWay(ModelBuilder& b, const Way& way) {
  b.options().integrator = way.integrator;
  b.options().constraints.projection = way.projection;
  b.options().time_step = 1e-3;
  b.options().relative_tolerance = 1e-10;
  b.options().absolute_tolerance = 1e-13;
}

TEST(JointDriveSignal, PositionDriveFollowsASmoothStepAndItsTorqueIsInertiaTimesAcceleration) {
  // q = h s^2 (3 - 2 s), s = (t - t0) / w: q'' = 6 h (1 - 2 s) / w^2, torque I q'' (compared
  // away from the kinks, where a step's last evaluation sees the new slope).
  for (const Way& way : kWays)
    for (const double h : {0.05, 0.8}) {
      const double t0 = 0.1, w = 0.4;
      ModelBuilder b;
      setWay(b, way);
      b.setJointDrive(disk(b),
                      driveOf(DriveMode::kPosition, Signal::smoothStep(t0, 0.0, t0 + w, h)));
      Simulator sim(b.build());
      double worst_q = 0.0, worst_torque = 0.0;
      while (sim.state().time < 0.7) {
        ASSERT_TRUE(sim.step().ok);
        const double t = sim.state().time;
        const double s = std::clamp((t - t0) / w, 0.0, 1.0);
        worst_q =
            std::max(worst_q, std::abs(angleOf(sim.state().bodies[0]) - h * s * s * (3 - 2 * s)));
        if (std::abs(t - t0) > 3e-3 && std::abs(t - t0 - w) > 3e-3) {
          const double accel = t >= t0 && t < t0 + w ? 6 * h * (1 - 2 * s) / (w * w) : 0.0;
          const double torque = sim.current().constraint_wrench[0].torque.z();
          worst_torque = std::max(worst_torque, std::abs(torque - kIz * accel));
        }
      }
      EXPECT_LT(worst_q, 2e-10) << way.name << " " << h;
      EXPECT_LT(worst_torque, 1e-6 * kIz * 6 * h / (w * w)) << way.name << " " << h;
    }
}

TEST(JointDriveSignal, PositionDriveFollowsASumOfSines) {
  // q = 0.2 sin(2 pi 1.5 t) + 0.1 sin(2 pi 4 t + 0.5) - 0.1 sin(0.5).
  ModelBuilder b;
  b.setJointDrive(
      disk(b),
      driveOf(DriveMode::kPosition,
              Signal::sines({{0.2, 1.5, 0.0, 0.0}, {0.1, 4.0, 0.5, -0.1 * std::sin(0.5)}})));
  Simulator sim(b.build());
  double worst = 0.0;
  for (int i = 0; i < 1500; ++i) {
    ASSERT_TRUE(sim.step().ok);
    const double t = sim.state().time;
    const double q =
        0.2 * std::sin(3 * kPi * t) + 0.1 * std::sin(8 * kPi * t + 0.5) - 0.1 * std::sin(0.5);
    worst = std::max(worst, std::abs(angleOf(sim.state().bodies[0]) - q));
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(JointDriveSignal, VelocityDriveAlongATableMovesByItsArea) {
  // Speeds 0.1 -> 0.5 m/s over [0.25, 0.375] s, held, back to 0.1 over [0.625, 0.75]: the
  // position is the area under the table, at every step's end (kWays).
  auto area = [](double t) {
    if (t <= 0.25) return 0.1 * t;
    if (t <= 0.375) return 0.025 + 0.1 * (t - 0.25) + 1.6 * (t - 0.25) * (t - 0.25);
    if (t <= 0.625) return 0.0625 + 0.5 * (t - 0.375);
    if (t <= 0.75) return 0.1875 + 0.5 * (t - 0.625) - 1.6 * (t - 0.625) * (t - 0.625);
    return 0.225 + 0.1 * (t - 0.75);
  };
  auto speed = [](double t) {
    if (t <= 0.25) return 0.1;
    if (t <= 0.375) return 0.1 + 3.2 * (t - 0.25);
    if (t <= 0.625) return 0.5;
    if (t <= 0.75) return 0.5 - 3.2 * (t - 0.625);
    return 0.1;
  };
  for (const Way& way : kWays)
    for (const double mass : {0.01, 1.0, 100.0}) {
      ModelBuilder b;
      setWay(b, way);
      const int j = slider(b, mass, 0.1);
      b.setJointDrive(
          j, driveOf(DriveMode::kVelocity,
                     Signal::table({{0.25, 0.1}, {0.375, 0.5}, {0.625, 0.5}, {0.75, 0.1}})));
      Simulator sim(b.build());
      double worst_x = 0.0, worst_v = 0.0;
      while (sim.state().time < 1.0) {
        ASSERT_TRUE(sim.step().ok);
        const double t = sim.state().time;
        worst_x = std::max(worst_x, std::abs(sim.state().bodies[0].position.x() - area(t)));
        worst_v = std::max(worst_v, std::abs(sim.state().bodies[0].velocity.x() - speed(t)));
      }
      // dopri5's speed to its tolerance: 1e-10 relative, a few of its steps' errors.
      const double v_bound = way.projection ? 2e-10 : 5e-9;
      EXPECT_LT(worst_x, 2e-10) << way.name << " " << mass;
      EXPECT_LT(worst_v, v_bound) << way.name << " " << mass;
    }
}

TEST(JointDriveSignal, VelocityStepUpAndDownIsFollowedWithTheProjection) {
  // v = 1e-5 m/s, 1e-4 from t = 0.25 s, 1e-5 again from 0.6 s: a rate-and-state test's
  // speeds. With the velocity projection the slider moves at the new speed from the end of
  // the step that crosses the jump on; its position is the step function's area.
  for (const double dt : {1e-3, 4e-4}) {
    ModelBuilder b;
    b.options().time_step = dt;
    b.options().constraints.projection = true;
    const int j = slider(b, 1.0, 1e-5);
    b.setJointDrive(j, driveOf(DriveMode::kVelocity,
                               Signal::function(
                                   [](double t) { return t < 0.25  ? 1e-5
                                                         : t < 0.6 ? 1e-4
                                                                   : 1e-5; },
                                   [](double) { return 0.0; }, {0.25, 0.6})));
    Simulator sim(b.build());
    auto area = [](double t) { return 1e-5 * t + 9e-5 * std::clamp(t - 0.25, 0.0, 0.35); };
    double worst_x = 0.0, worst_v = 0.0;
    const long n = std::lround(1.0 / dt);
    for (long i = 0; i < n; ++i) {
      ASSERT_TRUE(sim.step().ok);
      const double t = sim.state().time;
      const double v = t < 0.25 ? 1e-5 : t < 0.6 ? 1e-4 : 1e-5;  // as the signal compares
      worst_x = std::max(worst_x, std::abs(sim.state().bodies[0].position.x() - area(t)));
      worst_v = std::max(worst_v, std::abs(sim.state().bodies[0].velocity.x() - v));
    }
    EXPECT_LT(worst_x, 1e-12) << dt;  // of 4.1e-5 m travelled
    EXPECT_LT(worst_v, 1e-13) << dt;  // of speeds 1e-5 .. 1e-4 m/s
  }
}

TEST(JointDriveSignal, VelocityDriveAlongAFunctionMovesByItsIntegral) {
  // q' = A w cos(w t): q = A sin(w t).
  const double a = 0.03, w = 5.0;
  ModelBuilder b;
  const int j = disk(b);
  b.setJointDrive(j, driveOf(DriveMode::kVelocity,
                             Signal::function([=](double t) { return a * w * std::cos(w * t); })));
  Simulator sim(b.build());
  double worst = 0.0;
  for (int i = 0; i < 1500; ++i) {
    ASSERT_TRUE(sim.step().ok);
    worst = std::max(worst,
                     std::abs(angleOf(sim.state().bodies[0]) - a * std::sin(w * sim.state().time)));
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(JointDriveSignal, ADrivesBreakpointsAreTheIntegratorsStopTimes) {
  ModelBuilder b;
  b.setJointDrive(slider(b, 1.0),
                  driveOf(DriveMode::kVelocity, Signal::table({{0.2, 0.0}, {0.5, 1.0}})));
  const auto model = b.build();
  EXPECT_EQ(inputBreakpoints(*model), (std::vector<double>{0.2, 0.5}));
}

}  // namespace
}  // namespace tribo
