// The stop request inside a step: an adaptive integrator (bdf, dopri5) abandons a long step
// within one force evaluation of the request, returns interrupted with the state of the
// step's start, and a later step from there gives the uninterrupted result bit for bit.
// Fixed-step integrators finish their step (the caller checks between steps). The request
// is raised deterministically from inside the step, by a friction law that counts its calls.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "core/model_builder.hpp"
#include "core/simulator.hpp"
#include "friction/friction_law.hpp"

namespace tribo {
namespace {

// Regularized Coulomb that raises `stop` at its `trigger`-th call.
class TriggeringLaw final : public friction::FrictionLaw {
 public:
  TriggeringLaw(std::atomic<bool>* stop, long trigger)
      : inner_(friction::makeFrictionLaw(
            {"coulomb", {{"mu", 0.3}, {"v_eps", 1e-3}}, {{"regularization", "tanh"}}})),
        stop_(stop),
        trigger_(trigger) {}
  double coefficient(double v) const override {
    if (++calls_ == trigger_ && stop_) *stop_ = true;
    return inner_->coefficient(v);
  }
  double slope(double v) const override { return inner_->slope(v); }
  double maxCoefficient(double v) const override { return inner_->maxCoefficient(v); }
  double stickSpeed() const override { return inner_->stickSpeed(); }
  std::vector<double> breakpoints() const override { return inner_->breakpoints(); }
  std::string_view name() const override { return "coulomb"; }
  long calls() const { return calls_; }

 private:
  std::unique_ptr<const friction::FrictionLaw> inner_;
  std::atomic<bool>* stop_;
  long trigger_;
  mutable std::atomic<long> calls_{0};
};

// A 10 kg box on a stiff ground (1e7 N/m a corner), sliding at 1 m/s, held in the x-z plane:
// one step of `dt` takes the adaptive methods many internal steps.
std::shared_ptr<const Model> slidingBox(IntegratorType integrator, double dt,
                                        std::shared_ptr<const friction::FrictionLaw> law) {
  ModelBuilder b;
  b.options().integrator = integrator;
  b.options().time_step = dt;
  b.options().duration = 100.0;
  Body box;
  box.name = "box";
  box.mass = 10.0;
  box.inertia = Vec3(0.0417, 0.0417, 0.0667).asDiagonal();
  box.position = Vec3(0, 0, 0.05 - 10.0 * 9.81 / (4 * 1e7));
  box.velocity = Vec3(1.0, 0, 0);
  const BodyIndex ib = b.addBody(box);
  contact::Material material;
  material.normal.stiffness = 1e7;
  material.normal.damping = 0.95 * std::sqrt(1e7 * 10.0);
  material.friction = std::move(law);
  const int ground = b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
  const int shape = b.addGeometry("box_shape", ib, contact::Shape::box(Vec3(0.1, 0.1, 0.05)));
  b.addContactPair(ground, shape, b.addMaterial(material));
  b.addJoint("slide", JointType::kPlanarTranslation, BodyIndex::world(), ib, box.position,
             Vec3::UnitY());
  return b.build();
}

void expectSameState(const State& a, const State& b) {
  ASSERT_EQ(a.time, b.time);
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    EXPECT_EQ(a.bodies[i].position, b.bodies[i].position);
    EXPECT_EQ(a.bodies[i].velocity, b.bodies[i].velocity);
    EXPECT_EQ(a.bodies[i].orientation.coeffs(), b.bodies[i].orientation.coeffs());
    EXPECT_EQ(a.bodies[i].angular_velocity, b.bodies[i].angular_velocity);
  }
}

class IntegratorStop : public ::testing::TestWithParam<IntegratorType> {};

TEST_P(IntegratorStop, AnAdaptiveStepEndsWithinOneEvaluationOfTheRequestAtItsStart) {
  const IntegratorType method = GetParam();
  // The uninterrupted reference: one step of 0.5 s, then one more.
  Simulator reference(slidingBox(method, 0.5, std::make_shared<TriggeringLaw>(nullptr, -1)));
  ASSERT_TRUE(reference.step().ok);
  const State after_one = reference.state();
  ASSERT_TRUE(reference.step().ok);
  const long reference_evaluations = reference.stats().evaluations;
  ASSERT_GT(reference_evaluations, 400) << "the step must be long for the test to mean much";

  for (const long trigger : {60L, 300L}) {
    std::atomic<bool> stop{false};
    auto law = std::make_shared<TriggeringLaw>(&stop, trigger);
    Simulator sim(slidingBox(method, 0.5, law));
    sim.setStopRequest(&stop);
    const State start = sim.state();
    const StepStatus status = sim.step();
    ASSERT_TRUE(stop.load());
    EXPECT_FALSE(status.ok);
    EXPECT_TRUE(status.interrupted);
    EXPECT_EQ(status.quantity, "interrupted");
    EXPECT_NE(status.message.find("interrupted at t = "), std::string::npos) << status.message;
    // At most the rest of the evaluation that raised it: four corners, one call each.
    EXPECT_LE(law->calls() - trigger, 3) << "calls after the request";
    EXPECT_EQ(sim.stats().steps, 0);
    expectSameState(sim.state(), start);
    // Cleared, the run goes on from the step's start as if nothing had happened.
    stop = false;
    ASSERT_TRUE(sim.step().ok);
    expectSameState(sim.state(), after_one);
  }
}

INSTANTIATE_TEST_SUITE_P(Adaptive, IntegratorStop,
                         ::testing::Values(IntegratorType::kBdf, IntegratorType::kDopri5),
                         [](const auto& info) {
                           return info.param == IntegratorType::kBdf ? "bdf" : "dopri5";
                         });

TEST(IntegratorStopFixed, AFixedStepFinishesItsStepWhateverTheRequest) {
  for (const IntegratorType method : {IntegratorType::kRk4, IntegratorType::kSemiImplicitEuler}) {
    Simulator reference(slidingBox(method, 1e-4, std::make_shared<TriggeringLaw>(nullptr, -1)));
    std::atomic<bool> stop{true};
    Simulator sim(slidingBox(method, 1e-4, std::make_shared<TriggeringLaw>(nullptr, -1)));
    sim.setStopRequest(&stop);
    for (int i = 0; i < 10; ++i) {
      ASSERT_TRUE(reference.step().ok);
      const StepStatus status = sim.step();
      ASSERT_TRUE(status.ok);
      EXPECT_FALSE(status.interrupted);
    }
    expectSameState(sim.state(), reference.state());
  }
}

}  // namespace
}  // namespace tribo
