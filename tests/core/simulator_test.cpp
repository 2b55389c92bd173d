// Core dynamics against closed-form answers: free fall, a spring-mass oscillator on a
// prismatic joint, a compound pendulum on a revolute joint, a box resting on the ground and
// a box sliding to rest under Coulomb friction; plus the divergence guard.
#include "core/simulator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/flush_denormals.hpp"
#include "support/test_models.hpp"

namespace tribo {
namespace {

constexpr double kG = 9.81;

std::shared_ptr<const Model> freeBody(IntegratorType integrator, double dt) {
  ModelBuilder b;
  b.options().integrator = integrator;
  b.options().time_step = dt;
  Body body;
  body.name = "ball";
  body.mass = 2.0;
  body.inertia = Mat3::Identity() * 0.1;
  body.position = Vec3(0, 0, 10);
  body.velocity = Vec3(1, 0, 3);
  b.addBody(body);
  return b.build();
}

void runFor(Simulator& sim, double t) {
  const long n = std::lround(t / sim.model().options.time_step);
  for (long i = 0; i < n; ++i) ASSERT_TRUE(sim.step().ok);
}

TEST(Simulator, FreeFallIsExactWithRk4) {
  Simulator sim(freeBody(IntegratorType::kRk4, 0.01));
  runFor(sim, 2.0);
  const double t = sim.state().time;
  EXPECT_NEAR(t, 2.0, 1e-12);
  EXPECT_NEAR(sim.state().bodies[0].position.z(), 10 + 3 * t - 0.5 * kG * t * t, 1e-10);
  EXPECT_NEAR(sim.state().bodies[0].position.x(), t, 1e-12);
}

TEST(Simulator, SemiImplicitEulerFreeFallErrorIsFirstOrder) {
  // Semi-implicit Euler: z_n = z0 + v0 t - g t^2/2 - g h t/2 (exact sum of the scheme).
  for (double h : {0.01, 0.001}) {
    Simulator sim(freeBody(IntegratorType::kSemiImplicitEuler, h));
    runFor(sim, 1.0);
    const double t = sim.state().time;
    EXPECT_NEAR(sim.state().bodies[0].position.z(),
                10 + 3 * t - 0.5 * kG * t * t - 0.5 * kG * h * t, 1e-9);
  }
}

TEST(Simulator, SpringMassOnPrismaticJointMatchesCosine) {
  // x'' = -(k/m) x along the slider, gravity across the slider carried by the joint.
  const double m = 2.0, k = 50.0, x0 = 0.1;
  ModelBuilder b;
  b.options().time_step = 1e-3;
  Body body;
  body.name = "slider";
  body.mass = m;
  body.inertia = Mat3::Identity() * 0.01;
  body.position = Vec3(x0, 0, 0);
  const BodyIndex ib = b.addBody(body);
  b.addJoint("rail", JointType::kPrismatic, BodyIndex::world(), ib, Vec3(x0, 0, 0), Vec3::UnitX());
  b.addSpring("spring", BodyIndex::world(), Vec3(-1, 0, 0), ib, Vec3(x0, 0, 0), k, 0.0, 1.0);
  Simulator sim(b.build());
  runFor(sim, 3.0);
  const double w = std::sqrt(k / m);
  EXPECT_NEAR(sim.state().bodies[0].position.x(), x0 * std::cos(w * 3.0), 1e-8);
  EXPECT_NEAR(sim.state().bodies[0].position.z(), 0.0, 1e-8);  // joint holds against gravity
  EXPECT_LT(sim.stats().max_constraint_error, 1e-8);
}

// Compound pendulum: rod-like body of mass m, centre at distance d below a revolute pivot.
// Small-amplitude period T = 2 pi sqrt(I_pivot / (m g d)), I_pivot = I_cm + m d^2.
TEST(Simulator, PendulumOnRevoluteJointHasCompoundPeriodAndConservesEnergy) {
  const double m = 1.5, d = 0.8, i_cm = 0.05, theta0 = 0.02;
  ModelBuilder b;
  b.options().time_step = 1e-3;
  Body bob;
  bob.name = "bob";
  bob.mass = m;
  bob.inertia = Vec3(i_cm, i_cm, 0.01).asDiagonal();
  bob.position = Vec3(d * std::sin(theta0), 0, -d * std::cos(theta0));
  bob.orientation = Quat(Eigen::AngleAxisd(-theta0, Vec3::UnitY()));
  const BodyIndex ib = b.addBody(bob);
  b.addJoint("pivot", JointType::kRevolute, BodyIndex::world(), ib, Vec3::Zero(), Vec3::UnitY());
  Simulator sim(b.build());
  auto energy = [&](const State& s) {
    const BodyState& bs = s.bodies[0];
    return 0.5 * m * bs.velocity.squaredNorm() +
           0.5 * bs.angular_velocity.dot(
                     bs.orientation *
                     (bob.inertia * (bs.orientation.conjugate() * bs.angular_velocity))) +
           m * kG * bs.position.z();
  };
  const double e0 = energy(sim.state());
  // Time the upward zero crossings of x.
  std::vector<double> crossings;
  double x_prev = sim.state().bodies[0].position.x(), t_prev = 0.0;
  while (sim.state().time < 12.0) {
    ASSERT_TRUE(sim.step().ok);
    const double x = sim.state().bodies[0].position.x(), t = sim.state().time;
    if (x_prev < 0 && x >= 0) crossings.push_back(t_prev + (t - t_prev) * (-x_prev) / (x - x_prev));
    x_prev = x;
    t_prev = t;
  }
  ASSERT_GE(crossings.size(), 3u);
  const double period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  const double expected = 2 * std::numbers::pi * std::sqrt((i_cm + m * d * d) / (m * kG * d));
  // Finite amplitude lengthens the period by theta0^2/16 = 2.5e-5 relative.
  EXPECT_NEAR(period / expected, 1.0 + theta0 * theta0 / 16, 2e-5);
  const double swing = m * kG * d * (1 - std::cos(theta0));
  EXPECT_LT(std::abs(energy(sim.state()) - e0), 1e-3 * swing);
  EXPECT_LT(sim.stats().max_constraint_error, 1e-6);
}

TEST(Simulator, BoxRestsOnGroundWithWeightSharedByFourCorners) {
  const double m = 10.0, k = 2.5e5, c = 1.5e3;
  ModelBuilder b =
      test::boxOnGround(m, Vec3(0.2, 0.2, 0.1), 0.0, 0.3, k, c, IntegratorType::kRk4, 1e-3);
  b.options().gravity = Vec3(0, 0, -kG);
  Simulator sim(b.build());
  runFor(sim, 0.5);
  const Workspace& ws = sim.current();
  ASSERT_EQ(ws.contacts.size(), 4u);
  double total = 0.0;
  for (const auto& c4 : ws.contacts) {
    EXPECT_NEAR(c4.normal_force, m * kG / 4, 1e-6);
    EXPECT_NEAR(c4.point.depth, m * kG / (4 * k), 1e-9);
    total += c4.normal_force;
  }
  EXPECT_NEAR(total, m * kG, 1e-6);
  EXPECT_NEAR(sim.state().bodies[0].velocity.norm(), 0.0, 1e-9);
}

// Sliding box decelerates at mu g and stops after v0^2 / (2 mu g).
TEST(Simulator, SlidingBoxStopsAtCoulombDistance) {
  const double m = 5.0, mu = 0.4, v0 = 2.0;
  for (IntegratorType integrator : {IntegratorType::kRk4, IntegratorType::kSemiImplicitEuler}) {
    ModelBuilder b =
        test::boxOnGround(m, Vec3(0.2, 0.2, 0.1), v0, mu, 2.5e5, 1.5e3, integrator, 2e-4);
    Simulator sim(b.build());
    runFor(sim, 0.8);
    const double expected = v0 * v0 / (2 * mu * kG);
    EXPECT_NEAR(sim.state().bodies[0].position.x(), expected, 2e-3 * expected)
        << integratorName(integrator);
    EXPECT_LT(std::abs(sim.state().bodies[0].velocity.x()), 1e-3);
  }
}

std::shared_ptr<const Model> slider(double k, double dt) {
  ModelBuilder b;
  b.options().time_step = dt;
  Body body;
  body.name = "slider";
  body.mass = 1.0;
  body.inertia = Mat3::Identity() * 0.01;
  body.position = Vec3(0.1, 0, 0);
  const BodyIndex ib = b.addBody(body);
  b.addJoint("rail", JointType::kPrismatic, BodyIndex::world(), ib, Vec3(0.1, 0, 0), Vec3::UnitX());
  b.addSpring("spring", BodyIndex::world(), Vec3(-1, 0, 0), ib, Vec3(0.1, 0, 0), k, 0.0, 1.0);
  return b.build();
}

TEST(Simulator, DivergenceStopsWithBodyAndStepAndKeepsLastGoodState) {
  // A stiff spring stepped far beyond RK4's limit: sqrt(k/m) h = 316 >> 2.8.
  Simulator sim(slider(1e9, 1e-2));
  StepStatus status;
  int steps = 0;
  for (; steps < 1000 && status.ok; ++steps) status = sim.step();
  ASSERT_FALSE(status.ok);
  EXPECT_NE(status.message.find("diverged at step " + std::to_string(steps)), std::string::npos)
      << status.message;
  EXPECT_NE(status.message.find("body 'slider'"), std::string::npos) << status.message;
  EXPECT_TRUE(sim.state().bodies[0].position.allFinite());
  EXPECT_TRUE(sim.state().bodies[0].velocity.allFinite());
  EXPECT_NEAR(sim.state().time, (steps - 1) * 1e-2, 1e-9);
}

TEST(Simulator, StableStepOfTheSameSpringDoesNotTripTheGuard) {
  Simulator sim(slider(1e9, 2e-5));  // sqrt(k/m) h = 0.63
  for (int i = 0; i < 2000; ++i) ASSERT_TRUE(sim.step().ok);
}

TEST(Simulator, PenetrationDeeperThanTheBodyIsRecordedNotAStop) {
  // 100 m/s into a soft ground: the contact cannot stop the box within its 0.1 m height. The
  // energy only falls (the ground is soft, not unstable), so the run goes on; the depth is
  // recorded against the box's half height (its half width along the contact normal).
  const double h = 0.05;
  ModelBuilder b = test::boxOnGround(1.0, Vec3(0.2, 0.2, 2 * h), 0.0, 0.3, 1e3, 0.0,
                                     IntegratorType::kRk4, 1e-3, -100.0);
  const auto model = b.build();
  Simulator sim(model);
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(sim.step().ok);
  const StepStats& s = sim.stats();
  EXPECT_GT(s.deep_penetrations, 0);
  ASSERT_GE(s.deepest_geometry, 0);
  EXPECT_EQ(model->geometries[s.deepest_geometry].name, "box_shape");
  EXPECT_NEAR(s.deepest_extent, h, 1e-12);
  EXPECT_GT(s.deepest_depth, h);
  // Before touching, the box fell from 0.05 m above the ground at 100 m/s: 0.5 ms.
  EXPECT_GT(s.first_deep_time, 0.0);
  EXPECT_LT(s.first_deep_time, (0.05 + 2 * h) / 100.0 + 1e-3);
}

// core/flush_denormals.hpp: subnormal numbers read as zero inside the guard (they cost ~100
// cycles an operation), and the caller's floating-point mode is back after it.
TEST(FlushDenormals, SubnormalsAreZeroInsideTheGuardOnlyAndStepRestoresTheMode) {
  volatile double tiny = 1e-310;  // subnormal: below 2.2e-308
  volatile double one = 1.0;
  ASSERT_GT(tiny * one, 0.0);
#if defined(__SSE__) || defined(_M_X64)
  {
    const ScopedFlushDenormals flush;
    EXPECT_EQ(tiny * one, 0.0);
  }
  EXPECT_GT(tiny * one, 0.0);
  const unsigned before = _mm_getcsr();
  Simulator sim(freeBody(IntegratorType::kRk4, 1e-3));
  ASSERT_TRUE(sim.step().ok);
  EXPECT_EQ(_mm_getcsr(), before);
#else
  GTEST_SKIP() << "no SSE control register on this processor";
#endif
  EXPECT_GT(tiny * one, 0.0);
}

}  // namespace
}  // namespace tribo
