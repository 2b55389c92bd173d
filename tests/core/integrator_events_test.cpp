// Event location of the adaptive integrators at friction regime changes, against motions
// whose regime changes are known in closed form:
//   a box dragged by a belt (Roh & Yoo law, beta = 1) reaches the stick speed v_s at
//     T = ln((mu_k e^(L (v_b - v_s)) + D) / (mu_k + D)) / (L mu_k g),  L = ln a, D = mu_s - mu_k
//     (from ds/dt = -g mu(s), mu = mu_k + D a^-(s - v_s)), then its slip decays as
//     s = v_s exp(-g mu_s (t - T) / v_s);
//   a box sliding against a spring (Coulomb, tanh-regularized over 1e-6 m/s) reverses its slip at
//     t1 = atan(v0 k / (w mu m g)) / w   (harmonic motion about -mu m g / k while sliding).
#include <gtest/gtest.h>

#include <cmath>

#include "core/model_builder.hpp"
#include "core/simulator.hpp"
#include "friction/friction_law.hpp"

namespace tribo {
namespace {

constexpr double kG = 9.81, kM = 10.0, kContact = 2.5e5, kDamping = 1.5e3;
constexpr double kMuS = 0.35, kMuK = 0.3, kVs = 0.01, kA = 1.5, kVb = 1.5;

// A 0.2 x 0.2 x 0.1 m box at its static depth on the plane z = 0, sliding in the x-z plane
// without rotating. The plane belongs to a kinematic belt whose surface moves at v_b.
ModelBuilder boxOnPlane(const friction::LawSpec& law, double surface_speed, double vx) {
  ModelBuilder b;
  Body belt;
  belt.name = "belt";
  belt.kind = BodyKind::kKinematic;
  belt.surface_velocity = Vec3(surface_speed, 0, 0);
  const BodyIndex ibelt = b.addBody(belt);
  Body box;
  box.name = "box";
  box.mass = kM;
  box.inertia = Vec3(0.0417, 0.0417, 0.0667).asDiagonal();
  box.position = Vec3(0, 0, 0.05 - kM * kG / (4 * kContact));
  box.velocity = Vec3(vx, 0, 0);
  const BodyIndex ibox = b.addBody(box);
  contact::Material material;
  material.normal.stiffness = kContact;
  material.normal.damping = kDamping;
  material.friction = friction::makeFrictionLaw(law);
  const int plane = b.addGeometry("plane", ibelt, contact::Shape::halfSpace());
  const int shape = b.addGeometry("box_shape", ibox, contact::Shape::box(Vec3(0.1, 0.1, 0.05)));
  b.addContactPair(plane, shape, b.addMaterial(material));
  b.addJoint("slide", JointType::kPlanarTranslation, BodyIndex::world(), ibox, box.position,
             Vec3::UnitY());
  return b;
}

friction::LawSpec rohYooLinearRise() {
  return {"roh_yoo", {{"mu_s", kMuS}, {"mu_k", kMuK}, {"v_s", kVs}, {"a", kA}, {"beta", 1.0}}, {}};
}

TEST(IntegratorEvents, BeltDraggedBoxReachesTheStickSpeedWhenTheClosedFormSays) {
  const double lambda = std::log(kA), drop = kMuS - kMuK;
  const double t_stick = std::log((kMuK * std::exp(lambda * (kVb - kVs)) + drop) / (kMuK + drop)) /
                         (lambda * kMuK * kG);
  const double t_check = t_stick + 0.005;
  const double slip_check = kVs * std::exp(-kG * kMuS * (t_check - t_stick) / kVs);
  for (IntegratorType type : {IntegratorType::kDopri5, IntegratorType::kBdf}) {
    for (bool events : {true, false}) {
      ModelBuilder b = boxOnPlane(rohYooLinearRise(), kVb, 0.0);
      b.options().integrator = type;
      b.options().time_step = 1e-3;
      b.options().relative_tolerance = 1e-9;
      b.options().absolute_tolerance = 1e-12;
      b.options().event_location = events;
      Simulator sim(b.build());
      const std::string who = integratorName(type) + (events ? " with events" : " without");
      double first_event = NAN;
      while (sim.state().time < t_check - 1e-9) {
        const StepStatus s = sim.step();
        ASSERT_TRUE(s.ok) << who << ": " << s.message;
        if (std::isnan(first_event) && sim.stats().events > 0)
          first_event = sim.stats().last_event_time;
      }
      // Sampled at the output step nearest to t_check (1 ms grid).
      const double t = sim.state().time;
      const double slip = kVb - sim.state().bodies[1].velocity.x();
      const double expected = kVs * std::exp(-kG * kMuS * (t - t_stick) / kVs);
      EXPECT_NEAR(slip, expected, 1e-6) << who << " at t = " << t;
      EXPECT_NEAR(t, t_check, 1e-3);
      (void)slip_check;
      if (events) {
        EXPECT_NEAR(first_event, t_stick, 1e-6) << who;
      } else {
        EXPECT_EQ(sim.stats().events, 0) << who;
      }
    }
  }
}

TEST(IntegratorEvents, SlipReversalAgainstASpringIsLocated) {
  // Static ground (no surface speed), spring to the wall, thrown at v0 = 1 m/s from the
  // spring's rest position. While sliding forward: x'' = -(k/m) x - mu g.
  const double k = 400.0, mu = 0.3, v0 = 1.0, v_eps = 1e-6;
  const double w = std::sqrt(k / kM);
  const double t_reverse = std::atan(v0 * k / (w * mu * kM * kG)) / w;
  friction::LawSpec coulomb{
      "coulomb", {{"mu", mu}, {"v_eps", v_eps}}, {{"regularization", "tanh"}}};
  for (IntegratorType type : {IntegratorType::kDopri5, IntegratorType::kBdf}) {
    ModelBuilder b = boxOnPlane(coulomb, 0.0, v0);
    b.addSpring("wall", BodyIndex::world(), Vec3(-1, 0, 0.05 - kM * kG / (4 * kContact)),
                BodyIndex{1}, Vec3(0, 0, 0.05 - kM * kG / (4 * kContact)), k, 0.0, 1.0);
    b.options().integrator = type;
    b.options().time_step = 0.01;
    b.options().relative_tolerance = 1e-9;
    b.options().absolute_tolerance = 1e-12;
    Simulator sim(b.build());
    while (sim.state().time < t_reverse + 0.005) ASSERT_TRUE(sim.step().ok);
    // Three regime changes within the regularization band around the reversal: |s| falls
    // through v_eps, s reverses, |s| rises through v_eps (threshold events alone make two).
    // Inside the band the acceleration is at least k x / m - mu g = 1.1 m/s^2, so the band
    // lasts a few v_eps / (1.1 m/s^2), some 1e-6 s.
    EXPECT_GE(sim.stats().events, 3) << integratorName(type);
    EXPECT_NEAR(sim.stats().last_event_time, t_reverse, 1e-5) << integratorName(type);
  }
}

}  // namespace
}  // namespace tribo
