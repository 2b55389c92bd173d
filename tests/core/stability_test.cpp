// The a-priori step limit against the integrators' known stability boundaries, and against
// what actually happens when the model is stepped just below and just above it.
#include "core/stability.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/simulator.hpp"
#include "test_models.hpp"

namespace tribo {
namespace {

TEST(StableStep, MatchesKnownBoundariesOfTheUndampedOscillator) {
  const double w = 50.0;
  // RK4 on the imaginary axis: |z| <= 2 sqrt(2); semi-implicit Euler: h w <= 2.
  EXPECT_NEAR(stableStep(IntegratorType::kRk4, w * w, 0.0) * w, 2 * std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(stableStep(IntegratorType::kSemiImplicitEuler, w * w, 0.0) * w, 2.0, 1e-6);
}

TEST(StableStep, PureDecayMatchesTheRealAxisBoundary) {
  // v' = -r v: explicit Euler h r <= 2; RK4 h r <= 2.785293563 (root of 1+z+z^2/2+z^3/6+z^4/24 =
  // 1).
  const double r = 1e4;
  EXPECT_NEAR(stableStep(IntegratorType::kSemiImplicitEuler, 0.0, r) * r, 2.0, 1e-6);
  EXPECT_NEAR(stableStep(IntegratorType::kRk4, 0.0, r) * r, 2.785293563, 1e-6);
}

TEST(StabilityEstimate, NamesTheStiffestElementAndPredictsTheContactLimit) {
  const double m = 1.0, k = 1e6;
  ModelBuilder b = test::boxOnGround(m, Vec3(0.2, 0.2, 0.1), 0.0, 0.3, k, 0.0, IntegratorType::kRk4,
                                     1e-3, -0.05);
  const auto model = b.build();
  const StabilityReport report = estimateStableStep(*model);
  EXPECT_NE(report.limit.element.find("contact pair (ground, box_shape)"), std::string::npos)
      << report.limit.element;
  const double w = std::sqrt(4 * k / m);
  // The coulomb tanh law (v_eps 1e-4) is stiffer than the contact: g mu / v_eps = 29430/s.
  EXPECT_LT(report.limit.max_step, 2 * std::sqrt(2.0) / w);
  EXPECT_NE(report.limit.element.find("friction"), std::string::npos);
}

TEST(StabilityEstimate, UndampedContactBouncesStablyBelowAndBlowsUpAboveTheLimit) {
  // Frictionless box dropped on the ground with no contact damping: energy conserving, so
  // the bounce height must stay bounded below the limit and grow above it.
  const double m = 1.0, k = 1e6;
  auto run = [&](double h) {
    ModelBuilder b =
        test::boxOnGround(m, Vec3(0.2, 0.2, 0.1), 0.0, 0.0, k, 0.0, IntegratorType::kRk4, h, -0.5);
    Simulator sim(b.build());
    double vmax = 0;
    for (int i = 0; i < std::lround(0.5 / h); ++i) {
      if (!sim.step().ok) return std::numeric_limits<double>::infinity();
      vmax = std::max(vmax, sim.state().bodies[0].velocity.norm());
    }
    return vmax;
  };
  ModelBuilder probe =
      test::boxOnGround(m, Vec3(0.2, 0.2, 0.1), 0.0, 0.0, k, 0.0, IntegratorType::kRk4, 1e-3);
  const double limit = estimateStableStep(*probe.build()).limit.max_step;
  EXPECT_NEAR(limit * std::sqrt(4 * k / m), 2 * std::sqrt(2.0), 1e-6);
  EXPECT_LT(run(0.5 * limit), 0.51);  // never faster than the impact speed (plus gravity)
  EXPECT_GT(run(1.2 * limit), 1.0);   // energy grows without a source
}

}  // namespace
}  // namespace tribo
