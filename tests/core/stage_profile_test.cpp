// The stage profile (core/stage_profile.hpp) of a contact scene, a box sliding on the ground
// on a planar joint: off by default and all zero; on, every stage's time is >= 0, the stages
// sum to no more than the steps' wall time, detection takes time, and every evaluation is
// counted.
#include "core/stage_profile.hpp"

#include <gtest/gtest.h>

#include <chrono>

#include "core/simulator.hpp"
#include "support/test_models.hpp"

namespace tribo {
namespace {

std::shared_ptr<const Model> slidingBox(IntegratorType integrator) {
  ModelBuilder b =
      test::boxOnGround(5.0, Vec3(0.2, 0.2, 0.1), 1.0, 0.4, 2.5e5, 1.5e3, integrator, 1e-3);
  return b.build();
}

// Wall time of n steps [s].
double stepFor(Simulator& sim, int n) {
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < n; ++i) EXPECT_TRUE(sim.step().ok);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(StageProfile, OffByDefaultAndAllZero) {
  Simulator sim(slidingBox(IntegratorType::kRk4));
  stepFor(sim, 50);
  const StageProfile& p = sim.stats().profile;
  for (std::size_t k = 0; k < kStageCount; ++k)
    EXPECT_EQ(p.seconds[k], 0.0) << stageName(static_cast<Stage>(k));
  EXPECT_EQ(p.evaluations, 0);
  EXPECT_EQ(p.fcl, 0.0);
  EXPECT_EQ(p.step, 0.0);
  EXPECT_GT(sim.stats().evaluations, 0);
}

TEST(StageProfile, StagesAreTimedWithinTheStepsAndEveryEvaluationIsCounted) {
  for (IntegratorType integrator : {IntegratorType::kRk4, IntegratorType::kSemiImplicitEuler}) {
    Simulator sim(slidingBox(integrator));
    sim.setProfiling(true);
    const double wall = stepFor(sim, 200);
    const StepStats& stats = sim.stats();
    const StageProfile& p = stats.profile;
    ASSERT_EQ(sim.current().contacts.size(), 4u);
    for (std::size_t k = 0; k < kStageCount; ++k)
      EXPECT_GE(p.seconds[k], 0.0) << stageName(static_cast<Stage>(k));
    EXPECT_GT(p[Stage::kDetect], 0.0);
    EXPECT_GT(p[Stage::kConstraints], 0.0);     // the planar joint
    EXPECT_EQ(p[Stage::kFrictionStates], 0.0);  // memoryless friction: no states to advance
    EXPECT_LE(p.total(), p.step);
    EXPECT_LE(p.step, wall);
    EXPECT_EQ(p.fcl, 0.0);  // box on a half-space: closed form, FCL never asked
    EXPECT_EQ(p.evaluations, stats.evaluations);
    EXPECT_EQ(p.evaluations, integrator == IntegratorType::kRk4 ? 4 * 200 + 1 : 200 + 1);
  }
}

TEST(StageProfile, SwitchingOnStartsFromZeroAndOffKeepsTheTotals) {
  Simulator sim(slidingBox(IntegratorType::kRk4));
  stepFor(sim, 20);
  const long before = sim.stats().evaluations;
  sim.setProfiling(true);
  stepFor(sim, 20);
  EXPECT_EQ(sim.stats().profile.evaluations, sim.stats().evaluations - before);
  sim.setProfiling(false);
  const StageProfile kept = sim.stats().profile;
  stepFor(sim, 20);
  EXPECT_EQ(sim.stats().profile.evaluations, kept.evaluations);
  EXPECT_EQ(sim.stats().profile.step, kept.step);
}

TEST(StageProfile, NamesFollowThePipeline) {
  EXPECT_EQ(stageName(Stage::kPoses), "poses");
  EXPECT_EQ(stageName(Stage::kContactKinematics), "contact_kinematics");
  EXPECT_EQ(stageName(Stage::kFrictionStates), "friction_states");
}

}  // namespace
}  // namespace tribo
