// Continuation steps by the return map (study/orbit/branch_return_map.hpp) against orbits
// found independently of them: the belt's stick-slip branch, each such point against the orbit
// Newton's method alone finds at its parameter, and a strongly damped forced oscillator's
// branch in the forcing frequency against the closed-form steady response. The estimated
// multipliers against the whole monodromy's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "io/scene_loader.hpp"
#include "study/orbit/orbit_branch.hpp"
#include "study/orbit/periodic_orbit.hpp"

namespace tribo {
namespace {

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";
const std::string kOscillator = std::string(TRIBO_SOURCE_DIR) + "/scenes/forced_oscillator.yaml";

std::string assign(const std::string& name, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return name + "=" + buf;
}

TEST(BranchReturnMap, TheBeltsStickSlipPointsAreNewtonsOrbitsAtTheirSpeed) {
  study::BranchSpec spec;
  spec.parameter = "v_b";
  spec.from = 1.0;
  spec.to = 1.9;
  spec.step = 0.2;
  spec.orbit.settle = 30.0;
  const study::BranchResult r = study::continueOrbit(kBelt, {}, spec);
  ASSERT_TRUE(r.reached_end) << r.stop_reason;
  int by_return_map = 0;
  for (std::size_t i = 1; i < r.points.size(); ++i) {
    const study::BranchPoint& p = r.points[i];
    if (!p.by_return_map) continue;
    ++by_return_map;
    SCOPED_TRACE("v_b " + std::to_string(p.parameter));
    // The orbit at that speed from a settling run of its own, the scene's 60 s (with the whole
    // monodromy). (Above 2 m/s the oscillation grows from steady sliding for longer than that.)
    const study::OrbitResult o =
        study::findPeriodicOrbit(io::loadScene(kBelt, {assign("v_b", p.parameter)}));
    // The same orbit (measured within 1.2e-11 in period and 4.2e-14 in amplitude).
    EXPECT_NEAR(p.period / o.period, 1.0, 1e-9);
    EXPECT_NEAR(p.amplitude_pp / o.amplitude_pp, 1.0, 1e-8);
    EXPECT_LE(p.residual, 1e-9);
    // The estimates: the trivial multiplier within the step's error of 1, as the monodromy's
    // (both 2e-4 to 7e-4 at 1 ms: the flow's error, which the two differences sample at
    // different points); the others collapsed by the stick phase, as the monodromy's (1.7e-6;
    // the estimates 1e-7 to 1e-6: both at the finite differences' resolution).
    ASSERT_GE(p.trivial, 0);
    EXPECT_LT(p.trivial_error, 1e-3);
    EXPECT_LT(o.trivial_error, 1e-3);
    EXPECT_LT(p.largest, 1e-4);
    EXPECT_LT(o.largest_multiplier, 1e-4);
    EXPECT_TRUE(p.stable);
    EXPECT_EQ(p.multipliers.size(), 3u);  // the trivial one and two leading others
  }
  // Every point after the first (the branch is stick-slip throughout).
  EXPECT_EQ(by_return_map, static_cast<int>(r.points.size()) - 1);
  EXPECT_TRUE(r.events.empty());
  // Newton's method alone draws the same branch: each of its points within 1e-6 of the return
  // map branch's amplitude, interpolated linearly between neighbours (measured 8.5e-9: the
  // two branches' points lie at the same speeds to 6 digits, the predictions being the same).
  study::BranchSpec dense = spec;
  dense.orbit.return_map = false;
  const study::BranchResult d = study::continueOrbit(kBelt, {}, dense);
  ASSERT_TRUE(d.reached_end) << d.stop_reason;
  for (const study::BranchPoint& q : d.points) {
    for (std::size_t i = 0; i + 1 < r.points.size(); ++i) {
      const study::BranchPoint &a = r.points[i], &b = r.points[i + 1];
      if (q.parameter < a.parameter || q.parameter > b.parameter) continue;
      const double s = (q.parameter - a.parameter) / (b.parameter - a.parameter);
      EXPECT_NEAR(q.amplitude_pp, a.amplitude_pp + s * (b.amplitude_pp - a.amplitude_pp),
                  1e-6 * q.amplitude_pp)
          << q.parameter;
    }
  }
}

TEST(BranchReturnMap, AStronglyDampedForcedBranchIsTheClosedFormResponse) {
  // Damping ratio 0.7: the pair of multipliers of modulus exp(-c T / 2m), 1.6e-4 to 0.03 over
  // 0.8 to 2 Hz (the guide's constraint directions contract faster).
  const double m = 1.0, k = 100.0, c = 14.0, F0 = 10.0;
  study::BranchSpec spec;
  spec.parameter = "f";
  spec.from = 0.8;
  spec.to = 2.0;
  spec.step = 0.3;
  const study::BranchResult r = study::continueOrbit(kOscillator, {assign("c", c)}, spec);
  ASSERT_TRUE(r.reached_end) << r.stop_reason;
  ASSERT_TRUE(r.forced);
  int by_return_map = 0;
  for (const study::BranchPoint& p : r.points) {
    SCOPED_TRACE("f " + std::to_string(p.parameter));
    const double w = 2 * std::numbers::pi * p.parameter;
    const double closed = 2 * F0 / std::hypot(k - m * w * w, c * w);
    EXPECT_NEAR(p.amplitude_pp / closed, 1.0, 1e-6);  // RK4 at 1 ms; measured 5.3e-10
    EXPECT_NEAR(p.period, 1.0 / p.parameter, 1e-12);
    if (!p.by_return_map) continue;
    ++by_return_map;
    EXPECT_EQ(p.trivial, -1);  // a forced orbit has none
    // The two leading multipliers: the damped pair, estimated within 10% (measured 1e-4).
    EXPECT_NEAR(p.largest / std::exp(-c * p.period / (2 * m)), 1.0, 0.1);
    EXPECT_TRUE(p.stable);
  }
  EXPECT_EQ(by_return_map, static_cast<int>(r.points.size()) - 1);
}

}  // namespace
}  // namespace tribo
