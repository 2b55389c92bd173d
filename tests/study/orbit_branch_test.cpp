// Continuation of periodic orbits (study/orbit/orbit_branch.hpp) against independent
// expectations: the belt's stick-slip branch in the belt speed, each of three points' period
// and amplitude against the paper's one-degree-of-freedom model integrated in the test at that
// point's speed (tests/study/one_dof_cycle.hpp, the reference periodic_orbit_test uses, held
// to the same 1e-3); and the event detector on made-up branches whose events are known by
// construction (a fold where dp/ds changes sign, a real multiplier through -1, a complex pair
// through the unit circle, a real one through +1, the smallest slip speed through the stick
// speed); and a real fold of cycles: the damped belt with Stribeck's law, whose subcritical
// Hopf point (located in closed form here) sends an unstable cycle up to meet the stick-slip
// one.
#include "study/orbit/orbit_branch.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "io/scene_parameters.hpp"
#include "one_dof_cycle.hpp"
#include "stribeck_hopf.hpp"

namespace tribo {
namespace {

using study::BranchEventKind;
using study::BranchPoint;
using Mu = std::complex<double>;

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

TEST(OrbitBranch, TheBeltsBranchInBeltSpeedIsTheOneDofModelsCycleAtEachPoint) {
  const auto wall = std::chrono::steady_clock::now();
  study::BranchSpec spec;
  spec.parameter = "v_b";
  spec.from = 1.0;
  spec.to = 1.5;
  spec.step = 0.2;
  spec.max_points = 6;
  spec.orbit.settle = 30.0;
  std::size_t reported = 0;
  const study::BranchResult r =
      study::continueOrbit(kBelt, {}, spec, [&](const BranchPoint&, std::size_t i) {
        EXPECT_EQ(i, reported);
        ++reported;
      });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
  ASSERT_TRUE(r.reached_end) << r.stop_reason;
  ASSERT_GE(r.points.size(), 3u);
  EXPECT_EQ(reported, r.points.size());
  EXPECT_EQ(r.points.front().parameter, 1.0);
  EXPECT_GE(r.points.back().parameter, 1.5);
  // The first, a middle and the last point, each at the speed the continuation put it at.
  for (std::size_t i : {std::size_t{0}, r.points.size() / 2, r.points.size() - 1}) {
    const BranchPoint& p = r.points[i];
    const ReferenceCycle ref = oneDofCycle(10.0, p.parameter);
    EXPECT_NEAR(p.period / ref.period, 1.0, 1e-3) << i << ": v_b " << p.parameter;
    EXPECT_NEAR(p.amplitude_pp / ref.amplitude_pp, 1.0, 1e-3) << i << ": v_b " << p.parameter;
    EXPECT_LE(p.residual, 1e-9) << i;
    // Sticking: the smallest slip speed below the stick speed, for the reference's share of
    // the period (measured within 5e-4 of it; 3e-3 is three of the orbit's 1 ms samples in
    // its 1.15 s period). Period and amplitude came out within 1e-6 and 4e-7 (relative).
    EXPECT_LT(p.min_slip, 0.01) << i;
    EXPECT_NEAR(p.stick_fraction, ref.stick_fraction, 3e-3) << i << ": v_b " << p.parameter;
  }
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const BranchPoint& p = r.points[i];
    // Stick-slip all along: the stick phase collapses every non-trivial direction (as for a
    // single orbit), the belt speed grows monotonically along the branch, no event.
    EXPECT_TRUE(p.stable) << i;
    EXPECT_LT(p.largest, 0.05) << i;
    EXPECT_LT(p.trivial_error, 1e-3) << i;
    EXPECT_GT(p.dp_ds, 0.0) << i;
    if (i > 0) {
      EXPECT_GT(p.parameter, r.points[i - 1].parameter) << i;
      EXPECT_GT(p.arclength, r.points[i - 1].arclength) << i;
    }
  }
  EXPECT_TRUE(r.events.empty());
  RecordProperty("seconds", std::to_string(seconds));
}

// The speed where steady sliding on the damped belt turns stable (tests/study/stribeck_hopf.hpp).
double stribeckHopfSpeed(double c) { return DampedStribeckBelt{c}.hopfSpeed(); }

TEST(OrbitBranch, TheDampedBeltFoldsWhereStickSlipMeetsTheUnstableCycleOfItsSubcriticalHopf) {
  // Stribeck's smooth law and a 10 N s/m damper beside the wall spring: steady sliding is
  // stable above the Hopf speed v_H (closed form above, 0.2271 m/s), yet the stable
  // oscillation found below it goes on past v_H: the Hopf is subcritical, an unstable cycle
  // grows out of it towards higher speeds and meets the stable one in a fold of cycles. The
  // branch from 0.15 m/s must go up to the fold, lose its stability there, and come back down
  // as the unstable cycle, shrinking like sqrt(v_b - v_H) into the Hopf point, where its
  // period is the undamped one 2 pi sqrt(m / k) (the damper and the slope cancel).
  study::BranchSpec spec;
  spec.parameter = "v_b";
  spec.from = 0.15;
  spec.to = 0.5;
  spec.step = 0.02;
  spec.max_points = 30;
  spec.orbit.settle = 30.0;
  const study::BranchResult r =
      study::continueOrbit(kBelt, {"friction=stribeck", "springs[wall_spring].damping=10"}, spec);
  const double v_h = stribeckHopfSpeed(10.0);
  // Events: the fold with its stability change, then the Hopf point, where the branch stops
  // (measured: 18 points).
  ASSERT_EQ(r.events.size(), 3u) << r.stop_reason;
  EXPECT_EQ(r.events[0].kind, BranchEventKind::kFold);
  EXPECT_EQ(r.events[1].kind, BranchEventKind::kStabilityChange);
  EXPECT_EQ(r.events[2].kind, BranchEventKind::kHopf);
  const std::size_t fold_after = r.events[0].after;
  EXPECT_EQ(r.events[1].after, fold_after);
  EXPECT_EQ(r.events[2].after + 1, r.points.size());
  EXPECT_NE(r.stop_reason.find("Hopf"), std::string::npos) << r.stop_reason;
  EXPECT_FALSE(r.reached_end);
  // Stick-slip and steady sliding coexist above v_H: the fold lies beyond it (measured
  // 0.2598); the Hopf point, interpolated at the turn, is v_H (measured 0.227127 against
  // 0.227131).
  EXPECT_GT(r.events[0].parameter, v_h + 0.02);
  EXPECT_NEAR(r.events[2].parameter, v_h, 1e-3);
  // Stable up to the fold, unstable after it, going back down.
  const std::size_t nearest = r.events[2].before;  // the last point before the Hopf point
  for (std::size_t i = 0; i <= nearest; ++i) {
    EXPECT_EQ(r.points[i].stable, i < fold_after) << i << ": v_b " << r.points[i].parameter;
    if (i >= fold_after) {
      EXPECT_LT(r.points[i].dp_ds, 0.0) << i;
    }
  }
  // Into the Hopf point: the nearest point is small (3 mm of the fold's 8 cm), with the
  // undamped period (measured to 2.5e-5).
  const BranchPoint& last = r.points[nearest];
  EXPECT_NEAR(last.parameter, v_h, 1e-3);
  EXPECT_LT(last.amplitude_pp, 0.1 * r.points[fold_after].amplitude_pp);
  EXPECT_NEAR(last.period / (2.0 * std::numbers::pi * std::sqrt(10.0 / 300.0)), 1.0, 1e-3);
  // The amplitude grows like the square root of the distance to the Hopf point: A^2 / (v_b -
  // v_H) alike at the three points nearest it on the way down (measured within 12 %).
  const double ratio = std::pow(last.amplitude_pp, 2) / (last.parameter - v_h);
  for (std::size_t i : {nearest - 2, nearest - 1}) {
    const BranchPoint& p = r.points[i];
    EXPECT_NEAR(std::pow(p.amplitude_pp, 2) / (p.parameter - v_h) / ratio, 1.0, 0.25)
        << i << ": v_b " << p.parameter << ", A " << p.amplitude_pp;
  }
  // Steady sliding beside every point: unstable below v_H, stable above (the closed form),
  // so between v_H and the fold it coexists with the stable stick-slip: the hysteresis. Its
  // growth rate is (-c - mu'(v) m g) / (2 m) by the same closed form (measured to 1e-9 where
  // it grows); points within 2e-3 of v_H, where it nears 0, are not judged by sign.
  for (const BranchPoint& p : r.points) {
    ASSERT_TRUE(std::isfinite(p.steady_growth)) << p.parameter;
    if (std::abs(p.parameter - v_h) > 2e-3) {
      EXPECT_EQ(p.steady_growth > 0.0, p.parameter < v_h)
          << "v_b " << p.parameter << ": growth " << p.steady_growth;
    }
    if (p.parameter < v_h - 2e-3) {  // the growing mode is the in-plane one
      const double v = p.parameter, mu_slope_mg = 2.0 * 0.05 * v / (0.15 * 0.15) *
                                                  std::exp(-(v / 0.15) * (v / 0.15)) * 98.1;
      EXPECT_NEAR(p.steady_growth, (mu_slope_mg - 10.0) / 20.0, 1e-6) << "v_b " << v;  // 1e-9
    }
  }
}

TEST(OrbitBranch, RefusesAnUnknownOrNonNumericParameterBeforeAnyWork) {
  study::BranchSpec spec;
  spec.from = 1.0;
  spec.to = 2.0;
  spec.parameter = "nosuch";
  try {
    study::continueOrbit(kBelt, {}, spec);
    ADD_FAILURE() << "no error for an unknown parameter";
  } catch (const io::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("'nosuch'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("v_b"), std::string::npos) << e.what();
  }
  spec.parameter = "friction";
  try {
    study::continueOrbit(kBelt, {}, spec);
    ADD_FAILURE() << "no error for a non-numeric parameter";
  } catch (const io::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("expected a number"), std::string::npos) << e.what();
  }
  spec.parameter = "v_b";
  spec.to = 1.0;
  EXPECT_THROW(study::continueOrbit(kBelt, {}, spec), std::invalid_argument);
}

// A made-up point: parameter, arclength, dp/ds and non-trivial multipliers (the trivial 1 is
// added first).
BranchPoint point(double p, double s, double dp_ds, std::vector<Mu> others) {
  BranchPoint pt;
  pt.parameter = p;
  pt.arclength = s;
  pt.dp_ds = dp_ds;
  pt.multipliers.push_back(1.0);
  pt.trivial = 0;
  pt.stable = true;
  for (Mu mu : others) {
    pt.multipliers.push_back(mu);
    if (std::abs(mu) >= 1.0) pt.stable = false;
  }
  return pt;
}

TEST(BranchEvents, ARealMultiplierThroughMinusOneIsAPeriodDoublingLocatedByInterpolation) {
  const auto events = study::detectBranchEvents({point(1.0, 0.0, 1.0, {-0.5, 0.1}),
                                                 point(2.0, 1.0, 1.0, {-0.9, 0.1}),
                                                 point(3.0, 2.0, 1.0, {-1.1, 0.1})});
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, BranchEventKind::kPeriodDoubling);
  EXPECT_EQ(events[0].before, 1u);
  EXPECT_EQ(events[0].after, 2u);
  EXPECT_NEAR(events[0].parameter, 2.5, 1e-12);  // |mu| 0.9 -> 1.1: 1 half way
  EXPECT_EQ(study::branchEventName(events[0].kind), "period_doubling");
}

