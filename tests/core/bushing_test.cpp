// The bushing (core/bushing.hpp) and its SO(3) helpers (core/rotation_log.hpp), each against
// an independent expectation: the rotation vector of a known axis-angle, the right Jacobian
// of Sola et al. (a different formula), the wrench as minus the finite-difference gradient
// of the potential, the small-oscillation frequencies sqrt(k/m) and sqrt(k/I) per axis of a
// rotated frame A (distinct gains per axis, so axes cannot be mixed up) over orders of
// magnitude of mass and stiffness, two free bodies on the reduced mass, conservation of
// linear and angular momentum and of energy, the a-priori stable step, and the builder's
// checks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "core/energy.hpp"
#include "core/model_builder.hpp"
#include "core/rotation_log.hpp"
#include "core/simulator.hpp"
#include "core/stability.hpp"

namespace tribo {
namespace {

constexpr double kPi = std::numbers::pi;

Quat expMap(const Vec3& phi) {
  const double t = phi.norm();
  return t == 0.0 ? Quat::Identity() : Quat(Eigen::AngleAxisd(t, phi / t));
}

TEST(RotationLog, GivesTheAxisAngleItWasMadeFrom) {
  const Vec3 n = Vec3(0.3, -0.5, 0.8).normalized();
  // Angles from rounding level to just below pi; the quaternion's sign must not matter.
  for (double theta : {1e-12, 1e-6, 1e-3, 0.5, 2.0, 3.0, kPi - 1e-7}) {
    const Quat q(Eigen::AngleAxisd(theta, n));
    const Quat minus(-q.w(), -q.x(), -q.y(), -q.z());
    for (const Quat& r : {q, minus}) {
      const Vec3 phi = rotationLog(r);
      // Rounding of the quaternion's components (1e-16) over sin(theta/2): 1e-15 theta is
      // loose by 10x except near pi, where the axis comes from a vector of norm ~1.
      EXPECT_LT((phi - theta * n).norm(), 1e-14 * std::max(theta, 1.0)) << theta;
    }
  }
}

TEST(RotationLog, InverseRightJacobianInvertsSolasRightJacobian) {
  // J_r(phi) = I - (1 - cos t)/t^2 [phi]x + (t - sin t)/t^3 [phi]x^2 (Sola et al. 2018, eq. 143).
  for (double theta : {0.02, 0.3, 1.0, 2.5, 3.1}) {
    const Vec3 phi = theta * Vec3(-0.2, 0.9, 0.4).normalized();
    const Mat3 s = skew(phi);
    const double t = theta;
    const Mat3 jr = Mat3::Identity() - (1 - std::cos(t)) / (t * t) * s +
                    (t - std::sin(t)) / (t * t * t) * s * s;
    // Rounding only: the entries of both are O(1) up to t = 3.1.
    EXPECT_LT((inverseRightJacobian(phi) * jr - Mat3::Identity()).norm(), 1e-12) << theta;
  }
  // The series branch (t < 1e-2) against the closed form at the switch: both are beta to
  // 1e-13 (the series' next term t^6/1209600 is 1e-18; the closed form's cancellation ~1e-12).
  const Vec3 at = 0.0099999 * Vec3::UnitX() + 1e-4 * Vec3::UnitY();
  const Mat3 s = skew(at);
  const double t = at.norm();
  const double beta = 1 / (t * t) - (1 + std::cos(t)) / (2 * t * std::sin(t));
  const Mat3 closed = Mat3::Identity() + 0.5 * s + beta * s * s;
  EXPECT_LT((inverseRightJacobian(at) - closed).norm(), 1e-13);
}

TEST(RotationLog, RightJacobianMapsAChangeOfTheRotationVector) {
  // Exp(phi + e) = Exp(phi) Exp(J_r(phi) e) to O(e^2): so J_r^-1 maps the body-fixed
  // displacement back to the change of phi.
  const Vec3 phi = Vec3(0.7, -1.1, 0.5);
  const double e = 1e-6;
  for (int i = 0; i < 3; ++i) {
    const Vec3 d = e * Vec3::Unit(i);
    const Vec3 right = rotationLog(expMap(phi).conjugate() * expMap(phi + d));
    // O(e^2) = 1e-12 against a 1e-6 change: 1e-10 leaves room for rounding (1e-16 / 1e-6).
    EXPECT_LT((inverseRightJacobian(phi) * right - d).norm(), 1e-10) << i;
  }
}

// A body's pose and velocity, for the element functions.
BodyKinematics motion(const Vec3& p, const Quat& q, const Vec3& v = Vec3::Zero(),
                      const Vec3& w = Vec3::Zero()) {
  return {p, q.normalized(), q.normalized().toRotationMatrix(), v, w};
}

Bushing generalBushing() {
  Bushing b;
  b.name = "general";
  b.body_a = BodyIndex{0};
  b.body_b = BodyIndex{1};
  b.position_a = Vec3(0.1, -0.2, 0.05);
  b.orientation_a = Quat(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()));
  b.position_b = Vec3(-0.03, 0.07, 0.2);
  b.orientation_b = Quat(Eigen::AngleAxisd(-0.9, Vec3(0, 1, 1).normalized()));
  b.stiffness = Vec3(100, 450, 2000);
  b.rotational_stiffness = Vec3(3, 11, 40);
  return b;
}

TEST(Bushing, WrenchIsMinusTheGradientOfItsPotential) {
  // Large deflections (0.3 m, about 1.5 rad) and unequal gains: where the small-angle torque
  // -R_A K phi is no gradient. Each body is moved by e along and turned by e about each world
  // axis (about its centre of mass, the body origin); central differences of V give the
  // generalized force, to compare with the wrench (on A: -F at o_B and -T).
  const Bushing bushing = generalBushing();
  const Vec3 pa(0.2, 0.1, -0.3), pb(0.1, 0.4, -0.1);
  const Quat qa(Eigen::AngleAxisd(0.8, Vec3(0.2, -1, 0.3).normalized()));
  const Quat qb(Eigen::AngleAxisd(-1.2, Vec3(1, 0.5, -0.4).normalized()));
  auto energy = [&](const Vec3& xa, const Quat& ra, const Vec3& xb, const Quat& rb) {
    return bushingEnergy(bushing, bushingDeflection(bushing, motion(xa, ra), motion(xb, rb)));
  };
  const BushingDeflection d = bushingDeflection(bushing, motion(pa, qa), motion(pb, qb));
  ASSERT_GT(d.rotation.norm(), 1.0);
  const PairWrench w = bushingWrench(bushing, d);
  const Vec3 moment_b = (w.point - pb).cross(w.force) + w.torque;
  const Vec3 moment_a = (w.point - pa).cross(-w.force) - w.torque;
  const double e = 1e-6;
  for (int i = 0; i < 3; ++i) {
    const Vec3 u = e * Vec3::Unit(i);
    const double fb = -(energy(pa, qa, pb + u, qb) - energy(pa, qa, pb - u, qb)) / (2 * e);
    const double tb =
        -(energy(pa, qa, pb, expMap(u) * qb) - energy(pa, qa, pb, expMap(-u) * qb)) / (2 * e);
    const double fa = -(energy(pa + u, qa, pb, qb) - energy(pa - u, qa, pb, qb)) / (2 * e);
    const double ta =
        -(energy(pa, expMap(u) * qa, pb, qb) - energy(pa, expMap(-u) * qa, pb, qb)) / (2 * e);
    // Central differences: O(e^2) V''' ~ 1e-12 x 1e3, and rounding eps V / e ~ 1e-16 x 1e2 /
    // 1e-6 = 1e-8 N against forces of ~1e2 N: 1e-7 relative.
    const double scale = 1e-7 * (w.force.norm() + w.torque.norm());
    EXPECT_NEAR(w.force[i], fb, scale) << i;
    EXPECT_NEAR(moment_b[i], tb, scale) << i;
    EXPECT_NEAR(-w.force[i], fa, scale) << i;
    EXPECT_NEAR(moment_a[i], ta, scale) << i;
  }
}

TEST(Bushing, DampingOpposesTheRelativeMotionOfTheCoincidentPoints) {
  // Only damping, frames coincident: d' is B's velocity at o_B relative to A's material
  // point there, in A's axes; F_B = -R_A C_t d', T_B = -R_A C_r (w_B - w_A in A's axes).
  Bushing bushing = generalBushing();
  bushing.stiffness.setZero();
  bushing.rotational_stiffness.setZero();
  bushing.damping = Vec3(2, 5, 9);
  bushing.rotational_damping = Vec3(0.1, 0.3, 0.7);
  const Vec3 va(0.3, -0.1, 0.2), wa(0.5, 1.0, -2.0), vb(-0.4, 0.2, 0.1), wb(1.5, -0.5, 0.3);
  const Vec3 pa(0, 0, 0), pb(0.2, 0.1, 0.3);
  const Quat qa = Quat::Identity(), qb(Eigen::AngleAxisd(0.3, Vec3::UnitX()));
  const BushingDeflection d =
      bushingDeflection(bushing, motion(pa, qa, va, wa), motion(pb, qb, vb, wb));
  const PairWrench w = bushingWrench(bushing, d);
  const Mat3 ra = bushing.orientation_a.toRotationMatrix();  // A's body is unrotated
  const Vec3 ob = pb + qb * bushing.position_b;
  const Vec3 rel = (vb + wb.cross(ob - pb)) - (va + wa.cross(ob - pa));
  const Vec3 f = -(ra * bushing.damping.cwiseProduct(ra.transpose() * rel));
  const Vec3 t = -(ra * bushing.rotational_damping.cwiseProduct(ra.transpose() * (wb - wa)));
  EXPECT_LT((w.force - f).norm(), 1e-13 * f.norm());
  EXPECT_LT((w.torque - t).norm(), 1e-13 * t.norm());
  EXPECT_LT((w.point - ob).norm(), 1e-15);
}

// One body of mass m and inertia diag(I) in its frame, held by a bushing to the world whose
// frame A sits at `anchor`, turned by `frame`; frame B is the body frame. The body starts at
// frame A's pose displaced by `x0` along A's axis `axis` (translation) or turned by `x0`
// about it (rotation). No gravity, RK4 at 1/200 of the period.
struct Oscillator {
  double mass;
  Vec3 inertia;
  Vec3 stiffness, rotational_stiffness;
};

std::shared_ptr<const Model> bushingOnWorld(const Oscillator& o, const Quat& frame,
                                            const Vec3& anchor, int axis, bool rotation, double x0,
                                            double dt) {
  ModelBuilder b;
  Body body;
  body.name = "block";
  body.mass = o.mass;
  body.inertia = o.inertia.asDiagonal();
  body.position = anchor + (rotation ? Vec3::Zero() : Vec3(frame * (x0 * Vec3::Unit(axis))));
  body.orientation = rotation ? frame * expMap(x0 * Vec3::Unit(axis)) : frame;
  const BodyIndex i = b.addBody(body);
  Bushing bushing;
  bushing.name = "mount";
  bushing.body_b = i;
  bushing.position_a = anchor;
  bushing.orientation_a = frame;
  bushing.stiffness = o.stiffness;
  bushing.rotational_stiffness = o.rotational_stiffness;
  b.addBushing(bushing);
  b.options().gravity = Vec3::Zero();
  b.options().time_step = dt;
  return b.build();
}

TEST(Bushing, EachAxisOscillatesAtItsOwnFrequency) {
  // Every gain differs (by axis and between translation and rotation), frame A is turned so
  // no axis of it is a world axis: swapped or mis-rotated axes give a wrong frequency or
  // motion along another axis. Rotation about a principal axis that is one of A's axes, and
  // translation along one, stay on that axis: x = x0 cos(w t) exactly, w = sqrt(k/m) or
  // sqrt(k_r / I).
  const Quat frame(Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()));
  const Vec3 anchor(0.3, -1.2, 2.0);
  const Oscillator cases[] = {
      {2.0, {0.03, 0.05, 0.07}, {100, 400, 900}, {3, 7, 13}},
      {1e-3, {1e-7, 2e-7, 2.5e-7}, {1e6, 2e6, 5e6}, {0.01, 0.03, 0.05}},  // light and stiff
      {500.0, {50, 80, 100}, {1e4, 3e4, 9e4}, {2e3, 5e3, 1.1e4}},         // heavy
  };
  for (const Oscillator& o : cases)
    for (int axis = 0; axis < 3; ++axis)
      for (bool rotation : {false, true}) {
        const double k = rotation ? o.rotational_stiffness[axis] : o.stiffness[axis];
        const double m = rotation ? o.inertia[axis] : o.mass;
        const double w = std::sqrt(k / m), period = 2 * kPi / w;
        const double x0 = rotation ? 0.2 : 1e-3;
        Simulator sim(bushingOnWorld(o, frame, anchor, axis, rotation, x0, period / 200));
        double worst = 0.0, off_axis = 0.0;
        const long steps = 3 * 200;
        for (long s = 0; s < steps; ++s) {
          const StepStatus status = sim.step();
          ASSERT_TRUE(status.ok) << status.message;
          const BodyState& b = sim.state().bodies[0];
          const Vec3 x = rotation ? rotationLog(frame.conjugate() * b.orientation)
                                  : Vec3(frame.conjugate() * (b.position - anchor));
          const Vec3 other = rotation ? Vec3(frame.conjugate() * (b.position - anchor))
                                      : rotationLog(frame.conjugate() * b.orientation);
          Vec3 across = x;
          across[axis] = 0.0;
          worst = std::max(worst, std::abs(x[axis] - x0 * std::cos(w * sim.state().time)));
          off_axis = std::max({off_axis, across.norm() / x0, other.norm()});
        }
        std::printf(
            "m %g %s axis %d: w %.6g rad/s, worst |x - x0 cos(w t)| / x0 %.2e, "
            "off-axis %.1e\n",
            o.mass, rotation ? "rotation" : "translation", axis, w, worst / x0, off_axis);
        // RK4 at w h = 2 pi / 200: phase error (w h)^5 / 120 = 2.6e-10 per step, 1.5e-7 x0
        // after 600 steps; 1e-6 leaves 6x.
        EXPECT_LT(worst, 1e-6 * x0) << o.mass << " " << axis << " " << rotation;
        // Motion on other axes starts from rounding of the initial pose (1e-16) and is not
        // driven: 1e-10 is far below any coupling a mixed-up axis would give (order 1).
        EXPECT_LT(off_axis, 1e-10) << o.mass << " " << axis << " " << rotation;
      }
}

