// Joint actuators (core/joint_actuator.hpp) against closed forms, in zero gravity:
//   position servo on a slider of mass m, a constant target r from rest: m e'' + kd e' + kp e = 0
//     with e = r - q, e(0) = r, e'(0) = 0, at three masses and three gain sets (under-,
//     critically near and over-damped), its overshoot r exp(-zeta pi / sqrt(1 - zeta^2));
//   saturation: while kp e - kd q' exceeds tau_max the slider accelerates at tau_max / m;
//   velocity servo: q' = s (1 - exp(-kd t / m)), s the target clamped to the velocity limit;
//   motor torque ramp on a flywheel: w = rate t^2 / (2 I), then tau_max t / I once saturated;
//   the angle error of a revolute servo taken the short way round; the actuator's power in
//   the energy account; the stable step estimate counting kp and kd; the builder's checks.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "core/energy.hpp"
#include "core/model_builder.hpp"
#include "core/simulator.hpp"
#include "core/stability.hpp"

namespace tribo {
namespace {

// A block of mass m on a prismatic joint along x from the world, RK4 at dt.
struct Slider {
  ModelBuilder builder;
  int joint = -1;
  Slider(double m, double dt, double duration = 1.0) {
    Body body;
    body.name = "block";
    body.mass = m;
    body.inertia = Mat3::Identity() * m * 0.01;
    const BodyIndex b = builder.addBody(body);
    joint = builder.addJoint("slide", JointType::kPrismatic, BodyIndex::world(), b, Vec3::Zero(),
                             Vec3::UnitX());
    builder.options().gravity = Vec3::Zero();
    builder.options().integrator = IntegratorType::kRk4;
    builder.options().time_step = dt;
    builder.options().duration = duration;
  }
};

JointActuator servo(double target, double kp, double kd) {
  JointActuator a;
  a.name = "servo";
  a.kind = ActuatorKind::kPositionServo;
  a.target = Signal::constant(target);
  a.kp = kp;
  a.kd = kd;
  return a;
}

// e(t) / e(0) for e'' + 2 zeta w e' + w^2 e = 0 from rest.
double servoError(double zeta, double w, double t) {
  if (zeta < 1.0) {
    const double wd = w * std::sqrt(1.0 - zeta * zeta);
    return std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t));
  }
  const double root = w * std::sqrt(zeta * zeta - 1.0);
  const double s1 = -zeta * w + root, s2 = -zeta * w - root;
  return (-s2 * std::exp(s1 * t) + s1 * std::exp(s2 * t)) / (s1 - s2);
}

TEST(JointActuator, PositionServoFollowsTheSecondOrderResponse) {
  struct Gains {
    double w, zeta;
  };
  for (const double m : {0.05, 1.0, 40.0})
    for (const Gains g : {Gains{20.0, 0.1}, Gains{60.0, 0.7}, Gains{15.0, 2.5}}) {
      const double r = 0.01, dt = 1e-4;
      Slider s(m, dt);
      s.builder.setJointActuator(s.joint, servo(r, m * g.w * g.w, 2 * g.zeta * m * g.w));
      Simulator sim(s.builder.build());
      double peak = 0.0, worst = 0.0;
      while (sim.state().time < 1.0 - 1e-12) {
        ASSERT_TRUE(sim.step().ok);
        const double q = sim.state().bodies[0].position.x();
        worst =
            std::max(worst, std::abs(q - r * (1.0 - servoError(g.zeta, g.w, sim.state().time))));
        peak = std::max(peak, q);
      }
      // RK4's global error ~ (w dt)^4 of the amplitude: below 2e-8 here.
      EXPECT_LT(worst, 1e-7 * r) << "m " << m << " w " << g.w << " zeta " << g.zeta;
      if (g.zeta < 1.0) {
        const double overshoot =
            r * std::exp(-g.zeta * std::numbers::pi / std::sqrt(1.0 - g.zeta * g.zeta));
        // Sampled every dt: the peak is missed by at most |q''| dt^2 / 2 <= w^2 r dt^2.
        EXPECT_NEAR(peak - r, overshoot, g.w * g.w * r * dt * dt) << m << " " << g.zeta;
      } else {
        EXPECT_LE(peak, r * (1.0 + 1e-9)) << "an overdamped servo does not overshoot";
      }
    }
}

