// The run guards that stop an integration loudly: energy rising without a source (also under
// an applied load; with the power of sources measured against its closed form: friction
// force times belt speed, spring force times the speed of a moving kinematic body), and
// failures of the adaptive integrators reported with time, body and quantity instead of a
// silent or NaN state.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/energy.hpp"
#include "core/model_builder.hpp"
#include "core/simulator.hpp"
#include "core/stability.hpp"
#include "friction/friction_law.hpp"

namespace tribo {
namespace {

constexpr double kG = 9.81;

contact::Material material(double k, double c, double mu) {
  contact::Material m;
  m.normal.stiffness = k;
  m.normal.damping = c;
  m.friction = friction::makeFrictionLaw(
      {"coulomb", {{"mu", mu}, {"v_eps", 1e-4}}, {{"regularization", "tanh"}}});
  return m;
}

// A 1 kg box thrown down at 0.5 m/s onto an undamped, frictionless ground (k per corner),
// optionally on a kinematic belt body moving its surface at `belt` m/s.
ModelBuilder droppedBox(IntegratorType integrator, double dt, double k, double mu = 0.0,
                        double belt = 0.0, double vz = -0.5) {
  ModelBuilder b;
  b.options().integrator = integrator;
  b.options().time_step = dt;
  Body ground;
  ground.name = "ground";
  ground.kind = BodyKind::kKinematic;
  ground.surface_velocity = Vec3(belt, 0, 0);
  const BodyIndex ig = b.addBody(ground);
  Body box;
  box.name = "box";
  box.mass = 1.0;
  box.inertia = Vec3(0.0042, 0.0042, 0.0067).asDiagonal();
  box.position = Vec3(0, 0, vz == 0.0 ? 0.05 - kG / (4 * k) : 0.05);
  box.velocity = Vec3(0, 0, vz);
  const BodyIndex ib = b.addBody(box);
  const int plane = b.addGeometry("plane", ig, contact::Shape::halfSpace());
  const int shape = b.addGeometry("box_shape", ib, contact::Shape::box(Vec3(0.1, 0.1, 0.05)));
  b.addContactPair(plane, shape, b.addMaterial(material(k, 0.0, mu)));
  b.addJoint("slide", JointType::kPlanarTranslation, BodyIndex::world(), ib, box.position,
             Vec3::UnitY());
  return b;
}

double rk4Limit(double k) {
  return estimateStableStep(*droppedBox(IntegratorType::kRk4, 1e-3, k).build()).limit.max_step;
}

TEST(EnergyGuard, StopsAnUnstableBounceBeforeAnyQuantityIsNotFinite) {
  const double k = 1e6;
  Simulator sim(droppedBox(IntegratorType::kRk4, 1.5 * rk4Limit(k), k).build());
  StepStatus status;
  for (int i = 0; i < 100000 && status.ok; ++i) status = sim.step();
  ASSERT_FALSE(status.ok);
  EXPECT_EQ(status.quantity, "energy") << status.message;
  EXPECT_EQ(status.body, "box") << status.message;
  EXPECT_NE(status.message.find("energy rising without a source"), std::string::npos);
  EXPECT_TRUE(sim.state().bodies[1].velocity.allFinite());
}

TEST(EnergyGuard, ALoadDoesNotHideADivergence) {
  // The same unstable bounce while an applied load pushes the box along x: the load's work
  // enters the account as work done (core/applied_load.hpp), not as an excuse for the rise.
  const double k = 1e6;
  ModelBuilder b = droppedBox(IntegratorType::kRk4, 1.5 * rk4Limit(k), k);
  AppliedLoad push;
  push.name = "push";
  push.body = *b.findBody("box");
  push.force = {Signal::ramp(20.0, 0.0, 5.0), Signal(), Signal()};
  b.addLoad(push);
  Simulator sim(b.build());
  StepStatus status;
  for (int i = 0; i < 100000 && status.ok; ++i) status = sim.step();
  ASSERT_FALSE(status.ok);
  EXPECT_EQ(status.quantity, "energy") << status.message;
  EXPECT_EQ(status.body, "box") << status.message;
  EXPECT_TRUE(sim.state().bodies[1].velocity.allFinite());
}

TEST(EnergyGuard, StaysQuietOnStableRunsWithAndWithoutSources) {
  // A conservative bounce with RK4 at half its limit, and the same box dragged by a belt
  // (friction 0.3) whose power enters the account as a source.
  const double k = 1e6;
  for (const double belt : {0.0, 1.5}) {
    const double dt = 0.5 * rk4Limit(k);
    Simulator sim(droppedBox(IntegratorType::kRk4, dt, k, belt > 0 ? 0.3 : 0.0, belt).build());
    for (long i = 0; i < std::lround(1.0 / dt); ++i) {
      const StepStatus s = sim.step();
      ASSERT_TRUE(s.ok) << "belt " << belt << ": " << s.message;
    }
  }
}

TEST(EnergyGuard, ReadsSemiImplicitEulerThroughItsModifiedEnergy) {
  // Spring-mass (k/m = 2500 1/s^2, no geometry, so no floor) at 0.95 of the semi-implicit
  // Euler limit: a stable step whose plain energy swings by (2 + hw)/(2 - hw) = 39, which the
  // guard must not read as a rise.
  ModelBuilder b;
  b.options().integrator = IntegratorType::kSemiImplicitEuler;
  b.options().time_step = 0.95 * 2.0 / 50.0;
  Body body;
  body.name = "slider";
  body.mass = 1.0;
  body.position = Vec3(0.1, 0, 0);
  const BodyIndex ib = b.addBody(body);
  b.addJoint("rail", JointType::kPrismatic, BodyIndex::world(), ib, Vec3(0.1, 0, 0), Vec3::UnitX());
  b.addSpring("spring", BodyIndex::world(), Vec3(-1, 0, 0), ib, Vec3(0.1, 0, 0), 2500.0, 0.0, 1.0);
  Simulator sim(b.build());
  double lowest = INFINITY, highest = 0.0;
  for (int i = 0; i < 500; ++i) {
    const StepStatus s = sim.step();
    ASSERT_TRUE(s.ok) << s.message;
    const double e = measureEnergy(sim.model(), sim.state(), sim.current()).total();
    lowest = std::min(lowest, e);
    highest = std::max(highest, e);
  }
  EXPECT_GT(highest / lowest, 10.0);  // the swing the plain energy would have shown
}

TEST(EnergyAccount, InputPowerOfABeltIsItsFrictionForceTimesItsSurfaceSpeed) {
  // Box at rest at its static depth on a belt at v_b: the belt pushes with mu(v_b) m g along
  // its motion, delivering mu m g v_b (tanh(v_b / v_eps) = 1 to double precision).
  const double k = 1e6, mu = 0.3, v_b = 1.5;
  Simulator sim(droppedBox(IntegratorType::kRk4, 1e-4, k, mu, v_b, 0.0).build());
  const EnergyAccount a = measureEnergy(sim.model(), sim.state(), sim.current());
  EXPECT_NEAR(a.input_power, mu * 1.0 * kG * v_b, 1e-9);
  EXPECT_NEAR(a.elastic, 4 * 0.5 * k * std::pow(kG / (4 * k), 2), 1e-15);
  EXPECT_NEAR(a.kinetic, 0.0, 1e-15);
}

TEST(EnergyAccount, InputPowerOfAMovingKinematicBodyThroughASpring) {
  // A kinematic pusher at x = 0 moving at u towards a free box 0.6 m away, joined by a spring
  // of rest length 0.5 m: tension k (0.1 m) pulls the pusher forward, so the pusher does work
  // -k 0.1 u on the system (it slackens the spring).
  const double k = 200.0, u = 0.7;
  ModelBuilder b;
  b.options().gravity = Vec3::Zero();
  Body pusher;
  pusher.name = "pusher";
  pusher.kind = BodyKind::kKinematic;
  pusher.velocity = Vec3(u, 0, 0);
  const BodyIndex ip = b.addBody(pusher);
  Body box;
  box.name = "box";
  box.mass = 2.0;
  box.position = Vec3(0.6, 0, 0);
  const BodyIndex ib = b.addBody(box);
  b.addSpring("spring", ip, Vec3::Zero(), ib, Vec3(0.6, 0, 0), k, 0.0, 0.5);
  Simulator sim(b.build());
  const EnergyAccount a = measureEnergy(sim.model(), sim.state(), sim.current());
  EXPECT_NEAR(a.input_power, -k * 0.1 * u, 1e-12);
  EXPECT_NEAR(a.elastic, 0.5 * k * 0.01, 1e-12);
}

// A flywheel on a revolute joint, without geometry, driven through a spring by a kinematic
// driver turning at W about the same axis (issue #11): the guard's floor must reflect what
// the driver moves through the system, not the flywheel's (absent) size. Small angles:
// I th'' = k R^2 (W t - th), so th = W t - (W / w) sin(w t), w = R sqrt(k / I).
TEST(EnergyGuard, FlywheelDrivenThroughASpringRunsAsTheClosedForm) {
  struct Case {
    double inertia, mass, radius, k, spin;
  };
  for (const Case& c : {Case{0.02, 1.0, 0.1, 2e4, 0.5}, Case{4.0, 50.0, 0.5, 1e5, 1.0},
                        Case{1e-5, 0.01, 0.01, 1e3, 2.0}}) {
    const double w = c.radius * std::sqrt(c.k / c.inertia);
    ModelBuilder b;
    b.options().gravity = Vec3::Zero();
    b.options().time_step = 0.05 / w;  // RK4, far inside 2.8 / w
    Body driver;
    driver.name = "driver";
    driver.kind = BodyKind::kKinematic;
    driver.angular_velocity = Vec3(0, 0, c.spin);
    const BodyIndex id = b.addBody(driver);
    Body wheel;
    wheel.name = "flywheel";
    wheel.mass = c.mass;
    wheel.inertia = Vec3(0.5 * c.inertia, 0.5 * c.inertia, c.inertia).asDiagonal();
    const BodyIndex iw = b.addBody(wheel);
    b.addJoint("axle", JointType::kRevolute, BodyIndex::world(), iw, Vec3::Zero(), Vec3::UnitZ());
    // Tangential spring at rest: from the driver's point (R, -R, 0) to the wheel's (R, 0, 0).
    b.addSpring("belt", id, Vec3(c.radius, -c.radius, 0), iw, Vec3(c.radius, 0, 0), c.k, 0.0, -1.0);
    Simulator sim(b.build());
    double worst = 0.0;
    const int steps = static_cast<int>(std::ceil(4 * 2 * M_PI / w / b.options().time_step));
    for (int i = 0; i < steps; ++i) {
      const StepStatus status = sim.step();
      ASSERT_TRUE(status.ok) << status.message;
      const double t = sim.state().time;
      const Quat q = sim.state().bodies[iw.value].orientation;
      const double th = 2 * std::atan2(q.z(), q.w());
      worst = std::max(worst, std::abs(th - (c.spin * t - c.spin / w * std::sin(w * t))));
    }
    // The linear model's error: the relative angle reaches phi = 2 W / w, and the spring's
    // torque k R^2 phi (1 + O(phi)) is off by a share of order phi of it.
    const double phi = 2 * c.spin / w;
    EXPECT_LT(worst, phi * phi) << c.inertia;
  }
}

TEST(AdaptiveFailure, UnreachableToleranceIsReportedAndTheStateKept) {
  for (IntegratorType type : {IntegratorType::kDopri5, IntegratorType::kBdf}) {
    ModelBuilder b = droppedBox(type, 0.01, 1e6, 0.3, 0.0, 0.0);
    b.options().relative_tolerance = 1e-16;
    b.options().absolute_tolerance = 1e-300;
    Simulator sim(b.build());
    const State before = sim.state();
    const StepStatus status = sim.step();
    ASSERT_FALSE(status.ok) << integratorName(type);
    EXPECT_EQ(status.quantity, "integrator");
    EXPECT_NE(status.message.find("integrator " + integratorName(type) + " failed"),
              std::string::npos)
        << status.message;
    EXPECT_EQ(sim.state().time, before.time);
    EXPECT_EQ(sim.state().bodies[1].position, before.bodies[1].position);
  }
}

TEST(AdaptiveFailure, NonFiniteStateNamesTheBodyAndComponent) {
  for (IntegratorType type : {IntegratorType::kDopri5, IntegratorType::kBdf}) {
    Simulator sim(droppedBox(type, 0.01, 1e6, 0.3, 0.0, 0.0).build());
    State bad = sim.state();
    bad.bodies[1].velocity.z() = std::numeric_limits<double>::quiet_NaN();
    sim.setState(bad);
    const StepStatus status = sim.step();
    ASSERT_FALSE(status.ok) << integratorName(type);
    EXPECT_EQ(status.body, "box") << status.message;
    EXPECT_NE(status.message.find("non-finite derivative of body 'box'"), std::string::npos)
        << status.message;
  }
}

}  // namespace
}  // namespace tribo
