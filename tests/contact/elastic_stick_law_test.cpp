// The stateful elastic_stick law: the property tests every law passes (zero force without
// load, odd symmetry, bounded by mu_s F_n, continuity of the stuck branch), and its state
// machine: stuck below the static limit, breaking away above it, sliding at mu_k F_n
// against the slip, re-sticking when the slip stops or turns.
#include "friction/elastic_stick_law.hpp"

#include <gtest/gtest.h>

#include <random>

namespace tribo::friction {
namespace {

using Eigen::Vector3d;

const ElasticStickParams kParams{
    .mu_s = 0.35, .mu_k = 0.3, .stiffness = 1e5, .damping = 50.0, .stick_speed = 1e-4};

StickView stuck(const Vector3d& u) { return {true, false, u}; }
StickView sliding(const Vector3d& u) { return {true, true, u}; }

TEST(ElasticStick, FactoryBuildsItAndChecksItsKeys) {
  const auto law =
      makeFrictionLaw({"elastic_stick", {{"mu_s", 0.35}, {"mu_k", 0.3}, {"stiffness", 1e5}}, {}});
  EXPECT_TRUE(law->stateful());
  EXPECT_EQ(law->name(), "elastic_stick");
  EXPECT_THROW(
      makeFrictionLaw({"elastic_stick", {{"mu_s", 0.2}, {"mu_k", 0.3}, {"stiffness", 1e5}}, {}}),
      FrictionParameterError);
  EXPECT_THROW(makeFrictionLaw({"elastic_stick", {{"mu_s", 0.3}, {"mu_k", 0.3}}, {}}),
               FrictionParameterError);  // stiffness missing
  EXPECT_THROW(
      makeFrictionLaw(
          {"elastic_stick", {{"mu_s", 0.3}, {"mu_k", 0.3}, {"stiffness", 1e5}, {"v_s", 1}}, {}}),
      FrictionParameterError);  // unknown key
  EXPECT_EQ(knownStatefulFrictionLaws(), std::vector<std::string>{"elastic_stick"});
}

TEST(ElasticStick, PropertiesOnRandomStates) {
  const ElasticStickLaw law(kParams);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const Vector3d slip(u(rng) * 0.01, u(rng) * 0.01, 0.0);
    const Vector3d e(u(rng) * 2e-5, u(rng) * 2e-5, 0.0);
    const double fn = 10.0 * (1.0 + u(rng));
    for (const StickView& view : {stuck(e), sliding(e)}) {
      double mu = -1.0;
      const Vector3d f = law.stickForce(slip, fn, view, &mu);
      EXPECT_LE(f.norm(), kParams.mu_s * fn * (1 + 1e-12));  // bounded
      EXPECT_NEAR(mu, f.norm() / fn, 1e-12);
      EXPECT_TRUE(f.isZero(0) || std::abs(f.z()) < 1e-15);  // stays in the tangent plane
      // Odd: mirrored slip and elongation give the mirrored force.
      const Vector3d g =
          law.stickForce(-slip, fn, {view.anchored, view.sliding, -view.elongation}, nullptr);
      EXPECT_TRUE((f + g).isZero(1e-12 * (1 + f.norm())));
      // No force without load.
      EXPECT_TRUE(law.stickForce(slip, 0.0, view, nullptr).isZero(0));
      // Dissipative when sliding: the force opposes the slip; a sliding contact whose slip
      // has turned against its sliding direction (the dragged anchor) has stopped within the
      // step and feels its anchored spring, the stuck branch.
      if (view.sliding && slip.dot(e) >= 0.0) {
        EXPECT_LE(f.dot(slip), 0.0);
      } else if (view.sliding) {
        EXPECT_TRUE(f.isApprox(law.stickForce(slip, fn, stuck(e), nullptr), 1e-15));
      }
    }
  }
}

TEST(ElasticStick, StuckBranchIsTheSpringDamperUpToTheStaticLimit) {
  const ElasticStickLaw law(kParams);
  const double fn = 10.0;
  // Below the limit: exactly -k u - c s.
  const Vector3d u(2e-5, -1e-5, 0.0), s(1e-3, 0.0, 0.0);
  EXPECT_TRUE(law.stickForce(s, fn, stuck(u), nullptr)
                  .isApprox(-kParams.stiffness * u - kParams.damping * s, 1e-15));
  // Just above mu_s F_n / k: breaks away at mu_k F_n along the spring.
  const Vector3d far(1.01 * kParams.mu_s * fn / kParams.stiffness, 0.0, 0.0);
  const Vector3d f = law.stickForce(Vector3d::Zero(), fn, stuck(far), nullptr);
  EXPECT_NEAR(f.norm(), kParams.mu_k * fn, 1e-12);
  EXPECT_LT(f.x(), 0.0);
}

TEST(ElasticStick, ModeChangesAfterAStep) {
  const ElasticStickLaw law(kParams);
  const double fn = 10.0, hold = kParams.mu_k * fn / kParams.stiffness;
  // Stuck and loaded below the limit: keeps its elongation.
  const Vector3d u(1e-5, 0, 0);
  StickUpdate up = law.advance(Vector3d::Zero(), fn, stuck(u));
  EXPECT_FALSE(up.sliding);
  EXPECT_TRUE(up.elongation.isApprox(u));
  // Overloaded: slides, anchor dragged to hold mu_k F_n along the slip.
  up = law.advance(Vector3d(0.2, 0, 0), fn, stuck(Vector3d(4e-5, 0, 0)));
  EXPECT_TRUE(up.sliding);
  EXPECT_TRUE(up.elongation.isApprox(Vector3d(hold, 0, 0)));
  // Sliding on: the anchor follows the slip direction.
  up = law.advance(Vector3d(0, 0.5, 0), fn, sliding(Vector3d(hold, 0, 0)));
  EXPECT_TRUE(up.sliding);
  EXPECT_TRUE(up.elongation.isApprox(Vector3d(0, hold, 0)));
  // The slip turned against the spring (the body stopped within the step): re-sticks,
  // holding at most the kinetic force.
  up = law.advance(Vector3d(-1e-3, 0, 0), fn, sliding(Vector3d(2 * hold, 0, 0)));
  EXPECT_FALSE(up.sliding);
  EXPECT_NEAR(up.elongation.norm(), hold, 1e-18);
  // Slower than stick_speed: re-sticks too.
  up = law.advance(Vector3d(5e-5, 0, 0), fn, sliding(Vector3d(hold, 0, 0)));
  EXPECT_FALSE(up.sliding);
  // No load: relaxed and stuck.
  up = law.advance(Vector3d(1, 0, 0), 0.0, sliding(Vector3d(hold, 0, 0)));
  EXPECT_FALSE(up.sliding);
  EXPECT_TRUE(up.elongation.isZero(0));
}

TEST(ElasticStick, MemorylessCurveIsTheKineticBranch) {
  const ElasticStickLaw law(kParams);
  EXPECT_EQ(law.coefficient(0.3), 0.3);
  EXPECT_EQ(law.coefficient(-0.3), -0.3);
  EXPECT_EQ(law.coefficient(0.0), 0.0);
  EXPECT_EQ(law.maxCoefficient(1.0), 0.35);
}

}  // namespace
}  // namespace tribo::friction