TEST(BranchEvents, AComplexPairThroughTheUnitCircleIsATorus) {
  const Mu in = std::polar(0.8, 1.0), out = std::polar(1.2, 1.1);
  const auto events = study::detectBranchEvents(
      {point(0.0, 0.0, -1.0, {in, std::conj(in)}), point(-1.0, 1.0, -1.0, {out, std::conj(out)})});
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, BranchEventKind::kTorus);
  EXPECT_NEAR(events[0].parameter, -0.5, 1e-12);
  EXPECT_EQ(study::branchEventName(events[0].kind), "torus");
}

TEST(BranchEvents, ASignChangeOfDpDsIsAFoldAtTheVertexOfTheInterpolatedParameter) {
  // p(s) = 2 - (s - 1.25)^2 sampled at s = 0, 1, 2: dp/ds = 2.5, 0.5, -1.5, the vertex
  // p = 2 at s = 1.25 between the second and third points; linear dp/ds in s is exact here.
  auto p = [](double s) { return 2.0 - (s - 1.25) * (s - 1.25); };
  // A real multiplier through +1 with it: the branch's stability changes at the fold too.
  const auto events = study::detectBranchEvents(
      {point(p(0), 0.0, 2.5, {0.5}), point(p(1), 1.0, 0.5, {0.9}), point(p(2), 2.0, -1.5, {1.3})});
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].kind, BranchEventKind::kFold);
  EXPECT_EQ(events[0].before, 1u);
  EXPECT_EQ(events[0].after, 2u);
  EXPECT_NEAR(events[0].parameter, 2.0, 1e-12);
  EXPECT_EQ(events[1].kind, BranchEventKind::kStabilityChange);
  EXPECT_EQ(study::branchEventName(events[0].kind), "fold");
}

