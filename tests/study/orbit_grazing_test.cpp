// Grazing of a law with a kink (study/orbit/branch_grazing.hpp, orbit_branch.cpp): where the
// damped belt's stable stick-slip cycle stops sticking as the belt speeds up, located by the
// continuation past its last regular point, against the belt speed where the paper's
// one-degree-of-freedom model with the wall damper c (tests/support/one_dof_belt.hpp: RK4 at
// the scene's 1 ms, sharing nothing with the engine but the friction law) stops sticking:
//   m x'' = -k x - c x' + mu(v_b - x') m g,
// started stuck at the break-away point (x = (mu_s m g - c v_b) / k, x' = v_b), a point of
// the stick-slip cycle; it sticks at v_b when its slip speed still falls below the law's stick
// speed over the last 20 s of 300 (the cycle's multipliers there are at most 0.95: 260
// periods bring any start onto it). The speed is bisected to 1e-9 m/s.
// The same grazing point as a corner of the branch from the Hopf point, against the same
// model and the Hopf speed's closed form (OrbitGrazingCorner, below).
// And the bracketing itself on made-up sides whose boundary is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/simulator.hpp"
#include "friction/friction_law.hpp"
#include "io/scene_loader.hpp"
#include "study/orbit/branch_grazing.hpp"
#include "study/orbit/orbit_branch.hpp"
#include "support/one_dof_belt.hpp"