// Two free bodies on a bushing, generic: frames off the centres of mass and turned, unequal
// gains, large initial deflection and arbitrary velocities.
std::shared_ptr<const Model> twoFreeBodies(double dt, bool damping) {
  ModelBuilder b;
  Body a;
  a.name = "a";
  a.mass = 1.3;
  a.inertia << 0.05, 0.01, -0.004, 0.01, 0.07, 0.002, -0.004, 0.002, 0.09;
  a.position = Vec3(0.2, 0.1, -0.3);
  a.orientation = Quat(Eigen::AngleAxisd(0.8, Vec3(0.2, -1, 0.3).normalized()));
  a.velocity = Vec3(0.3, -0.2, 0.1);
  a.angular_velocity = Vec3(0.3, -0.2, 0.5);
  Body c;
  c.name = "c";
  c.mass = 0.4;
  c.inertia = Vec3(0.004, 0.006, 0.009).asDiagonal();
  c.velocity = Vec3(-0.5, 0.4, 0.8);
  c.angular_velocity = Vec3(-0.6, 0.3, 0.2);
  Bushing bushing = generalBushing();
  // Unequal rotational gains (J_r^-1 matters), but within 2.5x, and an initial relative
  // rotation phi0 of 0.77 rad: |phi| then stays clear of the log's ridge at pi (the largest
  // is printed).
  bushing.rotational_stiffness = Vec3(10, 15, 25);
  const Vec3 phi0(0.5, -0.4, 0.3);
  c.orientation =
      a.orientation * bushing.orientation_a * expMap(phi0) * bushing.orientation_b.conjugate();
  // And a translational deflection d0 of 7 cm: the force's moment about B's centre of mass
  // (frame B is 0.2 m off it) spins the light body no faster than the rotational gains do.
  const Vec3 d0(0.05, -0.03, 0.04);
  c.position = a.position + a.orientation * (bushing.position_a + bushing.orientation_a * d0) -
               c.orientation * bushing.position_b;
  bushing.body_a = b.addBody(a);
  bushing.body_b = b.addBody(c);
  if (damping) {
    bushing.damping = Vec3(1, 2, 3);
    bushing.rotational_damping = Vec3(0.01, 0.02, 0.05);
  }
  b.addBushing(bushing);
  b.options().gravity = Vec3::Zero();
  b.options().time_step = dt;
  return b.build();
}

