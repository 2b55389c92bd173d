// Kinematic bodies along signals (core/prescribed_motion.hpp) against closed forms:
// - the motion itself: a shaker's position is the integral of its velocity signal and a
//   turntable's angle that of its rate, exact at every step's end for every integrator;
// - what it drives: a block on a spring to a shaker moving as X sin(W t) follows the forced
//   undamped oscillator u = X w^2 / (w^2 - W^2) (sin W t - (W / w) sin w t), and a disc on a
//   torsional spring to a turntable spun up at a constant rate's slope a lags it by
//   e = -(a / w^2) (1 - cos w t): the accelerations the integrators see between step ends
//   are the signals' derivatives, and the spring's forces come from the exact pose;
// - kinks: a shaker whose velocity is a table stops dopri5 at its corners;
// - refusals: a dynamic body with a motion, an axis that is not unit, a joint to the body.
#include "core/prescribed_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "core/input_breakpoints.hpp"
#include "core/model_builder.hpp"
#include "core/simulator.hpp"

namespace tribo {
namespace {

constexpr double kPi = std::numbers::pi;

struct Way {
  const char* name;
  IntegratorType integrator;
  double shaker;     // tolerance on the block's motion relative to its amplitude
  double turntable;  // on the disc's lag relative to its amplitude
};
// rk4 at 1 ms: its global error ~ T w^5 h^4 / 120 ~ 2.5e-9 of the amplitude on a
// 10 rad/s oscillator over 3 s (measured 1.1e-9 and 7.6e-10); semi-implicit Euler is
// first order (measured 5.7e-5, 3.8e-5); the adaptive ones hold 1e-10 relative to the state
// per step: the block sits at x = 1 m, 20 times its amplitude, and the disc turns through
// 1 rad, 100 times its lag, so over 2000-3000 output steps dopri5 comes to 1.7e-8 and
// 2.5e-7 of them, BDF (looser local control) to 1.7e-7 and 2.4e-7.
constexpr Way kWays[] = {{"rk4", IntegratorType::kRk4, 3e-9, 3e-9},
                         {"semi_implicit_euler", IntegratorType::kSemiImplicitEuler, 1e-4, 1e-4},
                         {"dopri5", IntegratorType::kDopri5, 3e-8, 1e-6},
                         {"bdf", IntegratorType::kBdf, 1e-6, 1e-6}};

void setWay(ModelBuilder& b, const Way& way, double duration) {
  b.options().integrator = way.integrator;
  b.options().time_step = 1e-3;
  b.options().duration = duration;
  b.options().relative_tolerance = 1e-10;
  b.options().absolute_tolerance = 1e-13;
  b.options().gravity = Vec3::Zero();
}

Body kinematic(const std::string& name, std::shared_ptr<PrescribedMotion> motion) {
  Body body;
  body.name = name;
  body.kind = BodyKind::kKinematic;
  body.motion = std::move(motion);
  return body;
}

// x(t) = X sin(W t): v = X W cos(W t) = X W sin(W t + pi / 2).
Signal shakerVelocity(double amplitude, double omega) {
  return Signal::sines({{amplitude * omega, omega / (2 * kPi), kPi / 2, 0.0}});
}

TEST(PrescribedMotion, PoseAndVelocityAreTheSignalsIntegralsAndValues) {
  PrescribedMotion m;
  m.velocity = {shakerVelocity(0.05, 4.0), Signal::ramp(0.3, 1.0, 0.2), Signal::constant(-1.5)};
  m.spin_axis = Vec3(1, 2, 2) / 3.0;
  m.spin_rate = Signal::ramp(0.5);
  Body body = kinematic("k", nullptr);
  body.position = Vec3(1, -2, 3);
  body.orientation = Quat(Eigen::AngleAxisd(0.7, Vec3::UnitY()));
  for (double t : {0.0, 0.3, 1.0, 1.7, 12.5}) {
    const BodyState s = m.at(body, t);
    const double ramp_area = 0.2 * t + (t > 1.0 ? 0.15 * (t - 1) * (t - 1) : 0.0);
    const Vec3 p = body.position + Vec3(0.05 * std::sin(4 * t), ramp_area, -1.5 * t);
    EXPECT_LT((s.position - p).norm(), 1e-14 * (1 + p.norm())) << t;
    const Vec3 v(0.2 * std::cos(4 * t), 0.2 + (t > 1.0 ? 0.3 * (t - 1) : 0.0), -1.5);
    EXPECT_LT((s.velocity - v).norm(), 1e-14) << t;
    const Quat q = Quat(Eigen::AngleAxisd(0.25 * t * t, m.spin_axis)) * body.orientation;
    EXPECT_LT(s.orientation.angularDistance(q), 1e-14) << t;
    EXPECT_LT((s.angular_velocity - 0.5 * t * m.spin_axis).norm(), 1e-15) << t;
    EXPECT_LT(
        (m.linearAcceleration(t) - Vec3(-0.8 * std::sin(4 * t), t >= 1.0 ? 0.3 : 0.0, 0.0)).norm(),
        1e-14)
        << t;
    EXPECT_LT((m.angularAcceleration(t) - 0.5 * m.spin_axis).norm(), 1e-15) << t;
  }
  // |v| grows to its largest at t = 2 (its last sample).
  EXPECT_NEAR(m.speedBound(2.0), std::hypot(0.2 * std::cos(8.0), 0.5, 1.5), 1e-15);
  EXPECT_NEAR(m.spinBound(2.0), 1.0, 1e-15);
}

// A block of mass m on a spring k to a shaker moving as X sin(W t) along x (rest length 1,
// so the spring stays along x); no gravity, no contact.
TEST(PrescribedMotion, ABlockOnASpringToAShakerIsTheForcedOscillator) {
  const double mass = 2.0, k = 200.0, amplitude = 0.05, omega = 4.0, duration = 3.0;
  const double w = std::sqrt(k / mass);
  for (const Way& way : kWays) {
    SCOPED_TRACE(way.name);
    ModelBuilder b;
    setWay(b, way, duration);
    auto motion = std::make_shared<PrescribedMotion>();
    motion->velocity[0] = shakerVelocity(amplitude, omega);
    const BodyIndex shaker = b.addBody(kinematic("shaker", motion));
    Body block;
    block.name = "block";
    block.mass = mass;
    block.inertia = Mat3::Identity() * 0.01;
    block.position = Vec3(1, 0, 0);
    const BodyIndex blk = b.addBody(block);
    b.addSpring("spring", shaker, Vec3::Zero(), blk, Vec3(1, 0, 0), k, 0.0, 1.0);
    Simulator sim(b.build());
    EXPECT_EQ((sim.state().bodies[shaker.value].velocity - Vec3(amplitude * omega, 0, 0)).norm(),
              0.0);
    double worst_shaker = 0.0, worst_block = 0.0;
    const int steps = static_cast<int>(std::lround(duration / 1e-3));
    for (int i = 0; i < steps; ++i) {
      ASSERT_TRUE(sim.step().ok) << i;
      const double t = sim.state().time;
      const BodyState& s = sim.state().bodies[shaker.value];
      worst_shaker =
          std::max({worst_shaker, std::abs(s.position.x() - amplitude * std::sin(omega * t)),
                    std::abs(s.velocity.x() - amplitude * omega * std::cos(omega * t))});
      const double u = amplitude * w * w / (w * w - omega * omega) *
                       (std::sin(omega * t) - omega / w * std::sin(w * t));
      worst_block =
          std::max(worst_block, std::abs(sim.state().bodies[blk.value].position.x() - 1.0 - u));
    }
    EXPECT_LT(worst_shaker, 1e-15);
    EXPECT_LT(worst_block, way.shaker * amplitude);
    std::cout << way.name << ": shaker " << worst_shaker << " m, block " << worst_block / amplitude
              << " of X\n";
  }
}

// A disc (I_z) on a torsional spring k to a turntable whose rate is a t about z: the
// turntable's angle is a t^2 / 2 exactly, the disc's lags it by (a / w^2)(1 - cos w t).
TEST(PrescribedMotion, ADiscOnATorsionalSpringToASpunUpTurntableLagsByTheClosedForm) {
  const double iz = 0.02, k = 2.0, a = 0.5, duration = 2.0;
  const double w = std::sqrt(k / iz);
  for (const Way& way : kWays) {
    SCOPED_TRACE(way.name);
    ModelBuilder b;
    setWay(b, way, duration);
    auto motion = std::make_shared<PrescribedMotion>();
    motion->spin_rate = Signal::ramp(a);
    const BodyIndex table = b.addBody(kinematic("turntable", motion));
    Body disc;
    disc.name = "disc";
    disc.inertia = Vec3(iz / 2, iz / 2, iz).asDiagonal();
    const BodyIndex d = b.addBody(disc);
    b.addTorsionalSpring("shaft", table, d, Vec3::UnitZ(), k, 0.0, 0.0);
    Simulator sim(b.build());
    double worst_table = 0.0, worst_lag = 0.0;
    const int steps = static_cast<int>(std::lround(duration / 1e-3));
    auto angle = [](const Quat& q) {
      const Mat3 r = q.toRotationMatrix();
      return std::atan2(r(1, 0), r(0, 0));
    };
    for (int i = 0; i < steps; ++i) {
      ASSERT_TRUE(sim.step().ok) << i;
      const double t = sim.state().time;
      const double phi = a * t * t / 2;
      worst_table =
          std::max(worst_table, std::abs(angle(sim.state().bodies[table.value].orientation) - phi));
      const double lag = -(a / (w * w)) * (1 - std::cos(w * t));
      worst_lag =
          std::max(worst_lag, std::abs(angle(sim.state().bodies[d.value].orientation) - phi - lag));
    }
    EXPECT_LT(worst_table, 1e-14);
    EXPECT_LT(worst_lag, way.turntable * 2 * a / (w * w));
    std::cout << way.name << ": turntable " << worst_table << " rad, lag "
              << worst_lag / (2 * a / (w * w)) << " of its amplitude\n";
  }
}

// A shaker whose speed is a table with corners at 0.25 and 0.6 s: the corners are the
// adaptive integrators' stop times, and the position is the table's area (dopri5 on a
// model with nothing to integrate: only kinematic bodies).
TEST(PrescribedMotion, ATableOfSpeedsStopsTheAdaptiveIntegratorAtItsCorners) {
  ModelBuilder b;
  setWay(b, kWays[2], 1.0);
  auto motion = std::make_shared<PrescribedMotion>();
  motion->velocity[1] = Signal::table({{0.25, 0.0}, {0.6, 0.7}});
  const BodyIndex shaker = b.addBody(kinematic("shaker", motion));
  const auto model = b.build();
  const std::vector<double> stops = inputBreakpoints(*model);
  ASSERT_EQ(stops.size(), 2u);
  EXPECT_EQ(stops[0], 0.25);
  EXPECT_EQ(stops[1], 0.6);
  Simulator sim(model);
  for (int i = 0; i < 1000; ++i) {
    const StepStatus status = sim.step();
    ASSERT_TRUE(status.ok) << i << ": " << status.message;
  }
  // Area: 0 up to 0.25, the triangle 0.35 * 0.7 / 2, then 0.7 a second for 0.4 s.
  EXPECT_NEAR(sim.state().bodies[shaker.value].position.y(), 0.35 * 0.7 / 2 + 0.7 * 0.4, 1e-15);
  EXPECT_EQ(sim.state().bodies[shaker.value].velocity.y(), 0.7);
}

TEST(PrescribedMotion, RefusesADynamicBodyAnAxisNotUnitAndAJointToTheBody) {
  auto motion = std::make_shared<PrescribedMotion>();
  motion->velocity[0] = Signal::ramp(1.0);
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  {
    ModelBuilder b;
    Body body = kinematic("plate", motion);
    body.kind = BodyKind::kDynamic;
    EXPECT_NE(message([&] { b.addBody(body); })
                  .find("body 'plate': a velocity along signals is "
                        "for kinematic bodies"),
              std::string::npos);
  }
  {
    ModelBuilder b;
    auto tilted = std::make_shared<PrescribedMotion>(*motion);
    tilted->spin_axis = Vec3(1, 1, 0);
    EXPECT_NE(message([&] {
                b.addBody(kinematic("plate", tilted));
              }).find("the turning axis must be a unit vector (got 1.41421"),
              std::string::npos);
  }
  {
    ModelBuilder b;
    const BodyIndex plate = b.addBody(kinematic("plate", motion));
    Body arm;
    arm.name = "arm";
    const BodyIndex a = b.addBody(arm);
    b.addJoint("hinge", JointType::kRevolute, plate, a, Vec3::Zero(), Vec3::UnitZ());
    EXPECT_NE(message([&] { b.build(); })
                  .find("joint 'hinge': body 'plate' moves along signals, and a joint cannot "
                        "follow its acceleration"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace tribo