TEST(JointActuator, SaturatedServoAcceleratesAtTheEffortLimit) {
  for (const double m : {0.2, 1.0, 25.0}) {
    const double tau_max = 2.0 * m, r = 1.0, dt = 1e-3;
    Slider s(m, dt);
    JointActuator a = servo(r, 1e5 * m, 10.0 * m);
    a.max_effort = tau_max;
    s.builder.setJointActuator(s.joint, a);
    Simulator sim(s.builder.build());
    // Saturated while kp (r - q) - kd q' > tau_max: q = t^2 up to q near 1 (t near 1).
    while (sim.state().time < 0.5 - 1e-12) ASSERT_TRUE(sim.step().ok);
    const double t = sim.state().time;
    // A constant force: RK4 exact up to rounding.
    EXPECT_NEAR(sim.state().bodies[0].position.x(), 0.5 * tau_max / m * t * t, 1e-12);
    EXPECT_NEAR(sim.state().bodies[0].velocity.x(), tau_max / m * t, 1e-12);
    const ActuatorOutput& out = sim.current().actuator_output[0];
    EXPECT_TRUE(out.saturated);
    EXPECT_EQ(out.effort, tau_max);
    EXPECT_EQ(out.target, r);
  }
}

TEST(JointActuator, VelocityServoApproachesItsClampedTarget) {
  for (const double limit : {std::numeric_limits<double>::infinity(), 0.3}) {
    const double m = 2.0, kd = 8.0, target = 0.5, dt = 1e-4;
    Slider s(m, dt);
    JointActuator a;
    a.name = "spindle";
    a.kind = ActuatorKind::kVelocityServo;
    a.target = Signal::constant(target);
    a.kd = kd;
    a.max_velocity = limit;
    s.builder.setJointActuator(s.joint, a);
    Simulator sim(s.builder.build());
    const double goal = std::min(target, limit);
    while (sim.state().time < 1.0 - 1e-12) {
      ASSERT_TRUE(sim.step().ok);
      const double t = sim.state().time;
      ASSERT_NEAR(sim.state().bodies[0].velocity.x(), goal * (1.0 - std::exp(-kd * t / m)), 1e-12)
          << t;
    }
    EXPECT_EQ(sim.current().actuator_output[0].target, goal);
  }
}

TEST(JointActuator, MotorRampSpinsAFlywheelUntilItSaturates) {
  const double iz = 0.4, rate = 3.0, tau_max = 1.5, dt = 1e-3;
  ModelBuilder b;
  Body wheel;
  wheel.name = "wheel";
  wheel.mass = 5.0;
  wheel.inertia = Vec3(0.3, 0.3, iz).asDiagonal();
  const BodyIndex w = b.addBody(wheel);
  const int joint =
      b.addJoint("axle", JointType::kRevolute, BodyIndex::world(), w, Vec3::Zero(), Vec3::UnitZ());
  JointActuator motor;
  motor.name = "motor";
  motor.target = Signal::ramp(rate);
  motor.max_effort = tau_max;
  b.setJointActuator(joint, motor);
  b.options().gravity = Vec3::Zero();
  b.options().integrator = IntegratorType::kRk4;
  b.options().time_step = dt;
  b.options().duration = 1.0;
  Simulator sim(b.build());
  const double t_sat = tau_max / rate;  // 0.5 s, on a step
  while (sim.state().time < 1.0 - 1e-12) {
    ASSERT_TRUE(sim.step().ok);
    const double t = sim.state().time;
    const double want = t <= t_sat ? rate * t * t / (2 * iz)
                                   : rate * t_sat * t_sat / (2 * iz) + tau_max * (t - t_sat) / iz;
    ASSERT_NEAR(sim.state().bodies[0].angular_velocity.z(), want, 1e-9 * want + 1e-15) << t;
  }
  EXPECT_TRUE(sim.current().actuator_output[0].saturated);
}

TEST(JointActuator, RevoluteServoTakesTheShortWayRound) {
  JointActuator a = servo(-3.0, 2.0, 0.0);
  // From q = 3.0 to -3.0: the short way is +(2 pi - 6) through pi, not -6.
  const ActuatorOutput out = actuatorEffort(a, 0.0, 3.0, 0.0, true);
  EXPECT_NEAR(out.effort, 2.0 * (2 * std::numbers::pi - 6.0), 1e-12);
  // A prismatic coordinate's error is not wrapped.
  EXPECT_NEAR(actuatorEffort(a, 0.0, 3.0, 0.0, false).effort, -12.0, 1e-12);
  // The target's derivative enters the damping term: r = 2 t, q' = 0.5: kd (2 - 0.5).
  a.target = Signal::ramp(2.0);
  a.kd = 4.0;
  EXPECT_NEAR(actuatorEffort(a, 1.0, 2.0, 0.5, false).effort, 4.0 * 1.5, 1e-12);
}