struct Momenta {
  Vec3 linear, angular;  // angular about the world origin
};

Momenta momenta(const Model& model, const State& state) {
  Momenta m{Vec3::Zero(), Vec3::Zero()};
  for (std::size_t i = 0; i < model.bodies.size(); ++i) {
    const Body& body = model.bodies[i];
    const BodyState& s = state.bodies[i];
    const Mat3 r = s.orientation.toRotationMatrix();
    m.linear += body.mass * s.velocity;
    m.angular += body.mass * s.position.cross(s.velocity) +
                 r * body.inertia * r.transpose() * s.angular_velocity;
  }
  return m;
}

TEST(Bushing, WrenchesOnTheTwoBodiesHaveNoResultant) {
  // Exact at each evaluation: sum F = 0 and sum (x_b x F_b + T_b) = 0 to rounding.
  Simulator sim(twoFreeBodies(1e-3, true));
  const Workspace& ws = sim.current();
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  double scale = 0.0;
  for (int i = 0; i < 2; ++i) {
    const Wrench& w = ws.spring_wrench[i];
    force += w.force;
    moment += sim.state().bodies[i].position.cross(w.force) + w.torque;
    scale += w.force.norm() + w.torque.norm();
  }
  ASSERT_GT(scale, 10.0);
  // Rounding of sums of O(1e2) terms: 1e-14 relative.
  EXPECT_LT(force.norm(), 1e-14 * scale);
  EXPECT_LT(moment.norm(), 1e-14 * scale);
}

