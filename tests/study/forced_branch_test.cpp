// Branches of forced orbits (study/orbit/orbit_branch.hpp, a scene whose inputs vary in time):
// the frequency response followed in the forcing frequency, against expectations from outside
// the continuation:
// - the forced linear oscillator (scenes/forced_oscillator.yaml) across its resonance: every
//   point's amplitude is the closed form 2 F0 / sqrt((k - m w^2)^2 + (c w)^2), its period the
//   forcing's 1 / f, and both multipliers of the damped oscillator over one period have the
//   modulus exp(-c T / (2 m)); no fold, no event;
// - the forced pendulum (scenes/forced_pendulum.yaml), whose restoring torque softens with the
//   swing: its response folds twice, stable below the first fold, unstable between the folds,
//   stable after the second; at a frequency between the folds a plain simulation started at
//   rest settles on the small stable swing and one started from a large swing on the large
//   one, each the branch's stable response there (the hysteresis a frequency sweep shows as
//   a jump);
// - the oscillator's damping followed down to the scene's refusal of c < 0 with a largest step
//   far below the first: the branch ends within two of its smallest steps of c = 0;
// - the undamped oscillator (c = 0) from 0.55 to 0.9 of its resonance frequency, at three
//   masses: its response is the closed form 2 F0 / |k - m w^2| and both multipliers
//   exp(+-i w_n T) lie on the unit circle, so no point is stable or unstable (every one
//   undecided, no event); with a damper of 1e-3 N s/m per kg (|mu| = 1 - 5e-4 T) every point
//   is decided stable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "study/csv_text.hpp"
#include "study/orbit/orbit_branch.hpp"

