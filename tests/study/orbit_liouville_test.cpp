// The planar belt oscillator's non-trivial Floquet multiplier against Liouville's formula.
// For a planar autonomous system y' = f(y) the product of the two multipliers of a periodic
// orbit is exp(integral over the period of tr(df/dy)) (Liouville; e.g. Seydel, "Practical
// Bifurcation and Stability Analysis", 3rd ed., Springer 2010, sec. 7.4), and one of them is
// the trivial 1, so the other is that exponential. The belt scene reduced to its sliding
// coordinate, m x'' = -k x - c x' + mu(v_b - x') m g, has
//   tr(df/dy) = -c / m - g mu'(v_b - x'),
// which the test integrates (trapezoids) along each orbit the engine returns: x' by central
// differences of the orbit's own samples, mu' the law's slope. The engine's multipliers come
// from finite differences of its full three-dimensional flow (a box on four penalty corners
// with its contact and pitch modes, which collapse to near zero): its largest non-trivial one
// must be the planar formula's.
// The orbits: the damped Stribeck belt (smooth law, 10 N s/m damper) from its subcritical Hopf
// point, pure sliding all along: unstable cycles (multiplier above 1) growing to the fold of
// cycles, where the multiplier passes 1, and the stable ones after it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "friction/friction_law.hpp"
#include "study/orbit/orbit_branch.hpp"

namespace tribo {
namespace {

TEST(OrbitLiouville, TheBeltsNonTrivialMultiplierIsTheExponentialOfTheTracesIntegral) {
  const double m = 10.0, c = 10.0, g = 9.81;
  const auto law = friction::makeFrictionLaw(
      {"stribeck", {{"mu_s", 0.35}, {"mu_k", 0.3}, {"v_st", 0.15}, {"v_eps", 0.01}}, {}});
  study::BranchSpec spec;
  spec.parameter = "v_b";
  spec.from = 0.15;
  spec.to = 0.5;
  spec.from_hopf = true;
  spec.step = 0.01;
  spec.max_points = 12;
  const study::BranchResult r =
      study::continueOrbit(std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml",
                           {"friction=stribeck", "springs[wall_spring].damping=10"}, spec);
  ASSERT_GE(r.points.size(), 10u) << r.stop_reason;
  int above = 0, below = 0;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const study::BranchPoint& p = r.points[i];
    SCOPED_TRACE("point " + std::to_string(i) + ", v_b " + std::to_string(p.parameter));
    const std::vector<double>&t = p.t, &x = p.x;
    ASSERT_GE(t.size(), 100u);
    const std::size_t n = t.size();
    auto velocity = [&](std::size_t k) {
      if (k == 0) return (x[1] - x[0]) / (t[1] - t[0]);
      if (k + 1 == n) return (x[n - 1] - x[n - 2]) / (t[n - 1] - t[n - 2]);
      return (x[k + 1] - x[k - 1]) / (t[k + 1] - t[k - 1]);
    };
    auto trace = [&](std::size_t k) { return -c / m - g * law->slope(p.parameter - velocity(k)); };
    double integral = 0.0;
    for (std::size_t k = 0; k + 1 < n; ++k)
      integral += 0.5 * (trace(k) + trace(k + 1)) * (t[k + 1] - t[k]);
    const double liouville = std::exp(integral);
    // The engine's largest non-trivial multiplier: real (a planar orbit's are).
    std::complex<double> largest = 0.0;
    for (std::size_t j = 0; j < p.multipliers.size(); ++j)
      if (static_cast<int>(j) != p.trivial && std::abs(p.multipliers[j]) > std::abs(largest))
        largest = p.multipliers[j];
    EXPECT_NEAR(largest.imag(), 0.0, 1e-9);
    // Measured within 7e-8 (at the Hopf point) to 1.2e-4 (the largest, stable cycle, whose
    // slowest sliding reaches the law's steep part, where the samples' differences err most).
    EXPECT_NEAR(largest.real() / liouville, 1.0, 5e-4) << largest << " vs " << liouville;
    (liouville > 1.0 ? above : below) += 1;
  }
  // Unstable cycles from the Hopf point, the multiplier through 1 at the fold, stable after.
  EXPECT_GE(above, 3);
  EXPECT_GE(below, 2);
}

}  // namespace
}  // namespace tribo