// Largest drift over 1 s of linear momentum, angular momentum and energy, relative to the
// initial |p|, |L| and E.
struct Drift {
  double linear = 0.0, angular = 0.0, energy = 0.0;
  double largest_angle = 0.0;  // |phi| [rad]
};

Drift driftOver1s(double dt, bool damping) {
  Simulator sim(twoFreeBodies(dt, damping));
  const Model& model = sim.model();
  const Momenta m0 = momenta(model, sim.state());
  const double e0 = measureEnergy(model, sim.state(), sim.current()).total();
  Drift d;
  for (long s = 0; s < std::lround(1.0 / dt); ++s) {
    const StepStatus status = sim.step();
    EXPECT_TRUE(status.ok) << status.message;
    if (!status.ok) break;
    const Momenta m = momenta(model, sim.state());
    d.linear = std::max(d.linear, (m.linear - m0.linear).norm() / m0.linear.norm());
    d.angular = std::max(d.angular, (m.angular - m0.angular).norm() / m0.angular.norm());
    const double e = measureEnergy(model, sim.state(), sim.current()).total();
    d.energy = std::max(d.energy, std::abs(e - e0) / e0);
    const Bushing& bushing = model.bushings[0];
    d.largest_angle =
        std::max(d.largest_angle,
                 bushingDeflection(
                     bushing, bodyKinematics(sim.state(), sim.current().rotation, bushing.body_a),
                     bodyKinematics(sim.state(), sim.current().rotation, bushing.body_b))
                     .rotation.norm());
  }
  return d;
}