// Near a fold at a kink (a joint stop engaging) the finite-difference tangent is noisy:
// dp/ds flips sign at points where the branch has not turned. p(s) = 4.2 - (s - 5.3)^2 / 100
// at s = 0..10 turns once, at s = 5.3; dp/ds is the exact slope with noise that flips its
// sign at s = 2, 4 and 8 (a made-up tangent, the points' parameters exact): one fold, at the
// interpolated vertex between the points at s = 5 and 6.
TEST(BranchEvents, ASignChangeOfDpDsWhereTheParametersDoNotTurnIsNoFold) {
  auto p = [](double s) { return 4.2 - (s - 5.3) * (s - 5.3) / 100.0; };
  auto slope = [](double s) { return -(s - 5.3) / 50.0; };
  const double noise[] = {0, 0, -0.1, 0, -0.1, 0, 0, 0, 0.2, 0, 0};
  std::vector<BranchPoint> points;
  for (int k = 0; k <= 10; ++k) points.push_back(point(p(k), k, slope(k) + noise[k], {0.5}));
  const auto events = study::detectBranchEvents(points);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, BranchEventKind::kFold);
  EXPECT_EQ(events[0].before, 5u);
  EXPECT_NEAR(events[0].parameter, 4.2, 1e-12);  // linear dp/ds is exact on a parabola
  // The same turn with the tangent's sign wrong at both points beside it (no sign change
  // there): the fold at the vertex of the parabola through the three points around the turn.
  points[5].dp_ds = -0.01;
  const auto turned = study::detectBranchEvents(points);
  ASSERT_EQ(turned.size(), 1u);
  EXPECT_EQ(turned[0].kind, BranchEventKind::kFold);
  EXPECT_EQ(turned[0].before, 5u);  // the vertex at s = 5.3, between the points at 5 and 6
  EXPECT_NEAR(turned[0].parameter, 4.2, 1e-12);
}