TEST(JointActuator, ItsPowerEntersTheEnergyAccount) {
  const double m = 3.0;
  Slider s(m, 1e-3);
  JointActuator a = servo(0.2, 50.0, 4.0);
  a.target = Signal::sines({{0.2, 1.5, 0.0, 0.0}});
  s.builder.setJointActuator(s.joint, a);
  Simulator sim(s.builder.build());
  for (int i = 0; i < 300; ++i) ASSERT_TRUE(sim.step().ok);
  const Workspace& ws = sim.current();
  const double v = sim.state().bodies[0].velocity.x();
  const EnergyAccount e = measureEnergy(sim.model(), sim.state(), ws);
  const double tau = ws.actuator_output[0].effort;
  ASSERT_GT(std::abs(tau * v), 1e-3);
  EXPECT_NEAR(e.input_power, tau * v, 1e-9 * std::abs(tau * v));
}

TEST(JointActuator, StableStepEstimateCountsTheServoGains) {
  const double m = 0.5, kp = 2e6, kd = 40.0;
  Slider s(m, 1e-5);
  s.builder.setJointActuator(s.joint, servo(0.0, kp, kd));
  const StabilityReport report = estimateStableStep(*s.builder.build());
  EXPECT_NEAR(report.limit.max_step, stableStep(IntegratorType::kRk4, kp / m, kd / m),
              1e-12 * report.limit.max_step);
  EXPECT_NE(report.limit.element.find("actuator 'servo'"), std::string::npos)
      << report.limit.element;
}

TEST(JointActuator, BuilderRefusesWhatCannotAct) {
  auto error = [](auto&& change) {
    Slider s(1.0, 1e-3);
    try {
      change(s);
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  auto has = [](const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
  };
  EXPECT_TRUE(has(error([](Slider& s) { s.builder.setJointActuator(s.joint, servo(0, -1, 0)); }),
                  "kp must be finite and >= 0"));
  EXPECT_TRUE(has(error([](Slider& s) { s.builder.setJointActuator(s.joint, servo(0, 0, 0)); }),
                  "needs kp > 0 or kd > 0"));
  EXPECT_TRUE(has(error([](Slider& s) {
                    JointActuator a = servo(0, 1, 1);
                    a.kind = ActuatorKind::kVelocityServo;
                    s.builder.setJointActuator(s.joint, a);
                  }),
                  "takes kd only"));
  EXPECT_TRUE(has(error([](Slider& s) {
                    JointActuator a = servo(0, 0, 1);
                    a.kind = ActuatorKind::kMotor;
                    s.builder.setJointActuator(s.joint, a);
                  }),
                  "a motor takes no gains"));
  EXPECT_TRUE(has(error([](Slider& s) {
                    JointActuator a = servo(0, 1, 1);
                    a.max_effort = -2.0;
                    s.builder.setJointActuator(s.joint, a);
                  }),
                  "effort limit must be > 0 (got -2)"));
  EXPECT_TRUE(has(error([](Slider& s) {
                    s.builder.setJointActuator(s.joint, servo(0, 1, 1));
                    s.builder.setJointActuator(s.joint, servo(0, 1, 1));
                  }),
                  "an actuator of that name is on joint 'slide'"));
  EXPECT_TRUE(has(error([](Slider& s) {
                    s.builder.setJointDrive(s.joint, JointDrive{});
                    s.builder.setJointActuator(s.joint, servo(0, 1, 1));
                  }),
                  "the joint has a drive"));
  // A rated joint lends its rating to limits left infinite.
  Slider s(1.0, 1e-3);
  s.builder.setJointRating(s.joint, 7.0, 2.0);
  s.builder.setJointActuator(s.joint, servo(0, 1, 1));
  const JointActuator& a = *s.builder.joints()[0].elements.actuator;
  EXPECT_EQ(a.max_effort, 7.0);
  EXPECT_EQ(a.max_velocity, 2.0);
}

}  // namespace
}  // namespace tribo