namespace tribo {
namespace {

using study::BranchEventKind;
using study::BranchPoint;

const std::string kOscillator = std::string(TRIBO_SOURCE_DIR) + "/scenes/forced_oscillator.yaml";
const std::string kPendulum = std::string(TRIBO_SOURCE_DIR) + "/scenes/forced_pendulum.yaml";

// The branch in the forcing frequency f with the scaled arclength norm (SI would weigh a
// velocity in m/s against f in Hz) and a first step of `step` in its units.
study::BranchSpec frequencySpec(double from, double to, int max_points, double step) {
  study::BranchSpec spec;
  spec.norm = study::ArclengthNorm::kScaled;
  spec.step = step;
  spec.parameter = "f";
  spec.from = from;
  spec.to = to;
  spec.max_points = max_points;
  return spec;
}

TEST(ForcedBranch, TheLinearOscillatorsResponseAcrossResonanceIsTheClosedForm) {
  // m 1 kg, k 100 N/m (resonance 1.59 Hz), c 2 N s/m, F0 10 N: from 0.8 to 2.5 Hz.
  const double m = 1.0, k = 100.0, c = 2.0, F0 = 10.0;
  const study::BranchResult r =
      study::continueOrbit(kOscillator, {}, frequencySpec(0.8, 2.5, 60, 0.3));
  ASSERT_TRUE(r.reached_end) << r.stop_reason;
  EXPECT_TRUE(r.forced);
  ASSERT_GE(r.points.size(), 6u);
  double largest = 0.0;
  for (const BranchPoint& p : r.points) {
    const double w = 2.0 * std::numbers::pi * p.parameter;
    const double closed = 2.0 * F0 / std::hypot(k - m * w * w, c * w);
    // RK4 at 1 ms: measured within 7e-6 over the range.
    EXPECT_NEAR(p.amplitude_pp / closed, 1.0, 1e-4) << "f " << p.parameter;
    // The period row T = 1 / f, solved with the others to the corrector's tolerance (1e-9).
    EXPECT_NEAR(p.period * p.parameter, 1.0, 1e-9) << "f " << p.parameter;
    EXPECT_EQ(p.trivial, -1);
    EXPECT_TRUE(p.stable);
    ASSERT_GE(p.multipliers.size(), 2u);
    // Both multipliers exp((-zeta w_n +- i w_d) T): measured within 5e-8.
    EXPECT_NEAR(std::abs(p.multipliers[0]), std::exp(-c * p.period / (2 * m)), 1e-6)
        << "f " << p.parameter;
    EXPECT_GT(p.dp_ds, 0.0);
    largest = std::max(largest, p.amplitude_pp);
  }
  EXPECT_TRUE(r.events.empty());
  // The branch went through the resonance: its largest response near the peak's
  // 2 F0 / (c w_n sqrt(1 - zeta^2)) (the points lie where they lie: within 15%).
  EXPECT_GT(largest, 0.85 * 2.0 * F0 / (c * 10.0));
}

// The observed coordinate's peak to peak over the last forcing period of a plain run of
// `seconds` at frequency f from the swing angle theta0 (at rest).
double settledAmplitude(double f, double theta0, double seconds) {
  const io::Scene scene = io::loadScene(
      kPendulum, {"f=" + study::csvNumber(f, 17), "theta0=" + std::to_string(theta0)});
  Simulator sim(scene.model);
  const double h = scene.model->options.time_step;
  const long steps = std::lround(seconds / h), last = std::lround(1.0 / (f * h));
  double lo = INFINITY, hi = -INFINITY;
  for (long i = 0; i < steps; ++i) {
    const StepStatus status = sim.step();
    if (!status.ok) {
      ADD_FAILURE() << status.message;
      return NAN;
    }
    if (i >= steps - last) {
      lo = std::min(lo, sim.state().bodies[0].position.x());
      hi = std::max(hi, sim.state().bodies[0].position.x());
    }
  }
  return hi - lo;
}

TEST(ForcedBranch, ThePendulumsFoldsBoundTheRangeWhereSmallAndLargeSwingsAreBothStable) {
  const study::BranchResult r =
      study::continueOrbit(kPendulum, {}, frequencySpec(0.40, 0.50, 120, 1.0));
  ASSERT_TRUE(r.reached_end) << r.stop_reason;
  // Two folds, each with the real multiplier through +1 between the same points (measured:
  // 0.4637 and 0.4329 Hz), and nothing else.
  ASSERT_EQ(r.events.size(), 4u) << r.stop_reason;
  EXPECT_EQ(r.events[0].kind, BranchEventKind::kFold);
  EXPECT_EQ(r.events[1].kind, BranchEventKind::kStabilityChange);
  EXPECT_EQ(r.events[2].kind, BranchEventKind::kFold);
  EXPECT_EQ(r.events[3].kind, BranchEventKind::kStabilityChange);
  const double upper = r.events[0].parameter, lower = r.events[2].parameter;
  EXPECT_GT(upper, lower + 0.01);
  // Stable, unstable between the folds, stable again; the frequency turns at each fold.
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const bool between = i >= r.events[0].after && i < r.events[2].after;
    EXPECT_EQ(r.points[i].stable, !between) << i << ": f " << r.points[i].parameter;
    EXPECT_EQ(r.points[i].dp_ds < 0.0, between) << i << ": f " << r.points[i].parameter;
  }
  // Between the folds: the stable point of the small swing (before the first fold) and that
  // of the large swing (after the second) nearest the middle of the range. A plain run of
  // 200 s (15 decay times of the small swing's damping) at each one's frequency, from rest and
  // from a 75-degree swing, settles on that point's response (measured within 1.5e-5 and
  // 1.2e-7).
  const double middle = 0.5 * (upper + lower);
  const BranchPoint* small = nullptr;
  const BranchPoint* large = nullptr;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const BranchPoint& p = r.points[i];
    if (p.parameter <= lower || p.parameter >= upper) continue;
    const BranchPoint*& side = i < r.events[0].after ? small : large;
    if (i >= r.events[0].after && i < r.events[2].after) continue;  // the unstable middle
    if (!side || std::abs(p.parameter - middle) < std::abs(side->parameter - middle)) side = &p;
  }
  ASSERT_TRUE(small && large);
  EXPECT_GT(large->amplitude_pp, 2.0 * small->amplitude_pp);
  EXPECT_NEAR(settledAmplitude(small->parameter, 0.0, 200.0) / small->amplitude_pp, 1.0, 2e-4)
      << "f " << small->parameter;
  EXPECT_NEAR(settledAmplitude(large->parameter, 1.3, 200.0) / large->amplitude_pp, 1.0, 2e-4)
      << "f " << large->parameter;
}

