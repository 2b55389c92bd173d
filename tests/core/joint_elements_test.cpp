// What acts on a joint's coordinate, against closed forms: torsion spring and damper
// (damped oscillator), constant effort, limits (static deflection, elastic rebound, derived
// gains), friction through the friction-law strategy under a constant and a reaction load
// (stopping distance, spin-down time, and a pendulum whose pin load depends on its own
// friction against a hand-reduced one-degree-of-freedom reference), drives and couplings;
// and the builder's checks on them.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "core/constraint_rows.hpp"
#include "core/simulator.hpp"
#include "friction/friction_law.hpp"
#include "support/joint_test_models.hpp"
#include "support/test_models.hpp"

namespace tribo {
namespace {

constexpr double kG = 9.81;
constexpr double kIz = 0.04;  // disk inertia about its axis [kg m^2]

std::shared_ptr<const friction::FrictionLaw> coulomb(double mu) {
  return friction::makeFrictionLaw(
      {"coulomb", {{"mu", mu}, {"v_eps", 1e-4}}, {{"regularization", "tanh"}}});
}

// A disk turning about the world z axis through its centre; no gravity. Returns the joint.
int disk(ModelBuilder& b, double w0 = 0.0, const std::string& name = "disk",
         const Vec3& at = Vec3::Zero(), double iz = kIz) {
  Body body;
  body.name = name;
  body.inertia = Vec3(iz / 2, iz / 2, iz).asDiagonal();
  body.position = at;
  body.angular_velocity = Vec3(0, 0, w0);
  const BodyIndex i = b.addBody(body);
  b.options().gravity = Vec3::Zero();
  return b.addJoint(name + "_axle", JointType::kRevolute, BodyIndex::world(), i, at, Vec3::UnitZ());
}

double angleOf(const BodyState& s) {
  const Mat3 r = s.orientation.toRotationMatrix();
  return std::atan2(r(1, 0), r(0, 0));
}

// A 2 kg slider on a rail along `axis` through the origin, gravity -z.
int slider(ModelBuilder& b, const Vec3& axis, double v0) {
  Body body;
  body.name = "slider";
  body.mass = 2.0;
  body.inertia = Mat3::Identity() * 0.01;
  body.velocity = v0 * axis;
  const BodyIndex i = b.addBody(body);
  return b.addJoint("rail", JointType::kPrismatic, BodyIndex::world(), i, Vec3::Zero(), axis);
}

void run(Simulator& sim, double t) {
  const long n = std::lround(t / sim.model().options.time_step);
  for (long i = 0; i < n; ++i) {
    const StepStatus status = sim.step();
    ASSERT_TRUE(status.ok) << status.message;
  }
}

TEST(JointElements, TorsionSpringAndDamperMakeTheDampedOscillator) {
  // I q'' = -k q - c q',  q(0) = 0, q'(0) = w0:  q = w0/wd e^(-zeta wn t) sin(wd t).
  const double k = 1.0, c = 0.02, w0 = 0.5;
  ModelBuilder b;
  const int j = disk(b, w0);
  b.setJointSpring(j, {k, 0.0});
  b.setJointDamping(j, c);
  Simulator sim(b.build());
  const double wn = std::sqrt(k / kIz), zeta = c / (2 * std::sqrt(k * kIz));
  const double wd = wn * std::sqrt(1 - zeta * zeta);
  double worst = 0.0;
  for (int i = 0; i < 3000; ++i) {
    ASSERT_TRUE(sim.step().ok);
    const double t = sim.state().time;
    const double q = w0 / wd * std::exp(-zeta * wn * t) * std::sin(wd * t);
    worst = std::max(worst, std::abs(angleOf(sim.state().bodies[0]) - q));
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(JointElements, ConstantEffortAcceleratesAtTorqueOverInertia) {
  ModelBuilder b;
  b.setJointEffort(disk(b), 0.2);
  Simulator sim(b.build());
  run(sim, 1.0);
  EXPECT_NEAR(sim.state().bodies[0].angular_velocity.z(), 0.2 / kIz, 1e-9);
}

TEST(JointElements, LimitHoldsTheWeightAtItsStaticDeflection) {
  // Vertical slider dropped 0.1 m onto its lower limit: rests at lower - m g / k.
  ModelBuilder b;
  b.options().gravity = Vec3(0, 0, -kG);
  const int j = slider(b, Vec3::UnitZ(), 0.0);
  b.setJointLimit(j, {-0.1, 0.5, 1e4, 200.0});
  Simulator sim(b.build());
  run(sim, 2.0);
  EXPECT_NEAR(sim.state().bodies[0].position.z(), -0.1 - 2.0 * kG / 1e4, 1e-8);
}

TEST(JointElements, UndampedLimitReturnsTheSlidersSpeed) {
  // A horizontal slider at 1 m/s into a spring stop: it leaves at -1 m/s after half a period
  // pi sqrt(m / k) in contact.
  // The stop's force has a kink at contact, where RK4 drops to second order: 0.1 ms steps.
  ModelBuilder b;
  b.options().gravity = Vec3(0, 0, -kG);
  b.options().time_step = 1e-4;
  const int j = slider(b, Vec3::UnitX(), 1.0);
  b.setJointLimit(j, {-1.0, 0.1, 1e4, 0.0});
  Simulator sim(b.build());
  run(sim, 0.3);
  EXPECT_NEAR(sim.state().bodies[0].velocity.x(), -1.0, 1e-6);
  const double t_out = 0.1 + std::numbers::pi * std::sqrt(2.0 / 1e4);
  EXPECT_NEAR(sim.state().bodies[0].position.x(), 0.1 - (0.3 - t_out), 1e-5);
}

// A disk on a free axle turning at w0 towards the upper end of a range, with an undamped stop
// of stiffness k: ranges that cross +-pi (a shoulder's [-1.3, 4.45] rad), that lie beyond it
// on either side, and one across 0 for comparison. Passing through pi does nothing (the
// kinetic energy is unchanged to rounding until the stop), the stop engages where the range
// says (the farthest turn is upper + w0 sqrt(I / k), the closed form of a spring stop), and
// the disk leaves at -w0.
TEST(JointElements, LimitRangesAcrossPiEngageOnlyAtTheirEnds) {
  const double k = 400.0, w0 = 2.0;
  for (const auto& [lower, upper] : std::vector<std::pair<double, double>>{
           {-1.3, 4.45}, {2.5, 3.9}, {-3.9, -2.5}, {-std::numbers::pi - 0.5, -2.0}, {-1.0, 1.0}}) {
    ModelBuilder b;
    b.options().time_step = 1e-4;
    const double start = upper - 1.0;  // 0.5 s before the stop
    const int j = disk(b, w0, "disk", Vec3::Zero(), kIz);
    b.setJointLimit(j, {lower, upper, k, 0.0});
    // The disk starts turned to `start` (its coordinate counts from the configuration at 0).
    auto model = b.build();
    Model turned = *model;
    turned.bodies[0].orientation = Quat(Eigen::AngleAxisd(start, Vec3::UnitZ()));
    Simulator sim(std::make_shared<const Model>(turned));
    const double e0 = 0.5 * kIz * w0 * w0;
    double angle = start, farthest = start, previous_yaw = start;
    const double contact_time = std::numbers::pi * std::sqrt(kIz / k);
    const long n = std::lround((0.5 + contact_time + 0.2) / 1e-4);
    for (long i = 0; i < n; ++i) {
      ASSERT_TRUE(sim.step().ok);
      const Quat& q = sim.state().bodies[0].orientation;
      const double yaw = 2.0 * std::atan2(q.z(), q.w());
      angle += wrapAngle(yaw - previous_yaw);  // the turn, unwrapped
      previous_yaw = yaw;
      farthest = std::max(farthest, angle);
      const double w = sim.state().bodies[0].angular_velocity.z();
      if (angle < upper - 0.05 && w > 0.0) {
        ASSERT_NEAR(0.5 * kIz * w * w, e0, 1e-9 * e0) << lower << " " << upper << " at " << angle;
      }
    }
    EXPECT_NEAR(farthest, upper + w0 * std::sqrt(kIz / k), 1e-4) << lower << " " << upper;
    EXPECT_NEAR(sim.state().bodies[0].angular_velocity.z(), -w0, 1e-4) << lower << " " << upper;
  }
}

TEST(JointElements, LimitGainsLeftOutAreDerivedFromTheStepAndTheChild) {
  // Critically damped at w = 0.5 / time_step for the child on a fixed parent: k = m w^2,
  // c = 2 m w.
  ModelBuilder b;
  b.options().time_step = 2e-3;
  b.setJointLimit(slider(b, Vec3::UnitX(), 0.0), {-0.1, 0.1, 0.0, 0.0});
  const auto model = b.build();
  const JointLimit& l = *model->joints[0].elements.limit;
  EXPECT_DOUBLE_EQ(l.stiffness, 2.0 * 250.0 * 250.0);
  EXPECT_DOUBLE_EQ(l.damping, 2.0 * 2.0 * 250.0);
}

TEST(JointElements, ConstantLoadFrictionStopsTheSliderAtTheCoulombDistance) {
  // mu N / m = 0.5 * 10 / 2 = 2.5 m/s^2 from 1 m/s: stops after 0.2 m.
  ModelBuilder b;
  const int j = slider(b, Vec3::UnitX(), 1.0);
  b.setJointFriction(j, {coulomb(0.5), JointFrictionLoad::kConstant, 10.0, 1.0});
  Simulator sim(b.build());
  run(sim, 1.0);
  EXPECT_NEAR(sim.state().bodies[0].position.x(), 0.2, 1e-3 * 0.2);
  EXPECT_LT(std::abs(sim.state().bodies[0].velocity.x()), 1e-3);
}

TEST(JointElements, ReactionLoadFrictionOnARailCarriesTheWeight) {
  // The rail's reaction is the weight: decelerates at mu g, stops after v0^2 / (2 mu g).
  const double mu = 0.3, v0 = 2.0;
  ModelBuilder b;
  b.options().gravity = Vec3(0, 0, -kG);
  const int j = slider(b, Vec3::UnitX(), v0);
  b.setJointFriction(j, {coulomb(mu), JointFrictionLoad::kReaction, 0.0, 1.0});
  Simulator sim(b.build());
  run(sim, 1.0);
  const double expected = v0 * v0 / (2 * mu * kG);
  EXPECT_NEAR(sim.state().bodies[0].position.x(), expected, 1e-3 * expected);
}

TEST(JointElements, ReactionLoadFrictionSpinsAWheelDownOnItsAxle) {
  // A wheel on a horizontal axle (pin radius r) carries its weight: torque mu m g r, so
  // w(t) = w0 - mu m g r t / I.
  const double mu = 0.2, r = 0.01, w0 = 20.0, m = 1.0;
  ModelBuilder b;
  Body wheel;
  wheel.name = "wheel";
  wheel.mass = m;
  wheel.inertia = Vec3(kIz / 2, kIz, kIz / 2).asDiagonal();
  wheel.angular_velocity = Vec3(0, w0, 0);
  const BodyIndex i = b.addBody(wheel);
  const int j =
      b.addJoint("axle", JointType::kRevolute, BodyIndex::world(), i, Vec3::Zero(), Vec3::UnitY());
  b.setJointFriction(j, {coulomb(mu), JointFrictionLoad::kReaction, 0.0, r});
  Simulator sim(b.build());
  run(sim, 1.0);
  EXPECT_NEAR(sim.state().bodies[0].angular_velocity.y(), w0 - mu * m * kG * r / kIz, 1e-6 * w0);
}

// A bob of mass m and inertia i_cm (each axis) on a pin about y at the origin, released
// horizontal (centre at (d, 0, 0)); the pin's friction is coulomb (tanh at v_eps) with
// coefficient mu at radius r under the joint's reaction load.
std::shared_ptr<const Model> pinnedPendulum(double m, double d, double i_cm, double mu, double r,
                                            double v_eps, double dt) {
  ModelBuilder b;
  b.options().time_step = dt;
  b.options().gravity = Vec3(0, 0, -kG);
  Body bob;
  bob.name = "bob";
  bob.mass = m;
  bob.inertia = Mat3::Identity() * i_cm;
  bob.position = Vec3(d, 0, 0);
  const BodyIndex ib = b.addBody(bob);
  const int j =
      b.addJoint("pin", JointType::kRevolute, BodyIndex::world(), ib, Vec3::Zero(), Vec3::UnitY());
  b.setJointFriction(
      j, {friction::makeFrictionLaw(
              {"coulomb", {{"mu", mu}, {"v_eps", v_eps}}, {{"regularization", "tanh"}}}),
          JointFrictionLoad::kReaction, 0.0, r});
  return b.build();
}

TEST(JointElements, PinFrictionOfASwingingPendulumMatchesTheReducedReference) {
  // The pin load is the reaction |m (a_cm - g)|, which depends on the friction torque
  // itself. Reference: I_O th'' = -m g d sin th - mu tanh(r th' / v_eps) N r with N solved
  // by fixed-point iteration at each RK4 stage (1-DOF, 10 us).
  const double m = 1.0, d = 0.5, i_cm = 0.01, mu = 0.3, r = 0.05, v_eps = 1e-4;
  const double i_o = i_cm + m * d * d;
  auto accel = [&](double th, double w) {
    double a = 0.0;
    for (int k = 0; k < 100; ++k) {
      const double ax = d * (a * std::cos(th) - w * w * std::sin(th));
      const double az = d * (a * std::sin(th) + w * w * std::cos(th));
      const double n = m * std::hypot(ax, az + kG);
      const double next =
          (-m * kG * d * std::sin(th) - mu * std::tanh(r * w / v_eps) * n * r) / i_o;
      if (std::abs(next - a) < 1e-15) return next;
      a = next;
    }
    return a;
  };
  double th = std::numbers::pi / 2, w = 0.0;
  const double h = 1e-5;
  for (int i = 0; i < 200000; ++i) {
    const double k1t = w, k1w = accel(th, w);
    const double k2t = w + 0.5 * h * k1w, k2w = accel(th + 0.5 * h * k1t, w + 0.5 * h * k1w);
    const double k3t = w + 0.5 * h * k2w, k3w = accel(th + 0.5 * h * k2t, w + 0.5 * h * k2w);
    const double k4t = w + h * k3w, k4w = accel(th + h * k3t, w + h * k3w);
    th += h / 6 * (k1t + 2 * k2t + 2 * k3t + k4t);
    w += h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
  }
  Simulator sim(pinnedPendulum(m, d, i_cm, mu, r, v_eps, 1e-4));
  run(sim, 2.0);
  const Vec3 p = sim.state().bodies[0].position;
  const double th_engine = std::atan2(p.x(), -p.z());
  EXPECT_NEAR(th_engine, th, 2e-6) << "reference " << th;
  EXPECT_LT(std::abs(th), std::numbers::pi / 2 - 0.05);  // friction took energy out
  EXPECT_EQ(sim.stats().joint_friction_unconverged, 0);  // mu r m d / I_O = 0.03: contracts
}

// The reaction-load iteration contracts by about mu r m d / I_O (docs/joints.md); near 1 it
// cannot settle in its 20 iterations, and the run must say so rather than pass it over.
TEST(JointElements, PinFrictionThatCannotSettleIsCounted) {
  const double m = 1.0, d = 0.5, i_cm = 0.01;
  auto pendulum = [&](double mu, double r) {
    Simulator sim(pinnedPendulum(m, d, i_cm, mu, r, 1e-2, 1e-3));
    run(sim, 0.5);
    return sim.stats();
  };
  EXPECT_EQ(pendulum(0.3, 0.05).joint_friction_unconverged, 0);
  // mu r m d / I_O = 0.9 * 0.5 / 0.26 = 1.7: no contraction while the pin slips.
  const StepStats hard = pendulum(0.9, 0.5);
  EXPECT_GT(hard.joint_friction_unconverged, 0);
  EXPECT_GE(hard.first_unconverged_time, 0.0);
}

TEST(JointElements, PositionDriveTracksAndItsTorqueIsInertiaTimesAcceleration) {
  // q = A sin(W t): the drive's reaction about the axis is I q''.
  const double a = 0.3, w = 4.0;
  ModelBuilder b;
  b.setJointDrive(disk(b), {DriveMode::kPosition, {0, 0, a, w, 0}});
  Simulator sim(b.build());
  double worst_q = 0.0, worst_torque = 0.0;
  for (int i = 0; i < 1500; ++i) {
    ASSERT_TRUE(sim.step().ok);
    const double t = sim.state().time;
    worst_q = std::max(worst_q, std::abs(angleOf(sim.state().bodies[0]) - a * std::sin(w * t)));
    const double torque = sim.current().constraint_wrench[0].torque.z();
    worst_torque = std::max(worst_torque, std::abs(torque + kIz * a * w * w * std::sin(w * t)));
  }
  EXPECT_LT(worst_q, 1e-9);
  EXPECT_LT(worst_torque, 1e-8);  // of an amplitude I a w^2 = 0.19 N m
}

TEST(JointElements, MimicCouplingSharesTheLeadersEffort) {
  // q_f = 2 q_l; effort tau on the leader drives both: (I_l + 4 I_f) q_l'' = tau.
  const double tau = 0.3, i_f = 0.01;
  ModelBuilder b;
  const int leader = disk(b, 0.0, "leader");
  const int follower = disk(b, 0.0, "follower", Vec3(1, 0, 0), i_f);
  b.setJointEffort(leader, tau);
  b.addJointCoupling("gear", leader, follower, 2.0, 0.0);
  Simulator sim(b.build());
  run(sim, 0.5);
  const double q_l = 0.5 * tau / (kIz + 4 * i_f) * 0.25;
  EXPECT_NEAR(angleOf(sim.state().bodies[0]), q_l, 1e-9);
  EXPECT_NEAR(angleOf(sim.state().bodies[1]), 2 * q_l, 1e-9);
}

TEST(JointElements, BuilderRejectsWhatCannotWork) {
  ModelBuilder b;
  Body body;
  body.name = "ball";
  const BodyIndex i = b.addBody(body);
  const int ball = b.addJoint("socket", JointType::kSpherical, BodyIndex::world(), i, Vec3::Zero(),
                              Vec3::UnitZ());
  EXPECT_NE(test::modelErrorOf([&] {
              b.setJointLimit(ball, {-1, 1, 0, 0});
            })
                .find("joint 'socket': a limit needs a revolute or prismatic joint (this one is "
                      "spherical)"),
            std::string::npos);
  ModelBuilder c;
  const int j = disk(c);
  EXPECT_NE(test::modelErrorOf([&] {
              c.setJointLimit(j, {1, -1, 0, 0});
            }).find("expected finite lower <= upper"),
            std::string::npos);
  EXPECT_NE(test::modelErrorOf([&] {
              c.setJointFriction(j, {coulomb(0.3), JointFrictionLoad::kReaction, 0.0, 0.0});
            }).find("radius must be > 0"),
            std::string::npos);
  EXPECT_NE(
      test::modelErrorOf([&] { c.addJointCoupling("self", j, j, 1, 0); }).find("the same joint"),
      std::string::npos);
  EXPECT_NE(test::modelErrorOf([&] {
              c.addJoint("u", JointType::kUniversal, BodyIndex::world(), BodyIndex{0}, Vec3::Zero(),
                         Vec3::UnitZ());
            }).find("needs its second axis"),
            std::string::npos);
  EXPECT_NE(test::modelErrorOf([&] {
              c.addJoint("u", JointType::kUniversal, BodyIndex::world(), BodyIndex{0}, Vec3::Zero(),
                         Vec3::UnitZ(), Vec3(1, 0, 1));
            }).find("axis2 must be normal to axis"),
            std::string::npos);
}

TEST(JointElements, ADriveOnAMotionAlreadyFixedIsAnError) {
  // Both disks driven, and coupled as well: the coupling has nothing left to fix.
  ModelBuilder b;
  const int l = disk(b, 0.0, "a"), f = disk(b, 0.0, "b", Vec3(1, 0, 0));
  b.setJointDrive(l, {DriveMode::kVelocity, {1, 0, 0, 0, 0}});
  b.setJointDrive(f, {DriveMode::kVelocity, {2, 0, 0, 0, 0}});
  b.addJointCoupling("gear", l, f, 2.0, 0.0);
  EXPECT_NE(test::modelErrorOf([&] { b.build(); })
                .find("coupling 'gear': it prescribes a motion the other "
                      "constraints already fix"),
            std::string::npos);
}

}  // namespace
}  // namespace tribo