TEST(BranchEvents, TheSmallestSlipSpeedThroughTheStickSpeedIsGrazing) {
  std::vector<BranchPoint> points = {point(1.0, 0.0, 1.0, {0.1}), point(2.0, 1.0, 1.0, {0.1}),
                                     point(3.0, 2.0, 1.0, {0.1})};
  points[0].min_slip = 0.002;
  points[1].min_slip = 0.006;
  points[2].min_slip = 0.014;  // sticking ends between the last two, at 0.01: half way
  const auto events = study::detectBranchEvents(points, 0.01);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, BranchEventKind::kGrazing);
  EXPECT_EQ(events[0].before, 1u);
  EXPECT_NEAR(events[0].parameter, 2.5, 1e-12);
  EXPECT_EQ(study::branchEventName(events[0].kind), "grazing");
  EXPECT_TRUE(study::detectBranchEvents(points).empty());  // no stick speed: not looked for
}

TEST(BranchEvents, ATurnWhereTheOrbitShrinksToNothingIsAHopfPoint) {
  // p - p_H = A^2 on both sides of the turn (the orbit from its maximum, then from its
  // minimum): the turn at the smallest amplitude is the Hopf point.
  std::vector<BranchPoint> points = {point(1.09, 0.0, -1.0, {1.2}), point(1.04, 0.1, -0.8, {1.1}),
                                     point(1.0025, 0.2, -0.2, {1.05}),
                                     point(1.01, 0.3, 0.6, {1.07})};
  const double amplitude[] = {0.3, 0.2, 0.05, 0.1};  // below 0.2 of the largest at the turn
  for (std::size_t i = 0; i < points.size(); ++i) points[i].amplitude_pp = amplitude[i];
  auto events = study::detectBranchEvents(points);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, BranchEventKind::kHopf);
  EXPECT_EQ(events[0].before, 2u);
  EXPECT_EQ(study::branchEventName(events[0].kind), "hopf");
  // The same turn with the orbit as large as before it: a fold.
  points[2].amplitude_pp = 0.25;
  points[3].amplitude_pp = 0.3;
  events = study::detectBranchEvents(points);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, BranchEventKind::kFold);
}

