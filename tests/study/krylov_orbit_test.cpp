// Matrix-free shooting (OrbitSolver::kKrylov, study/orbit/krylov.hpp) against independent
// expectations: on n belt oscillators in parallel lanes joined by bushings
// (tests/support/belt_lanes.hpp) the orbit is the in-phase motion, which is the single belt's
// stick-slip cycle of the paper's one-degree-of-freedom model integrated by hand
// (tests/study/one_dof_cycle.hpp), at 12 to 120 unknowns; Krylov and dense shooting solve the
// same equations, so they agree on the orbit to Newton's tolerance and on the leading
// multipliers; the forced linear oscillator's multipliers exp(-c T / 2m) come out of Arnoldi;
// and the leading multipliers are the largest of the dense set.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>

#include "io/scene_loader.hpp"
#include "one_dof_cycle.hpp"
#include "study/orbit/periodic_orbit.hpp"
#include "support/belt_lanes.hpp"

namespace tribo {
namespace {

study::OrbitResult shoot(const std::string& yaml, study::OrbitSolver solver) {
  study::OrbitSpec spec;
  spec.solver = solver;
  return study::findPeriodicOrbit(io::loadSceneFromString(yaml, "lanes.yaml"), spec);
}

class KrylovLanes : public ::testing::TestWithParam<int> {};

TEST_P(KrylovLanes, FindTheSingleBeltsCycleInPhase) {
  const int lanes = GetParam();
  const study::OrbitResult r = shoot(test::beltLanes(lanes), study::OrbitSolver::kAuto);
  EXPECT_EQ(r.solver, lanes * 12 >= study::kKrylovFromUnknowns ? "krylov" : "dense");
  const ReferenceCycle ref = oneDofCycle(10.0, 1.5);
  // The engine's belt follows the 1-DOF model to 1e-3 (periodic_orbit_test's BeltOrbit).
  EXPECT_NEAR(r.period / ref.period, 1.0, 1e-3);
  EXPECT_NEAR(r.amplitude_pp / ref.amplitude_pp, 1.0, 1e-3);
  EXPECT_LE(r.residual, 1e-9);
  ASSERT_GE(r.trivial, 0);
  EXPECT_LT(r.trivial_error, 1e-3);
  EXPECT_TRUE(r.stable);
  // Every lane moves with the first: the start state repeats per box.
  for (int i = 1; i < lanes; ++i)
    EXPECT_NEAR(r.start[12 * i], r.start[0], 1e-7) << "box" << i << ".x";
}

INSTANTIATE_TEST_SUITE_P(Lanes, KrylovLanes, ::testing::Values(1, 4, 10));

TEST(KrylovOrbit, AgreesWithDenseShootingOnTheOrbitAndItsLeadingMultipliers) {
  const std::string yaml = test::beltLanes(3);
  const study::OrbitResult dense = shoot(yaml, study::OrbitSolver::kDense);
  const study::OrbitResult krylov = shoot(yaml, study::OrbitSolver::kKrylov);
  EXPECT_EQ(krylov.solver, "krylov");
  EXPECT_NEAR(krylov.period, dense.period, 1e-9 * dense.period);
  EXPECT_NEAR(krylov.amplitude_pp, dense.amplitude_pp, 1e-8);
  EXPECT_EQ(krylov.multipliers.size(), 8u);
  EXPECT_EQ(dense.multipliers.size(), 36u);
  // The trivial multiplier: its error is the step's (1.8e-4); the two estimates of it differ
  // by the finite differences' error.
  EXPECT_NEAR(std::abs(krylov.multipliers[static_cast<std::size_t>(krylov.trivial)] -
                       dense.multipliers[static_cast<std::size_t>(dense.trivial)]),
              0.0, 1e-5);
  EXPECT_EQ(krylov.stable, dense.stable);
  // Krylov costs fewer flows than the dense Jacobian's 2 (n + 1) per iteration.
  EXPECT_LT(krylov.flows, dense.flows);
}

TEST(KrylovOrbit, ArnoldiGivesTheForcedOscillatorsMultipliers) {
  const std::string scene = std::string(TRIBO_SOURCE_DIR) + "/scenes/forced_oscillator.yaml";
  study::OrbitSpec spec;
  spec.solver = study::OrbitSolver::kKrylov;
  const study::OrbitResult r = study::findPeriodicOrbit(io::loadScene(scene), spec);
  // m = 1, k = 100, c = 2, F0 = 10, f = 1.2 Hz in the scene.
  const double w = 2 * std::acos(-1.0) * 1.2;
  EXPECT_NEAR(r.amplitude_pp, 2 * 10 / std::hypot(100 - w * w, 2 * w), 1e-6);
  const double slide = std::exp(-2 * r.period / 2);
  EXPECT_NEAR(std::abs(r.multipliers[0]), slide, 1e-6);
  EXPECT_NEAR(std::abs(r.multipliers[1]), slide, 1e-6);
  EXPECT_LT(std::abs(r.multipliers[2]), 1e-6);
}

}  // namespace
}  // namespace tribo
