// Very stiff contacts: a 10 kg box resting on a 1e9 N/m-per-corner ground (damping ratio
// 0.95). The implicit method steps far beyond the explicit stability limit, the explicit
// adaptive one is held to the step its stability region allows (as core/stability.hpp
// predicts), and a fixed explicit step beyond the limit is stopped, naming the box.
#include <gtest/gtest.h>

#include <cmath>

#include "core/model_builder.hpp"
#include "core/simulator.hpp"
#include "core/stability.hpp"
#include "friction/friction_law.hpp"

namespace tribo {
namespace {

constexpr double kG = 9.81, kM = 10.0, kStiff = 1e9;
const double kDampingRatio = 0.95;

// Box released at rest just touching the ground (z = half height).
std::shared_ptr<const Model> stiffBox(IntegratorType integrator, double dt) {
  ModelBuilder b;
  b.options().integrator = integrator;
  b.options().time_step = dt;
  b.options().relative_tolerance = 1e-6;
  b.options().absolute_tolerance = 1e-12;
  Body box;
  box.name = "box";
  box.mass = kM;
  box.inertia = Vec3(0.0417, 0.0417, 0.0667).asDiagonal();
  box.position = Vec3(0, 0, 0.05);
  const BodyIndex ib = b.addBody(box);
  contact::Material material;
  material.normal.stiffness = kStiff;
  // Four corners share the mass: per-corner c = zeta sqrt(k m) gives damping ratio zeta.
  material.normal.damping = kDampingRatio * std::sqrt(kStiff * kM);
  material.friction = friction::makeFrictionLaw(
      {"coulomb", {{"mu", 0.3}, {"v_eps", 1e-3}}, {{"regularization", "tanh"}}});
  const int ground = b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
  const int shape = b.addGeometry("box_shape", ib, contact::Shape::box(Vec3(0.1, 0.1, 0.05)));
  b.addContactPair(ground, shape, b.addMaterial(material));
  b.addJoint("slide", JointType::kPlanarTranslation, BodyIndex::world(), ib, box.position,
             Vec3::UnitY());
  return b.build();
}

TEST(IntegratorStiff, Dopri5RealAxisStabilityBoundary) {
  // |R(x)| = 1 for R(x) = sum_{k<=5} x^k/k! + x^6/600 at x = -3.3065679 (Hairer & Wanner,
  // Solving ODEs II, Fig. IV.2.1: the DOPRI5 region reaches about -3.3).
  const double r = 1e4;
  EXPECT_NEAR(stableStep(IntegratorType::kDopri5, 0.0, r) * r, 3.3065679, 1e-6);
  EXPECT_TRUE(std::isinf(stableStep(IntegratorType::kBdf, 1e12, 0.0)));
}

TEST(IntegratorStiff, BdfSettlesTheStiffContactAtItsStaticDepthFarBeyondTheExplicitLimit) {
  const auto model = stiffBox(IntegratorType::kBdf, 0.05);
  const double rk4_limit = [&] {
    auto m = std::make_shared<Model>(*model);
    m->options.integrator = IntegratorType::kRk4;
    return estimateStableStep(*m).limit.max_step;
  }();
  Simulator sim(model);
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(sim.step().ok);  // 1 s
  const Workspace& ws = sim.current();
  ASSERT_EQ(ws.contacts.size(), 4u);
  for (const auto& c : ws.contacts)
    EXPECT_NEAR(c.point.depth, kM * kG / (4 * kStiff), 1e-4 * kM * kG / (4 * kStiff));
  EXPECT_NEAR(sim.state().bodies[0].velocity.norm(), 0.0, 1e-9);
  // An explicit method would need 1 s / limit steps; BDF takes fewer than a tenth of them.
  EXPECT_LT(sim.stats().integrator_steps, 0.1 * 1.0 / rk4_limit)
      << "steps " << sim.stats().integrator_steps << ", rk4 limit " << rk4_limit;
}

TEST(IntegratorStiff, Dopri5IsHeldToTheStepItsStabilityRegionAllows) {
  // Error control cannot buy a step beyond the stability limit: over 0.2 s the number of
  // accepted steps is close to 0.2 s / (estimated limit).
  const auto model = stiffBox(IntegratorType::kDopri5, 0.05);
  const double limit = estimateStableStep(*model).limit.max_step;
  Simulator sim(model);
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(sim.step().ok);
  const double predicted = 0.2 / limit;
  const double steps = static_cast<double>(sim.stats().integrator_steps);
  EXPECT_GT(steps, 0.5 * predicted) << "limit " << limit;
  EXPECT_LT(steps, 3.0 * predicted) << "limit " << limit;
}

TEST(IntegratorStiff, FixedExplicitStepBeyondTheLimitStopsNamingTheBox) {
  const auto model = stiffBox(IntegratorType::kRk4, 2e-3);
  ASSERT_GT(2e-3, 10 * estimateStableStep(*model).limit.max_step);
  Simulator sim(model);
  StepStatus status;
  for (int i = 0; i < 1000 && status.ok; ++i) status = sim.step();
  ASSERT_FALSE(status.ok);
  EXPECT_EQ(status.body, "box") << status.message;
  EXPECT_FALSE(status.quantity.empty()) << status.message;
  EXPECT_GT(status.time, 0.0);
  EXPECT_NE(status.message.find("t = "), std::string::npos) << status.message;
  EXPECT_TRUE(sim.state().bodies[0].position.allFinite());
  EXPECT_TRUE(sim.state().bodies[0].velocity.allFinite());
}

}  // namespace
}  // namespace tribo