TEST(Bushing, TwoFreeBodiesConserveMomentumAndEnergy) {
  // Fastest mode: k 2000 N/m on the reduced mass 0.31 kg, w ~ 80 rad/s, and the rotational
  // gains on the small body's 0.004 kg m^2, w ~ 100 rad/s: h = 2e-4 s is w h <= 0.02.
  const Drift coarse = driftOver1s(2e-4, false);
  const Drift fine = driftOver1s(1e-4, false);
  std::printf(
      "h 2e-4: drift |p| %.2e, |L| %.2e, E %.2e;  h 1e-4: %.2e, %.2e, %.2e; largest "
      "|phi| %.3f rad\n",
      coarse.linear, coarse.angular, coarse.energy, fine.linear, fine.angular, fine.energy,
      coarse.largest_angle);
  // RK4 keeps linear invariants exactly: forces cancel at every stage, so p moves by
  // rounding only (1e-16 per step over 1e4 steps).
  EXPECT_LT(coarse.linear, 1e-12);
  // Angular momentum and energy are conserved by the exact flow only if the wrench is
  // moment-free and the exact gradient: RK4's global error is O(h^4), so the drift must be
  // small (w h = 0.02: (w h)^4 ~ 1.6e-7 before RK4's small constants) and fall by about 16
  // when h halves (>= 8 asked, for rounding and the start of the asymptotic range). A
  // moment-carrying or non-conservative element drifts at O(1) and does not fall with h.
  EXPECT_LT(coarse.angular, 1e-7);
  EXPECT_LT(coarse.energy, 1e-7);
  EXPECT_GT(coarse.angular, 8 * fine.angular);
  EXPECT_GT(coarse.energy, 8 * fine.energy);
  // With damping the momenta are still conserved (the damping wrench is a pair too).
  const Drift damped = driftOver1s(2e-4, true);
  EXPECT_LT(damped.linear, 1e-12);
  EXPECT_LT(damped.angular, 1e-7);
}

