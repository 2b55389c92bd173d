// The scaled arclength norm of a continuation (study/orbit/orbit_branch.hpp, BranchSpec::norm):
// each unknown over its own scale, so that the branch does not depend on the units the
// parameter is given in. The independent expectation is that invariance itself: the belt's
// speed given in mm/s (a parameter `d_c`, v_b = d_c / 1000) must give the same points, p times
// 1000, as v_b in m/s, with the same events. And the physics at the default step: the damped
// Stribeck belt's fold of cycles and its subcritical Hopf point, whose speed is the closed
// form of tests/study/stribeck_hopf.hpp, found with no --step chosen for the units (with the
// SI norm and its default step the mm/s branch is lost at the fold: docs/orbits.md).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "stribeck_hopf.hpp"
#include "study/orbit/orbit_branch.hpp"

namespace tribo {
namespace {

using study::BranchEventKind;
using study::BranchPoint;

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";
const std::string kMilliSpeed = "v_b=$d_c / 1000";

struct Twin {
  study::BranchResult si_units, milli;  // v_b in m/s, and d_c = 1000 v_b in mm/s
};

// The same branch in v_b and in d_c = 1000 v_b (the belt's rate_state critical slip distance,
// which roh_yoo and stribeck do not read, given this new use), both with the scaled norm.
study::BranchSpec scaledSpec(const std::string& parameter, double from, double to, int max_points) {
  study::BranchSpec spec;
  spec.norm = study::ArclengthNorm::kScaled;
  spec.parameter = parameter;
  spec.from = from;
  spec.to = to;
  spec.max_points = max_points;
  spec.orbit.settle = 30.0;
  return spec;
}

Twin twin(std::vector<std::string> overrides, double from, double to, int max_points) {
  Twin t;
  t.si_units = study::continueOrbit(kBelt, overrides, scaledSpec("v_b", from, to, max_points));
  overrides.insert(overrides.end(), kMilliSpeed);
  t.milli =
      study::continueOrbit(kBelt, overrides, scaledSpec("d_c", 1000 * from, 1000 * to, max_points));
  return t;
}

// Point by point: the parameter times 1000, the same period, amplitude and arclength (measured
// within 5e-11, 2e-9 at a 0.3 mm orbit beside a Hopf point: rounding of the two flows); the
// tangent's dp/ds times 1000 (measured within 1e-9 of the range, 4e-4 beside the Hopf point,
// where the branch turns and dp/ds passes 0); events at the same points, located at the
// parameter times 1000 (measured within 1.1e-8).
void expectSameBranch(const Twin& t, double range) {
  ASSERT_EQ(t.si_units.points.size(), t.milli.points.size());
  for (std::size_t i = 0; i < t.si_units.points.size(); ++i) {
    const BranchPoint &a = t.si_units.points[i], &b = t.milli.points[i];
    EXPECT_NEAR(b.parameter / (1000 * a.parameter), 1.0, 1e-9) << i;
    EXPECT_NEAR(b.period / a.period, 1.0, 1e-9) << i;
    EXPECT_NEAR(b.amplitude_pp / a.amplitude_pp, 1.0, 1e-7) << i;
    EXPECT_NEAR(b.arclength, a.arclength, 1e-9) << i;
    EXPECT_EQ(b.stable, a.stable) << i;
    EXPECT_NEAR(b.dp_ds / 1000, a.dp_ds, 1e-3 * range) << i;
  }
  ASSERT_EQ(t.si_units.events.size(), t.milli.events.size());
  for (std::size_t i = 0; i < t.si_units.events.size(); ++i) {
    EXPECT_EQ(t.milli.events[i].kind, t.si_units.events[i].kind) << i;
    EXPECT_EQ(t.milli.events[i].after, t.si_units.events[i].after) << i;
    EXPECT_NEAR(t.milli.events[i].parameter / (1000 * t.si_units.events[i].parameter), 1.0, 1e-7)
        << i;
  }
  EXPECT_EQ(t.milli.reached_end, t.si_units.reached_end);
  EXPECT_EQ(t.milli.lost, t.si_units.lost);
}

TEST(OrbitScaledNorm, TheBeltsBranchIsTheSameInMetresAndMillimetresPerSecond) {
  // The stick-slip branch of the paper's belt, three points from 1 m/s.
  const Twin t = twin({}, 1.0, 1.5, 3);
  ASSERT_EQ(t.si_units.points.size(), 3u) << t.si_units.stop_reason;
  expectSameBranch(t, 0.5);
  // A step of 0.1 of the balance moves the speed by a tenth of the range or less.
  for (std::size_t i = 1; i < t.si_units.points.size(); ++i) {
    const double dp = t.si_units.points[i].parameter - t.si_units.points[i - 1].parameter;
    EXPECT_GT(dp, 0.0) << i;
    EXPECT_LE(dp, 0.4 * 0.5 + 1e-12) << i;  // at most max_step = 4 x 0.1 of the range 0.5
  }
  // The weights: the period's is the first period, the parameter's the range.
  ASSERT_EQ(t.milli.weights.size(), t.si_units.weights.size());
  const Eigen::Index n = t.si_units.weights.size();
  EXPECT_EQ(t.si_units.weights[n - 1], 0.5);
  EXPECT_EQ(t.milli.weights[n - 1], 500.0);
  EXPECT_EQ(t.si_units.weights[n - 2], t.si_units.points.front().period);
}

TEST(OrbitScaledNorm, TheDampedBeltsFoldAndHopfPointAtTheDefaultStepInEitherUnit) {
  // The damped Stribeck belt of orbit_branch_test: stable stick-slip up to a fold of cycles
  // beyond the Hopf speed v_H, then the unstable cycle shrinking into the Hopf point.
  const Twin t = twin({"friction=stribeck", "springs[wall_spring].damping=10"}, 0.15, 0.5, 40);
  const study::BranchResult& r = t.si_units;
  const double v_h = DampedStribeckBelt{10.0}.hopfSpeed();
  ASSERT_EQ(r.events.size(), 3u) << r.stop_reason;
  EXPECT_EQ(r.events[0].kind, BranchEventKind::kFold);
  EXPECT_EQ(r.events[1].kind, BranchEventKind::kStabilityChange);
  EXPECT_EQ(r.events[2].kind, BranchEventKind::kHopf);
  // The fold beyond v_H (measured 0.25975, as the SI norm's branch at its chosen step finds
  // it), the Hopf point at v_H (measured 1.3e-7 off the closed form).
  EXPECT_GT(r.events[0].parameter, v_h + 0.02);
  EXPECT_LT(r.events[0].parameter, v_h + 0.04);
  EXPECT_NEAR(r.events[2].parameter, v_h, 1e-5);
  EXPECT_FALSE(r.lost) << r.stop_reason;
  expectSameBranch(t, 0.35);
}

}  // namespace
}  // namespace tribo