TEST(BranchEvents, NoEventWhereNothingCrosses) {
  // Multipliers that move inside the unit circle, a negative one staying above -1, a pair
  // turning real: no crossing, and dp/ds keeps its sign.
  const Mu pair = std::polar(0.7, 2.0);
  EXPECT_TRUE(study::detectBranchEvents({point(1.0, 0.0, 1.0, {-0.2, pair, std::conj(pair)}),
                                         point(1.5, 0.6, 0.8, {-0.95, 0.6, 0.5}),
                                         point(2.0, 1.2, 0.1, {-0.99, 0.3, 0.2})})
                  .empty());
  // A stable branch that turns unstable without a crossing the kinds above name (a pair
  // that turned real outside): a plain stability change.
  const auto events = study::detectBranchEvents(
      {point(1.0, 0.0, 1.0, {pair, std::conj(pair)}), point(2.0, 1.0, 1.0, {1.4, 0.3})});
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, BranchEventKind::kStabilityChange);
}

TEST(BranchEvents, AStabilityChangeLiesBetweenTheDecidedPointsAroundUndecidedOnes) {
  // Undecided: a multiplier on the unit circle within the flow's accuracy (stable false).
  auto undecided = [](BranchPoint pt) {
    pt.undecided = true;
    pt.stable = false;
    return pt;
  };
  // Stable (|mu| 0.5), undecided, unstable (1.5): one change between the first and the last,
  // where |mu| interpolated between them crosses 1 (half way: p = 2).
  auto events = study::detectBranchEvents({point(1.0, 0.0, 1.0, {0.5}),
                                           undecided(point(2.0, 1.0, 1.0, {1.0 + 1e-9})),
                                           point(3.0, 2.0, 1.0, {1.5})});
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, BranchEventKind::kStabilityChange);
  EXPECT_EQ(events[0].before, 0u);
  EXPECT_EQ(events[0].after, 2u);
  EXPECT_NEAR(events[0].parameter, 2.0, 1e-12);
  // Stable on both sides of two undecided points: no change, whatever `stable` says between.
  EXPECT_TRUE(study::detectBranchEvents(
                  {point(1.0, 0.0, 1.0, {0.5}), undecided(point(2.0, 1.0, 1.0, {1.0 - 1e-9})),
                   undecided(point(3.0, 2.0, 1.0, {1.0 + 1e-9})), point(4.0, 3.0, 1.0, {0.6})})
                  .empty());
  // A period doubling between the decided points explains their change: no second event.
  events = study::detectBranchEvents({point(1.0, 0.0, 1.0, {-0.5}),
                                      undecided(point(2.0, 1.0, 1.0, {-1.0 - 1e-9})),
                                      point(3.0, 2.0, 1.0, {-1.5})});
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, BranchEventKind::kPeriodDoubling);
  EXPECT_EQ(events[0].before, 0u);
  EXPECT_EQ(events[0].after, 2u);
  // Only undecided points: nothing to compare.
  EXPECT_TRUE(study::detectBranchEvents(
                  {undecided(point(1.0, 0.0, 1.0, {1.0})), undecided(point(2.0, 1.0, 1.0, {1.0}))})
                  .empty());
}

}  // namespace
}  // namespace tribo