TEST(Bushing, TwoFreeBodiesTranslateOnTheReducedMass) {
  // Body B displaced by x0 along A's axis y from A's frame at A's centre: both centres of
  // mass on that axis, so the force has no moment about either; the separation oscillates at
  // w = sqrt(k (m_a + m_b) / (m_a m_b)).
  for (const auto& [ma, mb, k] : {std::tuple{1.0, 3.0, 200.0}, {1e-3, 2e-3, 1e6}, {50, 0.5, 1e4}}) {
    ModelBuilder b;
    Body a;
    a.name = "a";
    a.mass = ma;
    a.inertia = Mat3::Identity() * ma * 1e-2;
    Body c;
    c.name = "c";
    c.mass = mb;
    c.inertia = Mat3::Identity() * mb * 1e-2;
    const double x0 = 1e-3;
    c.position = Vec3(0, x0, 0);
    Bushing bushing;
    bushing.name = "link";
    bushing.body_a = b.addBody(a);
    bushing.body_b = b.addBody(c);
    bushing.stiffness = Vec3(k / 3, k, 7 * k);
    bushing.rotational_stiffness = Vec3(1, 2, 3) * k * 1e-4;
    b.addBushing(bushing);
    b.options().gravity = Vec3::Zero();
    const double w = std::sqrt(k * (ma + mb) / (ma * mb));
    b.options().time_step = 2 * kPi / w / 200;
    Simulator sim(b.build());
    double worst = 0.0;
    for (int s = 0; s < 600; ++s) {
      ASSERT_TRUE(sim.step().ok);
      const double y = sim.state().bodies[1].position.y() - sim.state().bodies[0].position.y();
      worst = std::max(worst, std::abs(y - x0 * std::cos(w * sim.state().time)));
    }
    std::printf("m_a %g, m_b %g, k %g: worst |y - x0 cos(w t)| / x0 %.2e\n", ma, mb, k, worst / x0);
    EXPECT_LT(worst, 1e-6 * x0);  // as for one body (600 RK4 steps at w h = 2 pi / 200)
  }
}

