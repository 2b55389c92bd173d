// Every integrator against closed-form motion: the observed order of the fixed-step methods,
// the global error of the adaptive ones following their tolerance, rigid-body rotation
// through the quaternion state (torque-free symmetric top: Euler's equations in closed form,
// conserved angular momentum and energy), and a restart from the same state repeating the
// run bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include "core/model_builder.hpp"
#include "core/simulator.hpp"

namespace tribo {
namespace {

// A 2 kg slider on a prismatic joint along x with a 50 N/m spring: x = x0 cos(w t), w = 5.
constexpr double kMass = 2.0, kStiffness = 50.0, kX0 = 0.1;

std::shared_ptr<const Model> slider(IntegratorType integrator, double dt, double rtol = 1e-6) {
  ModelBuilder b;
  b.options().integrator = integrator;
  b.options().time_step = dt;
  b.options().relative_tolerance = rtol;
  b.options().absolute_tolerance = 1e-3 * rtol;
  Body body;
  body.name = "slider";
  body.mass = kMass;
  body.inertia = Mat3::Identity() * 0.01;
  body.position = Vec3(kX0, 0, 0);
  const BodyIndex ib = b.addBody(body);
  b.addJoint("rail", JointType::kPrismatic, BodyIndex::world(), ib, Vec3(kX0, 0, 0), Vec3::UnitX());
  b.addSpring("spring", BodyIndex::world(), Vec3(-1, 0, 0), ib, Vec3(kX0, 0, 0), kStiffness, 0.0,
              1.0);
  return b.build();
}

double sliderError(const std::shared_ptr<const Model>& model, double t_end) {
  Simulator sim(model);
  const long n = std::lround(t_end / model->options.time_step);
  for (long i = 0; i < n; ++i) {
    const StepStatus s = sim.step();
    EXPECT_TRUE(s.ok) << s.message;
    if (!s.ok) return INFINITY;
  }
  const double w = std::sqrt(kStiffness / kMass);
  return std::abs(sim.state().bodies[0].position.x() - kX0 * std::cos(w * sim.state().time));
}

TEST(IntegratorAccuracy, FixedStepMethodsConvergeAtTheirOrder) {
  // Halving the step divides the error by 2^order.
  const double e1 = sliderError(slider(IntegratorType::kSemiImplicitEuler, 4e-3), 2.0);
  const double e2 = sliderError(slider(IntegratorType::kSemiImplicitEuler, 2e-3), 2.0);
  EXPECT_NEAR(std::log2(e1 / e2), 1.0, 0.15) << e1 << " " << e2;
  const double r1 = sliderError(slider(IntegratorType::kRk4, 2e-2), 2.0);
  const double r2 = sliderError(slider(IntegratorType::kRk4, 1e-2), 2.0);
  EXPECT_NEAR(std::log2(r1 / r2), 4.0, 0.15) << r1 << " " << r2;
}

TEST(IntegratorAccuracy, AdaptiveGlobalErrorFollowsTheTolerance) {
  // Each hundredfold tighter tolerance cuts the error by at least 10, and the error stays
  // within 100 rtol of the amplitude over these 2.4 periods (local error control).
  for (IntegratorType type : {IntegratorType::kDopri5, IntegratorType::kBdf}) {
    double previous = INFINITY;
    for (double rtol : {1e-4, 1e-6, 1e-8}) {
      const double e = sliderError(slider(type, 0.05, rtol), 3.0);
      EXPECT_LT(e, 100 * rtol * kX0) << integratorName(type) << " rtol " << rtol;
      EXPECT_LT(e, previous / 10) << integratorName(type) << " rtol " << rtol;
      previous = e;
    }
  }
}

// Torque-free axisymmetric body, I = diag(1, 1, 2), no gravity. In the body frame Euler's
// equations give w = (a cos(W t), a sin(W t), w3) with W = (I3 - I1) / I1 w3; the world
// angular momentum R I w_body and the energy w_body . I w_body / 2 stay constant.
TEST(IntegratorAccuracy, TorqueFreeSymmetricTopFollowsEulersEquations) {
  const Mat3 inertia = Vec3(1.0, 1.0, 2.0).asDiagonal();
  const double a = 1.0, w3 = 5.0, big_w = (2.0 - 1.0) / 1.0 * w3, t_end = 2.0;
  const Quat q0(Eigen::AngleAxisd(0.3, Vec3(1, 2, 0).normalized()));
  struct Case {
    IntegratorType type;
    double dt;
    double tolerance;
  };
  for (const Case c :
       {Case{IntegratorType::kRk4, 1e-3, 1e-8}, Case{IntegratorType::kDopri5, 0.05, 1e-6},
        Case{IntegratorType::kBdf, 0.05, 1e-6}}) {
    ModelBuilder b;
    b.options().integrator = c.type;
    b.options().time_step = c.dt;
    b.options().gravity = Vec3::Zero();
    b.options().relative_tolerance = 1e-9;
    b.options().absolute_tolerance = 1e-12;
    Body body;
    body.name = "top";
    body.inertia = inertia;
    body.orientation = q0;
    body.angular_velocity = q0 * Vec3(a, 0.0, w3);
    b.addBody(body);
    Simulator sim(b.build());
    const Vec3 momentum0 = q0 * (inertia * Vec3(a, 0.0, w3));
    const double energy0 = 0.5 * Vec3(a, 0, w3).dot(inertia * Vec3(a, 0, w3));
    const long n = std::lround(t_end / c.dt);
    for (long i = 0; i < n; ++i) ASSERT_TRUE(sim.step().ok);
    const BodyState& s = sim.state().bodies[0];
    const Vec3 w_body = s.orientation.conjugate() * s.angular_velocity;
    const std::string who = integratorName(c.type);
    EXPECT_NEAR(s.orientation.norm(), 1.0, 1e-12) << who;
    EXPECT_NEAR(w_body.x(), a * std::cos(big_w * t_end), c.tolerance) << who;
    EXPECT_NEAR(w_body.y(), a * std::sin(big_w * t_end), c.tolerance) << who;
    EXPECT_NEAR(w_body.z(), w3, c.tolerance) << who;
    EXPECT_LT((s.orientation * (inertia * w_body) - momentum0).norm(),
              c.tolerance * momentum0.norm())
        << who;
    EXPECT_NEAR(0.5 * w_body.dot(inertia * w_body), energy0, c.tolerance * energy0) << who;
  }
}

TEST(IntegratorAccuracy, AdaptiveRestartFromTheSameStateRepeatsTheRunBitForBit) {
  // setState drops the method's history; from the same state the same steps follow.
  for (IntegratorType type : {IntegratorType::kDopri5, IntegratorType::kBdf}) {
    Simulator sim(slider(type, 0.01, 1e-6));
    const State start = sim.state();
    for (int i = 0; i < 50; ++i) ASSERT_TRUE(sim.step().ok);
    const State first = sim.state();
    sim.setState(start);
    for (int i = 0; i < 50; ++i) ASSERT_TRUE(sim.step().ok);
    EXPECT_EQ(sim.state().time, first.time) << integratorName(type);
    EXPECT_EQ(sim.state().bodies[0].position, first.bodies[0].position) << integratorName(type);
    EXPECT_EQ(sim.state().bodies[0].velocity, first.bodies[0].velocity) << integratorName(type);
  }
}

}  // namespace
}  // namespace tribo
