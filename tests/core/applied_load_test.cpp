// Applied loads (core/applied_load.hpp) on free bodies in zero gravity against closed forms:
// a constant and a ramped force (position), a torque on a flywheel (w = T t / I), a force
// off the centre of mass (r x F / I), a follower force on a spinning body (a circle), the
// load's work against the kinetic energy it gives, the energy guard's account of it, and
// the builder's checks.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/energy.hpp"
#include "core/model_builder.hpp"
#include "core/simulator.hpp"

namespace tribo {
namespace {

constexpr double kPi = std::numbers::pi;

struct Free {
  double mass = 2.0;
  Vec3 inertia{0.3, 0.4, 0.5};  // principal, body frame [kg m^2]
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
};

// One free body (index 0) in zero gravity with `load`, RK4 at `dt`.
std::shared_ptr<const Model> freeBody(const Free& f, AppliedLoad load, double dt,
                                      double duration = 10.0) {
  ModelBuilder b;
  Body body;
  body.name = "block";
  body.mass = f.mass;
  body.inertia = f.inertia.asDiagonal();
  body.velocity = f.velocity;
  body.angular_velocity = f.angular_velocity;
  load.body = b.addBody(body);
  if (load.name.empty()) load.name = "push";
  b.addLoad(load);
  b.options().gravity = Vec3::Zero();
  b.options().integrator = IntegratorType::kRk4;
  b.options().time_step = dt;
  b.options().duration = duration;
  return b.build();
}

TEST(AppliedLoad, ConstantForceGivesHalfATSquared) {
  for (const double force : {1e-3, 1.0, 1e3}) {
    AppliedLoad load;
    load.force = {Signal::constant(force), Signal::constant(-0.5 * force), Signal()};
    const Free f;
    Simulator sim(freeBody(f, load, 1e-3));
    while (sim.state().time < 1.0 - 1e-12) ASSERT_TRUE(sim.step().ok);
    const double t = sim.state().time;
    // x = F t^2 / (2 m): a quadratic, which RK4 integrates exactly up to rounding.
    const Vec3 want = Vec3(force, -0.5 * force, 0.0) * t * t / (2 * f.mass);
    EXPECT_LT((sim.state().bodies[0].position - want).norm(), 1e-9 * want.norm()) << force;
    EXPECT_LT((sim.state().bodies[0].velocity - 2 * want / t).norm(), 1e-9 * want.norm() / t);
    EXPECT_NEAR(sim.state().bodies[0].angular_velocity.norm(), 0.0, 1e-15);
  }
}

TEST(AppliedLoad, RampedForceGivesTCubed) {
  // F = rate (t - t0) after t0: x = rate (t - t0)^3 / (6 m) after t0, 0 before.
  for (const auto& [rate, t0] : {std::pair{1.0, 0.0}, {50.0, 0.25}, {1e-2, 0.5}}) {
    AppliedLoad load;
    load.force = {Signal(), Signal(), Signal::ramp(rate, t0)};
    const Free f;
    Simulator sim(freeBody(f, load, 1e-3));
    while (sim.state().time < 2.0 - 1e-12) {
      ASSERT_TRUE(sim.step().ok);
      if (sim.state().time < t0 - 1e-9) {
        ASSERT_EQ(sim.state().bodies[0].position.z(), 0.0);
      }
    }
    const double s = sim.state().time - t0;
    const double want = rate * s * s * s / (6 * f.mass);
    // RK4 is exact for a force linear in t; the ramp's corner lies on a step boundary up to
    // the rounding of the accumulated time.
    EXPECT_NEAR(sim.state().bodies[0].position.z(), want, 1e-9 * want) << rate;
    EXPECT_NEAR(sim.state().bodies[0].velocity.z(), rate * s * s / (2 * f.mass),
                1e-9 * rate * s * s / (2 * f.mass));
  }
}

TEST(AppliedLoad, TorqueSpinsAFlywheelAtTtOverI) {
  for (const double torque : {0.01, 2.0, 300.0}) {
    AppliedLoad load;
    load.torque = {Signal(), Signal(), Signal::constant(torque)};
    const Free f;
    Simulator sim(freeBody(f, load, 1e-3));
    while (sim.state().time < 1.0 - 1e-12) ASSERT_TRUE(sim.step().ok);
    const double t = sim.state().time, iz = f.inertia.z();
    const Vec3 w = sim.state().bodies[0].angular_velocity;
    EXPECT_NEAR(w.z(), torque * t / iz, 1e-9 * torque * t / iz);
    EXPECT_NEAR(w.head<2>().norm(), 0.0, 1e-12 * w.z());
    // Angle T t^2 / (2 I) (a turn about z: yaw from the quaternion), where the turn per
    // step is small (at 300 N m the body ends at 0.6 rad a step, where RK4 on the
    // normalized quaternion is off by ~1e-3 rad: the integrator's error, not the load's).
    const Quat& q = sim.state().bodies[0].orientation;
    const double angle = torque * t * t / (2 * iz);
    const double yaw = 2 * std::atan2(q.z(), q.w());
    if (w.z() * 1e-3 < 0.01) {
      EXPECT_NEAR(std::remainder(yaw - angle, 2 * kPi), 0.0, 1e-9 * std::max(1.0, angle));
    }
    EXPECT_NEAR(sim.state().bodies[0].position.norm(), 0.0, 1e-15);
  }
}

TEST(AppliedLoad, ForceOffTheCentreOfMassTurnsTheBody) {
  // Force F at body point r: a = F / m, alpha = I^-1 (r x F) at rest (no gyroscopic term).
  const Free f;
  for (const LoadFrame frame : {LoadFrame::kWorld, LoadFrame::kBody}) {
    AppliedLoad load;
    load.force = {Signal::constant(1.5), Signal::constant(4.0), Signal::constant(-2.0)};
    load.torque = {Signal::constant(0.25), Signal(), Signal()};
    load.point = Vec3(0.3, -0.2, 0.1);
    load.frame = frame;
    Simulator sim(freeBody(f, load, 1e-3));
    const Workspace& ws = sim.current();
    const Vec3 force(1.5, 4.0, -2.0);
    const Vec3 torque = load.point.cross(force) + Vec3(0.25, 0, 0);
    EXPECT_LT((ws.linear_acceleration[0] - force / f.mass).norm(), 1e-14);
    EXPECT_LT((ws.angular_acceleration[0] - torque.cwiseQuotient(f.inertia)).norm(), 1e-13);
    EXPECT_LT((ws.load_force[0] - force).norm(), 1e-15);
  }
}

TEST(AppliedLoad, FollowerForceOnASpinningBodyMovesItOnACircle) {
  // A body spinning at w about z (a principal axis: no torque, so w stays) with a force F
  // along its own x axis, applied at its centre of mass. Its x axis is (cos wt, sin wt, 0),
  // so m dv/dt = F (cos wt, sin wt, 0) and v(t) = v(0) + F / (m w) (sin wt, 1 - cos wt, 0).
  // Starting with v(0) = (0, -F / (m w), 0): v(t) = F / (m w) (sin wt, -cos wt, 0) and
  //   x(t) = F / (m w^2) (1 - cos wt, -sin wt, 0),
  // a circle of radius F / (m w^2) about (F / (m w^2), 0, 0), run once per turn of the body.
  for (const auto& [force, w] : {std::pair{1.0, 2 * kPi}, {40.0, 15.0}, {0.05, 0.7}}) {
    Free f;
    f.angular_velocity = Vec3(0, 0, w);
    f.velocity = Vec3(0, -force / (f.mass * w), 0);
    AppliedLoad load;
    load.force = {Signal::constant(force), Signal(), Signal()};
    load.frame = LoadFrame::kBody;
    const double period = 2 * kPi / w, radius = force / (f.mass * w * w);
    Simulator sim(freeBody(f, load, period / 4000, 2 * period));
    double worst = 0.0;
    while (sim.state().time < 1.5 * period) {
      ASSERT_TRUE(sim.step().ok);
      const double t = sim.state().time;
      const Vec3 want = radius * Vec3(1 - std::cos(w * t), -std::sin(w * t), 0);
      worst = std::max(worst, (sim.state().bodies[0].position - want).norm());
    }
    // RK4's global error at 4000 steps a turn: ~(2 pi / 4000)^4 of the radius.
    EXPECT_LT(worst, 1e-9 * radius) << force << " " << w;
    EXPECT_NEAR(sim.state().bodies[0].angular_velocity.z(), w, 1e-12 * w);
  }
}

TEST(AppliedLoad, WorkDoneEqualsTheKineticEnergyGiven) {
  // Varying force off the centre of mass, a follower torque and a tumbling body: the work
  // integral of P = F . v_point + T . w (trapezoidal over the steps, the account's P_in)
  // against the kinetic energy change.
  Free f;
  f.angular_velocity = Vec3(0.4, -1.0, 2.0);
  f.velocity = Vec3(0.1, 0.0, -0.2);
  AppliedLoad load;
  load.force = {Signal::sines({{2.0, 1.3, 0.2, 0.5}}), Signal::ramp(1.5, 0.3, -0.5),
                Signal::smoothStep(0.2, 0.0, 0.9, 3.0)};
  load.torque = {Signal(), Signal::table({{0.0, 0.2}, {0.5, -0.4}, {1.0, 0.1}}), Signal()};
  load.frame = LoadFrame::kBody;
  load.point = Vec3(0.2, 0.1, -0.3);
  const double dt = 1e-4;
  Simulator sim(freeBody(f, load, dt));
  const Model& model = sim.model();
  const double e0 = measureEnergy(model, sim.state(), sim.current()).kinetic;
  double power = measureEnergy(model, sim.state(), sim.current()).input_power, work = 0.0;
  // P_in is the load's power F . (v + w x r_W) + tau . w, computed independently here.
  auto direct = [&](const State& s, const Workspace& ws) {
    const BodyState& b = s.bodies[0];
    const Vec3 r = ws.rotation[0] * load.point;
    const Vec3 tau = ws.rotation[0] * Vec3(0, load.torque[1].value(s.time), 0);
    return ws.load_force[0].dot(b.velocity + b.angular_velocity.cross(r)) +
           tau.dot(b.angular_velocity);
  };
  EXPECT_NEAR(power, direct(sim.state(), sim.current()), 1e-12 * std::abs(power) + 1e-14);
  while (sim.state().time < 1.5 - 1e-12) {
    ASSERT_TRUE(sim.step().ok);
    const EnergyAccount a = measureEnergy(model, sim.state(), sim.current());
    EXPECT_NEAR(a.input_power, direct(sim.state(), sim.current()),
                1e-12 * (std::abs(a.input_power) + 1.0));
    work += 0.5 * dt * (power + a.input_power);
    power = a.input_power;
  }
  const double e1 = measureEnergy(model, sim.state(), sim.current()).kinetic;
  ASSERT_GT(std::abs(e1 - e0), 0.1);
  // Trapezoidal rule: O(dt^2) of the work, and the power is only piecewise smooth (kinks
  // of the ramp, the table and the smooth step's ends): ~1e-8 of ~1 J.
  EXPECT_NEAR(work, e1 - e0, 1e-6 * std::abs(e1 - e0));
}

TEST(AppliedLoad, EnergyGuardLetsALoadPushAndRunsLong) {
  // A body with no geometry in zero gravity: its energy floor is 1e-9 J, so a push read as
  // energy from nowhere would stop the run at once; counted as work done it runs.
  AppliedLoad load;
  load.force = {Signal::ramp(100.0), Signal::sines({{50.0, 2.0, 0.0, 0.0}}), Signal()};
  load.torque = {Signal(), Signal(), Signal::constant(5.0)};
  const Free f;
  Simulator sim(freeBody(f, load, 1e-3, 5.0));
  while (sim.state().time < 5.0 - 1e-12) {
    const StepStatus status = sim.step();
    ASSERT_TRUE(status.ok) << status.message;
  }
  EXPECT_GT(sim.state().bodies[0].velocity.x(), 100.0);
}

TEST(AppliedLoad, BuilderRefusesWhatCannotCarryALoad) {
  ModelBuilder b;
  Body dynamic;
  dynamic.name = "block";
  Body wall;
  wall.name = "wall";
  wall.kind = BodyKind::kKinematic;
  const BodyIndex d = b.addBody(dynamic), k = b.addBody(wall);
  AppliedLoad load;
  load.name = "push";
  auto refused = [&](const AppliedLoad& l, const std::string& part) {
    try {
      b.addLoad(l);
      ADD_FAILURE() << "accepted: " << part;
    } catch (const ModelError& e) {
      EXPECT_NE(std::string(e.what()).find("load '" + l.name + "'"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  load.body = k;
  refused(load, "kinematic");
  load.body = BodyIndex{7};
  refused(load, "out of range");
  load.body = BodyIndex::world();
  refused(load, "world");
  load.body = d;
  load.point = Vec3(0, NAN, 0);
  refused(load, "point");
  load.point = Vec3::Zero();
  b.addLoad(load);
  refused(load, "already exists");
}

}  // namespace
}  // namespace tribo