TEST(ForcedBranch, AMaxStepFarBelowTheFirstStepStillHalvesDownToTheScenesBoundary) {
  // The oscillator's damping c followed down from a few starts, past the scene's refusal of
  // c < 0, with a first step of 1 and a largest step of 0.1 (so the steps are 0.1 at most).
  // The smallest step defaults to 1/64 of the smaller of the two, 0.1 / 64: the steps that
  // cross c = 0 are refused and halved until the branch ends within two of the smallest
  // steps of the boundary, saying why. (With 1/64 of the first step, 1/64 > 0.1 / 8, the
  // branch ended 0.006 to 0.018 short of the boundary from these starts.)
  const double largest = 0.1, smallest = largest / 64.0;
  for (const double from : {0.53, 0.61, 0.517}) {
    study::BranchSpec spec;
    spec.parameter = "c";
    spec.from = from;
    spec.to = -1.0;
    spec.step = 1.0;
    spec.max_step = largest;
    spec.max_points = 40;
    const study::BranchResult r = study::continueOrbit(kOscillator, {}, spec);
    ASSERT_TRUE(r.lost) << from << ": " << r.stop_reason;
    EXPECT_NE(r.stop_reason.find("damping must be >= 0"), std::string::npos) << r.stop_reason;
    // No contact, no stick speed to graze: the reason says nothing of grazing.
    EXPECT_EQ(r.stop_reason.find("grazing"), std::string::npos) << r.stop_reason;
    const double last = r.points.back().parameter;
    EXPECT_GE(last, 0.0) << from;
    EXPECT_LT(last, 2.0 * smallest) << from << ": " << r.stop_reason;
    for (std::size_t i = 1; i < r.points.size(); ++i)
      EXPECT_LE(r.points[i].step, largest * (1.0 + 1e-12)) << from << ", point " << i;
  }
}

struct Undamped {
  double m, k, c;
};

class UndampedOscillator : public ::testing::TestWithParam<Undamped> {};

TEST_P(UndampedOscillator, ItsForcedResponseIsNeitherStableNorUnstableAndADamperDecidesIt) {
  const Undamped u = GetParam();
  const double F0 = 10.0 * u.m;  // the same 2F0 / |k - m w^2| at every mass
  const double fn = std::sqrt(u.k / u.m) / (2.0 * std::numbers::pi);  // 1.59 Hz
  const std::vector<std::string> overrides = {
      "m=" + study::csvNumber(u.m, 17), "k=" + study::csvNumber(u.k, 17),
      "c=" + study::csvNumber(u.c, 17), "F0=" + study::csvNumber(F0, 17)};
  // From 0.55 to 0.9 of the resonance: T w_n = 2 pi fn / f stays off whole turns (at f = fn / 2
  // every orbit of period T is one: a family, no single response).
  const study::BranchResult r =
      study::continueOrbit(kOscillator, overrides, frequencySpec(0.55 * fn, 0.9 * fn, 40, 0.3));
  ASSERT_TRUE(r.reached_end) << r.stop_reason;
  ASSERT_GE(r.points.size(), 3u);
  for (const BranchPoint& p : r.points) {
    const double w = 2.0 * std::numbers::pi * p.parameter;
    const double closed = 2.0 * F0 / std::abs(u.k - u.m * w * w);
    EXPECT_NEAR(p.amplitude_pp / closed, 1.0, 1e-4) << "f " << p.parameter;
    ASSERT_GE(p.multipliers.size(), 2u);
    const double modulus = std::exp(-u.c * p.period / (2.0 * u.m));
    // The two leading ones (the others, the joint's constrained directions, vanish): the
    // finite-difference monodromy's moduli measured within 2.3e-7 of it.
    for (int i = 0; i < 2; ++i)
      EXPECT_NEAR(std::abs(p.multipliers[i]), modulus, 5e-7) << "f " << p.parameter;
    if (u.c == 0.0) {
      EXPECT_TRUE(p.undecided) << "f " << p.parameter << " |mu| " << p.largest;
      EXPECT_FALSE(p.stable) << "f " << p.parameter;
    } else {
      EXPECT_FALSE(p.undecided) << "f " << p.parameter << " |mu| " << p.largest;
      EXPECT_TRUE(p.stable) << "f " << p.parameter;
    }
  }
  for (const study::BranchEvent& e : r.events)
    ADD_FAILURE() << study::branchEventName(e.kind) << " at f " << e.parameter;
}

INSTANTIATE_TEST_SUITE_P(Masses, UndampedOscillator,
                         ::testing::Values(Undamped{1.0, 100.0, 0.0}, Undamped{0.01, 1.0, 0.0},
                                           Undamped{100.0, 1e4, 0.0}, Undamped{1.0, 100.0, 1e-3},
                                           Undamped{0.01, 1.0, 1e-5}),
                         [](const ::testing::TestParamInfo<Undamped>& info) {
                           const Undamped& u = info.param;
                           std::string name = u.m == 1.0  ? "one_kg"
                                              : u.m < 1.0 ? "ten_grams"
                                                          : "hundred_kg";
                           return name + (u.c == 0.0 ? "_undamped" : "_lightly_damped");
                         });

}  // namespace
}  // namespace tribo