namespace tribo {
namespace {

using study::branch::bracketGrazing;
using study::branch::GrazingSide;

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

TEST(BracketGrazing, TheBracketHoldsTheBoundaryAndIsAsNarrowAsAsked) {
  for (const double boundary : {1.0 + 1e-7, 1.0003, 1.0049, 1.02}) {
    for (const GrazingSide beyond : {GrazingSide::kCrossed, GrazingSide::kNone}) {
      int calls = 0;
      const auto g = bracketGrazing(1.0, 1.0, 1e-3, 1e-6, 4, 40, [&](double p) {
        ++calls;
        return p < boundary ? GrazingSide::kSame : beyond;
      });
      SCOPED_TRACE(boundary);
      EXPECT_EQ(calls, g.evaluations);
      if (boundary > 1.0 + 15e-3) {  // beyond h + 2h + 4h + 8h: not reached
        EXPECT_FALSE(g.bracketed);
        EXPECT_NEAR(g.inside, 1.015, 1e-12);
        EXPECT_EQ(g.evaluations, 4);
        continue;
      }
      ASSERT_TRUE(g.bracketed);
      EXPECT_LT(g.inside, boundary);
      EXPECT_GE(g.outside, boundary);
      EXPECT_LE(g.outside - g.inside, 1e-6);
      EXPECT_EQ(g.outside_side, beyond);
    }
  }
}

TEST(BracketGrazing, ItSearchesDownwardsAndStopsAtItsBudget) {
  // Downwards from 2 towards a boundary at 1.9993; a budget of 6 probes leaves the bracket
  // wider than asked but still holding it.
  int calls = 0;
  const auto g = bracketGrazing(2.0, -1.0, 1e-3, 1e-9, 4, 6, [&](double p) {
    ++calls;
    return p > 1.9993 ? GrazingSide::kSame : GrazingSide::kCrossed;
  });
  EXPECT_EQ(calls, 6);
  ASSERT_TRUE(g.bracketed);
  EXPECT_GT(g.inside, 1.9993);
  EXPECT_LE(g.outside, 1.9993);
  EXPECT_GT(g.inside - g.outside, 1e-9);
  // No step, or no width: nothing probed.
  EXPECT_EQ(bracketGrazing(1.0, 1.0, 0.0, 1e-6, 4, 6, [](double) { return GrazingSide::kSame; })
                .evaluations,
            0);
}

// The scene's law, roh_yoo with its parameters in scenes/belt.yaml.
std::unique_ptr<const friction::FrictionLaw> beltLaw() {
  return friction::makeFrictionLaw(
      {"roh_yoo",
       {{"mu_s", 0.35}, {"mu_k", 0.3}, {"v_s", 0.01}, {"a", 1.5}, {"beta", 1.0 / 3.0}},
       {}});
}

// The damped one-degree-of-freedom model's stick-slip cycle at (m, c, v_b), settled over
// 300 s from the break-away point: the peak to peak of x over the last 20 s.
double oneDofCyclePp(const friction::FrictionLaw& law, double m, double c, double v_b) {
  const double k = 300.0, g = 9.81;
  const test::OneDofBelt belt{m, k, v_b, g, &law, c};
  double x = (0.35 * m * g - c * v_b) / k, v = v_b, lo = INFINITY, hi = -INFINITY;
  belt.run(x, v, 1e-3, 300000, [&](double t, double x_t, double) {
    if (t > 280.0) lo = std::min(lo, x_t), hi = std::max(hi, x_t);
  });
  return hi - lo;
}

// Whether the damped one-degree-of-freedom model sticks at belt speed v_b (above).
bool oneDofSticks(double m, double c, double v_b) {
  const auto law = beltLaw();
  const double k = 300.0, g = 9.81, h = 1e-3, v_s = 0.01;
  const test::OneDofBelt belt{m, k, v_b, g, law.get(), c};
  double x = (0.35 * m * g - c * v_b) / k, v = v_b, slowest = INFINITY;
  const long steps = 300000, tail = 20000;
  long i = 0;
  belt.run(x, v, h, steps, [&](double, double, double vs) {
    if (++i > steps - tail) slowest = std::min(slowest, std::abs(v_b - vs));
  });
  return slowest < v_s;
}

// Where `sticks` changes between lo (sticking) and hi (not), bisected to 1e-9.
template <typename Sticks>
double bisectGrazing(double lo, double hi, Sticks&& sticks) {
  EXPECT_TRUE(sticks(lo)) << lo;
  EXPECT_FALSE(sticks(hi)) << hi;
  while (std::abs(hi - lo) > 1e-9) {
    const double mid = 0.5 * (lo + hi);
    (sticks(mid) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The belt speed where the damped one-degree-of-freedom model stops sticking.
double oneDofGrazingSpeed(double m, double c, double lo, double hi) {
  return bisectGrazing(lo, hi, [&](double v_b) { return oneDofSticks(m, c, v_b); });
}

struct GrazingCase {
  double m, c;      // the box's mass [kg], the wall damper [N s/m]
  double from, to;  // the continuation's range in v_b
  double lo, hi;    // the reference's bracket
  const char* name;
  const char* id;  // the case's suffix in the test's name
};

void PrintTo(const GrazingCase& k, std::ostream* os) { *os << k.id; }

class OrbitGrazing : public ::testing::TestWithParam<GrazingCase> {};

// The bound: the orbit's smallest slip speed is sampled once a step, and the sampled minimum
// lies above the true one by up to s'' dt^2 / 8, s'' the slip speed's curvature at its
// minimum, w_n^2 times the box's speed swing (about 30 s^-2 x 0.7 m/s on these cycles):
// 2.6e-6 m/s at 1 ms. Near grazing the smallest slip speed moves about 0.2 to 0.3 per unit
// of v_b, so grazing read off the samples can lie 1e-5 m/s of belt speed from the
// reference's, read off its drifting samples over 17 periods.
constexpr double kSampledBound = 2e-5;

TEST_P(OrbitGrazing, TheStableStickSlipEndsWhereTheOneDofModelStopsSticking) {
  const GrazingCase& k = GetParam();
  const double reference = oneDofGrazingSpeed(k.m, k.c, k.lo, k.hi);
  study::BranchSpec spec;
  spec.parameter = "v_b";
  spec.from = k.from;
  spec.to = k.to;
  spec.max_points = 40;
  spec.orbit.settle = 30.0;
  char m[64], c[64];
  std::snprintf(m, sizeof m, "m=%.17g", k.m);
  std::snprintf(c, sizeof c, "springs[wall_spring].damping=%.17g", k.c);
  const study::BranchResult r = study::continueOrbit(kBelt, {m, c}, spec);
  const auto e = std::find_if(r.events.begin(), r.events.end(), [](const study::BranchEvent& e) {
    return e.kind == study::BranchEventKind::kGrazing;
  });
  ASSERT_NE(e, r.events.end()) << r.stop_reason;
  std::printf("%s: grazing at v_b = %.9f (one-dof model %.9f, %+.2e), %zu points, %.1f s: %s\n",
              k.name, e->parameter, reference, e->parameter - reference, r.points.size(), r.seconds,
              r.stop_reason.c_str());
  EXPECT_NEAR(e->parameter, reference, kSampledBound);
  // Before it, the last sticking orbit is stable and sticks within 1e-3 of the stick speed:
  // the cycle still exists there, at the point of losing its sticking phase.
  const study::BranchPoint& before = r.points[e->before];
  EXPECT_TRUE(before.stable);
  EXPECT_LT(before.min_slip, 0.01);
  EXPECT_GT(before.min_slip, 0.01 * (1 - 1e-3));
  if (e->before == e->after) {  // the branch's end: no orbit past it
    EXPECT_EQ(e->before, r.points.size() - 1);
    EXPECT_TRUE(r.lost);
    EXPECT_NE(r.stop_reason.find("stop sticking (grazing)"), std::string::npos) << r.stop_reason;
    // Steady sliding is stable past the Hopf point: the reason says how to go round.
    EXPECT_NE(r.stop_reason.find("--from-hopf"), std::string::npos) << r.stop_reason;
  } else {  // passed: the orbit after it slips, just
    const study::BranchPoint& after = r.points[e->after];
    EXPECT_TRUE(after.fixed_parameter);
    EXPECT_GE(after.min_slip, 0.01);
    EXPECT_LT(after.min_slip, 0.01 * (1 + 1e-3));
  }
}

// Three cycles ending at three belt speeds: the scene's box with a light damper, a box four
// times as heavy with a heavier one (from near its grazing point, and from 1 m/s with steps
// ten times as long: there no orbit is found past the bracket, and the branch ends at it),
// and a damper that ends stick-slip at a third of the speed (the shortest: the one the
// sanitized build runs, tests/release_only.txt).
INSTANTIATE_TEST_SUITE_P(
    DampedBelts, OrbitGrazing,
    ::testing::Values(GrazingCase{10.0, 1.5, 0.6, 0.8, 0.6, 0.9, "10 kg, 1.5 N s/m", "m10_c1p5"},
                      GrazingCase{40.0, 5.0, 1.2, 1.26, 1.0, 1.5, "40 kg, 5 N s/m", "m40_c5"},
                      GrazingCase{40.0, 5.0, 1.0, 2.0, 1.0, 1.5, "40 kg, 5 N s/m, from 1 m/s",
                                  "m40_c5_from1"},
                      GrazingCase{10.0, 1.8, 0.25, 0.27, 0.2, 0.3, "10 kg, 1.8 N s/m", "m10_c1p8"}),
    [](const ::testing::TestParamInfo<GrazingCase>& info) { return std::string(info.param.id); });

// From the Hopf point of the damped belt (subcritical: steady sliding is stable past it, c =
// -m g mu'(v_b) there), the unstable cycles that never stick grow until they meet the stable
// sticking cycles where the one-dof model stops sticking: the branch turns at that corner (a
// fold, the change of stability and grazing, each once, there and nowhere else) and goes
// back along the sticking cycles to the range's end, where the last orbit's amplitude is the
// one-dof model's settled cycle's. Continued in the belt speed, or in the box's mass at a
// fixed belt speed (there the corrector gives up on the unstable cycles 18% above the stick
// speed, the corner's events are interpolated between points 8e-4 kg apart, and before the
// check of a jump across grazing the branch jumped from an unstable cycle at 9.99 kg to a
// sticking one at 9.96 kg and reported both events there).
struct CornerCase {
  double m, c;      // the box's mass [kg] (unused when continued in m), the damper [N s/m]
  double v_b;       // the belt speed, continued in m; 0: continued in v_b
  double from, to;  // the continuation's range
  double lo, hi;    // the grazing reference's bracket (lo sticks)
  double bound;     // how far from the reference the events may lie
  const char* id;
};

void PrintTo(const CornerCase& k, std::ostream* os) { *os << k.id; }

class OrbitGrazingCorner : public ::testing::TestWithParam<CornerCase> {};

TEST_P(OrbitGrazingCorner, TheHopfPointsUnstableCyclesTurnOntoTheStickingOnesAtGrazing) {
  const CornerCase& k = GetParam();
  const bool in_mass = k.v_b > 0.0;
  const auto law = beltLaw();
  auto slope = [&](double v) {  // mu' by central differences
    const double h = 1e-6;
    return (law->coefficient(v + h) - law->coefficient(v - h)) / (2 * h);
  };
  // The Hopf point: in m, m_H = -c / (g mu'(v_b)); in v_b, where c + m g mu'(v_b) changes
  // sign.
  double hopf = -k.c / (9.81 * slope(k.v_b));
  if (!in_mass) {
    auto net_damping = [&](double v) { return k.c + k.m * 9.81 * slope(v); };
    double h_lo = k.from, h_hi = k.to;
    EXPECT_LT(net_damping(h_lo) * net_damping(h_hi), 0.0);
    while (h_hi - h_lo > 1e-12) {
      const double mid = 0.5 * (h_lo + h_hi);
      (net_damping(mid) * net_damping(h_lo) > 0.0 ? h_lo : h_hi) = mid;
    }
    hopf = 0.5 * (h_lo + h_hi);
  }
  const double grazing =
      in_mass ? bisectGrazing(k.lo, k.hi, [&](double m) { return oneDofSticks(m, k.c, k.v_b); })
              : oneDofGrazingSpeed(k.m, k.c, k.lo, k.hi);

  study::BranchSpec spec;
  spec.parameter = in_mass ? "m" : "v_b";
  spec.from = k.from;
  spec.to = k.to;
  spec.from_hopf = true;
  spec.max_points = 40;
  spec.orbit.settle = 30.0;
  char m[64], c[64], v[64];
  std::snprintf(m, sizeof m, "m=%.17g", k.m);
  std::snprintf(c, sizeof c, "springs[wall_spring].damping=%.17g", k.c);
  std::snprintf(v, sizeof v, "v_b=%.17g", k.v_b);
  const study::BranchResult r = study::continueOrbit(
      kBelt, in_mass ? std::vector<std::string>{c, v} : std::vector<std::string>{m, c}, spec);
  std::printf("%s: Hopf %.9f (closed form %.9f), grazing reference %.9f, %zu points, %.1f s: %s\n",
              k.id, r.hopf_parameter, hopf, grazing, r.points.size(), r.seconds,
              r.stop_reason.c_str());
  EXPECT_NEAR(r.hopf_parameter, hopf, 1e-6 * std::max(1.0, hopf));
  ASSERT_TRUE(r.reached_end) << r.stop_reason;

  // Unstable and slipping on the Hopf point's side of the corner; stable and sticking past it.
  const auto first_sticking =
      std::find_if(r.points.begin(), r.points.end(),
                   [](const study::BranchPoint& p) { return p.min_slip < 0.01; });
  ASSERT_NE(first_sticking, r.points.end());
  for (auto p = r.points.begin(); p != r.points.end(); ++p) {
    SCOPED_TRACE(p->parameter);
    if (p >= first_sticking) {
      EXPECT_LT(p->min_slip, 0.01);
      EXPECT_TRUE(p->stable);
    } else if ((p->parameter - grazing) * (hopf - grazing) > 0.0 &&
               std::abs(p->parameter - grazing) > k.bound) {
      EXPECT_FALSE(p->stable);
    }
  }
  // The turn's three events, once each, at the model's grazing point.
  for (const study::BranchEventKind kind :
       {study::BranchEventKind::kFold, study::BranchEventKind::kStabilityChange,
        study::BranchEventKind::kGrazing}) {
    SCOPED_TRACE(study::branchEventName(kind));
    EXPECT_EQ(std::count_if(r.events.begin(), r.events.end(),
                            [&](const study::BranchEvent& e) { return e.kind == kind; }),
              1);
  }
  for (const study::BranchEvent& e : r.events) {
    std::printf("  %s at %.9f (%+.2e)\n", study::branchEventName(e.kind).c_str(), e.parameter,
                e.parameter - grazing);
    EXPECT_NEAR(e.parameter, grazing, k.bound) << study::branchEventName(e.kind);
  }

  // The last orbit, far along the sticking cycles, against the model's cycle there: settled
  // over 300 s from the break-away point, its peak to peak over the last 20 s.
  const study::BranchPoint& last = r.points.back();
  const double model = in_mass ? oneDofCyclePp(*law, last.parameter, k.c, k.v_b)
                               : oneDofCyclePp(*law, k.m, k.c, last.parameter);
  std::printf("  last at %s = %.6f: amplitude %.9f (model %.9f)\n", spec.parameter.c_str(),
              last.parameter, last.amplitude_pp, model);
  EXPECT_NEAR(last.amplitude_pp, model, 1e-3 * model);
}

// The scene's box with a light damper, a box four times as heavy with a heavier one, a damper
// that moves both points to a third of the speed, and the first continued in the mass at a
// belt speed just below its corner (in v_b).
INSTANTIATE_TEST_SUITE_P(
    DampedBelts, OrbitGrazingCorner,
    ::testing::Values(CornerCase{10.0, 1.5, 0.0, 0.5, 2.0, 0.6, 0.9, kSampledBound, "m10_c1p5"},
                      CornerCase{40.0, 5.0, 0.0, 1.0, 2.0, 1.0, 1.5, kSampledBound, "m40_c5"},
                      CornerCase{10.0, 1.8, 0.0, 0.2, 0.5, 0.2, 0.3, kSampledBound, "m10_c1p8"},
                      CornerCase{10.0, 1.5, 0.72, 5.0, 20.0, 10.5, 9.0, 2e-3,
                                 "vb0p72_c1p5_in_mass"}),
    [](const ::testing::TestParamInfo<CornerCase>& info) { return std::string(info.param.id); });

// Between the Hopf point and the corner, stick-slip and steady sliding are both stable: a run
// started at rest (the scene's start, the spring unstretched: outside the unstable cycle
// there) lands on stick-slip, and one started on steady sliding (the box where the spring
// balances mu(v_b) m g) stays there, at the same belt speed. The stick-slip against the
// one-dof model's cycle at that speed (peak to peak, 1e-3; settled from the break-away
// point), steady sliding against no oscillation at all. 10 kg with 1.5 N s/m at 0.71 m/s
// (Hopf point 0.70567, corner 0.73204; from rest the motion spirals out to the cycle over
// about 300 s), and 40 kg with 5 N s/m at 1.16 m/s (1.15533 and 1.23044).
TEST(OrbitGrazingHysteresis, FromRestItSticksAndSlipsFromSteadySlidingItSlidesOnAtTheSameSpeed) {
  struct Case {
    double m, c, v_b, settle;
  };
  for (const Case k : {Case{10.0, 1.5, 0.71, 350.0}, Case{40.0, 5.0, 1.16, 120.0}}) {
    SCOPED_TRACE(k.m);
    const double spring = 300.0, g = 9.81;
    const auto law = beltLaw();
    const double cycle = oneDofCyclePp(*law, k.m, k.c, k.v_b);
    // The engine's box from x0 for `seconds`: its peak to peak over the last 10 s.
    auto engine_pp = [&](double x0, double seconds) -> double {
      char m[64], c[64], vb[64], x0s[64];
      std::snprintf(m, sizeof m, "m=%.17g", k.m);
      std::snprintf(c, sizeof c, "springs[wall_spring].damping=%.17g", k.c);
      std::snprintf(vb, sizeof vb, "v_b=%.17g", k.v_b);
      std::snprintf(x0s, sizeof x0s, "x0=%.17g", x0);
      const io::Scene scene = io::loadScene(kBelt, {m, c, vb, x0s});
      std::size_t box = 0;
      while (scene.model->bodies[box].name != "box") ++box;
      Simulator sim(scene.model);
      const double h = scene.model->options.time_step;
      const long steps = std::lround(seconds / h), tail = std::lround(10.0 / h);
      double x_lo = INFINITY, x_hi = -INFINITY;
      for (long i = 0; i < steps; ++i) {
        const StepStatus status = sim.step();
        if (!status.ok) {
          ADD_FAILURE() << status.message;
          return NAN;
        }
        if (i >= steps - tail) {
          x_lo = std::min(x_lo, sim.state().bodies[box].position.x());
          x_hi = std::max(x_hi, sim.state().bodies[box].position.x());
        }
      }
      return x_hi - x_lo;
    };
    const double from_rest = engine_pp(0.0, k.settle);
    const double from_sliding = engine_pp(law->coefficient(k.v_b) * k.m * g / spring, 60.0);
    std::printf(
        "%g kg, %g N s/m at %g m/s: from rest %.9f m peak to peak (one-dof model's "
        "cycle %.9f), from steady sliding %.3g m\n",
        k.m, k.c, k.v_b, from_rest, cycle, from_sliding);
    EXPECT_NEAR(from_rest, cycle, 1e-3 * cycle);
    EXPECT_LT(from_sliding, 1e-9 * cycle);
  }
}

}  // namespace
}  // namespace tribo
