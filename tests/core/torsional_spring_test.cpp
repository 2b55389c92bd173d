// The torsional spring-damper (core/torsional_spring.hpp) against independent expectations:
// its torque as minus the finite-difference gradient of its potential (with the bodies tilted
// off the axis), a flywheel on a revolute joint at sqrt(k/I), two free coaxial bodies at the
// reduced inertia I_a I_b / (I_a + I_b), the damped decay rate c / (2 I), energy and angular
// momentum of two tumbling free bodies, the a-priori stable step and the builder's checks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "core/energy.hpp"
#include "core/model_builder.hpp"
#include "core/simulator.hpp"
#include "core/stability.hpp"

namespace tribo {
namespace {

constexpr double kPi = std::numbers::pi;

Quat turn(double angle, const Vec3& axis) {
  return Quat(Eigen::AngleAxisd(angle, axis.normalized()));
}

BodyKinematics motion(const Quat& q, const Vec3& w = Vec3::Zero()) {
  return {Vec3::Zero(), q, q.toRotationMatrix(), Vec3::Zero(), w};
}

// Angle of body state s about world z (s turning about z only).
double yaw(const BodyState& s) { return 2 * std::atan2(s.orientation.z(), s.orientation.w()); }

TorsionalSpring spring(double k, double c, double rest) {
  TorsionalSpring s;
  s.name = "coupling";
  s.body_a = BodyIndex{0};
  s.body_b = BodyIndex{1};
  s.axis_a = Vec3(0.2, 0.3, 0.9).normalized();
  s.reference_a = s.axis_a.unitOrthogonal();
  s.reference_b = turn(0.4, Vec3(1, 1, 0)) * Vec3(0.3, -0.8, 0.1).normalized();
  s.stiffness = k;
  s.damping = c;
  s.rest_angle = rest;
  return s;
}

TEST(TorsionalSpring, TorqueIsMinusTheGradientOfItsPotential) {
  // Bodies tilted off the axis: the torque has components normal to it, those of V.
  const TorsionalSpring s = spring(7.0, 0.0, 0.3);
  const Quat qa = turn(0.6, Vec3(1, -1, 0.5)), qb = turn(1.4, Vec3(-0.3, 0.2, 1));
  auto energy = [&](const Quat& a, const Quat& b) {
    return torsionalEnergy(s, torsionalDeflection(s, motion(a), motion(b)));
  };
  const TorsionalDeflection d = torsionalDeflection(s, motion(qa), motion(qb));
  const Vec3 tau = torsionalTorque(s, d);
  const Vec3 axis_world = qa * s.axis_a;
  ASSERT_GT(tau.cross(axis_world).norm(), 0.05 * tau.norm());  // off the axis indeed
  const double e = 1e-6;
  for (int i = 0; i < 3; ++i) {
    const Quat p = turn(e, Vec3::Unit(i)), m = turn(-e, Vec3::Unit(i));
    const double tb = -(energy(qa, p * qb) - energy(qa, m * qb)) / (2 * e);
    const double ta = -(energy(p * qa, qb) - energy(m * qa, qb)) / (2 * e);
    // Central differences: O(e^2) and rounding eps V / e = 1e-16 x 1 / 1e-6: 1e-9 N m on
    // torques of ~1 N m.
    EXPECT_NEAR(tau[i], tb, 1e-8) << i;
    EXPECT_NEAR(-tau[i], ta, 1e-8) << i;
  }
  // The rate is the same gradient applied to the relative angular velocity.
  const Vec3 wa(0.3, -1.0, 0.2), wb(2.0, 0.5, -0.7);
  const double h = 1e-7;
  const Quat qa2 = turn(h * wa.norm(), wa) * qa, qb2 = turn(h * wb.norm(), wb) * qb;
  const double numeric = (torsionalDeflection(s, motion(qa2), motion(qb2)).angle - d.angle) / h;
  EXPECT_NEAR(torsionalDeflection(s, motion(qa, wa), motion(qb, wb)).rate, numeric, 1e-6);
}

TEST(TorsionalSpring, CoaxialTurnIsTheAngleAboutTheAxis) {
  // B turned by theta about A's axis: delta = theta - theta0, torque -k delta along the axis.
  TorsionalSpring s = spring(3.0, 0.0, 0.25);
  s.reference_b = s.reference_a;
  for (double theta : {-3.0, -1.0, 0.0, 0.5, 3.0}) {
    const TorsionalDeflection d =
        torsionalDeflection(s, motion(Quat::Identity()), motion(turn(theta, s.axis_a)));
    const double delta = std::remainder(theta - 0.25, 2 * kPi);
    EXPECT_NEAR(d.angle, delta, 1e-14) << theta;
    EXPECT_LT((torsionalTorque(s, d) + 3.0 * delta * s.axis_a).norm(), 1e-14) << theta;
  }
}

// A flywheel (inertia `iz` about z) on a revolute joint to the world, held by a torsional
// spring from the world about z, relaxed at yaw 0: it starts at yaw q0 (rest angle -q0, the
// angle counting from the start).
std::shared_ptr<const Model> flywheel(double iz, double k, double c, double q0, double dt) {
  ModelBuilder b;
  Body body;
  body.name = "wheel";
  body.mass = 2.0;
  body.inertia = Vec3(iz * 0.6, iz * 0.6, iz).asDiagonal();
  body.orientation = turn(q0, Vec3::UnitZ());
  const BodyIndex i = b.addBody(body);
  b.addJoint("axle", JointType::kRevolute, BodyIndex::world(), i, Vec3::Zero(), Vec3::UnitZ());
  b.addTorsionalSpring("torsion", BodyIndex::world(), i, Vec3(0, 0, 2), k, c, -q0);
  b.options().gravity = Vec3::Zero();
  b.options().time_step = dt;
  return b.build();
}

TEST(TorsionalSpring, FlywheelOscillatesAtSqrtKOverI) {
  for (const auto& [iz, k] : {std::pair{0.01, 1.0}, {0.5, 200.0}, {20.0, 5.0}, {1e-6, 1e3}}) {
    const double w = std::sqrt(k / iz), q0 = 0.3;
    Simulator sim(flywheel(iz, k, 0.0, q0, 2 * kPi / w / 200));
    double worst = 0.0;
    for (int s = 0; s < 600; ++s) {
      const StepStatus status = sim.step();
      ASSERT_TRUE(status.ok) << status.message;
      worst = std::max(worst,
                       std::abs(yaw(sim.state().bodies[0]) - q0 * std::cos(w * sim.state().time)));
    }
    std::printf("I %g, k %g: worst |yaw - q0 cos(w t)| / q0 %.2e\n", iz, k, worst / q0);
    // RK4 at w h = 2 pi / 200 over 600 steps: phase error 1.5e-7 (see bushing_test); the
    // joint's Baumgarte terms act on the (zero) off-axis motion only.
    EXPECT_LT(worst, 1e-6 * q0) << iz << " " << k;
  }
}

TEST(TorsionalSpring, DampedFlywheelDecaysAtCOver2I) {
  // I q'' + c q' + k q = 0: q = q0 e^(-s t) (cos(wd t) + s / wd sin(wd t)), s = c / (2 I).
  // The decay rate is also read off successive maxima: ln(q_n / q_n+1) / T_d.
  const double iz = 0.05, k = 8.0, c = 0.02, q0 = 0.4;
  const double wn = std::sqrt(k / iz), sigma = c / (2 * iz);
  const double wd = std::sqrt(wn * wn - sigma * sigma);
  Simulator sim(flywheel(iz, k, c, q0, 2 * kPi / wd / 400));
  // q(-h) = q(h) to O(h^3 sigma): t = 0 is a maximum and not counted as a peak.
  double worst = 0.0, prev = q0, prev2 = q0;
  std::vector<double> peaks;
  while (sim.state().time < 5 * 2 * kPi / wd) {
    ASSERT_TRUE(sim.step().ok);
    const double t = sim.state().time;
    const double q = yaw(sim.state().bodies[0]);
    const double exact =
        q0 * std::exp(-sigma * t) * (std::cos(wd * t) + sigma / wd * std::sin(wd * t));
    worst = std::max(worst, std::abs(q - exact));
    // A maximum at the last step: the vertex of the parabola through the three samples.
    if (prev > prev2 && prev > q)
      peaks.push_back(prev - (q - prev2) * (q - prev2) / (8 * (prev2 - 2 * prev + q)));
    prev2 = prev;
    prev = q;
  }
  ASSERT_GE(peaks.size(), 4u);
  // Successive maxima of the closed form are T_d apart with ratio e^(sigma T_d). The parabola
  // through samples 1/400 of a period apart finds each to O((w h)^4) = 6e-8 relative, RK4's
  // error is below 1e-8: over 4 periods (sigma T = 0.4 in the log) the rate is good to 1e-6;
  // 1e-5 asked.
  const double rate = std::log(peaks.front() / peaks.back()) / ((peaks.size() - 1) * 2 * kPi / wd);
  std::printf(
      "decay rate %.8g 1/s (c / 2I = %.8g) from %zu maxima, worst |q - closed form| / "
      "q0 %.2e\n",
      rate, sigma, peaks.size(), worst / q0);
  EXPECT_NEAR(rate, sigma, 1e-5 * sigma);
  EXPECT_LT(worst, 1e-6 * q0);  // RK4 at 1/400 of a period
}

TEST(TorsionalSpring, TwoFreeBodiesTurnOnTheReducedInertia) {
  // No joint: two bodies turning about their common principal axis z, the spring between
  // them; the relative angle oscillates at sqrt(k (I_a + I_b) / (I_a I_b)).
  for (const auto& [ia, ib, k] :
       {std::tuple{0.1, 0.3, 5.0}, {2e-6, 1e-6, 10.0}, {40.0, 0.01, 200.0}}) {
    ModelBuilder b;
    Body a;
    a.name = "a";
    a.inertia = Vec3(ia, ia * 1.5, ia).asDiagonal();
    Body c;
    c.name = "c";
    c.inertia = Vec3(ib * 0.7, ib * 0.6, ib).asDiagonal();
    c.position = Vec3(0.3, 0, 0);
    const double q0 = 0.5;
    c.orientation = turn(q0, Vec3::UnitZ());
    const BodyIndex ai = b.addBody(a), ci = b.addBody(c);
    b.addTorsionalSpring("shaft", ai, ci, Vec3::UnitZ(), k, 0.0, -q0);
    b.options().gravity = Vec3::Zero();
    const double w = std::sqrt(k * (ia + ib) / (ia * ib));
    b.options().time_step = 2 * kPi / w / 200;
    Simulator sim(b.build());
    double worst = 0.0;
    for (int s = 0; s < 600; ++s) {
      ASSERT_TRUE(sim.step().ok);
      const double rel = yaw(sim.state().bodies[1]) - yaw(sim.state().bodies[0]);
      worst = std::max(worst, std::abs(rel - q0 * std::cos(w * sim.state().time)));
    }
    std::printf("I_a %g, I_b %g, k %g: worst |relative angle - q0 cos(w t)| / q0 %.2e\n", ia, ib, k,
                worst / q0);
    EXPECT_LT(worst, 1e-6 * q0);  // as the flywheel
  }
}

// Two tumbling free bodies joined by a torsional spring (no joint holds them coaxial).
std::shared_ptr<const Model> tumbling(double dt) {
  ModelBuilder b;
  Body a;
  a.name = "a";
  a.mass = 1.0;
  a.inertia = Vec3(0.02, 0.03, 0.04).asDiagonal();
  a.angular_velocity = Vec3(1.0, -2.0, 3.0);
  a.velocity = Vec3(0.1, 0, 0);
  Body c;
  c.name = "c";
  c.mass = 1.0;
  c.velocity = Vec3(0.1, 0, 0);
  c.inertia = Vec3(0.01, 0.015, 0.012).asDiagonal();
  c.position = Vec3(0, 0.4, 0);
  c.orientation = turn(0.3, Vec3(1, 2, 3));
  c.angular_velocity = Vec3(-2.0, 0.5, 1.0);
  const BodyIndex ai = b.addBody(a), ci = b.addBody(c);
  b.addTorsionalSpring("shaft", ai, ci, Vec3(0.1, 0.2, 1), 2.0, 0.0, 0.4);
  b.options().gravity = Vec3::Zero();
  b.options().time_step = dt;
  return b.build();
}

TEST(TorsionalSpring, TumblingBodiesConserveEnergyAndAngularMomentum) {
  auto drift = [](double dt) {
    Simulator sim(tumbling(dt));
    const Model& model = sim.model();
    auto angular = [&] {
      Vec3 l = Vec3::Zero();
      for (int i = 0; i < 2; ++i) {
        const BodyState& s = sim.state().bodies[i];
        const Mat3 r = s.orientation.toRotationMatrix();
        l += model.bodies[i].mass * s.position.cross(s.velocity) +
             r * model.bodies[i].inertia * r.transpose() * s.angular_velocity;
      }
      return l;
    };
    const Vec3 l0 = angular();
    const double e0 = measureEnergy(model, sim.state(), sim.current()).total();
    double dl = 0.0, de = 0.0;
    for (long s = 0; s < std::lround(2.0 / dt); ++s) {
      EXPECT_TRUE(sim.step().ok);
      dl = std::max(dl, (angular() - l0).norm() / l0.norm());
      de = std::max(de,
                    std::abs(measureEnergy(model, sim.state(), sim.current()).total() - e0) / e0);
    }
    return std::pair{dl, de};
  };
  const auto [l1, e1] = drift(1e-3);
  const auto [l2, e2] = drift(5e-4);
  std::printf("h 1e-3: drift |L| %.2e, E %.2e;  h 5e-4: %.2e, %.2e\n", l1, e1, l2, e2);
  // As for the bushing: RK4's O(h^4) error (spins of ~4 rad/s and w = sqrt(2 / 0.01) = 14
  // rad/s: w h = 0.014), falling by about 16 when h halves (>= 8 asked). The potential is
  // smooth here (u_B stays well away from the axis); a torque that is not its gradient would
  // drift at O(1) whatever h.
  EXPECT_LT(l1, 1e-7);
  EXPECT_LT(e1, 1e-7);
  EXPECT_GT(l1, 8 * l2);
  EXPECT_GT(e1, 8 * e2);
}

TEST(TorsionalSpring, StableStepOnTheReducedInertiaAboutTheAxis) {
  // Flywheel I_z = 1e-6 on k = 1e3: RK4 limit 2 sqrt(2) / sqrt(k / I).
  const auto model = flywheel(1e-6, 1e3, 0.0, 0.0, 1e-5);
  const StabilityReport r = estimateStableStep(*model);
  const double expected = 2 * std::sqrt(2.0) / std::sqrt(1e3 / 1e-6);
  EXPECT_NEAR(r.limit.max_step, expected, 1e-6 * expected);  // bisection tolerance
  EXPECT_EQ(r.limit.element, "torsional spring 'torsion'");
}

TEST(TorsionalSpring, BuilderRejectsBadInput) {
  auto error = [](const std::function<void(ModelBuilder&, BodyIndex)>& add) {
    ModelBuilder b;
    Body body;
    body.name = "wheel";
    const BodyIndex i = b.addBody(body);
    try {
      add(b, i);
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const BodyIndex w = BodyIndex::world();
  EXPECT_EQ(error([&](ModelBuilder& b, BodyIndex i) {
              b.addTorsionalSpring("t", w, i, Vec3::UnitZ(), -1.0, 0.0, 0.0);
            }),
            "torsional spring 't': stiffness must be >= 0 (got -1)");
  EXPECT_EQ(error([&](ModelBuilder& b, BodyIndex i) {
              b.addTorsionalSpring("t", w, i, Vec3::UnitZ(), 1.0, -0.5, 0.0);
            }),
            "torsional spring 't': damping must be >= 0 (got -0.5)");
  EXPECT_EQ(error([&](ModelBuilder& b, BodyIndex i) {
              b.addTorsionalSpring("t", w, i, Vec3::Zero(), 1.0, 0.0, 0.0);
            }),
            "torsional spring 't': axis must be a finite, non-zero vector (got [0, 0, 0])");
  EXPECT_EQ(error([&](ModelBuilder& b, BodyIndex i) {
              b.addTorsionalSpring("t", i, i, Vec3::UnitZ(), 1.0, 0.0, 0.0);
            }),
            "torsional spring 't': both ends on the same body");
  EXPECT_EQ(error([&](ModelBuilder& b, BodyIndex i) {
              b.addTorsionalSpring("t", w, i, Vec3::UnitZ(), 1.0, 0.0, INFINITY);
            }),
            "torsional spring 't': rest angle must be finite (got inf)");
}

}  // namespace
}  // namespace tribo
