// Round shapes resting on round shapes through the whole engine (the closed forms of
// contact/round_contacts.hpp, the linear penalty law, RK4 at 1 ms): a capsule lying along a
// fixed capsule with a partial overlap is held at the two ends of the overlap by the lever
// rule's loads, and a sphere in the groove between two parallel fixed capsules sinks to the
// height the force balance 2 k d cos(alpha) = m g gives, solved in the test by bisection.
// Sizes from a centimetre to a metre, masses from 10 g to 100 kg.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/model_builder.hpp"
#include "core/simulator.hpp"
#include "friction/friction_law.hpp"

namespace tribo {
namespace {

constexpr double kG = 9.81;

int material(ModelBuilder& b, double k, double c) {
  contact::Material m;
  m.normal = {contact::NormalLawType::kLinear, k, c};
  m.friction = friction::makeFrictionLaw({"coulomb", {{"mu", 0.5}, {"v_eps", 1e-3}}, {}});
  return b.addMaterial(m);
}

// Lying along x: a capsule's local z turned onto the world x axis.
Eigen::Isometry3d lyingAt(const Vec3& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitY()).toRotationMatrix();
  t.translation() = p;
  return t;
}

Body dynamicBody(const char* name, double m, double size, const Vec3& p) {
  Body body;
  body.name = name;
  body.mass = m;
  body.inertia = Mat3::Identity() * m * size * size / 5;
  body.position = p;
  return body;
}

TEST(RoundResting, ACapsuleLyingAlongAnotherCarriesTheLeverRuleLoadsAtTheOverlapsEnds) {
  struct Case {
    double scale, m;
  };
  for (const Case c : {Case{0.05, 0.01}, Case{1.0, 1.0}, Case{2.0, 100.0}}) {
    // Fixed capsule A: half length 0.3 s along x at the origin; capsule B: half length 0.2 s,
    // centre at x = 0.2 s, so the overlap runs from x = 0 to 0.3 s and B's centre of mass
    // is at 2/3 of it: loads m g / 3 at x = 0 and 2 m g / 3 at x = 0.3 s.
    const double s = c.scale, r = 0.05 * s;
    const double k = 1e5 * c.m / s, damping = 2.0 * std::sqrt(k * c.m);
    ModelBuilder b;
    b.options().integrator = IntegratorType::kRk4;
    b.options().time_step = 1e-4 * std::sqrt(s);
    const int mat = material(b, k, damping);
    const int a = b.addGeometry("rail", BodyIndex::world(), contact::Shape::capsule(r, 0.3 * s),
                                lyingAt(Vec3::Zero()));
    const double mean_depth = c.m * kG / (2 * k);
    const BodyIndex ib =
        b.addBody(dynamicBody("log", c.m, s, Vec3(0.2 * s, 0, 2 * r - mean_depth)));
    const int top =
        b.addGeometry("log_shape", ib, contact::Shape::capsule(r, 0.2 * s), lyingAt(Vec3::Zero()));
    b.addContactPair(a, top, mat);
    Simulator sim(b.build());
    const long steps = std::lround(0.5 * std::sqrt(s) / b.options().time_step);
    for (long i = 0; i < steps; ++i) ASSERT_TRUE(sim.step().ok) << "scale " << s;
    const auto& contacts = sim.current().contacts;
    ASSERT_EQ(contacts.size(), 2U) << "scale " << s << ": the two ends of the overlap";
    double near = 0, far = 0, total = 0;
    for (const auto& rec : contacts) {
      const double x = rec.point.position.x();
      total += rec.force().z();
      // The points sit midway between the surfaces along a normal tilted by B's small pitch:
      // within r times the pitch (about 1e-5 s) of the overlap's ends.
      if (std::abs(x) < 1e-3 * s) near = rec.force().z();
      if (std::abs(x - 0.3 * s) < 1e-3 * s) far = rec.force().z();
    }
    const double w = c.m * kG;
    std::printf("scale %g, m %g: loads %.9g and %.9g of m g (1/3, 2/3), total %.12g\n", s, c.m,
                near / w, far / w, total / w);
    EXPECT_NEAR(total / w, 1.0, 1e-6);
    EXPECT_NEAR(near / w, 1.0 / 3.0, 1e-4);
    EXPECT_NEAR(far / w, 2.0 / 3.0, 1e-4);
    EXPECT_LT(sim.state().bodies[ib.value].velocity.norm(), 1e-6 * std::sqrt(kG * s));
  }
}

// Height of a sphere (radius rs, mass m) resting on two parallel horizontal capsules (radius
// rc, axes at y = +-w, z = 0), each contact a linear spring k along the line of centres:
// with L = rs + rc - d the centre distance and sin(alpha) = w / L, the balance is
// 2 k d cos(alpha) = m g; solved for d by bisection, independent of the engine.
double grooveHeight(double rs, double rc, double w, double m, double k) {
  double lo = 0.0, hi = 0.5 * (rs + rc - w);
  for (int i = 0; i < 200; ++i) {
    const double d = 0.5 * (lo + hi);
    const double len = rs + rc - d;
    const double cos_a = std::sqrt(1.0 - (w / len) * (w / len));
    (2 * k * d * cos_a < m * kG ? lo : hi) = d;
  }
  const double len = rs + rc - 0.5 * (lo + hi);
  return std::sqrt(len * len - w * w);
}

TEST(RoundResting, ASphereInTheGrooveOfTwoCapsulesSinksToTheForceBalancesHeight) {
  struct Case {
    double rs, m;
  };
  for (const Case c : {Case{0.01, 0.01}, Case{0.2, 2.0}, Case{1.0, 100.0}}) {
    const double rc = 0.5 * c.rs, w = 0.8 * c.rs;
    const double k = 1e4 * c.m / c.rs, damping = 2.0 * std::sqrt(k * c.m);
    ModelBuilder b;
    b.options().integrator = IntegratorType::kRk4;
    // The regularized law's slope mu N / v_eps on rolling along the groove gives an eigenvalue
    // of about -2e4 1/s at every size here (mu N / v_eps (1/m + r^2/I)); RK4 is stable below
    // 2.78 / 2e4 s, so one step for all sizes (2e-4 sqrt(r) at r = 1 grew a rolling motion).
    b.options().time_step = 2e-5;
    const int mat = material(b, k, damping);
    const int left = b.addGeometry("left", BodyIndex::world(),
                                   contact::Shape::capsule(rc, 3 * c.rs), lyingAt(Vec3(0, -w, 0)));
    const int right = b.addGeometry("right", BodyIndex::world(),
                                    contact::Shape::capsule(rc, 3 * c.rs), lyingAt(Vec3(0, w, 0)));
    const double height = grooveHeight(c.rs, rc, w, c.m, k);
    const BodyIndex ib = b.addBody(dynamicBody("ball", c.m, c.rs, Vec3(0.3 * c.rs, 0, height)));
    const int ball = b.addGeometry("ball_shape", ib, contact::Shape::sphere(c.rs));
    b.addContactPair(left, ball, mat);
    b.addContactPair(ball, right, mat);  // either order of the pair
    Simulator sim(b.build());
    const long steps = std::lround(0.5 * std::sqrt(c.rs) / b.options().time_step);
    for (long i = 0; i < steps; ++i) ASSERT_TRUE(sim.step().ok) << "radius " << c.rs;
    const Vec3 p = sim.state().bodies[ib.value].position;
    std::printf("sphere r %g, m %g: height %.12g against %.12g, y %.3g\n", c.rs, c.m, p.z(), height,
                p.y());
    EXPECT_EQ(sim.current().contacts.size(), 2U);
    EXPECT_NEAR(p.z(), height, 1e-9 * c.rs);
    EXPECT_NEAR(p.y(), 0.0, 1e-9 * c.rs);
    EXPECT_NEAR(p.x(), 0.3 * c.rs, 1e-9 * c.rs);  // nothing pushes it along the groove
  }
}

}  // namespace
}  // namespace tribo