TEST(Bushing, StableStepIsThatOfTheStiffestAxis) {
  // Light (1e-3 kg) and stiff (5e6 N/m along z): RK4's undamped limit h w = 2 sqrt(2), with
  // w = sqrt(5e6 / 1e-3); the rotational axes (k_r / I = 0.05 / 2.5e-7 = 2e5) are slower.
  const Oscillator o{1e-3, {1e-7, 2e-7, 2.5e-7}, {1e6, 2e6, 5e6}, {0.01, 0.03, 0.05}};
  const auto model = bushingOnWorld(o, Quat::Identity(), Vec3::Zero(), 0, false, 0.0, 1e-6);
  const StabilityReport report = estimateStableStep(*model);
  const double expected = 2 * std::sqrt(2.0) / std::sqrt(5e6 / 1e-3);
  // The estimate bisects on the step matrix's spectral radius: 1e-6 relative.
  EXPECT_NEAR(report.limit.max_step, expected, 1e-6 * expected);
  EXPECT_NE(report.limit.element.find("bushing 'mount' along z"), std::string::npos)
      << report.limit.element;
  // The same body with a soft translation: the stiffest rotation, about z, limits.
  const Oscillator soft{1e-3, {1e-7, 2e-7, 2.5e-7}, {1, 1, 1}, {0.01, 0.03, 0.05}};
  const StabilityReport r2 = estimateStableStep(
      *bushingOnWorld(soft, Quat::Identity(), Vec3::Zero(), 0, false, 0.0, 1e-6));
  const double e2 = 2 * std::sqrt(2.0) / std::sqrt(0.05 / 2.5e-7);
  EXPECT_NEAR(r2.limit.max_step, e2, 1e-6 * e2);
  EXPECT_NE(r2.limit.element.find("bushing 'mount' about z"), std::string::npos)
      << r2.limit.element;
}

TEST(Bushing, BuilderRejectsBadInput) {
  auto error = [](const std::function<void(Bushing&)>& change) {
    ModelBuilder b;
    Body body;
    body.name = "block";
    Bushing bushing;
    bushing.name = "mount";
    bushing.body_b = b.addBody(body);
    change(bushing);
    try {
      b.addBushing(bushing);
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error([](Bushing& x) { x.stiffness = Vec3(1, -2, 3); }),
            "bushing 'mount': stiffness must be 3 finite values >= 0 (got [1, -2, 3])");
  EXPECT_EQ(error([](Bushing& x) { x.rotational_damping = Vec3(0, NAN, 0); }),
            "bushing 'mount': rotational_damping must be 3 finite values >= 0 (got [0, nan, 0])");
  EXPECT_EQ(error([](Bushing& x) { x.body_a = x.body_b; }),
            "bushing 'mount': both frames on the same body");
  EXPECT_EQ(error([](Bushing& x) { x.body_a = BodyIndex{5}; }),
            "bushing 'mount' body A: body index 5 out of range");
  EXPECT_EQ(error([](Bushing& x) { x.orientation_b = Quat(0, 0, 0, 0); }),
            "bushing 'mount': frame B orientation must be a finite, non-zero quaternion");
  EXPECT_EQ(error([](Bushing&) {}), "");
}

}  // namespace
}  // namespace tribo
